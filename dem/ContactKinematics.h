// @sect3{The ContactKinematics struct}
//
// Why it exists: a contact law needs a dozen numbers about the two bodies (normal,
// overlap, relative velocity at the contact point, effective mass and radius, the time
// step, the friction coefficient). Bundling them keeps the law's signature short and,
// more importantly, makes particle-particle and particle-wall contacts go through the
// *same* law code: only the two builders below differ (DEM-NOTES section 1).
//
// Sphere-sphere (i, j), with $d = x_j - x_i$, $r = |d|$:
// $$ n = d/r,\quad \delta = R_i + R_j - r,\quad \tilde R_k = R_k - \delta/2,$$
// $$ v_{rel} = (v_j - v_i) - (\tilde R_i\omega_i + \tilde R_j\omega_j)\times n,
//    \quad v_n = v_{rel}\cdot n \ (\dot\delta = -v_n),\quad v_t = v_{rel} - v_n n.$$
// Sphere-plane (the wall is body i, infinite radius and mass, normal $n_w$ into the
// specimen, velocity $V_w$, no spin), $h = (x - p_w)\cdot n_w$:
// $$ \delta = R - h,\quad n = n_w,\quad v_{rel} = (v - V_w) - \tilde R\,\omega\times n_w.$$
// Effective values: $1/m^* = 1/m_i + 1/m_j$, $1/R^* = 1/R_i + 1/R_j$; for a wall
// $m^* = m$, $R^* = R$ (the limits of the pair formulas).
//
// `spin` is the mean spin of the two bodies about n, used to turn the tangential spring
// with the pair about the normal (DEM-NOTES section 2, Yade's spin term). `w_rel`
// ($\omega_j - \omega_i$) is filled only for laws with a rolling part, and `bonding` tells a
// cohesion part whether bonds may form at this contact (the engine sets it false for
// walls unless asked otherwise).
#pragma once

#include "dem/Types.h"

namespace geocomp::dem {

struct ContactKinematics
{
  Vec3 normal;             ///< unit normal, from body i to body j
  Vec3 v_t;                ///< tangential relative velocity of j w.r.t. i at the contact point
  double v_n = 0.0;        ///< normal relative velocity, v_rel . n (negative when approaching)
  double overlap = 0.0;    ///< delta > 0
  double overlap_old = 0.0;///< delta at the previous evaluation (0 for a new contact)
  double m_eff = 0.0;      ///< m*
  double r_eff = 0.0;      ///< R*
  double spin = 0.0;       ///< (omega_i + omega_j) . n / 2
  double dt = 0.0;         ///< increment for the history (0: evaluate without advancing)
  double mu = 0.0;         ///< Coulomb friction coefficient of this pair of surfaces
  Vec3 w_rel;              ///< omega_j - omega_i (rolling parts only; not set otherwise)
  bool bonding = true;     ///< cohesion parts: bonds and adhesion may form here
};

/// Fills the geometric part of `k` for spheres i and j in contact (r = |d| > 0 given).
/// Returns the lever arms (R_i - delta/2, R_j - delta/2) through `lever_i`, `lever_j`.
GEOCOMP_CONTACT_KERNEL void sphere_sphere_kinematics(ContactKinematics& k, const Vec3& d, double r,
                                     double Ri, double Rj, const Vec3& vi, const Vec3& vj,
                                     const Vec3& wi, const Vec3& wj, double inv_mi, double inv_mj)
{
  // m* and R* from the bodies alone (not through r), so that every pair of the same two
  // kinds of sphere gets the same bits: laws whose constants depend on (m*, R*) (S0's k_n)
  // can then reuse them from one contact to the next (PairBatchKernel.cpp).
  const double inv_m = inv_mi + inv_mj, r_sum = Ri + Rj;
  const double w = 1.0 / (inv_m * r_sum);
  const Vec3 n = d * (1.0 / r);
  const double delta = r_sum - r;
  const double li = Ri - 0.5 * delta, lj = Rj - 0.5 * delta;
  const Vec3 v_rel = (vj - vi) - (li * wi + lj * wj).cross(n);
  k.normal = n;
  k.overlap = delta;
  k.v_n = v_rel.dot(n);
  k.v_t = v_rel - k.v_n * n;
  k.m_eff = w * r_sum;
  k.r_eff = Ri * Rj * inv_m * w;
  k.spin = 0.5 * (wi + wj).dot(n);
}

/// Fills the geometric part of `k` for a sphere (body j) touching a plane wall (body i)
/// at signed distance h = (x - p_w) . n_w from the plane.
GEOCOMP_CONTACT_KERNEL void sphere_wall_kinematics(ContactKinematics& k, const Vec3& n_w, double h, double R,
                                   const Vec3& v, const Vec3& w, const Vec3& v_wall, double inv_m)
{
  const double delta = R - h;
  const double l = R - 0.5 * delta;
  const Vec3 v_rel = (v - v_wall) - l * w.cross(n_w);
  k.normal = n_w;
  k.overlap = delta;
  k.v_n = v_rel.dot(n_w);
  k.v_t = v_rel - k.v_n * n_w;
  k.m_eff = 1.0 / inv_m;
  k.r_eff = R;
  k.spin = 0.5 * w.dot(n_w);
}

}  // namespace geocomp::dem
