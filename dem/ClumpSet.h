// @sect3{The ClumpSet class: rigid clusters of spheres (S3, S4)}
//
// Why it exists: S3's clusters and S4's clumps are rigid bodies made of overlapping
// spheres. Contacts stay sphere contacts (the member spheres are ordinary entries of the
// ParticleStore, marked with the clump's `body` index so that the neighbour search never
// pairs two members of one clump), but the motion is that of one rigid body:
// translation of the centre of mass $x_G$ with the clump mass $M$, rotation with the
// principal inertias $I_1, I_2, I_3$ from voxel integration (ClumpMassProperties.h),
// orientation quaternion $q$ (body to world) and the body angular momentum
// $L_b = I\omega_b$ (RigidRotation.h). Per step (velocity Verlet, DEM-NOTES section 4):
//  1. half kick: $v_G \mathrel{+}= \tfrac{\Delta t}{2}F/M$, $L_b \mathrel{+}= \tfrac{\Delta t}{2}R(q)^T T$;
//  2. drift: $x_G \mathrel{+}= \Delta t\,v_G$, torque-free rotation of $(q, L_b)$;
//     members placed rigidly: $x_k = x_G + R(q)s_k$, $\omega_k = \omega = R(q)I^{-1}L_b$,
//     $v_k = v_G + \omega\times(x_k - x_G)$, so the contact-point velocity
//     $v_k + \omega\times(x_c - x_k) = v_G + \omega\times(x_c - x_G)$ is the rigid one;
//  3. forces on members; loads $F = \sum_k (F_k - m_k g) + Mg$,
//     $T = \sum_k (x_k - x_G)\times F_k + T_k$ (DEM-NOTES section 4);
//  4. half kick again, and member velocities from the clump.
// Members carry $1/M$ as inverse mass (so $m^*$ of a contact is the clumps' effective
// mass) and zero inverse inertia. The arrays are public, like ParticleStore's.
#pragma once

#include "dem/ClumpMassProperties.h"
#include "dem/Types.h"

#include <vector>

namespace geocomp::dem {

class ClumpSet
{
public:
  std::size_t size() const { return x.size(); }
  bool empty() const { return x.empty(); }

  /// Appends a clump with the given mass properties (per unit density, members' frame),
  /// density and member ids (in the order of `members`); returns its index.
  std::size_t add(const ClumpMassProperties& props, double density, const std::vector<ClumpMember>& members,
                  const std::vector<ParticleId>& ids);

  /// World angular velocity omega = R(q) I^-1 L_b.
  Vec3 angular_velocity(std::size_t c) const;
  /// Sets the world angular velocity (L_b = I R(q)^T omega).
  void set_angular_velocity(std::size_t c, const Vec3& omega);
  /// World angular momentum about the centre of mass, R(q) L_b.
  Vec3 angular_momentum(std::size_t c) const { return q[c] * L_body[c]; }
  /// Kinetic energy 1/2 M v^2 + 1/2 L_b . I^-1 L_b.
  double kinetic_energy(std::size_t c) const;

  /// Half kick of clump c with loads F, T (world frame).
  void kick(std::size_t c, double half_dt, const Vec3& f, const Vec3& t);
  /// Drift of clump c: translation and torque-free rotation.
  void drift(std::size_t c, double dt);

  // Rigid-body state.
  std::vector<Vec3> x, v, L_body, force, torque;
  std::vector<Quat> q;
  std::vector<double> mass, inv_mass;
  std::vector<Vec3> inertia, inv_inertia;  ///< principal moments I_1..3 and inverses
  // Members: ids member_id[member_offset[c] .. member_offset[c+1]) at body-frame offsets.
  std::vector<std::uint32_t> member_offset{0};
  std::vector<ParticleId> member_id;
  std::vector<Vec3> member_body;

  std::size_t memory_bytes() const;
};

}  // namespace geocomp::dem
