// @sect3{Vocabulary of the DEM core}
//
// Why this file exists: every DEM header speaks of the same few things (a 3-vector, a
// quaternion, a stable particle id, a storage index, the canonical key of a contact),
// and they must mean the same thing everywhere. Conventions (DEM-NOTES section 0):
// SI units; contact scalars positive in compression (overlap delta > 0 when bodies
// interpenetrate, normal force F_n > 0 repulsive); a pair (i, j) is reported and
// archived with id_i < id_j (in the neighbour lists: i earlier in storage), its normal
// points from i to j, and every per-contact vector is the one acting on j. A wall is
// body i of its contacts.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>

namespace geocomp::dem {

using Vec3 = Eigen::Vector3d;

/// Per-contact kernels of the step loop: inlined into the loop so the compiler can
/// overlap the long division/square-root chains of consecutive contacts (measured: GCC
/// otherwise keeps them as calls and the loop runs one contact at a time).
/// The same for the per-particle lambdas of DemSystem's block sweeps (a lambda's call
/// operator; measured: GCC kept it as a call per particle, its vectors spilled to the stack).
#if defined(__GNUC__)
#define GEOCOMP_CONTACT_KERNEL inline __attribute__((always_inline))
#define GEOCOMP_SWEEP_BODY __attribute__((always_inline))
#else
#define GEOCOMP_CONTACT_KERNEL inline
#define GEOCOMP_SWEEP_BODY
#endif
using Quat = Eigen::Quaterniond;

/// Stable particle id: survives reordering of the storage, neighbour rebuilds and
/// checkpoints. Ids of particles created later (clumps, breakage children) are new ids.
using ParticleId = std::uint32_t;
/// Position of a particle in the current storage order (changes on spatial sorting).
using Index = std::uint32_t;

/// `index_of` value of an id whose particle was removed (a broken sphere, S2): the id is
/// never reused, so histories and outputs keyed by ids stay unambiguous.
inline constexpr Index kNoIndex = 0xffffffffu;

/// `body` value of a sphere that is its own rigid body. A clump gives all its member
/// spheres the clump's body index; contacts inside one body are never generated.
/// Values <= kFirstSiblingGroup tag the overlapping children of one broken sphere
/// (DemSystem::replace_spheres): they do not touch each other until they have separated,
/// but each moves on its own (no rigid coupling).
inline constexpr std::int32_t kOwnBody = -1;
inline constexpr std::int32_t kFirstSiblingGroup = -2;

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
