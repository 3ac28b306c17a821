// S4's direct shear box (see DirectShearBox.h for the model and its choices).
#include "dem/program/DirectShearBox.h"

#include "dem/TimeStep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace geocomp::dem {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Volume-weighted centre of a clump's members (the scaling centre for growth).
Vec3 member_centroid(const std::vector<ClumpMember>& m)
{
  Vec3 c = Vec3::Zero();
  double w = 0.0;
  for (const ClumpMember& s : m) {
    const double v = s.radius * s.radius * s.radius;
    c += v * s.centre;
    w += v;
  }
  return c / w;
}

// The loading and the rest under sigma_n both end once their state held at the end of
// five chunks in a row, or after max_time of DEM time; one loop so that both end by the
// same rule. `run_chunk` runs one chunk of chunk_steps steps and says whether it held.
constexpr std::size_t chunk_steps = 200;

void run_until_held(const DemSystem& sys, const std::function<bool()>& run_chunk, double max_time,
                    const char* phase, const DirectShearBox::Progress& progress)
{
  const double t0 = sys.time();
  int held = 0;  // consecutive chunks ending with the state held
  while (held < 5 && sys.time() - t0 < max_time) {
    held = run_chunk() ? held + 1 : 0;
    if (progress) progress(phase, (sys.time() - t0) / max_time);
  }
}

}  // namespace

DirectShearBox::DirectShearBox(const DirectShearParameters& p) : p_(p)
{
  if (!(p_.length > 0.0 && p_.width > 0.0 && p_.half_height > 0.0))
    throw std::invalid_argument("DirectShearBox: box sizes must be positive");
  if (!(p_.max_shear > 0.0 && p_.max_shear < 0.5 * p_.length))
    throw std::invalid_argument("DirectShearBox: max shear must be in (0, L/2)");
  if (!(p_.normal_stress > 0.0) || !(p_.shear_speed > 0.0))
    throw std::invalid_argument("DirectShearBox: normal stress and shear speed must be positive");
  if (!(p_.growth_start > 0.0 && p_.growth_start <= 1.0) || p_.growth_stages < 1)
    throw std::invalid_argument("DirectShearBox: growth start in (0, 1] and at least one stage");
  if (p_.output_points < 1) throw std::invalid_argument("DirectShearBox: at least one output point");
  if (!(p_.lid_mass > 0.0)) throw std::invalid_argument("DirectShearBox: lid mass must be positive");
  if (!(p_.box_mass > 0.0) || !(p_.box_weight >= 0.0) || !(p_.box_max_rise > 0.0))
    throw std::invalid_argument("DirectShearBox: box mass and max rise must be positive, box weight >= 0");
  servo_target_ = target_load();
}

