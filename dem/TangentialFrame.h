// @sect3{Turning a tangential history vector with the contact frame}
//
// Why it exists: the tangential spring $\xi$ (or the Mindlin spring force) is stored in
// the lab frame, but the pair tumbles. If the stored vector is not turned with the
// contact, it picks up a normal component (spurious normal force and work), slides too
// early, and a rigid rotation of a loaded pair changes its force (DEM-NOTES section 2).
// Every step, before the increment:
//  1. spin about n by the mean spin of the pair, $\theta = \Delta t\,(\omega_i+\omega_j)\cdot n/2$:
//     $\xi \leftarrow \xi + \theta\, n\times\xi$ (Yade's spin term);
//  2. project onto the current tangent plane, $\xi' = \xi - (n\cdot\xi)n$;
//  3. restore the magnitude, $\xi' \leftarrow \xi'\,|\xi|/|\xi'|$ (projection alone would
//     leak stored shear by $\cos\theta$ per step).
// The magnitude is the one before step 1, so the rotation stores or releases no energy.
#pragma once

#include "dem/Types.h"

#include <cmath>

namespace geocomp::dem {

GEOCOMP_CONTACT_KERNEL void rotate_into_tangent_plane(Vec3& s, const Vec3& n, double spin_angle)
{
  const double s2 = s.squaredNorm();
  if (s2 == 0.0) return;
  Vec3 p = s + spin_angle * n.cross(s);
  p -= n.dot(p) * n;
  const double p2 = p.squaredNorm();
  if (!(p2 > 1e-24 * s2)) {
    s.setZero();  // spring stood along the normal: no tangential direction left
    return;
  }
  // sqrt(s2/p2): the frame turns little per step, so a 3rd-order series in
  // e = s2/p2 - 1 is exact to round-off for |e| < 1e-4 and saves a square root.
  const double e = s2 / p2 - 1.0;
  const double f = (std::abs(e) < 1e-4) ? 1.0 + e * (0.5 - e * (0.125 - e * 0.0625)) : std::sqrt(1.0 + e);
  s = p * f;
}

}  // namespace geocomp::dem
