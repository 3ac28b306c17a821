#include "dem/Integrator.h"

#include "dem/ParticleSweepKernel.h"

#include <algorithm>
#include <cstdint>

namespace geocomp::dem {

template <class BlockBody>
SweepResult Integrator::sweep_blocks(std::size_t n, int threads, BlockBody body)
{
  const std::size_t nb = n_blocks(n);
  block_sums_.assign(2 * nb, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t b = 0; b < std::int64_t(nb); ++b) {
    double sum = 0.0, max = 0.0;
    body(std::size_t(b) * kBlock, std::min(n, std::size_t(b + 1) * kBlock), sum, max);
    block_sums_[2 * b] = sum;
    block_sums_[2 * b + 1] = max;
  }
  SweepResult r;
  for (std::size_t b = 0; b < nb; ++b) {
    r.loss += block_sums_[2 * b];
    r.max_d2 = std::max(r.max_d2, block_sums_[2 * b + 1]);
  }
  return r;
}

template <class Body>
SweepResult Integrator::sweep_particles(std::size_t n, int threads, Body body)
{
  return sweep_blocks(n, threads, [&](std::size_t begin, std::size_t end, double& sum, double& max) GEOCOMP_SWEEP_BODY {
    for (std::size_t p = begin; p < end; ++p) body(p, sum, max);
  });
}

double Integrator::kick(const SweepTarget& t, double dt)
{
  ParticleStore& s = t.store;
  return sweep_particles(s.size(), t.threads, [&](std::size_t p, double& loss, double&) GEOCOMP_SWEEP_BODY {
           loss += kick_particle(s, p, dt);
         }).loss;
}

namespace {
/// What the batched sweep's scalar callbacks reach through KickDriftArgs::owner.
struct SweepOwner
{
  const Integrator& integrator;
  ParticleStore& store;
  const std::vector<Vec3>& x_ref;
};
}  // namespace

SweepResult Integrator::kick_drift(const SweepTarget& t, double dt, bool batched)
{
  ParticleStore& s = t.store;
  const std::vector<Vec3>& x_ref = t.x_ref;
  if (batched && s.size() > 0) {
    // Four spheres at a time (ParticleSweepKernel.h, the same bits as the loop below).
    SweepOwner owner{*this, s, x_ref};
    KickDriftArgs args;
    args.x = s.x.front().data();
    args.v = s.v.front().data();
    args.omega = s.omega.front().data();
    args.orientation = s.orientation.front().coeffs().data();
    args.force = s.force.front().data();
    args.torque = s.torque.front().data();
    args.inv_mass = s.inv_mass.data();
    args.inv_inertia = s.inv_inertia.data();
    args.x_ref = x_ref.front().data();
    args.dt = dt;
    args.owner = &owner;
    args.turn_scalar = [](const KickDriftArgs& a, std::size_t p) {
      SweepOwner& o = *static_cast<SweepOwner*>(a.owner);
      rotate_orientation(o.store.orientation[p], o.store.omega[p], a.dt);
    };
    args.kick_drift_scalar = [](const KickDriftArgs& a, std::size_t p) {
      SweepOwner& o = *static_cast<SweepOwner*>(a.owner);
      o.integrator.kick_particle(o.store, p, a.dt);  // no local damping on this path
      return drift_particle(o.store, o.x_ref, p, a.dt);
    };
    SweepResult r = sweep_blocks(s.size(), t.threads, [&](std::size_t begin, std::size_t end, double&, double& max_d2)
                                                          GEOCOMP_SWEEP_BODY {
                                                            max_d2 = std::max(max_d2, kick_drift_batched(args, begin, end));
                                                          });
    r.loss = 0.0;  // no local damping on this path
    return r;
  }
  return sweep_particles(s.size(), t.threads, [&](std::size_t p, double& loss, double& max_d2) GEOCOMP_SWEEP_BODY {
    loss += kick_particle(s, p, dt);
    max_d2 = std::max(max_d2, drift_particle(s, x_ref, p, dt));
  });
}

SweepResult Integrator::drift_overdamped(const SweepTarget& t, double dt)
{
  // S0 "Aristotelian" packing dynamics: v = F / gamma with gamma = m / (beta dt).
  ParticleStore& s = t.store;
  const std::vector<Vec3>& x_ref = t.x_ref;
  const double mobility = overdamped_ * dt;
  return sweep_particles(s.size(), t.threads, [&](std::size_t p, double& loss, double& max_d2) GEOCOMP_SWEEP_BODY {
    if (s.inv_mass[p] != 0.0) {  // kinematic particles keep their set velocity
      s.v[p] = (mobility * s.inv_mass[p]) * s.force[p];
      s.omega[p] = (mobility * s.inv_inertia[p]) * s.torque[p];
      loss += dt * (s.force[p].dot(s.v[p]) + s.torque[p].dot(s.omega[p]));
    }
    max_d2 = std::max(max_d2, drift_particle(s, x_ref, p, dt));
  });
}

// @sect4{FIRE velocity control (preparation)}

double Integrator::fire_velocities(ParticleStore& s, double alpha, int threads)
{
  // One serial pass in storage order (fixed: the same bits for any thread count) for the
  // power and the four global norms, then the update.
  const std::size_t n = s.size();
  double power = 0.0, v2 = 0.0, f2 = 0.0, w2 = 0.0, t2 = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (s.inv_mass[k] == 0.0) continue;
    power += s.force[k].dot(s.v[k]) + s.torque[k].dot(s.omega[k]);
    v2 += s.v[k].squaredNorm();
    f2 += s.force[k].squaredNorm();
    w2 += s.omega[k].squaredNorm();
    t2 += s.torque[k].squaredNorm();
  }
  // P > 0: v <- (1 - alpha) v + alpha |v| F/|F|; otherwise every particle stops.
  const bool downhill = power > 0.0;
  const double keep = downhill ? 1.0 - alpha : 0.0;
  const double sv = downhill && f2 > 0.0 ? alpha * std::sqrt(v2 / f2) : 0.0;
  const double sw = downhill && t2 > 0.0 ? alpha * std::sqrt(w2 / t2) : 0.0;
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < std::int64_t(n); ++k) {
    if (s.inv_mass[k] == 0.0) continue;
    if (!downhill) {
      s.v[k].setZero();
      s.omega[k].setZero();
      continue;
    }
    s.v[k] = keep * s.v[k] + sv * s.force[k];
    s.omega[k] = keep * s.omega[k] + sw * s.torque[k];
  }
  return power;
}

}  // namespace geocomp::dem
