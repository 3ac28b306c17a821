// @sect3{Free rotation of a rigid body: Euler's equations in the body frame, split}
//
// Why it exists: a clump is not a sphere; its angular velocity changes without any
// torque when its inertia is not isotropic. In the principal body frame, Euler's
// equations (S4 eqs. (9)-(11)) read
// $$ I_1\dot\omega_1 = \tau_1 + (I_2 - I_3)\,\omega_2\omega_3 \quad\text{(and cyclic)}, $$
// and the orientation quaternion (body to world) follows
// $\dot q = \tfrac12\, q\otimes(0, \omega_b)$ (S4 eq. (14)). With the torque applied as
// half kicks of the body angular momentum $L_b = I\omega_b$ (velocity Verlet), the
// torque-free part remains. We integrate it by splitting the kinetic energy
// $T = \sum_k L_k^2/(2I_k)$ into its three terms (Dullweber, Leimkuhler & McLachlan 1997,
// J. Chem. Phys. 107:5840): the flow of one term alone is an exact rotation about
// body axis k by $\theta_k = \Delta t\,L_k/I_k$ -- the body turns,
// $q \leftarrow q\otimes(\cos\tfrac{\theta}{2}, \sin\tfrac{\theta}{2}e_k)$ (S4 eq. (14) for a constant
// $\omega_b = \omega_k e_k$), and $L_b$ turns the other way so that $L_w = R(q)L_b$ stays fixed
// (Euler's equations for that term). The symmetric sequence
// $1(\Delta t/2)\,2(\Delta t/2)\,3(\Delta t)\,2(\Delta t/2)\,1(\Delta t/2)$ is second order, time
// reversible and symplectic: $L_w$ and $|L_b|$ are conserved to round-off and the kinetic
// energy error stays bounded, $O(\Delta t^2)$. Each sub-rotation keeps $|q| = 1$ exactly.
#pragma once

#include "dem/Types.h"

#include <cmath>

namespace geocomp::dem {

/// Exact flow of T_k = L_k^2 / (2 I_k) for time h: rotates the body about its axis k.
inline void rotate_about_body_axis(Quat& q, Vec3& L_b, int k, double inv_Ik, double h)
{
  const double theta = h * L_b[k] * inv_Ik;
  const double c = std::cos(theta), s = std::sin(theta);
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  // L_b(new) = R_k(theta)^T L_b: the body turns by +theta, so its coordinates of the
  // fixed world vector turn by -theta.
  const double la = L_b[a], lb = L_b[b];
  L_b[a] = c * la + s * lb;
  L_b[b] = -s * la + c * lb;
  Vec3 axis = Vec3::Zero();
  axis[k] = std::sin(0.5 * theta);
  q = q * Quat(std::cos(0.5 * theta), axis.x(), axis.y(), axis.z());  // S4 eq. (14), omega_b along e_k
}

/// One torque-free step of length dt (symmetric splitting, second order).
inline void free_rotation_step(Quat& q, Vec3& L_b, const Vec3& inv_I, double dt)
{
  rotate_about_body_axis(q, L_b, 0, inv_I[0], 0.5 * dt);
  rotate_about_body_axis(q, L_b, 1, inv_I[1], 0.5 * dt);
  rotate_about_body_axis(q, L_b, 2, inv_I[2], dt);
  rotate_about_body_axis(q, L_b, 1, inv_I[1], 0.5 * dt);
  rotate_about_body_axis(q, L_b, 0, inv_I[0], 0.5 * dt);
}

}  // namespace geocomp::dem
