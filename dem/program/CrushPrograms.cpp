#include "dem/program/CrushPrograms.h"

#include "dem/program/LatticePacking.h"
#include "dem/program/RadiusGrowth.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace geocomp::dem {

namespace {
/// S2's contact: linear springs kn, ks, Coulomb mu, PFC rolling resistance mu_r.
ContactModel s2_contact(const CrushContact& c)
{
  LinearRolling::Parameters rp;
  rp.mu_r = c.rolling_friction;
  return LinearRollingResistance(LinearNormal::with_stiffness(c.normal_stiffness, c.restitution),
                                 LinearTangential::with_ratio(c.shear_stiffness / c.normal_stiffness),
                                 LinearRolling(rp));
}

void configure(DemSystem& sys, const CrushSetup& s)
{
  sys.set_contact_model(s2_contact(s.contact));
  sys.set_friction(s.contact.friction);
  sys.set_local_damping(s.contact.local_damping);
}

std::string kv(const std::string& key, double v)
{
  std::ostringstream o;
  o << key << '\t' << std::setprecision(10) << v;
  return o.str();
}

/// Percent passing by mass at sieves bin, 2 bin, ... up to the largest size.
Table gradation(const std::vector<double>& d, const std::vector<double>& m, double bin)
{
  Table t;
  t.columns = {"size_mm", "percent_passing"};
  if (d.empty()) return t;
  const double total = [&] {
    double a = 0.0;
    for (double x : m) a += x;
    return a;
  }();
  const double d_max = *std::max_element(d.begin(), d.end());
  const int n = int(std::ceil(d_max / bin - 1e-9));
  for (int k = 1; k <= n; ++k) {
    const double sieve = k * bin;
    double pass = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i)
      if (d[i] <= sieve * (1.0 + 1e-12)) pass += m[i];
    t.rows.push_back({sieve * 1e3, 100.0 * pass / total});
  }
  return t;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// @sect4{Single-particle crushing (S2 section 1.2)}

/// One particle of diameter `d` in `sys` (empty) crushed between two platens until
/// `monitor` breaks it or the platens have closed by half the diameter; appends its curve
/// rows (particle number `index`) and returns the particle's mass.
double crush_one(const CrushSetup& s, DemSystem& sys, BreakageMonitor& monitor, double d, double index, Table& curve)
{
  const double R = 0.5 * d;
  configure(sys, s);
  sys.add_sphere(Vec3::Zero(), R, s.density * s.density_scaling);
  const double mass = sys.particles().mass[0];
  PlaneWall bottom, top;
  bottom.point = Vec3(0, 0, -R);
  bottom.normal = Vec3::UnitZ();
  bottom.velocity = Vec3(0, 0, 0.5 * s.single.platen_speed);
  bottom.mu = s.contact.wall_friction;
  top = bottom;
  top.point = Vec3(0, 0, R);
  top.normal = -Vec3::UnitZ();
  top.velocity = -bottom.velocity;
  sys.add_wall(bottom);
  const std::size_t top_wall = sys.add_wall(top);
  sys.set_time_step(s.time_step_safety * sys.critical_time_step());
  // The platens may close by at most half the diameter (a particle below d_L never breaks).
  const auto max_steps = std::uint64_t(0.5 * d / s.single.platen_speed / sys.time_step()) + 1;
  for (std::uint64_t n = 0; n < max_steps && monitor.n_broken() == 0; ++n) {
    sys.step();
    if (sys.n_steps() % s.record_interval == 0)
      curve.rows.push_back({index, 1e3 * sys.time() * s.single.platen_speed, sys.wall(top_wall).force.norm()});
    monitor.after_step(sys);
  }
  return mass;
}

CrushResults single_particle(const CrushSetup& s, const std::function<void(const std::string&)>& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  CrushResults out;
  out.curve.columns = {"particle", "approach_mm", "force_N"};
  out.crushing.columns = {"particle", "diameter_mm", "crushing_force_N", "sigma_MPa", "children", "lost_mass_kg", "run"};
  out.fragments.columns = {"particle", "parent_diameter_mm", "child_diameter_mm", "relative_size", "run"};
  std::mt19937_64 sizes(s.single.seed);
  std::uniform_real_distribution<double> size(s.single.d_min, s.single.d_max);
  std::vector<double> child_d, child_m;
  double parent_mass = 0.0, child_mass = 0.0, lost = 0.0, sigma_sum = 0.0;
  std::uint64_t steps = 0;
  int broken = 0;
  const int total = s.single.particles * s.single.runs;
  for (int i = 0; i < total; ++i) {
    const double d = size(sizes), run = double(i / s.single.particles);
    DemSystem sys;
    BreakageMonitor::Settings b = s.breakage;
    b.seed = s.breakage.seed + std::uint64_t(i);
    BreakageMonitor monitor(b);
    parent_mass += crush_one(s, sys, monitor, d, double(i), out.curve);
    steps += sys.n_steps();
    if (monitor.n_broken() == 0) {
      out.crushing.rows.push_back({double(i), 1e3 * d, 0.0, 0.0, 0.0, 0.0, run});
      continue;
    }
    ++broken;
    const BreakageEvent& e = monitor.events().front();
    out.curve.rows.push_back({double(i), 1e3 * sys.time() * s.single.platen_speed, e.max_force});
    out.crushing.rows.push_back({double(i), 1e3 * d, e.max_force, 1e-6 * e.max_force / (d * d), double(e.children),
                                 e.lost_mass, run});
    sigma_sum += e.max_force / (d * d);
    lost += e.lost_mass;
    const ParticleStore& p = sys.particles();
    for (Index k = 0; k < p.size(); ++k) {
      out.fragments.rows.push_back({double(i), 1e3 * d, 2e3 * p.radius[k], 2.0 * p.radius[k] / d, run});
      child_d.push_back(2.0 * p.radius[k]);
      child_m.push_back(p.mass[k]);
      child_mass += p.mass[k];
    }
    if (progress && (i + 1) % std::max(1, total / 5) == 0)
      progress("particle " + std::to_string(i + 1) + "/" + std::to_string(total) + ", broken " + std::to_string(broken));
  }
  out.gradation = gradation(child_d, child_m, s.gradation_bin);
  out.summary = {kv("particles", s.single.particles), kv("runs", s.single.runs), kv("broken", broken),
                 kv("fragments", double(child_d.size())),
                 kv("mean_sigma_at_crushing_MPa", broken ? 1e-6 * sigma_sum / broken : 0.0),
                 kv("characteristic_strength_MPa", 1e-6 * s.breakage.criterion.strength),
                 kv("relative_mass_error", parent_mass > 0 ? (child_mass + lost) / parent_mass - 1.0 : 0.0),
                 kv("lost_mass_fraction", parent_mass > 0 ? lost / parent_mass : 0.0), kv("steps", double(steps)),
                 kv("wall_seconds", seconds_since(t0))};
  return out;
}

// @sect4{Uniaxial (oedometric) compression with breakage (S2 section 2.4)}

/// Radius fraction at which the "grown" packing is placed before growth, and the steps
/// of rest after it.
constexpr double kGrowthStart = 0.7;
constexpr std::uint64_t kGrowthRest = 5000;

/// per_edge^3 spheres of the uniaxial diameter times `start` at random in a cube box whose
/// edge gives the packing fraction at full size: $L = (n \tfrac{\pi}{6} d^3 / \eta)^{1/3}$.
Packing random_start(const UniaxialSetup& u, double start, double rho)
{
  const std::size_t n = std::size_t(u.per_edge) * std::size_t(u.per_edge) * std::size_t(u.per_edge);
  const double L = std::cbrt(double(n) * M_PI / 6.0 * std::pow(u.diameter, 3) / u.packing_fraction);
  Packing p;
  p.density = rho;
  p.box_min = Eigen::Vector3d::Zero();
  p.box_max = Eigen::Vector3d::Constant(L);
  p.radius.assign(n, start * 0.5 * u.diameter);
  p.position = place_at_random(p.radius, p.box_min, p.box_max, u.seed);
  return p;
}

CrushResults uniaxial(const CrushSetup& s, const std::function<void(const std::string&)>& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  const UniaxialSetup& u = s.uniaxial;
  CrushResults out;
  out.curve.columns = {"strain", "vertical_stress_kPa", "bottom_stress_kPa", "particles", "broken",
                       "lost_mass_fraction", "time_step_s"};
  out.fragments.columns = {"time_s", "parent_id", "parent_diameter_mm", "max_force_N", "children", "lost_mass_kg"};
  const double rho = s.density * s.density_scaling;
  const bool grown = u.packing == "grown";
  const Packing pack = grown ? random_start(u, kGrowthStart, rho)
                             : jittered_lattice(u.per_edge, 0.5 * u.diameter, 0.0, u.lattice_gap, rho, u.seed);
  DemSystem sys;
  configure(sys, s);
  sys.reserve(pack.size() * 8);
  for (std::size_t k = 0; k < pack.size(); ++k) sys.add_sphere(pack.position[k], pack.radius[k], rho);
  const std::size_t first = sys.add_box(pack.box_min, pack.box_max, s.contact.wall_friction);
  std::uint64_t growth_steps = 0;
  if (grown) {
    // Frictionless growth to the target radii (S0's radius growth, RadiusGrowth.h).
    sys.set_friction(0.0);
    GrowthSettings g;
    g.rate = 1.0;
    g.time_step_safety = s.time_step_safety;
    growth_steps = grow_radii(sys, std::vector<double>(pack.size(), 0.5 * u.diameter), g).cost.steps;
    sys.set_friction(s.contact.friction);
    // Below jamming the growth leaves a loose gas with the overlaps of its last collisions:
    // let them push apart (damped), then stop every sphere, so that the seating stress is
    // reached by compaction, not by impacts.
    sys.run(kGrowthRest);
    for (std::size_t id = 0; id < sys.id_bound(); ++id) {
      sys.set_velocity(ParticleId(id), Vec3::Zero());
      sys.set_angular_velocity(ParticleId(id), Vec3::Zero());
    }
    growth_steps += kGrowthRest;
    if (progress) progress("grown to packing fraction " + std::to_string(u.packing_fraction) + " in " +
                           std::to_string(growth_steps) + " steps");
  }
  const std::size_t lid = first + 5, floor = first + 4;
  const double area = (pack.box_max.x() - pack.box_min.x()) * (pack.box_max.y() - pack.box_min.y());
  auto total_mass = [&] {
    double m = 0.0;
    for (double x : sys.particles().mass) m += x;
    return m;
  };
  const double mass0 = total_mass();
  const std::size_t n0 = sys.n_particles();
  sys.set_time_step(s.time_step_safety * sys.critical_time_step());
  const double dt0 = sys.time_step();

  // Seating: the lid comes down, breakage off, until it carries the seating stress.
  sys.set_wall_velocity(lid, Vec3(0, 0, -u.seating_speed));
  const double h_box = pack.box_max.z() - pack.box_min.z();
  while (std::min(sys.wall(lid).force.z(), -sys.wall(floor).force.z()) / area < u.seating_stress) {
    sys.step();
    if (sys.wall(lid).point.z() - pack.box_min.z() < 0.3 * h_box)
      throw std::runtime_error("uniaxial: the lid did not reach the seating stress before 70% strain");
  }
  const double h0 = sys.wall(lid).point.z() - pack.box_min.z();
  out.polar.emplace_back("seated", ContactPolarDistribution::of(sys, s.polar));
  const double seating_steps = double(sys.n_steps() - growth_steps);
  if (progress) progress("seated at height " + std::to_string(1e3 * h0) + " mm after " +
                         std::to_string(std::uint64_t(seating_steps)) + " steps");

  // Compression at constant lid speed, breakage on.
  sys.set_wall_velocity(lid, Vec3(0, 0, -u.lid_speed));
  BreakageMonitor monitor(s.breakage);
  double strain = 0.0, peak = 0.0, next_report = 0.1 * u.final_strain;
  double peak_recorded = 0.0, peak_strain = 0.0;
  ContactPolarDistribution peak_polar = out.polar.back().second;
  std::size_t events_seen = 0;
  const std::uint64_t step_limit = 50'000'000;
  while (strain < u.final_strain) {
    sys.step();
    strain = (h0 - (sys.wall(lid).point.z() - pack.box_min.z())) / h0;
    if (monitor.after_step(sys) > 0)
      sys.set_time_step(std::min(sys.time_step(), s.time_step_safety * sys.critical_time_step()));
    const double stress = sys.wall(lid).force.z() / area;
    peak = std::max(peak, stress);
    if (sys.n_steps() % s.record_interval == 0 && stress > peak_recorded) {
      // The most loaded state among the recorded rows (S2 Figs. 8-11 under load).
      peak_recorded = stress;
      peak_polar = ContactPolarDistribution::of(sys, s.polar);
      peak_strain = strain;
    }
    if (sys.n_steps() % s.record_interval == 0)
      out.curve.rows.push_back({strain, 1e-3 * stress, -1e-3 * sys.wall(floor).force.z() / area,
                                double(sys.n_particles()), double(monitor.n_broken()), monitor.lost_mass() / mass0,
                                sys.time_step()});
    if (progress && strain >= next_report) {
      progress("strain " + std::to_string(strain) + ", stress " + std::to_string(1e-3 * stress) + " kPa, broken " +
               std::to_string(monitor.n_broken()) + ", particles " + std::to_string(sys.n_particles()));
      next_report += 0.1 * u.final_strain;
    }
    if (sys.n_steps() > step_limit) throw std::runtime_error("uniaxial: step limit reached");
  }
  for (; events_seen < monitor.events().size(); ++events_seen) {
    const BreakageEvent& e = monitor.events()[events_seen];
    out.fragments.rows.push_back({e.time, double(e.parent), 1e3 * e.diameter, e.max_force, double(e.children),
                                  e.lost_mass});
  }
  out.polar.emplace_back("peak", peak_polar);
  out.polar.emplace_back("final", ContactPolarDistribution::of(sys, s.polar));
  const ContactPolarDistribution& roses = out.polar.back().second;
  const PolarRose& vertical = roses.rose(ContactPolarDistribution::vertical, ContactPolarDistribution::all);
  const double axial_force = vertical.sector(0.0, kPolarSectorHalfWidth).mean_force;
  const double lateral_force = vertical.sector(90.0, kPolarSectorHalfWidth).mean_force;
  const ParticleStore& p = sys.particles();
  std::vector<double> d(p.size());
  for (Index k = 0; k < p.size(); ++k) d[k] = 2.0 * p.radius[k];
  out.gradation = gradation(d, p.mass, s.gradation_bin);
  std::vector<double> distinct(d);
  for (double& x : distinct) x = std::round(x * 1e7);
  std::sort(distinct.begin(), distinct.end());
  const auto n_distinct = std::unique(distinct.begin(), distinct.end()) - distinct.begin();
  out.summary = {kv("initial_particles", double(n0)), kv("final_particles", double(sys.n_particles())),
                 kv("broken", double(monitor.n_broken())), kv("distinct_sizes", double(n_distinct)),
                 kv("peak_vertical_stress_kPa", 1e-3 * peak), kv("peak_recorded_strain", peak_strain),
                 kv("final_strain", strain),
                 kv("lost_mass_fraction", monitor.lost_mass() / mass0),
                 kv("relative_mass_error", (total_mass() + monitor.lost_mass()) / mass0 - 1.0),
                 kv("sheltered_particles", double(sys.n_sheltered())),
                 kv("particles_without_contact", double(roses.free_particles())),
                 kv("final_contacts", double(roses.contacts(ContactPolarDistribution::all))),
                 kv("final_mechanical_contacts", double(roses.contacts(ContactPolarDistribution::mechanical))),
                 kv("final_vertical_contact_a_c", vertical.contact_cos2()),
                 kv("final_vertical_axial_to_lateral_mean_force",
                    lateral_force > 0.0 ? axial_force / lateral_force : 0.0),
                 kv("growth_steps", double(growth_steps)), kv("seated_height_mm", 1e3 * h0),
                 kv("seating_steps", seating_steps),
                 kv("steps", double(sys.n_steps())), kv("initial_time_step_s", dt0),
                 kv("final_time_step_s", sys.time_step()), kv("wall_seconds", seconds_since(t0))};
  return out;
}
}  // namespace

