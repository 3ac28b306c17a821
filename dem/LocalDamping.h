// @sect3{Cundall local non-viscous damping}
//
// Why it exists: quasi-static DEM runs (PFC's default, optional here and off by default)
// drain kinetic energy without a viscosity: each component of a body's unbalanced load
// is reduced by a fraction lambda of its magnitude, against the body's velocity,
// $$ F_k \leftarrow F_k - \lambda\,|F_k|\,\mathrm{sign}(v_k), $$
// for the force with the velocity and the torque with the spin (DEM-NOTES section 4). The
// power taken out is $\sum_k \lambda |F_k|\,|v_k|$. Spheres (DemSystem.cpp) and clumps
// (DemSystemClumps.cpp) share this one implementation.
#pragma once

#include "dem/Types.h"

#include <cmath>

namespace geocomp::dem {

/// Damps the load vector f against the velocity v in place; returns the power dissipated.
inline double local_damping(Vec3& f, const Vec3& v, double lambda)
{
  double power = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double s = (v[a] > 0.0) ? 1.0 : (v[a] < 0.0 ? -1.0 : 0.0);
    power += lambda * std::abs(f[a]) * std::abs(v[a]);
    f[a] -= lambda * std::abs(f[a]) * s;
  }
  return power;
}

}  // namespace geocomp::dem
