// @sect3{The ParticleStore class}
//
// Why it exists: the hot loops (contact forces, gather, integration) stream over one
// attribute of many particles at a time, so the particles are stored as a structure of
// arrays: one contiguous array per attribute. The arrays are public members on
// purpose, like a LAMMPS atom vector; the invariants are that all arrays have the same
// length and that `inv_mass`/`inv_inertia` agree with `mass`/`radius` unless the
// particle is kinematic (flag::fixed, inverse values zero) or a clump member
// (flag::member: inverse mass of the whole clump, zero inverse inertia; ClumpSet.h).
//
// Spheres: inertia $I = \tfrac25 m R^2$. The orientation quaternion is integrated from
// $\omega$ (world frame) by the integrator, $q \leftarrow \exp(\Delta t\,\omega/2)\otimes q$.
//
// Seams (honoured by the core):
//  - `body`: index of the rigid body (clump) a sphere belongs to (kOwnBody for a free
//    sphere). The neighbour search never pairs two spheres of the same body.
//  - `id`: stable ids, so a broken sphere can be replaced by children with new ids
//    while the contact histories of the others stay keyed correctly.
//  - `permute()`: the storage order is not an identity; only ids are.
#pragma once

#include "dem/Types.h"

#include <cstddef>
#include <vector>

namespace geocomp::dem {

class ParticleStore
{
public:
  /// Appends a sphere of the given radius and mass; returns its storage index.
  Index add_sphere(ParticleId id, const Vec3& x, double radius, double mass);

  std::size_t size() const { return x.size(); }
  void reserve(std::size_t n);

  /// Makes particle k kinematic (fixed == true: infinite mass and inertia) or dynamic.
  void set_fixed(Index k, bool fixed);
  bool is_fixed(Index k) const { return (flags[k] & flag::fixed) != 0; }

  /// Removes storage index k: the last particle moves into slot k (the caller updates
  /// its id-to-index map).
  void remove(Index k);

  /// Reorders all arrays so that new[k] = old[order[k]]: each array gathered into one
  /// scratch buffer and copied back, both in parallel over `threads` (the scratch, the
  /// largest element times the count, lives for the call only).
  void permute(const std::vector<Index>& order, int threads = 1);

  /// Bytes held by the arrays (capacity, not size).
  std::size_t memory_bytes() const;

  // Kinematics and loads (world frame).
  std::vector<Vec3> x, v, omega, force, torque;
  std::vector<Quat> orientation;
  // Constant properties.
  std::vector<double> radius, mass, inv_mass, inv_inertia;
  // Identity and topology.
  std::vector<ParticleId> id;
  std::vector<std::int32_t> body;
  std::vector<std::uint32_t> flags;
};

}  // namespace geocomp::dem