// @sect4{Walls}
//
// Lower box (moves along x during shear): floor (unbounded), x-, x+, y-, y+, rim, x+ skirt.
// Upper box (free on z, or fixed; lid servo): lid, x-, x+, y-, y+, rim, x- skirt, y- skirt,
// y+ skirt. See the header for positions. The skirts stand a quarter of the smallest radius
// behind the box plates, so no grain inside touches both (overlaps stay ~3 % of R).
void DirectShearBox::build(const std::vector<std::vector<ClumpMember>>& clumps, double lid_height)
{
  const double L = p_.length, B = p_.width, H = p_.half_height, g = gap_;
  const double F = p_.max_shear + 0.1 * L;        // rim width
  const double top = H + g + 3.0 * H;             // upper sides reach far above the lid
  double r_min = 1e300;
  for (const auto& c : clumps)
    for (const ClumpMember& m : c) r_min = std::min(r_min, m.radius);
  const double o = 0.25 * r_min;                  // skirt offset behind the plates
  const double rise = p_.box_max_rise;
  auto sys = std::make_unique<DemSystem>();
  const double E = p_.youngs_modulus * p_.modulus_scale;
  sys->set_contact_model(HertzMindlin(
    HertzNormal({E, p_.poisson_ratio, HertzNormal::Damping::restitution, p_.restitution, 0.0, true}),
    MindlinTangential({E, p_.poisson_ratio, 1.0})));
  sys->set_friction(p_.mu_contact);
  sys->set_gravity(Vec3(0.0, 0.0, -p_.gravity));
  const Vec3 ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
  lower_.clear();
  upper_.clear();
  box_released_ = false;  // held at the set gap until the rest under sigma_n
  PlaneWall floor;
  floor.normal = ez;
  floor.mu = p_.mu_lid;  // top and bottom plates grip the specimen (S4: particle-lid 1.0)
  lower_.push_back(sys->add_wall(floor));
  lower_.push_back(sys->add_wall(rectangle_wall(Vec3(0, 0.5 * B, 0.5 * H), ex, ey, 0.5 * B, 0.5 * H, p_.mu_side)));
  lower_.push_back(sys->add_wall(rectangle_wall(Vec3(L, 0.5 * B, 0.5 * H), -ex, ey, 0.5 * B, 0.5 * H, p_.mu_side)));
  lower_.push_back(sys->add_wall(rectangle_wall(Vec3(0.5 * L, 0, 0.5 * H), ey, ex, 0.5 * L, 0.5 * H, p_.mu_side)));
  lower_.push_back(sys->add_wall(rectangle_wall(Vec3(0.5 * L, B, 0.5 * H), -ey, ex, 0.5 * L, 0.5 * H, p_.mu_side)));
  lower_.push_back(sys->add_wall(rectangle_wall(Vec3(-0.5 * F, 0.5 * B, H), ez, ex, 0.5 * F, 0.5 * B, p_.mu_side)));
  // x+ skirt of the lower box: z in [H - g, H + g + rise + o], behind the x+ side.
  const double zx = H - g, zx1 = H + g + rise + o;
  lower_.push_back(sys->add_wall(rectangle_wall(Vec3(L + o, 0.5 * B, 0.5 * (zx + zx1)), -ex, ey, 0.5 * B + o,
                                                0.5 * (zx1 - zx), p_.mu_side)));
  const double zc = 0.5 * (H + g + top), hz = 0.5 * (top - H - g);
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(0.5 * L, 0.5 * B, lid_height), -ez, ex, 0.5 * L, 0.5 * B, p_.mu_lid)));
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(0, 0.5 * B, zc), ex, ey, 0.5 * B, hz, p_.mu_side)));
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(L, 0.5 * B, zc), -ex, ey, 0.5 * B, hz, p_.mu_side)));
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(0.5 * L, 0, zc), ey, ex, 0.5 * L, hz, p_.mu_side)));
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(0.5 * L, B, zc), -ey, ex, 0.5 * L, hz, p_.mu_side)));
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(L + 0.5 * F, 0.5 * B, H + g), -ez, ex, 0.5 * F, 0.5 * B, p_.mu_side)));
  // Skirts of the upper box: z in [H - rise, H + g + o]; x- behind the x- side, y-/y+ behind
  // the y sides and along the rim (x in [-o, L + F]).
  const double zs = H - rise, zs1 = H + g + o, zsc = 0.5 * (zs + zs1), hs = 0.5 * (zs1 - zs);
  const double xs = 0.5 * (L + F - o), hxs = 0.5 * (L + F + o);
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(-o, 0.5 * B, zsc), ex, ey, 0.5 * B + o, hs, p_.mu_side)));
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(xs, -o, zsc), ey, ex, hxs, hs, p_.mu_side)));
  upper_.push_back(sys->add_wall(rectangle_wall(Vec3(xs, B + o, zsc), -ey, ex, hxs, hs, p_.mu_side)));
  box_seat_z_ = zc;
  for (const auto& c : clumps) sys->add_clump(c, p_.clumps.density);
  // Rayleigh step of the smallest sphere now (S4): T_R = pi R sqrt(rho/G)/(0.163 nu + 0.8766).
  const double G = E / (2.0 * (1.0 + p_.poisson_ratio));
  dt_ = p_.time_step_fraction * rayleigh_time_step(r_min, p_.clumps.density, G, p_.poisson_ratio);
  sys->set_time_step(dt_);
  sys->set_local_damping(p_.local_damping);
  sys_ = std::move(sys);
}

