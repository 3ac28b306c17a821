#include "dem/program/DemEngine.h"

#include "common/AtomicFile.h"
#include "common/BinaryState.h"
#include "dem/program/ContactParts.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <limits>
#include <sstream>

namespace geocomp::dem {

// @sect4{Contact law and system from the case file}

namespace {
/// k_t given in N/m or as a ratio of k_n; c_t given in N s/m, as a ratio of c_n, or by
/// default in the proportion of the springs: S0 eq. (2) uses k_n and c_n for the tangential
/// spring and dashpot, so with k_t = r k_n the dashpot is c_t = r c_n.
LinearTangential linear_tangential(const ContactParameters &c)
{
  LinearTangential::Parameters t;
  t.stiffness_is_ratio = !(c.tangential_stiffness > 0.0);
  t.k_t = t.stiffness_is_ratio ? c.tangential_stiffness_ratio : c.tangential_stiffness;
  t.damping_is_ratio = !(c.tangential_damping > 0.0);
  if (!t.damping_is_ratio)
    t.c_t = c.tangential_damping;
  else if (c.tangential_damping_ratio >= 0.0)
    t.c_t = c.tangential_damping_ratio;
  else if (t.stiffness_is_ratio)
    t.c_t = c.tangential_stiffness_ratio;
  else if (c.normal_stiffness > 0.0)
    t.c_t = c.tangential_stiffness / c.normal_stiffness;
  else
    throw std::invalid_argument("make_contact_model: c_t = (k_t/k_n) c_n needs k_n in N/m when k_t is given in N/m");
  return LinearTangential(t);
}

ContactModel make_base_contact_model(const ContactParameters &c)
{
  if (c.model == "hertz-mindlin") {
    HertzNormal::Parameters n; // S4 eq. (15), (18); damping from e (DEM-NOTES section 3)
    n.youngs_modulus = c.youngs_modulus;
    n.poisson_ratio = c.poisson_ratio;
    n.damping_input = HertzNormal::Damping::restitution;
    n.restitution = c.restitution;
    MindlinTangential::Parameters t; // S4 eq. (16), (19), same e for the tangential dashpot
    t.youngs_modulus = c.youngs_modulus;
    t.poisson_ratio = c.poisson_ratio;
    t.restitution = c.restitution;
    return HertzMindlin(HertzNormal(n), MindlinTangential(t));
  }
  if (c.model != "linear")
    throw std::invalid_argument("make_contact_model: unknown contact model '" + c.model + "'");
  LinearNormal::Parameters n; // S0 eq. (1)
  if (c.normal_stiffness > 0.0) {
    n.stiffness_input = LinearNormal::Stiffness::direct;
    n.k_n = c.normal_stiffness;
  } else {
    n.stiffness_input = LinearNormal::Stiffness::from_impact_velocity; // S0 k_n
    n.youngs_modulus = c.youngs_modulus;
    n.poisson_ratio = c.poisson_ratio;
    n.impact_velocity = c.impact_velocity;
  }
  if (c.normal_damping > 0.0) {
    n.damping_input = LinearNormal::Damping::direct;
    n.c_n = c.normal_damping;
  } else if (c.normal_damping_per_mass > 0.0) {
    n.damping_input = LinearNormal::Damping::per_unit_mass; // LIGGGHTS gamma_n
    n.gamma_n = c.normal_damping_per_mass;
  } else {
    n.damping_input = LinearNormal::Damping::restitution; // S0 c_n
    n.restitution = c.restitution;
  }
  return LinearSpringDashpot(LinearNormal(n), linear_tangential(c));
}
} // namespace

ContactModel make_contact_model(const ContactParameters &c)
{
  return with_contact_parts(make_base_contact_model(c), c); // rolling, bonds, S3 friction
}

void set_contact_law(DemSystem &system, const ContactParameters &c)
{
  system.set_contact_model(make_contact_model(c));
  system.set_wall_bonding(c.wall_bonding);
  system.set_bonding_walls(c.bonding_walls == "z" ? std::uint64_t(0b110000) : ~std::uint64_t(0)); // walls 4, 5: z-, z+
}

DemSystem make_system(const Packing &packing, const ContactParameters &c, const DemParameters &d)
{
  if (packing.size() == 0)
    throw std::invalid_argument("make_system: empty packing");
  DemSystem system;
  system.reserve(packing.size());
  system.add_box(packing.box_min, packing.box_max, c.wall_friction);
  double d_mean = 0.0;
  const bool moving = !packing.velocity.empty();
  for (std::size_t k = 0; k < packing.size(); ++k) {
    const ParticleId id = system.add_sphere(packing.position[k], packing.radius[k], packing.density,
                                            moving ? packing.velocity[k] : Vec3::Zero());
    if (moving)
      system.set_angular_velocity(id, packing.angular_velocity[k]);
    d_mean += 2.0 * packing.radius[k];
  }
  d_mean /= double(packing.size());
  set_contact_law(system, c);
  system.set_friction(c.particle_friction);
  system.set_skin(d.skin * d_mean);
  system.set_num_threads(int(d.threads)); // 0: from the problem size
  system.set_local_damping(d.local_damping);
  system.set_time_step(d.time_step_safety * system.critical_time_step());
  return system;
}

DemEngineParameters DemEngineParameters::from_case(const DemParameters &d)
{
  DemEngineParameters p;
  p.servo.proportional_gain = d.servo_gain;
  p.servo.integral_gain = d.servo_integral_gain;
  p.servo.max_velocity = d.servo_max_velocity;
  p.servo.kinematic_speed_ratio = d.servo_speed_ratio;
  p.guards.min_edge_diameters = d.guard_min_edge;
  p.guards.max_stress_ratio = d.guard_stress_ratio;
  return p;
}

// @sect4{Interrupts}

namespace {
volatile std::sig_atomic_t g_interrupt = 0;
std::atomic<bool> g_requested{false};
int g_requested_signal = 0;

extern "C" void on_interrupt_signal(int signal) { g_interrupt = signal; }

double wall_clock()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

Interrupted::Interrupted(int signal, std::filesystem::path checkpoint, double time)
  : std::runtime_error(checkpoint.empty() ? "DEM run interrupted (no checkpoint file configured)"
                                          : "DEM run interrupted; checkpoint written to " + checkpoint.string()),
    signal(signal), checkpoint(std::move(checkpoint)), time(time)
{
}

void install_interrupt_handlers()
{
  struct sigaction sa {};
  sa.sa_handler = on_interrupt_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

void restore_default_interrupt_handlers()
{
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

int interrupt_requested()
{
  if (g_interrupt)
    return int(g_interrupt);
  return g_requested.load(std::memory_order_relaxed) ? std::max(g_requested_signal, -1) : 0;
}

void request_interrupt(int signal)
{
  g_requested_signal = signal == 0 ? -1 : signal;
  g_requested.store(true);
}

void clear_interrupt()
{
  g_interrupt = 0;
  g_requested.store(false);
  g_requested_signal = 0;
}

// @sect4{Construction, drive and stepping}

DemEngine::DemEngine(DemSystem system, const DemEngineParameters &parameters)
  : system_(std::move(system)), prm_(parameters)
{
  // The engine reads contact forces only where advance_to lands (measure, snapshot,
  // Love-Weber stress): its last step records them, the others stream less memory.
  system_.set_contact_force_recording(DemSystem::ContactForceRecording::on_request);
  // The loads at the start, as the first step would find them: a specimen measured before
  // any step (a packing taken as given) reports its own stress.
  system_.evaluate_forces();
  if (system_.n_walls() < 6)
    throw std::invalid_argument("DemEngine: the system needs the six walls of add_box() as walls 0..5");
  for (int a = 0; a < 3; ++a)
    if (system_.wall(2 * a).normal[a] != 1.0 || system_.wall(2 * a + 1).normal[a] != -1.0)
      throw std::invalid_argument("DemEngine: walls 0..5 must be the box faces x-, x+, y-, y+, z-, z+");
  prm_.servo.validate();
  if (system_.n_particles() == 0)
    throw std::invalid_argument("DemEngine: no particles");
  s_.L0 = box_lengths();
  s_.t_origin = system_.time();
  const std::size_t n = system_.n_particles();
  s_.x_start.resize(n);
  double mass = 0.0, diameter = 0.0, volume = 0.0;
  const ParticleStore &p = system_.particles();
  for (std::size_t k = 0; k < n; ++k) {
    s_.x_start[p.id[k]] = p.x[k];
    const double r = p.radius[k];
    volume += 4.0 / 3.0 * M_PI * r * r * r;
    mass += p.mass[k];
    diameter += 2.0 * r;
  }
  s_.density = mass / volume;
  s_.mean_diameter = diameter / double(n);
  s_.max_diameter = 2.0 * *std::max_element(p.radius.begin(), p.radius.begin() + std::ptrdiff_t(n));
  const Tensor3 sigma0 = wall_stress();
  s_.reference_stress = sigma0.allFinite() ? sigma0.diagonal().cwiseAbs().maxCoeff() : 0.0;
  s_.solid_volume = volume;
  // Dashpot time c_n/k_n of a wall contact of the mean particle (overlap 0.1 % of R).
  ContactKinematics k;
  k.r_eff = 0.5 * s_.mean_diameter;
  k.m_eff = mass / double(n);
  k.overlap = 1e-3 * k.r_eff;
  s_.dashpot_time = std::visit(
    [&](const auto &law) {
      const NormalResponse r = law.normal().evaluate(k);
      return r.stiffness > 0.0 ? r.damping / r.stiffness : 0.0;
    },
    system_.contact_model());
  last_checkpoint_wall_ = wall_clock();
}

Vector3 DemEngine::box_lengths() const
{
  Vector3 L;
  for (int a = 0; a < 3; ++a)
    L[a] = system_.wall(2 * a + 1).point[a] - system_.wall(2 * a).point[a];
  return L;
}

std::vector<ExtraColumn> DemEngine::extra_columns() const
{
  return {{"love_weber_xx", "Pa", "Love-Weber stress xx over all contacts, particle-wall included"},
          {"love_weber_yy", "Pa", "Love-Weber stress yy"},
          {"love_weber_zz", "Pa", "Love-Weber stress zz"},
          {"love_weber_xy", "Pa", "Love-Weber stress xy (symmetric part)"},
          {"love_weber_yz", "Pa", "Love-Weber stress yz"},
          {"love_weber_xz", "Pa", "Love-Weber stress xz"},
          {"love_weber_mean", "Pa", "tr(sigma_LW)/3"},
          {"coordination", "1", "Z = 2 C / N, C touching particle-particle contacts"},
          {"mechanical_coordination", "1", "(2C - N1)/(N - N0 - N1), without particles of 0 or 1 contacts (Thornton)"},
          {"wall_contacts", "1", "touching particle-wall contacts"},
          {"fabric_xx", "1", "Phi_xx of the contact-normal fabric (1/C) sum n n"},
          {"fabric_yy", "1", "Phi_yy"},
          {"fabric_zz", "1", "Phi_zz"},
          {"fabric_anisotropy", "1", "sqrt(3/2 dev(Phi):dev(Phi))"},
          {"porosity", "1", "1 - solid volume / box volume"},
          {"kinetic_energy", "J", "translational + rotational"},
          {"inertial_number", "1",
           "gamma_dot d_mean sqrt(rho / p), gamma_dot = max - min of the axes' mean strain rates over the interval"},
          {"unbalanced_force_ratio", "1", "mean |net particle force| / mean |contact force|"},
          {"steps", "1", "DEM steps since the start of the run"},
          {"servo_deviation", "1", "largest |sigma_aa - goal|/|goal| of a stress-controlled axis at any step of the "
                                   "sampling interval (0 without one)"},
          {"servo_reversals", "1",
           "steps of the sampling interval at which a servo wall's speed changed sign (summed over the "
           "stress-controlled axes; an oscillating servo reverses every step)"},
          {"wall_rate_xx", "1/s", "engineering strain rate of the x walls at the sample's last step"},
          {"wall_rate_yy", "1/s", "the same for y"},
          {"wall_rate_zz", "1/s", "the same for z"},
          {"intact_bonds", "1", "S3 cohesive bonds now intact, particle-particle and particle-wall (0 without bonds)"},
          {"broken_bonds", "1", "S3 cohesive bonds broken for good since they formed (S3 eq. (8))"}};
}

namespace {
/// Two stages that drive the box the same way.
bool same_drive(const Stage &a, const Stage &b)
{
  if (a.isochoric != b.isochoric || a.lambda != b.lambda || a.isochoric_rate != b.isochoric_rate)
    return false;
  for (int k = 0; k < 3; ++k)
    if (a.axes[k].kind != b.axes[k].kind || a.axes[k].value != b.axes[k].value)
      return false;
  return true;
}
} // namespace

StageControl DemEngine::control() const
{
  StageControl c;
  c.stage = &s_.stage;
  c.t0 = s_.control_t0;
  c.eps0 = s_.control_eps0;
  c.direction = s_.control_direction;
  return c;
}

void DemEngine::begin_control(const StageControl &control)
{
  if (!control.stage)
    throw std::invalid_argument("DemEngine::begin_control: control without a stage");
  // The servo's learned speeds belong to a drive: a new one (another stage, a branch's
  // reversal) starts them afresh; the same drive again (the main path taken up after a
  // branch) keeps them, so branches leave the main path as it was.
  const bool same = s_.has_control && control.t0 == s_.control_t0 && control.direction == s_.control_direction &&
                    control.eps0 == s_.control_eps0 && same_drive(*control.stage, s_.stage);
  if (!same)
    for (AxisServo &servo : s_.servo)
      servo.reset();
  if (!control.stage->isochoric)
    for (const AxisDrive &a : control.stage->axes)
      if (a.is_stress())
        s_.reference_stress = std::max(s_.reference_stress, std::abs(a.value));
  s_.stage = *control.stage;
  s_.control_t0 = control.t0;
  s_.control_eps0 = control.eps0;
  s_.control_direction = control.direction;
  s_.has_control = true;
}

Tensor3 DemEngine::wall_stress() const
{
  const Vector3 L = box_lengths();
  Tensor3 s = Tensor3::Zero();
  for (int a = 0; a < 3; ++a) {
    const double area = L[(a + 1) % 3] * L[(a + 2) % 3];
    const Vec3 &f_lo = system_.wall(2 * a).force, &f_hi = system_.wall(2 * a + 1).force;
    for (int b = 0; b < 3; ++b)
      s(b, a) = -(f_hi[b] - f_lo[b]) / (2.0 * area); // DEM-NOTES section 6, wall stress
  }
  return 0.5 * (s + s.transpose());
}

Tensor3 DemEngine::love_weber_stress() const
{
  Tensor3 s = Tensor3::Zero();
  for (const ContactRecord &c : system_.contacts())
    s -= c.branch * c.force.transpose(); // DEM-NOTES section 6, branch form
  return 0.5 * (s + s.transpose()) / box_lengths().prod();
}

void DemEngine::step()
{
  const double dt = system_.time_step();
  const StageControl c = control();
  const double t_next = time() + dt;
  double lo_next[3], hi_next[3], v[3] = {0.0, 0.0, 0.0}; // v: outward speed of each wall of an axis
  double kinematic_speed = 0.0; // the fastest kinematic wall's
  for (int a = 0; a < 3; ++a) {
    if (!c.kinematic(a))
      continue;
    const double lo = system_.wall(2 * a).point[a], hi = system_.wall(2 * a + 1).point[a];
    const double L_next = s_.L0[a] * (1.0 + c.strain(a, t_next));
    const double centre = 0.5 * (lo + hi);
    lo_next[a] = centre - 0.5 * L_next;
    hi_next[a] = centre + 0.5 * L_next;
    v[a] = 0.5 * (L_next - (hi - lo)) / dt;
    kinematic_speed = std::max(kinematic_speed, std::abs(v[a]));
  }
  for (int a = 0; a < 3; ++a) {
    if (!c.kinematic(a)) {
      const double previous = system_.wall(2 * a + 1).velocity[a];
      v[a] = servo_velocity(a, c, dt, kinematic_speed);
      s_.servo_reversals += previous * v[a] < 0.0 ? 1 : 0;
    }
    Vec3 w = Vec3::Zero();
    w[a] = v[a];
    system_.set_wall_velocity(2 * a, -w);
    system_.set_wall_velocity(2 * a + 1, w);
    s_.rate[a] = 2.0 * v[a] / s_.L0[a];
  }
  system_.step();
  for (int a = 0; a < 3; ++a) {
    if (!c.kinematic(a))
      continue;
    Vec3 p = system_.wall(2 * a).point;
    p[a] = lo_next[a];
    system_.set_wall_position(2 * a, p);
    p = system_.wall(2 * a + 1).point;
    p[a] = hi_next[a];
    system_.set_wall_position(2 * a + 1, p);
  }
  accumulate(c, dt); // the stress guards first: a stress that is not finite moves the servo walls anywhere
  check_box();
}

void DemEngine::check_box() const
{
  const Vector3 L = box_lengths();
  const double min_edge = prm_.guards.min_edge_diameters * s_.max_diameter;
  for (int a = 0; a < 3; ++a)
    if (!(L[a] >= min_edge)) {
      std::ostringstream o;
      o << "guard: the box edge along " << "xyz"[a] << " is " << L[a] << " m, ";
      if (std::isfinite(L[a]))
        o << "below " << prm_.guards.min_edge_diameters << " particle diameters (" << min_edge << " m)";
      else
        o << "not a length";
      o << " at t = " << time() << " s: the program has squeezed the box shut";
      throw GuardError(o.str());
    }
}

void DemEngine::check_particles_inside() const
{
  const ParticleStore &p = system_.particles();
  for (std::size_t k = 0; k < p.size(); ++k)
    for (int a = 0; a < 3; ++a)
      if (!(p.x[k][a] >= system_.wall(2 * a).point[a] && p.x[k][a] <= system_.wall(2 * a + 1).point[a])) {
        std::ostringstream o;
        o << "guard: particle " << p.id[k] << " has left the box along " << "xyz"[a] << " (centre at "
          << p.x[k][a] << " m, walls at " << system_.wall(2 * a).point[a] << " and " << system_.wall(2 * a + 1).point[a]
          << " m) at t = " << time() << " s";
        throw GuardError(o.str());
      }
}

double DemEngine::servo_velocity(int a, const StageControl &c, double dt, double kinematic_speed)
{
  const int b = (a + 1) % 3, d = (a + 2) % 3;
  ServoInput in;
  in.goal = c.target_stress(a);
  in.area = (system_.wall(2 * b + 1).point[b] - system_.wall(2 * b).point[b]) *
            (system_.wall(2 * d + 1).point[d] - system_.wall(2 * d).point[d]);
  in.stress = -(system_.wall(2 * a + 1).force[a] - system_.wall(2 * a).force[a]) / (2.0 * in.area);
  // Wall contacts answer a wall speed v at once with k delta + c v: the stiffness seen in
  // one step is K_w (1 + c/(k dt)). Without the dashpot term the loop gain exceeds 1 for
  // g_P = 0.5 at e = 0.5 and the walls lock into a period-2 oscillation.
  in.stiffness = 0.5 * (system_.wall(2 * a).stiffness + system_.wall(2 * a + 1).stiffness) *
                 (1.0 + s_.dashpot_time / dt);
  in.dt = dt;
  in.kinematic_speed = kinematic_speed;
  return s_.servo[a].velocity(prm_.servo, in);
}

void DemEngine::accumulate(const StageControl &c, double dt)
{
  const Tensor3 sigma = wall_stress();
  const double largest = sigma.diagonal().cwiseAbs().maxCoeff();
  if (!sigma.allFinite() ||
      (s_.reference_stress > 0.0 && largest > prm_.guards.max_stress_ratio * s_.reference_stress)) {
    std::ostringstream o;
    o << "guard: the wall stress " << (sigma.allFinite() ? "reached " : "is not finite: ") << largest << " Pa";
    if (sigma.allFinite())
      o << ", above " << prm_.guards.max_stress_ratio << " times the reference stress " << s_.reference_stress << " Pa";
    o << ", at t = " << time() << " s";
    throw GuardError(o.str());
  }
  s_.stress_sum += dt * sigma;
  s_.rate_sum += dt * s_.rate;
  s_.window_time += dt;
  if (c.stage->isochoric)
    return;
  for (int a = 0; a < 3; ++a)
    if (!c.kinematic(a)) {
      const double goal = c.target_stress(a);
      const double deviation = std::abs(sigma(a, a) - goal) / (goal != 0.0 ? std::abs(goal) : 1.0);
      s_.max_servo_deviation = std::max(s_.max_servo_deviation, deviation);
    }
}

void DemEngine::maybe_checkpoint()
{
  if (prm_.checkpoint_file.empty())
    return;
  bool due = prm_.checkpoint_every_steps > 0 && system_.n_steps() % prm_.checkpoint_every_steps == 0;
  if (!due && prm_.checkpoint_every_seconds > 0.0 && system_.n_steps() % 64 == 0)
    due = wall_clock() - last_checkpoint_wall_ >= prm_.checkpoint_every_seconds;
  if (due) {
    write_checkpoint(prm_.checkpoint_file);
    last_checkpoint_wall_ = wall_clock();
  }
}

void DemEngine::advance_to(double t_end)
{
  if (!s_.has_control)
    throw std::logic_error("DemEngine: advance_to before begin_control");
  const double dt = system_.time_step();
  // Steps of dt, the last one shortened so that the engine lands on t_end exactly (the
  // runner's branch landing and the sample times rely on it). The trajectory therefore
  // depends on the sample times, deterministically: a restart replays the same ones.
  while (true) {
    const double remaining = t_end - time();
    if (remaining <= 1e-9 * dt)
      break;
    if (prm_.check_interrupts) {
      if (const int signal = interrupt_requested()) {
        if (!prm_.checkpoint_file.empty())
          write_checkpoint(prm_.checkpoint_file);
        throw Interrupted(std::max(signal, 0), prm_.checkpoint_file, time());
      }
    }
    if (remaining <= dt * (1.0 + 1e-9)) {  // the last step: measurements follow it
      system_.record_contact_forces();
      system_.set_time_step(remaining);
      step();
      system_.set_time_step(dt);
    } else {
      step();
    }
    maybe_checkpoint();
  }
}

// @sect4{Measurements}

ResponseSample DemEngine::measure()
{
  check_particles_inside();
  ResponseSample s;
  s.time = time();
  const Vector3 L = box_lengths();
  const double V = L.prod();
  for (int a = 0; a < 3; ++a)
    s.strain(a, a) = (L[a] - s_.L0[a]) / s_.L0[a];
  s.stress = wall_stress();
  s.stress_mean = s_.window_time > 0.0 ? Tensor3(s_.stress_sum / s_.window_time) : s.stress;

  const ParticleStore &p = system_.particles();
  const std::size_t n = p.size();
  std::vector<int> pp_contacts(n, 0);
  Tensor3 fabric = Tensor3::Zero(), lw = Tensor3::Zero();
  std::size_t C = 0, n_wall = 0, n_forces = 0;
  double sum_f = 0.0;
  for (const ContactRecord &c : system_.contacts()) {
    lw -= c.branch * c.force.transpose(); // DEM-NOTES section 6
    sum_f += c.force.norm();
    ++n_forces;
    if (c.wall) {
      ++n_wall;
      continue;
    }
    ++pp_contacts[system_.index_of(c.i)];
    ++pp_contacts[system_.index_of(c.j)];
    fabric += c.normal * c.normal.transpose();
    ++C;
  }
  lw = (0.5 / V) * (lw + lw.transpose()).eval(); // eval(): lw.transpose() aliases lw
  std::size_t n0 = 0, n1 = 0, n_dynamic = 0;
  double ke = 0.0, sum_net = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    n0 += pp_contacts[k] == 0 ? 1 : 0;
    n1 += pp_contacts[k] == 1 ? 1 : 0;
    if (p.inv_mass[k] == 0.0)
      continue;
    ++n_dynamic;
    ke += 0.5 * p.mass[k] * p.v[k].squaredNorm() + 0.5 / p.inv_inertia[k] * p.omega[k].squaredNorm();
    sum_net += p.force[k].norm();
  }
  const double Z = 2.0 * double(C) / double(n);
  const double Zm = n > n0 + n1 ? (2.0 * double(C) - double(n1)) / double(n - n0 - n1) : 0.0; // Thornton 2000
  double anisotropy = 0.0;
  if (C > 0) {
    fabric /= double(C);
    const Tensor3 d = fabric - fabric.trace() / 3.0 * Tensor3::Identity();
    anisotropy = std::sqrt(1.5 * (d.array() * d.array()).sum());
  }
  const double pressure = -mean_stress(s.stress);
  // The interval's mean strain rates (a servo wall's speed at one step carries its noise).
  const Vector3 rate = s_.window_time > 0.0 ? Vector3(s_.rate_sum / s_.window_time) : s_.rate;
  const double gamma_rate = rate.maxCoeff() - rate.minCoeff();
  const double inertial = gamma_rate == 0.0 ? 0.0
                          : pressure > 0.0   ? gamma_rate * s_.mean_diameter * std::sqrt(s_.density / pressure) // GDR MiDi
                                             : std::numeric_limits<double>::quiet_NaN();
  const double unbalanced =
    sum_f > 0.0 && n_dynamic > 0 ? (sum_net / double(n_dynamic)) / (sum_f / double(n_forces)) : 0.0;
  s.extras.resize(kExtraCount);
  s.extras[kLoveWeberXX] = lw(0, 0);
  s.extras[kLoveWeberYY] = lw(1, 1);
  s.extras[kLoveWeberZZ] = lw(2, 2);
  s.extras[kLoveWeberXY] = lw(0, 1);
  s.extras[kLoveWeberYZ] = lw(1, 2);
  s.extras[kLoveWeberXZ] = lw(0, 2);
  s.extras[kLoveWeberMean] = lw.trace() / 3.0;
  s.extras[kCoordination] = Z;
  s.extras[kMechanicalCoordination] = Zm;
  s.extras[kWallContacts] = double(n_wall);
  s.extras[kFabricXX] = fabric(0, 0);
  s.extras[kFabricYY] = fabric(1, 1);
  s.extras[kFabricZZ] = fabric(2, 2);
  s.extras[kFabricAnisotropy] = anisotropy;
  s.extras[kPorosity] = 1.0 - s_.solid_volume / V;
  s.extras[kKineticEnergy] = ke;
  s.extras[kInertialNumber] = inertial;
  s.extras[kUnbalancedForceRatio] = unbalanced;
  s.extras[kSteps] = double(system_.n_steps());
  s.extras[kServoDeviation] = s_.max_servo_deviation;
  s.extras[kServoReversals] = double(s_.servo_reversals);
  for (int a = 0; a < 3; ++a)
    s.extras[kWallRateXX + a] = s_.rate[a];
  const DemSystem::BondCount bonds = system_.bond_count();
  s.extras[kIntactBonds] = double(bonds.intact);
  s.extras[kBrokenBonds] = double(bonds.broken);
  s_.stress_sum = Tensor3::Zero(); // the next interval starts here
  s_.rate_sum = Vector3::Zero();
  s_.window_time = 0.0;
  s_.max_servo_deviation = 0.0;
  s_.servo_reversals = 0;
  return s;
}

ParticleFields DemEngine::snapshot(double label) const
{
  ParticleFields f;
  f.time = time();
  f.label = label;
  for (int a = 0; a < 3; ++a) {
    f.box_min[a] = system_.wall(2 * a).point[a];
    f.box_max[a] = system_.wall(2 * a + 1).point[a];
  }
  f.box_size0 = s_.L0;
  const std::size_t n = system_.n_particles();
  const ParticleStore &p = system_.particles();
  f.ids.resize(n);
  f.positions.resize(n);
  f.displacements.resize(n);
  f.velocities.resize(n);
  f.angular_velocities.resize(n);
  f.radii.resize(n);
  for (std::size_t id = 0; id < n; ++id) {
    const Index k = system_.index_of(ParticleId(id));
    f.ids[id] = std::int64_t(id);
    f.positions[id] = p.x[k];
    f.displacements[id] = p.x[k] - s_.x_start[id];
    f.velocities[id] = p.v[k];
    f.angular_velocities[id] = p.omega[k];
    f.radii[id] = p.radius[k];
  }
  for (const ContactRecord &c : system_.contacts()) {
    if (c.wall) {
      f.wall_contacts.push_back({std::int64_t(c.i), std::int64_t(c.j)});
      f.wall_contact_points.push_back(c.point);
      f.wall_contact_forces.push_back(c.force);
    } else {
      f.contact_pairs.push_back({std::int64_t(c.i), std::int64_t(c.j)});
      f.contact_points.push_back(c.point);
      f.contact_forces.push_back(c.force);
      f.contact_normal_forces.push_back(c.normal_force);
      f.contact_overlaps.push_back(c.overlap);
    }
  }
  return f;
}

// @sect4{Saved states and checkpoints}

struct DemEngine::Saved : EngineState
{
  DemSystem system;
  State state;
};

std::unique_ptr<EngineState> DemEngine::save() const
{
  auto s = std::make_unique<Saved>();
  s->system = system_;
  s->state = s_;
  return s;
}

void DemEngine::restore(const EngineState &state)
{
  const auto &s = dynamic_cast<const Saved &>(state);
  system_ = s.system;
  s_ = s.state;
}

namespace {
void put_stage(std::ostream &out, const Stage &st)
{
  for (const AxisDrive &a : st.axes) {
    binary::put<int>(out, a.is_stress() ? 1 : 0);
    binary::put(out, a.value);
  }
  binary::put(out, st.isochoric);
  binary::put(out, st.lambda);
  binary::put(out, st.isochoric_rate);
}

void get_stage(std::istream &in, Stage &st)
{
  for (AxisDrive &a : st.axes) {
    int stress = 0;
    binary::get(in, stress);
    a.kind = stress ? AxisDrive::Kind::Stress : AxisDrive::Kind::StrainRate;
    binary::get(in, a.value);
  }
  binary::get(in, st.isochoric);
  binary::get(in, st.lambda);
  binary::get(in, st.isochoric_rate);
}
} // namespace

void DemEngine::write_state(std::ostream &out, const State &s, const DemSystem &system)
{
  binary::put_tag(out, "GCDEMENG", 2);
  binary::put(out, s.L0);
  binary::put(out, s.t_origin);
  binary::put_vector(out, s.x_start);
  binary::put(out, s.density);
  binary::put(out, s.mean_diameter);
  binary::put(out, s.solid_volume);
  binary::put(out, s.dashpot_time);
  binary::put(out, s.max_diameter);
  binary::put(out, s.reference_stress);
  binary::put(out, s.has_control);
  put_stage(out, s.stage);
  binary::put(out, s.control_t0);
  binary::put(out, s.control_direction);
  binary::put(out, s.control_eps0);
  binary::put(out, s.rate);
  for (const AxisServo &servo : s.servo)
    binary::put(out, servo.integral_velocity());
  binary::put(out, s.stress_sum);
  binary::put(out, s.rate_sum);
  binary::put(out, s.window_time);
  binary::put(out, s.max_servo_deviation);
  binary::put(out, s.servo_reversals);
  system.write_state(out);
  binary::put_tag(out, "GCDEMEND", 1);
}

void DemEngine::read_state(std::istream &in, State &s, DemSystem &system)
{
  binary::expect_tag(in, "GCDEMENG", 2);
  binary::get(in, s.L0);
  binary::get(in, s.t_origin);
  binary::get_vector(in, s.x_start);
  binary::get(in, s.density);
  binary::get(in, s.mean_diameter);
  binary::get(in, s.solid_volume);
  binary::get(in, s.dashpot_time);
  binary::get(in, s.max_diameter);
  binary::get(in, s.reference_stress);
  binary::get(in, s.has_control);
  get_stage(in, s.stage);
  binary::get(in, s.control_t0);
  binary::get(in, s.control_direction);
  binary::get(in, s.control_eps0);
  binary::get(in, s.rate);
  for (AxisServo &servo : s.servo) {
    double v = 0.0;
    binary::get(in, v);
    servo.set_integral_velocity(v);
  }
  binary::get(in, s.stress_sum);
  binary::get(in, s.rate_sum);
  binary::get(in, s.window_time);
  binary::get(in, s.max_servo_deviation);
  binary::get(in, s.servo_reversals);
  system.read_state(in);
  binary::expect_tag(in, "GCDEMEND", 1);
  if (system.n_walls() < 6 || s.x_start.size() != system.n_particles())
    throw binary::StateError("checkpoint: inconsistent engine state");
}

void DemEngine::write_state(std::ostream &out, const EngineState &state) const
{
  const auto &saved = dynamic_cast<const Saved &>(state);
  write_state(out, saved.state, saved.system);
}

std::unique_ptr<EngineState> DemEngine::read_state(std::istream &in) const
{
  auto saved = std::make_unique<Saved>();
  read_state(in, saved->state, saved->system);
  return saved;
}

void DemEngine::write_checkpoint(const std::filesystem::path &path) const
{
  write_atomically(path, [&](const std::filesystem::path &tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw std::runtime_error("DemEngine: cannot write checkpoint " + tmp.string());
    write_state(out, s_, system_);
    out.flush();
    if (!out)
      throw std::runtime_error("DemEngine: writing checkpoint " + tmp.string() + " failed");
  });
}

void DemEngine::read_checkpoint(const std::filesystem::path &path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("DemEngine: cannot open checkpoint " + path.string());
  State s;
  DemSystem system;
  try {
    read_state(in, s, system);
  } catch (const binary::StateError &e) {
    throw binary::StateError(path.string() + ": " + e.what());
  }
  system_ = std::move(system);
  system_.set_contact_force_recording(DemSystem::ContactForceRecording::on_request);
  s_ = std::move(s);
}

std::unique_ptr<DemEngine> DemEngine::from_checkpoint(const std::filesystem::path &path,
                                                      const DemEngineParameters &parameters)
{
  std::unique_ptr<DemEngine> e(new DemEngine());
  e->prm_ = parameters;
  e->read_checkpoint(path);
  e->last_checkpoint_wall_ = wall_clock();
  return e;
}

// @sect4{Isotropic hold}

HoldResult hold_isotropic(DemEngine &engine, double pressure, double tolerance, double unbalanced, double max_time,
                          double check_interval)
{
  Stage stage;
  stage.axes = {AxisDrive::stress(-pressure), AxisDrive::stress(-pressure), AxisDrive::stress(-pressure)};
  StageControl control;
  control.stage = &stage;
  control.t0 = engine.time();
  engine.begin_control(control);
  HoldResult r;
  const double t0 = engine.time();
  while (true) {
    engine.advance_to(engine.time() + check_interval);
    const ResponseSample s = engine.measure();
    r.stress_error = 0.0;
    for (int a = 0; a < 3; ++a)
      r.stress_error = std::max(r.stress_error, std::abs(s.stress(a, a) + pressure) / pressure);
    r.unbalanced = s.extras[DemEngine::kUnbalancedForceRatio];
    r.time = engine.time() - t0;
    if (r.stress_error <= tolerance && r.unbalanced <= unbalanced) {
      r.converged = true;
      break;
    }
    if (r.time >= max_time)
      break;
  }
  return r;
}

} // namespace geocomp::dem
