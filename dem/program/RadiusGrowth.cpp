#include "dem/program/RadiusGrowth.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>

namespace geocomp::dem {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// DemSystem::ContactForceRecording::on_request while it lives, the caller's setting after:
/// the preparation reads contacts() only after a chunk of steps, whose last step it asks to
/// record, and the steps before stream less memory.
class RecordOnRequest
{
public:
  explicit RecordOnRequest(DemSystem &system) : system_(system), mode_(system.contact_force_recording())
  {
    system_.set_contact_force_recording(DemSystem::ContactForceRecording::on_request);
  }
  ~RecordOnRequest() { system_.set_contact_force_recording(mode_); }
  RecordOnRequest(const RecordOnRequest &) = delete;
  RecordOnRequest &operator=(const RecordOnRequest &) = delete;

private:
  DemSystem &system_;
  DemSystem::ContactForceRecording mode_;
};

/// n steps of which only the last keeps every contact's force.
void run_recording_last(DemSystem &system, std::uint64_t n)
{
  if (n == 0)
    return;
  const RecordOnRequest scope(system);
  system.run(n - 1);
  system.record_contact_forces();
  system.step();
}
} // namespace

// @sect4{Random placement}
//
// Random sequential addition with a cell grid of edge 2 R_max: a candidate is tested
// against the spheres of its own and the 26 neighbouring cells only.
std::vector<Vec3> place_at_random(const std::vector<double> &radii, const Vec3 &lo, const Vec3 &hi,
                                  std::uint64_t seed, std::size_t max_attempts)
{
  const std::size_t n = radii.size();
  if (n == 0)
    return {};
  const double r_max = *std::max_element(radii.begin(), radii.end());
  const Vec3 L = hi - lo;
  if (!(r_max > 0.0) || !(L.minCoeff() > 2.0 * r_max))
    throw std::invalid_argument("place_at_random: the box is smaller than the largest sphere");
  const double h = 2.0 * r_max;
  int dims[3];
  for (int a = 0; a < 3; ++a)
    dims[a] = std::max(1, int(std::floor(L[a] / h)));
  const double cell[3] = {L[0] / dims[0], L[1] / dims[1], L[2] / dims[2]};
  std::vector<std::int64_t> head(std::size_t(dims[0]) * dims[1] * dims[2], -1), next(n, -1);
  auto cell_of = [&](const Vec3 &x, int c[3]) {
    for (int a = 0; a < 3; ++a)
      c[a] = std::clamp(int((x[a] - lo[a]) / cell[a]), 0, dims[a] - 1);
  };
  auto flat = [&](int i, int j, int k) { return (std::size_t(k) * dims[1] + j) * dims[0] + i; };

  std::mt19937_64 rng(seed ^ 0x5eed9ac4ULL); // a stream apart from the radii's
  auto u01 = [&rng]() { return double(rng() >> 11) * 0x1.0p-53; }; // [0, 1), 53 bits
  std::vector<Vec3> x(n);
  for (std::size_t p = 0; p < n; ++p) {
    const double r = radii[p];
    bool placed = false;
    for (std::size_t attempt = 0; attempt < max_attempts && !placed; ++attempt) {
      Vec3 c;
      for (int a = 0; a < 3; ++a)
        c[a] = lo[a] + r + (L[a] - 2.0 * r) * u01();
      int ic[3];
      cell_of(c, ic);
      bool free = true;
      for (int dk = -1; dk <= 1 && free; ++dk)
        for (int dj = -1; dj <= 1 && free; ++dj)
          for (int di = -1; di <= 1 && free; ++di) {
            const int i = ic[0] + di, j = ic[1] + dj, k = ic[2] + dk;
            if (i < 0 || j < 0 || k < 0 || i >= dims[0] || j >= dims[1] || k >= dims[2])
              continue;
            for (std::int64_t q = head[flat(i, j, k)]; q >= 0; q = next[q]) {
              const double s = r + radii[q];
              if ((x[q] - c).squaredNorm() < s * s) {
                free = false;
                break;
              }
            }
          }
      if (free) {
        x[p] = c;
        const std::size_t f = flat(ic[0], ic[1], ic[2]);
        next[p] = head[f];
        head[f] = std::int64_t(p);
        placed = true;
      }
    }
    if (!placed)
      throw std::runtime_error("place_at_random: no free place for sphere " + std::to_string(p) + " after " +
                               std::to_string(max_attempts) + " attempts (start from smaller radii)");
  }
  return x;
}

// @sect4{Rest criteria}

RestState rest_state(const DemSystem &system)
{
  RestState s;
  const ParticleStore &p = system.particles();
  std::vector<int> contacts(p.size(), 0);
  double sum_f = 0.0;
  std::size_t n_f = 0;
  for (const ContactRecord &c : system.contacts()) {
    sum_f += c.force.norm();
    ++n_f;
    ++contacts[system.index_of(c.j)];
    if (!c.wall)
      ++contacts[system.index_of(c.i)];
  }
  double sum_net = 0.0;
  std::size_t n_dyn = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p.inv_mass[k] == 0.0)
      continue;
    sum_net += p.force[k].norm();
    ++n_dyn;
    if (contacts[k] < 2) {
      ++s.rattlers; // caged, carries no load: its motion is left out of the kinetic energy
      continue;
    }
    s.kinetic += 0.5 * p.mass[k] * p.v[k].squaredNorm() + 0.5 / p.inv_inertia[k] * p.omega[k].squaredNorm();
  }
  s.unbalanced = (sum_f > 0.0 && n_dyn > 0) ? (sum_net / double(n_dyn)) / (sum_f / double(n_f)) : 0.0;
  const EnergyLedger e = system.energy();
  s.elastic = e.elastic_normal + e.elastic_tangential;
  return s;
}

