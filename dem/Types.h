// @sect3{Vocabulary of the DEM core}
//
// Why this file exists: every DEM header speaks of the same few things (a 3-vector, a
// quaternion, a stable particle id, a storage index, the canonical key of a contact),
// and they must mean the same thing everywhere. Conventions (DEM-NOTES section 0):
// SI units; contact scalars positive in compression (overlap delta > 0 when bodies
// interpenetrate, normal force F_n > 0 repulsive); a pair (i, j) is stored with
// id_i < id_j, its normal points from i to j, and every per-contact vector is the one
// acting on j. A wall is body i of its contacts.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>

namespace geocomp::dem {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

/// Stable particle id: survives reordering of the storage, neighbour rebuilds and
/// checkpoints. Ids of particles created later (clumps, breakage children) are new ids.
using ParticleId = std::uint32_t;
/// Position of a particle in the current storage order (changes on spatial sorting).
using Index = std::uint32_t;

/// `body` value of a sphere that is its own rigid body. A clump gives all its member
/// spheres the clump's body index; contacts inside one body are never generated.
inline constexpr std::int32_t kOwnBody = -1;

/// Per-particle flag bits.
namespace flag {
/// Kinematic: the integrator does not change v and omega (inverse mass and inertia are
/// zero); the particle still moves with its prescribed velocity.
inline constexpr std::uint32_t fixed = 1u << 0;
/// Member sphere of a clump (ClumpSet.h): moved rigidly with its clump, not integrated
/// on its own; its `body` is the clump index.
inline constexpr std::uint32_t member = 1u << 1;
}  // namespace flag

/// Canonical history key of a particle pair: (id_lo << 32) | id_hi (DEM-NOTES section 5).
inline std::uint64_t pair_key(ParticleId a, ParticleId b)
{
  const ParticleId lo = a < b ? a : b;
  const ParticleId hi = a < b ? b : a;
  return (std::uint64_t(lo) << 32) | std::uint64_t(hi);
}

/// History key of a particle-wall contact: (wall << 32) | particle id. Kept in a
/// separate key space from pair keys (wall and pair histories live in separate lists).
inline std::uint64_t wall_key(std::uint32_t wall, ParticleId p)
{
  return (std::uint64_t(wall) << 32) | std::uint64_t(p);
}

}  // namespace geocomp::dem