std::vector<std::vector<ClumpMember>> DirectShearBox::clump_members() const
{
  std::vector<std::vector<ClumpMember>> out(sys_->n_clumps());
  const ParticleStore& st = sys_->particles();
  for (std::size_t c = 0; c < out.size(); ++c)
    for (ParticleId id : sys_->clump_members(c)) out[c].push_back({sys_->position(id), st.radius[sys_->index_of(id)]});
  return out;
}

// @sect4{Preparation: placement, growth, normal load}
void DirectShearBox::prepare(const Progress& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  const double L = p_.length, B = p_.width, H = p_.half_height;
  // Clumps: enough for V_box = (1 + e) V_solid unless n_clumps is given.
  std::vector<ClumpShape> shapes;
  if (p_.n_clumps > 0) {
    shapes = generate_s4_clumps(p_.n_clumps, p_.clumps, p_.seed);
  } else {
    const double mean_mass = std::exp(p_.clumps.log_mass_mean + 0.5 * p_.clumps.log_mass_sigma * p_.clumps.log_mass_sigma) * 1e-3;
    const double v_box = L * B * 2.0 * H;
    const std::size_t guess = std::size_t(2.0 * v_box * p_.clumps.density / ((1.0 + p_.void_ratio) * mean_mass)) + 10;
    std::vector<ClumpShape> all = generate_s4_clumps(guess, p_.clumps, p_.seed);
    double solid = 0.0;
    for (ClumpShape& s : all) {
      if ((1.0 + p_.void_ratio) * solid >= v_box) break;
      solid += s.mass / p_.clumps.density;
      shapes.push_back(std::move(s));
    }
  }
  double dsum = 0.0;
  std::size_t nsph = 0;
  for (const ClumpShape& s : shapes)
    for (const ClumpMember& m : s.members) {
      dsum += 2.0 * m.radius;
      ++nsph;
    }
  d_mean_ = dsum / double(nsph);
  gap_ = p_.gap_fraction * d_mean_;
  info_.n_clumps = shapes.size();
  info_.n_spheres = nsph;
  info_.gap = gap_;
  // Random placement at reduced size in the box column, up to three half-heights.
  const double z_top = 3.0 * H + gap_;
  auto clumps = place_clumps(shapes, Vec3(0, 0, 0), Vec3(L, B, z_top), p_.growth_start, p_.seed + 1);
  solid_volume_ = 0.0;
  for (const ClumpShape& s : shapes) solid_volume_ += s.mass / p_.clumps.density;
  build(clumps, z_top);
  set_friction(true);
  // Growth in stages: scale every clump about its centroid, rebuild, settle.
  double scale = p_.growth_start;
  for (int k = 1; k <= p_.growth_stages; ++k) {
    const double next = p_.growth_start * std::pow(1.0 / p_.growth_start, double(k) / p_.growth_stages);
    const double f = (k == p_.growth_stages ? 1.0 / scale : next / scale);
    auto members = clump_members();
    for (auto& c : members) {
      const Vec3 o = member_centroid(c);
      for (ClumpMember& m : c) {
        m.centre = o + f * (m.centre - o);
        m.radius *= f;
      }
    }
    if (k == p_.growth_stages) {  // exact full size: the generated radii
      for (std::size_t c = 0; c < members.size(); ++c)
        for (std::size_t j = 0; j < members[c].size(); ++j) members[c][j].radius = shapes[c].members[j].radius;
    }
    scale = next;
    build(members, z_top);
    set_friction(true);
    sys_->run(p_.settle_steps);
    if (progress) progress("growth", double(k) / p_.growth_stages);
  }
  // Seating: lid just above the highest sphere, compaction to seat_stress with the
  // preparation friction (S4's vibration compaction), the same for every sigma_n.
  double z_max = 0.0;
  const ParticleStore& st = sys_->particles();
  for (std::size_t i = 0; i < st.size(); ++i) z_max = std::max(z_max, st.x[i].z() + st.radius[i]);
  const Vec3 lid_point = sys_->wall(lid()).point;
  sys_->set_wall_position(lid(), Vec3(lid_point.x(), lid_point.y(), z_max));
  load_lid(std::min(p_.seat_stress, p_.normal_stress) * L * B, p_.load_max_time, progress);
  info_.void_ratio_seated = void_ratio();
  // Normal load with the full friction (S4: the load densifies the specimen further).
  set_friction(false);
  load_lid(target_load(), p_.load_max_time, progress);
  // Rest under sigma_n with the dynamics of the shear (loaded lid, no local damping).
  sys_->set_local_damping(0.0);
  sys_->set_wall_velocity(lid(), Vec3::Zero());
  box_released_ = p_.upper_box_free;  // the gap screws are backed off: the box is carried
  run_until_held(*sys_, [&] {
    for (std::size_t s = 0; s < chunk_steps; ++s) {
      drive_lid();
      drive_box();
      sys_->step();
    }
    const EnergyLedger e = sys_->energy();
    info_.rest_kinetic_ratio = e.kinetic() / std::max(e.elastic(), 1e-300);
    info_.load_error = std::abs(sys_->wall(lid()).force.z() / (target_load() + p_.lid_weight) - 1.0);
    return info_.rest_kinetic_ratio < p_.rest_ratio && info_.load_error < p_.load_tolerance;
  }, p_.rest_max_time, "rest", progress);
  info_.rest_lid_speed = std::abs(sys_->wall(lid()).velocity.z());
  info_.void_ratio = void_ratio();
  info_.time_step = dt_;
  info_.prepare_seconds = seconds_since(t0);
}