CrushResults run_crush(const CrushSetup& s, const std::function<void(const std::string&)>& progress)
{
  if (s.mode != "single particle" && s.mode != "uniaxial")
    throw std::invalid_argument("run_crush: unknown mode '" + s.mode + "'");
  CrushResults r = s.mode == "single particle" ? single_particle(s, progress) : uniaxial(s, progress);
  // What the run was, for the report (CrushReport.h): text values, tabs and line breaks as spaces.
  std::string title = s.title;
  for (char& ch : title)
    if (ch == '\t' || ch == '\n' || ch == '\r') ch = ' ';
  const char* cut[] = {"", "plain", "squared", "cubed"};
  const int power = s.breakage.rules.cut_power;
  r.summary.insert(r.summary.begin(),
                   {"title\t" + title, "program\t" + s.mode, "breakage_mode\t" + to_string(s.breakage.rules.mode),
                    std::string("cut_point\t") + (power >= 1 && power <= 3 ? cut[power] : "?")});
  return r;
}

void write_table(const std::string& path, const Table& t)
{
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  for (std::size_t c = 0; c < t.columns.size(); ++c) out << (c ? "\t" : "") << t.columns[c];
  out << '\n' << std::setprecision(10);
  for (const auto& r : t.rows) {
    for (std::size_t c = 0; c < r.size(); ++c) out << (c ? "\t" : "") << r[c];
    out << '\n';
  }
  if (!out) throw std::runtime_error("write failed: " + path);
}

}  // namespace geocomp::dem
