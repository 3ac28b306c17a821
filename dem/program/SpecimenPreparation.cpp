#include "dem/program/SpecimenPreparation.h"

#include "dem/program/SpecimenExchange.h"
#include "dem/program/SpecimenStore.h"
#include "dem/specimen/Packing.h"
#include "dem/specimen/SizeDistribution.h"

#include <chrono>
#include <filesystem>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace geocomp::dem {

namespace {

double sphere_volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Vec3 box_lengths(const DemSystem &s)
{
  Vec3 L;
  for (int a = 0; a < 3; ++a)
    L[a] = s.wall(2 * a + 1).point[a] - s.wall(2 * a).point[a];
  return L;
}

/// The case's contact law with mu_s = mu_p = 0 (S0: frictionless while the packing forms)
/// and without S3's parts: bonds, adhesion and the anchor-spring friction act from the
/// prepared state, when the program first evaluates the case's law (S3: anchors fixed at t_0
/// on every touching pair), not at the passing contacts of growth and consolidation; the
/// packing rests with Coulomb friction (a stick-slip law, k_phi = 0, never comes to rest).
/// So every S3 variant of a case starts from the same packing.
ContactParameters frictionless(const ContactParameters &c)
{
  ContactParameters f = c;
  f.particle_friction = 0.0;
  f.wall_friction = 0.0;
  f.cohesion = 0.0;
  f.adhesion = 0.0;
  f.tangential_model = "coulomb";
  return f;
}

/// The rest criteria of the frictionless phase, with FIRE when the case asks for it.
RestCriteria frictionless_rest(const DemCase &c, const PreparationCriteria &k)
{
  RestCriteria r = k.packing;
  r.fire = c.specimen.frictionless_relaxation == "fire";
  return r;
}

/// Sets the packing dynamics: first-order (Aristotelian) or Newtonian with damping.
void set_packing_dynamics(DemSystem &s, bool aristotelian, const PreparationCriteria &k)
{
  if (aristotelian) {
    s.set_overdamped(k.aristotelian_beta);
    s.set_local_damping(0.0);
  } else {
    s.set_overdamped(0.0);
    s.set_local_damping(k.preparation_damping);
  }
}

/// The case's stored specimen, refused (CaseError) when the store, the name or the
/// conditions it was prepared under do not match the case.
StoredSpecimen read_case_store(const DemCase &c)
{
  const SpecimenParameters &s = c.specimen;
  StoredSpecimen stored;
  try {
    stored = read_stored_specimen(s.store_file, s.store_name);
  } catch (const StoreError &e) {
    throw CaseError(c.file, e.missing_name ? "specimen/store name" : "specimen/store file",
                    std::string(e.what()) + " (a pack case with this store file and name builds it: geocomp pack <case>)");
  }
  // The stored state carries its contact law; a case that asks for another friction or
  // restitution would start out of equilibrium, so it is refused.
  auto same = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); };
  const auto mismatch = [&](const std::string &parameter, double stored_value, double case_value) {
    throw CaseError(c.file, parameter,
                    "the stored specimen '" + s.store_name + "' was prepared with " + std::to_string(stored_value) +
                      ", the case asks for " + std::to_string(case_value) +
                      "; set the case to the stored value or pack a new specimen");
  };
  if (!same(stored.metadata.contact.particle_friction, c.contact.particle_friction))
    mismatch("contact/particle friction", stored.metadata.contact.particle_friction, c.contact.particle_friction);
  if (!same(stored.metadata.contact.wall_friction, c.contact.wall_friction))
    mismatch("contact/wall friction", stored.metadata.contact.wall_friction, c.contact.wall_friction);
  // A specimen taken as given carries the pressure it was stored at; the entry is not used.
  if (s.preparation != "as given" && !same(stored.metadata.isotropic_pressure, c.specimen.isotropic_pressure))
    mismatch("specimen/isotropic pressure", stored.metadata.isotropic_pressure, c.specimen.isotropic_pressure);
  return stored;
}