void DirectShearBox::load_lid(double load, double max_time, const Progress& progress)
{
  servo_target_ = load;
  run_until_held(*sys_, [&] {
    run_servo(chunk_steps);
    info_.load_error = std::abs(sys_->wall(lid()).force.z() / load - 1.0);
    return info_.load_error < p_.load_tolerance;
  }, max_time, "load", progress);
}

void DirectShearBox::set_friction(bool preparation)
{
  sys_->set_friction(preparation ? p_.prep_friction : p_.mu_contact);
  const double side = preparation ? p_.prep_friction : p_.mu_side;
  const double grip = preparation ? p_.prep_friction : p_.mu_lid;
  for (std::size_t w : lower_) sys_->set_wall_friction(w, w == lower_.front() ? grip : side);
  for (std::size_t w : upper_) sys_->set_wall_friction(w, w == lid() ? grip : side);
}

double DirectShearBox::void_ratio() const
{
  return p_.length * p_.width * sys_->wall(lid()).point.z() / solid_volume_ - 1.0;
}

void DirectShearBox::servo_lid()
{
  const PlaneWall& w = sys_->wall(lid());
  const double P = w.force.z();  // particles push the lid up: compression positive
  const double K = std::max(w.stiffness, 1e-300);
  const double v = p_.servo_factor * (servo_target_ - P) / (K * dt_);
  const double vz = -std::clamp(v, -p_.servo_max_speed, p_.servo_max_speed);
  sys_->set_wall_velocity(lid(), Vec3(0.0, 0.0, vz));
}

// The loaded lid during rest and shear: a rigid plate that moves vertically under the
// particles' force and the applied load (a dead load, as in S4's test),
//   m_lid dv/dt = F_lid - P - W_lid,   P = sigma_n L B (the P of S4 eq. (22)),
// m_lid an inertia (W_lid, the lid's own weight, 0 by default). It follows
// a dilating specimen with the error m_lid a, negligible here, where the velocity servo of
// the loading lags by (dilation rate) K dt / servo_factor (30-40 % of P at 100 kPa).
// Semi-implicit Euler with the step's forces; stable for dt << sqrt(m_lid/K) (~3e-4 s here).
void DirectShearBox::drive_lid()
{
  const double f_lid = sys_->wall(lid()).force.z();
  const double v_lid = sys_->wall(lid()).velocity.z() + dt_ * (f_lid - servo_target_ - p_.lid_weight) / p_.lid_mass;
  sys_->set_wall_velocity(lid(), Vec3(0.0, 0.0, v_lid));
}

