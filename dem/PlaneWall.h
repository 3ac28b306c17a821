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
//
// Bounded walls (S4's split shear box): a wall may be a rectangle centred at `point`,
// half-sizes `half_u` along the in-plane unit `axis` and `half_v` along
// $b = n \times axis$. Contact is with the closest point of the rectangle (a thin,
// one-sided plate): with $d = x - p$, $h = d\cdot n$, $s = d\cdot a$, $t = d\cdot b$,
// if $|s| \le h_u$ and $|t| \le h_v$ the sphere meets the face (normal n, gap h, exactly
// the unbounded law, a negative h included); otherwise, for $h > 0$ only, it meets an edge
// or corner: $r = h n + (s - \bar s) a + (t - \bar t) b$ with $\bar s, \bar t$ clamped to
// the rectangle, gap $|r|$, normal $r/|r|$; behind the plane and outside the rectangle there
// is no contact. The force is continuous across the rim of the face. Two plates sharing an
// edge both touch a sphere at that edge (the edge is counted twice). The default half-sizes
// are huge (kUnbounded), so every sphere projects inside and unbounded walls take the face
// branch: the same arithmetic as before. NeighbourSearch selects wall candidates by plane
// distance, a superset of the plate contacts (the plate gap is never below h), so it needs
// no change.
#pragma once

#include "dem/Types.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace geocomp::dem {

struct PlaneWall
{
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();   ///< unit, into the specimen
  Vec3 velocity = Vec3::Zero();  ///< translation velocity (set by the driver)
  double mu = 0.0;               ///< particle-wall friction coefficient mu_p
  static constexpr double kUnbounded = 1e300;
  Vec3 axis = Vec3::UnitX();     ///< in-plane unit axis of a rectangle (made orthogonal to normal by add_wall)
  double half_u = kUnbounded;    ///< [m] half-size along `axis`
  double half_v = kUnbounded;    ///< [m] half-size along normal x axis

  // Recorded by the engine after every step (read only for users).
  Vec3 force = Vec3::Zero();     ///< total force of the particles on the wall
  Vec3 torque = Vec3::Zero();    ///< torque of that force about `point`
  double work = 0.0;             ///< cumulative work done by the wall on the particles
  double stiffness = 0.0;        ///< sum of k_n over touching contacts (servo gain)
  std::size_t n_contacts = 0;    ///< touching particles

  /// Signed distance of a point from the plane (positive inside the specimen).
  double distance(const Vec3& x) const { return (x - point).dot(normal); }

  bool bounded() const { return half_u < kUnbounded || half_v < kUnbounded; }

  /// Gap between a sphere centre x and the plate, and the contact normal n (from the
  /// plate towards x); +infinity (no contact) behind the plane outside the rectangle.
  double gap(const Vec3& x, Vec3& n) const
  {
    const Vec3 d = x - point;
    const double h = d.dot(normal);
    n = normal;
    if (!bounded()) return h;  // the common case: no rectangle arithmetic in the step loop
    const Vec3 b = normal.cross(axis);
    const double s = d.dot(axis), t = d.dot(b);
    const double es = s - std::clamp(s, -half_u, half_u);
    const double et = t - std::clamp(t, -half_v, half_v);
    if (es == 0.0 && et == 0.0) return h;  // the face
    if (!(h > 0.0)) return std::numeric_limits<double>::infinity();
    const Vec3 r = h * normal + es * axis + et * b;  // to the closest rim point
    const double g = r.norm();
    n = r / g;
    return g;
  }
};

/// A rectangular wall: centre, inward normal, in-plane axis and half-sizes along axis
/// and normal x axis.
inline PlaneWall rectangle_wall(const Vec3& centre, const Vec3& normal, const Vec3& axis, double half_u,
                                double half_v, double mu)
{
  PlaneWall w;
  w.point = centre;
  w.normal = normal.normalized();
  w.axis = (axis - axis.dot(w.normal) * w.normal).normalized();
  w.half_u = half_u;
  w.half_v = half_v;
  w.mu = mu;
  return w;
}

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