/// The spheres of `source = text`, refused (CaseError) when the file cannot be read or holds none.
Packing read_case_packing(const DemCase &c)
{
  // A FIFO would block the reader and a device never end: regular files only.
  std::error_code ec;
  const auto status = std::filesystem::status(c.specimen.text_file, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw CaseError(c.file, "specimen/text file", "'" + c.specimen.text_file + "' is not a regular file: expected a text file of spheres");
  Packing p;
  try {
    p = read_packing_file(c.specimen.text_file);
  } catch (const PackingFileError &e) {
    throw CaseError(c.file, "specimen/text file", e.what());
  }
  if (p.size() == 0)
    throw CaseError(c.file, "specimen/text file", "'" + c.specimen.text_file + "' holds no spheres");
  return p;
}

PreparedSpecimen from_store(const DemCase &c)
{
  StoredSpecimen stored = read_case_store(c);
  PreparedSpecimen out{std::move(stored.system), stored.record};
  out.system.set_num_threads(int(c.dem.threads)); // 0: from the problem size; results do not depend on it
  out.system.set_local_damping(c.dem.local_damping);
  return out;
}

/// `preparation = as given` of a text source: the file's spheres, and the velocities a
/// LAMMPS data file lists, in the file's box with the case's contact law and friction,
/// exactly as read (no rest, no consolidation).
PreparedSpecimen as_given(const DemCase &c)
{
  const auto start = std::chrono::steady_clock::now();
  Packing p = read_case_packing(c);
  p.density = c.specimen.density;
  PreparedSpecimen out{make_system(p, c.contact, c.dem), {}};
  PreparationRecord &rec = out.record;
  rec.method = "text file " + c.specimen.text_file + " as given (no rest, no consolidation)";
  rec.seed = c.seed;
  rec.particles = p.size();
  rec.size_distribution = "from file";
  rec.box_size = (p.box_max - p.box_min).x();
  rec.initial_packing_fraction = rec.grown_packing_fraction = rec.final_packing_fraction = p.packing_fraction();
  double r_sum = 0.0;
  for (double r : p.radius)
    r_sum += r;
  rec.mean_radius = r_sum / double(p.size());
  rec.wall_seconds = seconds_since(start);
  return out;
}

} // namespace

std::vector<std::string> ignored_specimen_entries(const DemCase &c)
{
  const SpecimenParameters &s = c.specimen, d{};
  std::vector<std::string> out;
  const auto note = [&](bool differs, const std::string &entry, const std::string &value, const std::string &why) {
    if (differs)
      out.push_back(c.file + ": specimen/" + entry + " = " + value + " is not used: " + why);
  };
  const auto number = [](double v) {
    std::ostringstream o;
    o << v;
    return o.str();
  };
  const bool imported = s.source != "generate";
  const std::string from = s.source == "store" ? "the stored specimen" : "the packing file";
  if (imported) {
    const std::string why = from + " gives the spheres and the box";
    note(s.particles != d.particles, "particles", std::to_string(s.particles), why);
    note(s.packing_fraction != d.packing_fraction, "packing fraction", number(s.packing_fraction), why);
    note(s.radius != d.radius, "radius", number(s.radius), why);
    note(s.size_distribution != d.size_distribution, "size distribution", s.size_distribution, why);
    note(s.radius_spread != d.radius_spread, "radius spread", number(s.radius_spread), why);
    note(s.lognormal_sigma != d.lognormal_sigma, "lognormal sigma", number(s.lognormal_sigma), why);
    note(s.box_size != d.box_size, "box size", number(s.box_size), why);
  }
  note(s.source == "store" && s.density != d.density, "density", number(s.density),
       "the stored specimen carries its masses");
  const bool no_rest = s.source == "store" || s.preparation == "as given";
  note(no_rest && s.aristotelian != d.aristotelian, "aristotelian", "true", "nothing is packed or relaxed");
  note(no_rest && s.frictionless_relaxation != d.frictionless_relaxation, "frictionless relaxation",
       s.frictionless_relaxation, "nothing is relaxed");
  note(s.preparation == "as given" && s.source == "text" && s.isotropic_pressure != d.isotropic_pressure,
       "isotropic pressure", number(s.isotropic_pressure), "the packing is taken as given, not consolidated");
  note(s.source != "text" && !s.text_file.empty(), "text file", s.text_file, "source = " + s.source);
  note(s.source != "store" && !s.store_file.empty(), "store file", s.store_file, "source = " + s.source);
  note(s.source != "store" && !s.store_name.empty(), "store name", s.store_name, "source = " + s.source);
  return out;
}

