// @sect3{The ContactMemory struct: history of the optional contact parts}
//
// Why it exists: the tangential spring lives in every contact slot (PairSlot::shear),
// but rolling resistance and S3's bonds need more per-contact history: the rolling
// spring moment $M_r$, the cohesive bond's anchor spring (its normal origin
// $\delta_0$ and tangential part $e_t$) and the bond and adhesion states. Sphere-only
// laws need none of it, so this history is kept in a separate array parallel to the
// slots (ContactLists::pair_memory / wall_memory), allocated only when the law asks
// for it (`Law::has_memory`). A plain run therefore streams exactly the bytes it did
// before the parts existed.
//
// The memory is carried across neighbour rebuilds by the same stable key as the
// tangential history (NeighbourSearch), written in checkpoints (DemSystem state) and
// exported with ContactState. A broken cohesive bond must never form again (S3), so
// the keys of broken bonds are also kept in a sorted set that outlives the pair's
// stay in the neighbour list.
//
// A contact created by fragment replacement (S2, DemSystem::replace_spheres) starts with
// a placement overlap $\delta_p$: the overlap the fragments had when they were put inside
// their parent. The contact parts see $\delta - \delta_p$ instead of $\delta$, and
// $\delta_p$ falls at the constant rate $\dot\delta_p$ to zero (ContactLaw.h), so the
// overlap is released gradually instead of as one explosive repulsion.
#pragma once

#include "dem/Types.h"

#include <cstdint>

namespace geocomp::dem {

struct ContactMemory
{
  /// State bits.
  enum : std::uint32_t {
    bonded = 1u << 0,          ///< a cohesive bond holds the pair (S3 eq. (8))
    bond_broken = 1u << 1,     ///< the bond broke: never formed again
    adhesion_active = 1u << 2, ///< capillary adhesion acts (formed at contact, S3 eq. (7))
  };

  Vec3 rolling = Vec3::Zero(); ///< rolling spring moment M_r acting on j (i receives -M_r)
  Vec3 bond = Vec3::Zero();    ///< tangential part e_t of the bond spring (j's anchor relative to i's)
  double bond_origin = 0.0;    ///< overlap delta_0 when the bond formed
  std::uint32_t state = 0;
  double placement = 0.0;      ///< placement overlap delta_p still to release [m] (S2 fragments)
  double placement_rate = 0.0; ///< its release rate [m/s]

  bool has(std::uint32_t bit) const { return (state & bit) != 0; }
  /// True when anything must be carried over to the next neighbour list.
  bool active() const { return state != 0 || rolling.squaredNorm() != 0.0 || placement != 0.0; }
};

/// The memory as seen with the pair's roles as given: `keep` returns it unchanged, else
/// i and j swap and the vectors acting on j (rolling moment, bond anchor) change sign.
inline ContactMemory oriented(ContactMemory m, bool keep)
{
  if (!keep) {
    m.rolling = -m.rolling;
    m.bond = -m.bond;
  }
  return m;
}

/// Memory carried across a rebuild, keyed like HistoryEntry.
struct MemoryEntry
{
  std::uint64_t key = 0;
  ContactMemory memory;
  bool operator<(const MemoryEntry& o) const { return key < o.key; }
};

}  // namespace geocomp::dem