// The free upper box: one rigid body (sides, rim, skirts) moving on z only (S4 section 3.2:
// "fixed horizontally, free vertically"; its x and y velocities stay 0),
//   m_B dv/dt = F_{B,z} - W_B + R,          the box's weight W_B of S4 eq. (22),
// F_{B,z} the particles' force on its plates, W_B its weight (S4 eq. 22), R the reaction of
// the seat (R >= 0, the box cannot sink below the set gap) or of the top stop (R <= 0, rise
// <= box_max_rise). Semi-implicit Euler with the step's forces, as the lid; a stop is a
// velocity constraint: the step that would pass it lands on it, R = m_B (v - v_free)/dt.
// Off the stops the mean of F_{B,z} over a time T is W_B + m_B (v(T) - v(0))/T: the side
// friction the box puts on the specimen is bounded by its weight. A held box only records
// F_{B,z} (the friction by which it presses the specimen down).
void DirectShearBox::drive_box()
{
  box_stop_ = 0.0;
  double f = 0.0;
  for (std::size_t j = 1; j < upper_.size(); ++j) f += sys_->wall(upper_[j]).force.z();
  if (!box_released_) {  // held (fixed box, or before the rest): its force is recorded only
    box_force_sum_ += f;
    ++box_steps_;
    return;
  }
  const double z = box_rise();
  const double v_free = sys_->wall(upper_[1]).velocity.z() + dt_ * (f - p_.box_weight) / p_.box_mass;
  double v = v_free;
  if (z + dt_ * v < 0.0) v = -z / dt_;                                      // seat
  else if (z + dt_ * v > p_.box_max_rise) v = (p_.box_max_rise - z) / dt_;  // top stop
  box_stop_ = p_.box_mass * (v - v_free) / dt_;
  for (std::size_t j = 1; j < upper_.size(); ++j) sys_->set_wall_velocity(upper_[j], Vec3(0.0, 0.0, v));  // z only
  box_force_sum_ += f;
  box_stop_sum_ += box_stop_;
  ++box_steps_;
  if (box_stop_ > 0.0) ++box_seated_steps_;
  if (box_stop_ < 0.0) ++box_top_steps_;
}

double DirectShearBox::grain_weight() const
{
  const ClumpSet& c = sys_->clumps();
  const double z_mid = p_.half_height + 0.5 * (gap_ + box_rise());
  double m = 0.0;
  for (std::size_t k = 0; k < c.x.size(); ++k)
    if (c.x[k].z() > z_mid) m += c.mass[k];
  return m * p_.gravity;
}

std::size_t DirectShearBox::escaped_spheres() const
{
  const double U = sys_->wall(lower_[1]).point.x();
  const ParticleStore& st = sys_->particles();
  std::size_t n = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const Vec3& x = st.x[i];
    if (x.y() < 0.0 || x.y() > p_.width || x.z() < 0.0 || x.x() < std::min(0.0, U) ||
        x.x() > p_.length + std::max(0.0, U))
      ++n;
  }
  return n;
}

double DirectShearBox::box_rise() const { return sys_->wall(upper_[1]).point.z() - box_seat_z_; }

void DirectShearBox::run_servo(std::size_t steps)
{
  for (std::size_t s = 0; s < steps; ++s) {
    servo_lid();
    sys_->step();
  }
}