void check_specimen(const DemCase &c)
{
  const SpecimenParameters &s = c.specimen;
  if (s.source == "store") {
    read_case_store(c);
    return;
  }
  if (s.source != "generate" && s.source != "text")
    throw CaseError(c.file, "specimen/source", "'" + s.source + "' is not one of generate, text, store");
  if (s.preparation == "as given" && s.source == "generate")
    throw CaseError(c.file, "specimen/preparation", "'as given' needs an imported packing (source = text or store)");
  if (s.preparation != "as given" && !(s.isotropic_pressure > 0.0))
    throw CaseError(c.file, "specimen/isotropic pressure",
                    "must be > 0 to consolidate a specimen (or set preparation = as given for an imported packing)");
  if (s.source == "generate")
    growth_target(c);
  else
    read_case_packing(c);
}

double mean_wall_pressure(const DemSystem &s)
{
  const Vec3 L = box_lengths(s);
  double p = 0.0;
  for (int w = 0; w < 6; ++w) {
    const int a = w / 2;
    p += -s.wall(w).force.dot(s.wall(w).normal) / (L[(a + 1) % 3] * L[(a + 2) % 3]);
  }
  return p / 6.0;
}

double packing_fraction(const DemSystem &system)
{
  double solid = 0.0;
  for (double r : system.particles().radius)
    solid += sphere_volume(r);
  return solid / box_lengths(system).prod();
}

std::string PreparationRecord::describe() const
{
  std::ostringstream o;
  o << particles << " spheres (" << size_distribution << ", mean R " << mean_radius << " m), " << method
    << " (seed " << seed << "): box " << box_size << " m, packing fraction " << initial_packing_fraction
    << " placed -> " << grown_packing_fraction << " grown (" << growth.steps << " steps, " << growth.wall_seconds
    << " s wall) -> at rest frictionless after " << frictionless.steps << " steps (unbalanced "
    << frictionless_rest.unbalanced << ", mean wall stress " << grown_pressure << " Pa) -> with friction after "
    << frictional.steps << " steps -> consolidated to " << pressure << " Pa after " << consolidation.steps
    << " steps (stress error " << consolidated.stress_error << ", unbalanced " << consolidated_rest.unbalanced
    << ", kinetic/elastic " << consolidated_rest.kinetic_ratio() << "): packing fraction "
    << final_packing_fraction << ", Z " << coordination << ", mean overlap " << mean_overlap << " d; " << steps
    << " steps, " << wall_seconds << " s wall";
  return o.str();
}

GrowthTarget growth_target(const DemCase &c)
{
  const SpecimenParameters &s = c.specimen;
  SizeDistribution dist;
  try {
    dist.kind = SizeDistribution::parse(s.size_distribution);
  } catch (const std::invalid_argument &e) {
    throw CaseError(c.file, "specimen/size distribution", e.what());
  }
  dist.mean_radius = s.radius;
  dist.spread = s.radius_spread;
  dist.sigma = s.lognormal_sigma;
  GrowthTarget t;
  t.radii = dist.sample(s.particles, c.seed);
  double solid = 0.0;
  for (double r : t.radii)
    solid += sphere_volume(r);
  if (s.box_size > 0.0) {
    // S0 gives N, eta, R and L0 together: L0 and eta win, the radii follow.
    const double scale = std::cbrt(s.packing_fraction * s.box_size * s.box_size * s.box_size / solid);
    if (std::abs(scale - 1.0) > 0.1)
      throw CaseError(c.file, "specimen/box size",
                      "L0 = " + std::to_string(s.box_size) + " m with N = " + std::to_string(s.particles) +
                        " and eta = " + std::to_string(s.packing_fraction) + " needs radii " +
                        std::to_string(scale) + " times the given ones (more than 10 % off); set box size = 0 "
                        "to derive L0 from N, eta and R");
    for (double &r : t.radii)
      r *= scale;
    t.box_size = s.box_size;
  } else {
    t.box_size = std::cbrt(solid / s.packing_fraction);
  }
  const double r_max = *std::max_element(t.radii.begin(), t.radii.end());
  if (t.box_size < 4.0 * r_max)
    throw CaseError(c.file, "specimen/particles", "the box (" + std::to_string(t.box_size) +
                                                    " m) is smaller than two of the largest spheres");
  return t;
}

