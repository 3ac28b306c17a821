// @sect3{The PlaneWall struct}
//
// Why it exists: S0's specimen is a cube between six rigid plates driven by a loading
// program (constant speeds, servo control, isochoric position control). A wall is a
// plane through `point` with unit `normal` pointing into the specimen; it translates
// with `velocity`, which the driver may change before any step. It is body i of its
// contacts (infinite radius and mass). The engine records on it the total force the
// particles exert, the torque of that force about `point`, the number of touching
// particles, the sum of their normal stiffnesses (the servo gain K_w of DEM-NOTES
// section 7) and the work the wall has done on the particles,
// $W \mathrel{+}= -\tfrac12(F^{old} + F^{new})\cdot V\Delta t$.
#pragma once

#include "dem/Types.h"

#include <cstddef>

namespace geocomp::dem {

struct PlaneWall
{
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();   ///< unit, into the specimen
  Vec3 velocity = Vec3::Zero();  ///< translation velocity (set by the driver)
  double mu = 0.0;               ///< particle-wall friction coefficient mu_p

  // Recorded by the engine after every step (read only for users).
  Vec3 force = Vec3::Zero();     ///< total force of the particles on the wall
  Vec3 torque = Vec3::Zero();    ///< torque of that force about `point`
  double work = 0.0;             ///< cumulative work done by the wall on the particles
  double stiffness = 0.0;        ///< sum of k_n over touching contacts (servo gain)
  std::size_t n_contacts = 0;    ///< touching particles

  /// Signed distance of a point from the plane (positive inside the specimen).
  double distance(const Vec3& x) const { return (x - point).dot(normal); }
};

/// The six inward-facing walls of the box [lo, hi]: order x-, x+, y-, y+, z-, z+.
inline PlaneWall box_face(const Vec3& lo, const Vec3& hi, int face, double mu)
{
  PlaneWall w;
  const int axis = face / 2;
  const bool upper = (face % 2) == 1;
  w.point = upper ? hi : lo;
  w.normal = Vec3::Zero();
  w.normal[axis] = upper ? -1.0 : 1.0;
  w.mu = mu;
  return w;
}

}  // namespace geocomp::dem
