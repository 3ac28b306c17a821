// @sect3{The Integrator class: kicks, drifts and FIRE over the particle store}
//
// Why it exists: the time integration is one concept, apart from the contact forces it
// reads. Velocity Verlet with rotations (DEM-NOTES section 4) splits into sweeps over the
// particles:
//   kick:  $v \mathrel{+}= \tfrac{\Delta t}{2}F/m$, $\omega \mathrel{+}= \tfrac{\Delta t}{2}T/I$;
//   drift: $x \mathrel{+}= \Delta t\,v$, $q \leftarrow \exp(\Delta t\,\omega/2)\otimes q$ (exact
//          axis-angle quaternion, a 5th-order series for small angles);
// the step's opening kick and drift run as one sweep (kick_drift), the closing kick
// inside pass B of the contact pass (ContactPass.h, through kick_particle()). Optional
// Cundall local damping replaces $F_k$ by $F_k - \lambda|F_k|\,\mathrm{sign}(v_k)$ in both
// kicks (LocalDamping.h). First-order dynamics (S0 packing, Klishin & Mikenina 2021)
// replaces kick and drift by $v = \beta\Delta t\,F/m$, $x \mathrel{+}= \Delta t\,v$; FIRE
// (Bitzek et al. 2006, DEM-NOTES section 8) mixes the velocities with the forces.
//
// Determinism (DEM-NOTES section 5): a sweep returns the sum (the local damping loss)
// and the maximum (the squared displacement since the last neighbour build, for the
// rebuild criterion) over fixed blocks of 256 particles, each block in storage order,
// combined in block order: the same bits for any number of threads. Where the processor
// has AVX2 and there is no local damping, the opening kick and drift run four spheres at
// a time (ParticleSweepKernel.h, the same IEEE operations in the same order).
#pragma once

#include "dem/LocalDamping.h"
#include "dem/ParticleStore.h"

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace geocomp::dem {

/// Fixed block size of every parallel reduction: block sums do not depend on the
/// number of threads, and are added in block order (DEM-NOTES section 5).
constexpr std::size_t kBlock = 256;
inline std::size_t n_blocks(std::size_t n) { return (n + kBlock - 1) / kBlock; }

/// q <- exp(dt omega / 2) (x) q with the exact axis-angle quaternion; for the small
/// angles of DEM steps (theta < 1e-2) a 5th-order series equals sin/cos to round-off. The
/// Hamilton product is written out, in the order the batched sweep (ParticleSweepKernel.h)
/// repeats.
inline void rotate_orientation(Quat& q, const Vec3& omega, double dt)
{
  const Vec3 h = (0.5 * dt) * omega;
  const double t2 = h.squaredNorm();
  double c, s;
  if (t2 < 1e-4) {
    c = 1.0 - t2 * (0.5 - t2 * (1.0 / 24.0));
    s = 1.0 - t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0));
  } else {
    const double t = std::sqrt(t2);
    c = std::cos(t);
    s = std::sin(t) / t;
  }
  const double ux = s * h.x(), uy = s * h.y(), uz = s * h.z();
  const double qx = q.x(), qy = q.y(), qz = q.z(), qw = q.w();
  q.w() = c * qw - ux * qx - uy * qy - uz * qz;
  q.x() = c * qx + ux * qw + uy * qz - uz * qy;
  q.y() = c * qy - ux * qz + uy * qw + uz * qx;
  q.z() = c * qz + ux * qy - uy * qx + uz * qw;
}

/// The particles a sweep runs over, with what the drift compares against.
struct SweepTarget
{
  ParticleStore& store;
  const std::vector<Vec3>& x_ref;  ///< positions at the last neighbour build
  int threads;
};

/// A sweep's results: the local damping (or first-order) loss, and the largest squared
/// displacement since the last neighbour build.
struct SweepResult
{
  double loss = 0.0;
  double max_d2 = 0.0;
};

class Integrator
{
public:
  /// Cundall local damping coefficient lambda_d (0: off).
  void set_local_damping(double lambda) { local_damping_ = lambda; }
  double local_damping() const { return local_damping_; }
  /// beta of first-order dynamics (0: velocity Verlet).
  void set_overdamped(double beta) { overdamped_ = beta; }
  double overdamped() const { return overdamped_; }

  /// Half a kick of particle p with its current load; returns the local damping loss.
  GEOCOMP_CONTACT_KERNEL double kick_particle(ParticleStore& s, std::size_t p, double dt) const
  {
    const double lambda = local_damping_;
    Vec3 f = s.force[p], t = s.torque[p];
    double loss = 0.0;
    if (lambda > 0.0 && s.inv_mass[p] != 0.0)
      loss = 0.5 * dt * (dem::local_damping(f, s.v[p], lambda) + dem::local_damping(t, s.omega[p], lambda));
    s.v[p] += (0.5 * dt * s.inv_mass[p]) * f;
    s.omega[p] += (0.5 * dt * s.inv_inertia[p]) * t;
    return loss;
  }
  /// The drift of particle p over dt with its current velocities (position, orientation);
  /// returns its squared displacement since the last neighbour build.
  static GEOCOMP_CONTACT_KERNEL double drift_particle(ParticleStore& s, const std::vector<Vec3>& x_ref,
                                                     std::size_t p, double dt)
  {
    const Vec3 x = s.x[p] + dt * s.v[p];
    s.x[p] = x;
    rotate_orientation(s.orientation[p], s.omega[p], dt);
    return (x - x_ref[p]).squaredNorm();
  }

  /// Half a kick of every particle; returns the local damping loss.
  double kick(const SweepTarget& t, double dt);
  /// The step's opening half kick and drift in one sweep; `batched`: four spheres at a
  /// time (precondition: no local damping, kick_drift_kernel_available()).
  SweepResult kick_drift(const SweepTarget& t, double dt, bool batched);
  /// First-order dynamics: $v = \beta\Delta t\,F/m$, $\omega = \beta\Delta t\,T/I$ (dynamic
  /// particles), then the drift; the loss is the power $F\cdot v + T\cdot\omega$ times dt.
  SweepResult drift_overdamped(const SweepTarget& t, double dt);
  /// FIRE's velocity mixing (DemSystem::fire_velocities); returns the power P.
  double fire_velocities(ParticleStore& s, double alpha, int threads);

  std::size_t memory_bytes() const { return block_sums_.capacity() * sizeof(double); }

private:
  /// body(begin, end, sum, max) once per fixed block of the n particles, the blocks split
  /// statically among the threads; returns the blocks' sums and maxima in block order.
  template <class BlockBody>
  SweepResult sweep_blocks(std::size_t n, int threads, BlockBody body);
  /// body(p, sum, max) for every particle, in the same blocks.
  template <class Body>
  SweepResult sweep_particles(std::size_t n, int threads, Body body);

  double local_damping_ = 0.0;
  double overdamped_ = 0.0;
  std::vector<double> block_sums_;  // per block: sum, max
};

}  // namespace geocomp::dem