GrownPacking grow_packing(const DemCase &c, const PreparationCriteria &k, const PreparationProgress &progress)
{
  const SpecimenParameters &s = c.specimen;
  if (!(k.initial_packing_fraction > 0.0 && k.initial_packing_fraction < s.packing_fraction))
    throw std::invalid_argument("grow_packing: the initial packing fraction must lie in (0, eta)");
  const GrowthTarget target = growth_target(c);
  // S0: small spheres at random, no overlap; f0 = (eta_0 / eta)^(1/3).
  const double f0 = std::cbrt(k.initial_packing_fraction / s.packing_fraction);
  Packing start;
  start.density = s.density;
  start.box_min = Vec3::Zero();
  start.box_max = Vec3::Constant(target.box_size);
  start.radius.resize(target.radii.size());
  for (std::size_t i = 0; i < target.radii.size(); ++i)
    start.radius[i] = f0 * target.radii[i];
  start.position = place_at_random(start.radius, start.box_min, start.box_max, c.seed);

  GrownPacking g{make_system(start, frictionless(c.contact), c.dem), {}, {}, start.packing_fraction()};
  double d_mean = 0.0;
  for (double r : target.radii)
    d_mean += 2.0 * r;
  d_mean /= double(target.radii.size());
  g.system.set_skin(c.dem.skin * d_mean); // the skin of the final radii
  set_packing_dynamics(g.system, s.aristotelian, k);

  // Growth rate from the inertial number at sigma_0 (DEM-NOTES section 8).
  GrowthSettings gs;
  gs.rate = k.growth_inertial_number / (d_mean * std::sqrt(s.density / s.isotropic_pressure));
  gs.interval = k.growth_interval;
  gs.time_step_safety = c.dem.time_step_safety;
  g.growth = grow_radii(g.system, target.radii, gs, progress);
  g.rest = relax(g.system, frictionless_rest(c, k), "rest (frictionless)", progress);
  return g;
}