// @sect4{Growth and relaxation}

GrowthResult grow_radii(DemSystem &system, const std::vector<double> &target, const GrowthSettings &g,
                        const PhaseProgress &progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = system.n_particles();
  if (target.size() != n)
    throw std::invalid_argument("grow_radii: one target radius per particle expected");
  if (!(g.rate > 0.0) || g.interval == 0)
    throw std::invalid_argument("grow_radii: the growth rate and interval must be positive");
  const ParticleStore &p = system.particles();
  double f = p.radius[system.index_of(0)] / target[0];
  if (!(f > 0.0 && f <= 1.0))
    throw std::invalid_argument("grow_radii: the current radii must be a fraction <= 1 of the targets");
  GrowthResult r;
  r.initial_factor = f;
  const std::uint64_t steps0 = system.n_steps();
  const double time0 = system.time();
  const std::size_t builds0 = system.n_rebuilds();
  std::uint64_t chunks = 0;
  std::vector<double> radii(n);
  while (f < 1.0) {
    system.set_time_step(g.time_step_safety * system.critical_time_step());
    // DEM-NOTES section 8: all radii times the same factor; the last factor lands on 1.
    const double f_next = std::min(1.0, f * std::exp(g.rate * system.time_step() * double(g.interval)));
    for (std::size_t id = 0; id < n; ++id)
      radii[id] = f_next == 1.0 ? target[id] : f_next * target[id];
    system.set_radii(radii);
    f = f_next;
    run_recording_last(system, g.interval);
    if (progress && ++chunks % 100 == 0) // the radius factor's way from f0 to 1, on a log scale
      progress("growth", system.time() - time0, std::log(f / r.initial_factor) / std::log(1.0 / r.initial_factor));
  }
  system.set_time_step(g.time_step_safety * system.critical_time_step());
  r.cost.steps = system.n_steps() - steps0;
  r.cost.time = system.time() - time0;
  r.cost.wall_seconds = seconds_since(t0);
  r.rebuilds = system.n_rebuilds() - builds0;
  if (progress)
    progress("growth", r.cost.time, 1.0);
  return r;
}

bool nothing_touches(DemSystem &system)
{
  system.evaluate_forces();
  const std::vector<double> &radius = system.particles().radius;
  if (radius.empty())
    return true;
  const double tolerance = 1e-9 * *std::min_element(radius.begin(), radius.end());
  for (const ContactRecord &c : system.contacts())
    if (c.overlap > tolerance)
      return false;
  return true;
}

RelaxResult relax(DemSystem &system, const RestCriteria &k, const std::string &phase, const PhaseProgress &progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  const std::uint64_t steps0 = system.n_steps();
  const double time0 = system.time();
  RelaxResult r;
  if (nothing_touches(system)) {
    r.converged = r.nothing_touches = true;
    r.rest = rest_state(system);
    if (progress)
      progress(phase + ": nothing touches, ended at once", 0.0, 1.0);
    return r;
  }
  std::uint64_t checks = 0;
  double first_unbalanced = 0.0, fraction = 0.0; // the progress estimate
  // FIRE state (RestCriteria::fire).
  const double dt0 = system.time_step(), damping0 = system.local_damping_coefficient();
  double dt = dt0, alpha = k.fire_alpha;
  unsigned positive = 0;
  if (k.fire)
    system.set_local_damping(0.0);
  while (true) {
    if (!k.fire) {
      run_recording_last(system, k.check_steps);
    } else {
      const RecordOnRequest scope(system);
      for (std::uint64_t n = 0; n < k.check_steps; ++n) {
        if (n + 1 == k.check_steps)
          system.record_contact_forces(); // rest_state reads the contacts after this chunk
        system.step();
        if (system.fire_velocities(alpha) > 0.0) {
          if (++positive > k.fire_delay) {
            dt = std::min(dt * k.fire_dt_growth, k.fire_dt_max * dt0);
            alpha *= k.fire_alpha_decay;
          }
        } else {  // the particles were stopped
          dt *= 0.5;
          alpha = k.fire_alpha;
          positive = 0;
        }
        system.set_time_step(dt);
      }
    }
    r.rest = rest_state(system);
    r.converged = k.satisfied_by(r.rest);
    if (r.converged || system.time() - time0 >= k.max_time)
      break;
    if (checks++ == 0)
      first_unbalanced = r.rest.unbalanced;
    fraction = std::max(fraction, log_progress(first_unbalanced, r.rest.unbalanced, k.unbalanced));
    if (progress && checks % 5 == 0)
      progress(phase, system.time() - time0, fraction);
  }
  if (k.fire) {
    system.set_time_step(dt0);
    system.set_local_damping(damping0);
  }
  r.cost.steps = system.n_steps() - steps0;
  r.cost.time = system.time() - time0;
  r.cost.wall_seconds = seconds_since(t0);
  if (progress)
    progress(phase, r.cost.time, 1.0);
  return r;
}

} // namespace geocomp::dem