// @sect4{Measurements (S4 eq. 22-24)}
ShearRecord DirectShearBox::measure(double U) const
{
  ShearRecord r;
  r.shear = U;
  r.time = sys_->time();
  r.lid_rise = sys_->wall(lid()).point.z() - lid_start_;
  r.grain_weight = grain_weight();
  r.normal_force = sys_->wall(lid()).force.z() + r.grain_weight + p_.box_weight;  // S4 eq. (22)
  // S4 eq. (22): F_S over the N_wall = 5 walls of S4's upper box, the lid and the four
  // sides; the rim plate and the skirts (our stand-ins for the box frame) are reported apart.
  for (std::size_t j = 0; j < 5; ++j) r.shear_force += sys_->wall(upper_[j]).force.x();
  for (std::size_t j = 5; j < upper_.size(); ++j) r.frame_force += sys_->wall(upper_[j]).force.x();
  for (std::size_t j = 1; j < upper_.size(); ++j) r.box_vertical_force += sys_->wall(upper_[j]).force.z();
  r.box_rise = box_rise();
  r.box_stop_force = box_stop_;
  r.area = corrected_area(p_.length, p_.width, U);                                // S4 eq. (23)
  r.sigma_z = r.normal_force / r.area;                                             // S4 eq. (23)
  r.tau_x = r.shear_force / r.area;                                                // S4 eq. (23)
  r.mu_b = r.normal_force > 0.0 ? r.shear_force / r.normal_force : 0.0;           // S4 eq. (24)
  r.inertial_number = 0.1 * p_.shear_speed * std::sqrt(p_.clumps.density / p_.normal_stress);
  return r;
}

// @sect4{Shear}
std::vector<ShearRecord> DirectShearBox::shear(const Progress& progress)
{
  if (!sys_) throw std::logic_error("DirectShearBox::shear: prepare() first");
  const auto t0 = std::chrono::steady_clock::now();
  sys_->set_local_damping(0.0);
  lid_start_ = sys_->wall(lid()).point.z();
  for (std::size_t w : lower_) sys_->set_wall_velocity(w, Vec3(p_.shear_speed, 0.0, 0.0));
  const auto total = std::uint64_t(std::ceil(p_.max_shear / (p_.shear_speed * dt_)));
  const std::uint64_t every = std::max<std::uint64_t>(1, total / p_.output_points);
  std::vector<ShearRecord> curve{measure(0.0)};
  const double t_start = sys_->time();
  box_force_sum_ = box_stop_sum_ = 0.0;
  box_steps_ = box_seated_steps_ = box_top_steps_ = 0;
  for (std::uint64_t s = 1; s <= total; ++s) {
    drive_lid();
    drive_box();
    sys_->step();
    if (s % every == 0 || s == total) {
      curve.push_back(measure(std::min(p_.max_shear, p_.shear_speed * (sys_->time() - t_start))));
      if (progress) progress("shear", double(s) / double(total));
    }
  }
  info_.steps = total;
  info_.escaped = escaped_spheres();
  if (box_steps_ > 0) {
    const double n = double(box_steps_);
    info_.box_force_mean = box_force_sum_ / n;
    info_.box_stop_mean = box_stop_sum_ / n;
    info_.box_seated_share = double(box_seated_steps_) / n;
    info_.box_top_share = double(box_top_steps_) / n;
  }
  info_.shear_seconds = seconds_since(t0);
  return curve;
}

ShearSummary DirectShearBox::summary(const std::vector<ShearRecord>& curve) const
{
  ShearSummary s = info_;
  s.inertial_number = 0.1 * p_.shear_speed * std::sqrt(p_.clumps.density / p_.normal_stress);
  for (const ShearRecord& r : curve) {
    if (r.mu_b > s.peak_mu_b) {
      s.peak_mu_b = r.mu_b;
      s.shear_at_peak = r.shear;
      s.frame_share_at_peak = r.frame_force / r.shear_force;
    }
    s.max_contraction = std::max(s.max_contraction, -r.lid_rise);
    s.box_force_max = std::max(s.box_force_max, r.box_vertical_force);
    s.box_rise_max = std::max(s.box_rise_max, r.box_rise);
  }
  if (!curve.empty()) {
    s.final_dilation = curve.back().lid_rise;
    s.box_rise_final = curve.back().box_rise;
  }
  return s;
}

}  // namespace geocomp::dem