PreparedSpecimen prepare_specimen(const DemCase &c, const PreparationCriteria &k,
                                  const PreparationProgress &progress)
{
  const SpecimenParameters &s = c.specimen;
  check_specimen(c);
  if (s.source == "store")
    return from_store(c);
  if (s.preparation == "as given")
    return as_given(c);

  const auto start = std::chrono::steady_clock::now();
  PreparationRecord rec;
  rec.seed = c.seed;
  rec.pressure = s.isotropic_pressure;
  rec.aristotelian = s.aristotelian;
  const std::string dynamics = s.aristotelian ? "Aristotelian"
                                : s.frictionless_relaxation == "fire" ? "Newtonian, FIRE rest" : "Newtonian";

  DemSystem system;
  if (s.source == "generate") {
    GrownPacking g = grow_packing(c, k, progress);
    system = std::move(g.system);
    rec.method = "radius growth (" + dynamics + ") + servo consolidation";
    rec.size_distribution = s.size_distribution;
    rec.initial_packing_fraction = g.initial_packing_fraction;
    rec.growth = g.growth.cost;
    rec.frictionless = g.rest.cost;
    rec.frictionless_rest = g.rest.rest;
    rec.frictionless_converged = g.rest.converged;
  } else {
    Packing p = read_case_packing(c);
    p.density = s.density;
    rec.method = "text file " + s.text_file + " (" + dynamics + " rest) + servo consolidation";
    rec.size_distribution = "from file";
    rec.initial_packing_fraction = p.packing_fraction();
    system = make_system(p, frictionless(c.contact), c.dem);
    set_packing_dynamics(system, s.aristotelian, k);
    const RelaxResult r = relax(system, frictionless_rest(c, k), "rest (frictionless)", progress);
    rec.frictionless = r.cost;
    rec.frictionless_rest = r.rest;
    rec.frictionless_converged = r.converged;
  }
  rec.particles = system.n_particles();
  rec.box_size = box_lengths(system).x();
  rec.grown_packing_fraction = packing_fraction(system);
  rec.grown_pressure = mean_wall_pressure(system);
  double r_sum = 0.0;
  for (double r : system.particles().radius)
    r_sum += r;
  rec.mean_radius = r_sum / double(system.n_particles());

  // S0: friction on, Newtonian motion from rest, relaxed at fixed walls.
  system.set_overdamped(0.0);
  system.set_local_damping(k.preparation_damping);
  for (ParticleId id = 0; id < system.n_particles(); ++id) {
    system.set_velocity(id, Vec3::Zero());
    system.set_angular_velocity(id, Vec3::Zero());
  }
  system.set_friction(c.contact.particle_friction);
  for (std::size_t w = 0; w < system.n_walls(); ++w)
    system.set_wall_friction(w, c.contact.wall_friction);
  const RelaxResult fr = relax(system, k.packing, "rest (friction on)", progress);
  rec.frictional = fr.cost;
  rec.frictional_rest = fr.rest;
  rec.frictional_converged = fr.converged;

  // Isotropic consolidation with the servo (DemEngine, Yade-like gain from the wall
  // stiffness, velocity cap) until sigma_0 on all three axes and at rest.
  const auto t_consolidation = std::chrono::steady_clock::now();
  const std::uint64_t steps0 = system.n_steps();
  const double time0 = system.time();
  DemEngine engine(std::move(system), DemEngineParameters::from_case(c.dem));
  const double interval = k.check_interval_steps * engine.system().time_step();
  double first_error = -1.0, fraction = 0.0; // the progress estimate: the stress error's way to its tolerance
  while (true) {
    const HoldResult h = hold_isotropic(engine, s.isotropic_pressure, k.stress_tolerance, k.unbalanced_force_ratio,
                                        50.0 * interval, interval);
    rec.consolidated = h;
    rec.consolidated_rest = rest_state(engine.system());
    const double spent = engine.system().time() - time0;
    if (first_error < 0.0)
      first_error = h.stress_error;
    fraction = std::max(fraction, std::min(log_progress(first_error, h.stress_error, k.stress_tolerance),
                                           h.converged ? 0.99 : 0.9));
    if (progress)
      progress("consolidation", spent, fraction);
    if (h.converged && rec.consolidated_rest.kinetic_ratio() <= k.kinetic_ratio)
      break;
    if (spent >= k.max_time)
      throw std::runtime_error("specimen preparation: the consolidation to " + std::to_string(s.isotropic_pressure) +
                               " Pa did not converge in " + std::to_string(k.max_time) +
                               " s of DEM time (stress error " + std::to_string(h.stress_error) +
                               ", unbalanced-force ratio " + std::to_string(h.unbalanced) + ")");
  }
  if (progress)
    progress("consolidation", engine.system().time() - time0, 1.0);
  rec.consolidation.steps = engine.system().n_steps() - steps0;
  rec.consolidation.time = engine.system().time() - time0;
  rec.consolidation.wall_seconds = seconds_since(t_consolidation);

  PreparedSpecimen out{engine.system(), {}};
  // S3 bonds form at the first step from here. A law without S3's parts is the one the
  // preparation ran (friction set since): left alone, so the prepared lists and every
  // S0 result keep their bits.
  const ContactParameters prepared = frictionless(c.contact);
  if (prepared.cohesion != c.contact.cohesion || prepared.adhesion != c.contact.adhesion ||
      prepared.tangential_model != c.contact.tangential_model)
    set_contact_law(out.system, c.contact);
  for (std::size_t w = 0; w < out.system.n_walls(); ++w)
    out.system.set_wall_velocity(w, Vec3::Zero());
  out.system.set_local_damping(c.dem.local_damping);
  rec.final_packing_fraction = packing_fraction(out.system);
  std::size_t pairs = 0;
  double overlap = 0.0;
  for (const ContactRecord &cr : out.system.contacts())
    if (!cr.wall) {
      ++pairs;
      overlap += cr.overlap;
    }
  rec.coordination = 2.0 * double(pairs) / double(out.system.n_particles());
  rec.mean_overlap = pairs > 0 ? overlap / double(pairs) / (2.0 * rec.mean_radius) : 0.0;
  rec.steps = out.system.n_steps();
  rec.wall_seconds = seconds_since(start);
  out.record = rec;
  return out;
}

} // namespace geocomp::dem
