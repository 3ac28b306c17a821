// @sect3{The batched kick-drift sweep of the sphere integrator}
//
// Why it exists: after the pair kernel, the opening half kick and drift of velocity Verlet
// was the next loop of the step (an eighth of it at 10 000 spheres): per sphere
// $v \mathrel{+}= \tfrac{\Delta t}{2} F/m$, $\omega \mathrel{+}= \tfrac{\Delta t}{2} T/I$,
// $x \mathrel{+}= \Delta t\, v$, the orientation $q \leftarrow \exp(\tfrac{\Delta t}{2}\omega)\otimes q$
// and the largest displacement since the last neighbour build (DEM-NOTES sections 4-5).
// Scalar, each sphere was a chain of 3-vector operations and a quaternion product. Here
// four consecutive spheres go at once in 256-bit vectors (AVX2): the kick and the drift run
// straight on the arrays of three doubles per sphere (elementwise, no shuffles), and the
// rotation and the displacement on four spheres' components at a time.
//
// Pass B's closing half kick runs the same way for four bodies without wall slots
// (close_and_kick4): their force and torque are their load rows (LoadScatter.h) as they
// are, then the kick.
//
// Same bits as the scalar sweep (DemSystem::kick_drift with `rotate_orientation` and
// `kick_particle`): the same IEEE operations in the same order, no FMA contraction; the
// test `PairBatchKernel.*` compares the two paths' whole states bit for bit. A batch with
// a rotation angle above the series' range (|h|^2 >= 1e-4, which the scalar code turns
// with sin and cos) is finished by the scalar code, through `turn_scalar`.
//
// Like PairBatchKernel.h, this header is free of Eigen (the translation unit is compiled
// with -mavx2); the caller passes the arrays as doubles: Vec3 as three, Quaterniond as
// four (x, y, z, w, Eigen's storage order).
#pragma once

#include <cstddef>

namespace geocomp::dem {

struct KickDriftArgs
{
  double* x = nullptr;             ///< 3 per particle
  double* v = nullptr;
  double* omega = nullptr;
  double* orientation = nullptr;   ///< 4 per particle (x, y, z, w)
  const double* force = nullptr;   ///< 3 per particle
  const double* torque = nullptr;
  const double* inv_mass = nullptr;     ///< 1 per particle
  const double* inv_inertia = nullptr;
  const double* x_ref = nullptr;   ///< positions at the last neighbour build, 3 per particle
  double dt = 0.0;
  /// The caller's scalar code, reached through `owner` (passed through to both):
  /// the rotation of particle p's orientation by its (already kicked) spin, for a batch
  /// whose angle leaves the series' range;
  void (*turn_scalar)(const KickDriftArgs& args, std::size_t p) = nullptr;
  /// the sweep of particle p (kick, drift, turn) for the last spheres of a range that do
  /// not fill a vector; returns p's squared displacement since the last build.
  double (*kick_drift_scalar)(const KickDriftArgs& args, std::size_t p) = nullptr;
  void* owner = nullptr;
};

/// The closing half kick of pass B (DemSystem::compute_forces_with) for bodies without
/// wall slots: force and torque are their summed rows, then the kick.
struct ClosingKickArgs
{
  const double* rows = nullptr;  ///< 8 per particle: force (3, 0), torque (3, 0); 32-byte aligned
  double* force = nullptr;       ///< 3 per particle
  double* torque = nullptr;
  double* v = nullptr;
  double* omega = nullptr;
  const double* inv_mass = nullptr;
  const double* inv_inertia = nullptr;
  double dt = 0.0;  ///< the kick is dt / 2
};

/// Force and torque of particles [p, p + 4) from their rows, then v += (dt/2 / m) F and
/// omega += (dt/2 / I) T (kick_particle without local damping). Precondition:
/// kick_drift_kernel_available().
void close_and_kick4(const ClosingKickArgs& args, std::size_t p);

/// True when the batched sweep exists in this build and runs on this processor.
bool kick_drift_kernel_available();

/// Half kick (no local damping), drift and rotation of particles [begin, end); returns
/// the largest squared displacement from x_ref among them (0 for none). Precondition:
/// kick_drift_kernel_available().
double kick_drift_batched(const KickDriftArgs& args, std::size_t begin, std::size_t end);

}  // namespace geocomp::dem
