// @sect3{The ContactLists struct: per-contact slots and the gather index}
//
// Why it exists: deterministic, thread-count independent force accumulation
// (DEM-NOTES section 5, option 1). Pass A loops over contact slots in parallel; each
// contact is computed once and writes only its own slot (overlap, tangential history) and
// its own entry of the loads beside the slots (force on j, lever term $n\times F_t$). A
// body's load is the sum of its incident slots in ascending slot order, starting from its
// weight: an order that depends only on the lists, never on the threads, so any thread
// count gives the same bits. Most bodies get that sum added up during pass A
// (LoadScatter.h); the bodies two workers share are gathered in pass B through the CSR
// index below.
//
// Torques from a slot: $T_k = -(R_k - \delta/2)\,(n\times F_t)$ for both bodies
// (DEM-NOTES section 1), which is why a load stores $n\times F_t$ and the slot $\delta$,
// not two torques. A slot whose bodies are apart holds zeros, and so does its load.
//
// Pairs are stored with i < j in storage (each particle's run of slots is its own, so the
// passes read i sequentially) and the slot vectors act on j; the history archive and
// every output (ContactRecord, ContactState) use id_i < id_j instead, flipping the
// vectors where the two orders differ. Wall slots are sorted
// by particle index, so each particle's wall contacts are one contiguous range.
//
// Laws with rolling or cohesion parts keep a ContactMemory per slot in `pair_memory` /
// `wall_memory` (same order as the slots); `with_memory` is false and both arrays are
// empty for the plain laws, so their slots are exactly what they were.
#pragma once

#include "dem/ContactMemory.h"
#include "dem/Types.h"

#include <cstddef>
#include <vector>

namespace geocomp::dem {

struct PairSlot
{
  Index i = 0, j = 0;        ///< storage indices, i < j
  double overlap = 0.0;      ///< delta at the last evaluation (0: apart)
  Vec3 shear = Vec3::Zero(); ///< tangential history (xi, or the Mindlin spring force)
};

struct WallSlot
{
  Index wall = 0, particle = 0;
  double overlap = 0.0;
  Vec3 shear = Vec3::Zero();
};

/// What a slot's contact exerts, kept beside the slots (`pair_loads`, `wall_loads`, same
/// order): the total force (on j, or on the particle for a wall slot) and the lever term
/// $n\times F_t$ of the torques.
struct SlotLoad
{
  Vec3 force = Vec3::Zero();
  Vec3 lever = Vec3::Zero();
};

/// History carried across a rebuild (and exported for checkpoints).
struct HistoryEntry
{
  std::uint64_t key = 0;
  double overlap = 0.0;
  Vec3 shear = Vec3::Zero();
  bool operator<(const HistoryEntry& o) const { return key < o.key; }
};

struct ContactLists
{
  std::vector<PairSlot> pairs;
  /// The pair slots' loads. Written for every slot only at the steps that record contact
  /// forces (DemSystem::set_contact_force_recording); at the other steps only for the
  /// slots of shared bodies (pass B1 gathers those) and, with zeros, for slots that come
  /// apart. The history (overlap, shear) alone stays in the slots, so the pass streams 40
  /// bytes a slot instead of 88.
  std::vector<SlotLoad> pair_loads;
  /// Incident slots of particle p: incident[incident_offset[p] .. incident_offset[p+1]),
  /// each entry (slot << 1) | role, role 1 when p is body j of the slot.
  std::vector<std::uint32_t> incident_offset, incident;
  std::vector<WallSlot> walls;
  /// The wall slots' loads, written at every step (the walls' records and pass B read them).
  std::vector<SlotLoad> wall_loads;
  /// Wall slots of particle p: walls[wall_offset[p] .. wall_offset[p+1]).
  std::vector<std::uint32_t> wall_offset;
  /// Per-slot memory of the optional contact parts (only when with_memory).
  bool with_memory = false;
  std::vector<ContactMemory> pair_memory, wall_memory;

  std::size_t memory_bytes() const
  {
    return pairs.capacity() * sizeof(PairSlot) + walls.capacity() * sizeof(WallSlot) +
           (pair_loads.capacity() + wall_loads.capacity()) * sizeof(SlotLoad) +
           (incident_offset.capacity() + incident.capacity() + wall_offset.capacity()) * sizeof(std::uint32_t) +
           (pair_memory.capacity() + wall_memory.capacity()) * sizeof(ContactMemory);
  }
};

}  // namespace geocomp::dem
