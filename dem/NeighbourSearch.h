// @sect3{The NeighbourSearch class: Verlet lists on cells, with history carried over}
//
// Why it exists: contacts are evaluated from a list of candidate pairs (and
// particle-wall candidates) that is rebuilt only when something may have come into
// range (DEM-NOTES section 5):
//  - a pair is listed if $|x_i - x_j| < R_i + R_j + s$, a wall candidate if $h < R + s$;
//  - the lists stay valid while every particle moved less than s/2 since the build
//    and, for walls, particle plus wall displacement stays below s.
// A rebuild (1) keeps the histories: while the particles are the ones of the last build
// in the same storage, the last build's slots are kept aside as they are; otherwise
// (checkpoint imports, particles added or removed) they are archived keyed by stable ids;
// (2) optionally reorders the particle storage into cell order (spatial sorting:
// neighbours become neighbours in memory), (3) builds the new lists, (4) carries each
// history over, from the kept slot of the same two particles (a scan of the few slots of
// one of them) or from the archive by its key: both give the same bits, and (5) builds
// the gather index. Every stage runs in parallel over particles or slots except a few
// prefix sums; everything is deterministic and independent of the thread count. Pairs inside one rigid body and
// pairs of two kinematic particles are never listed.
//
// Laws with memory (rolling, bonds: ContactMemory.h) have their per-slot memory carried
// the same way. Their interactions may outlive the overlap up to a gap `reach`, so the
// list range becomes $R_i + R_j + reach + s$. The keys of broken bonds are kept for good
// (a broken bond never forms again, S3), even after the pair has left the lists.
#pragma once

#include "dem/CellGrid.h"
#include "dem/ContactLists.h"
#include "dem/ContactMemory.h"
#include "dem/ParticleStore.h"
#include "dem/PlaneWall.h"
#include "dem/StepProfile.h"

#include <cstdlib>
#include <iosfwd>
#include <memory>
#include <vector>

namespace geocomp::dem {

class NeighbourSearch
{
public:
  void set_skin(double s);
  double skin() const { return skin_; }
  void set_spatial_sorting(bool on) { sort_ = on; }
  /// Largest gap at which a listed contact can still carry force (0 for the plain laws).
  void set_reach(double r);
  double reach() const { return reach_; }

  /// True when the lists may miss a contact, given the largest squared particle
  /// displacement since the build.
  bool needs_rebuild(double max_displacement2, const std::vector<PlaneWall>& walls) const;

  /// Positions at the last build (the displacement criterion's reference).
  const std::vector<Vec3>& reference_positions() const { return x_ref_; }

  /// Rebuilds `lists` for the current positions, possibly permuting `store`.
  /// Returns true if the storage order changed.
  bool rebuild(ParticleStore& store, const std::vector<PlaneWall>& walls, ContactLists& lists, int threads);

  /// Replaces the histories to be carried by the next rebuild (checkpoint import).
  void import_histories(std::vector<HistoryEntry> pairs, std::vector<HistoryEntry> walls);
  /// The same for the contact memory of laws with rolling or cohesion parts.
  void import_memory(std::vector<MemoryEntry> pairs, std::vector<MemoryEntry> walls);
  /// Keys of broken pair bonds, sorted (they stay broken for the rest of the run).
  const std::vector<std::uint64_t>& broken_bonds() const { return broken_pairs_; }

  std::size_t n_builds() const { return n_builds_; }
  /// Times the rebuild's parts into `p` (StepProfile::build_seconds; nullptr: off).
  void set_profile(StepProfile* p) { profile_ = p; }
  std::size_t memory_bytes() const;
  /// Checkpoint state: skin, flags, build references and carried histories (the cell
  /// grid is rebuilt at every build and is not part of it).
  void write_state(std::ostream& out) const;
  void read_state(std::istream& in);

private:
  /// The last build's slots and their indexes, kept aside while the new lists are built.
  struct Previous
  {
    struct Free
    {
      void operator()(PairSlot* p) const { std::free(p); }
    };
    std::unique_ptr<PairSlot[], Free> pairs;
    std::size_t capacity = 0;  ///< slots `pairs` holds room for
    std::vector<std::uint32_t> run_start;
    std::vector<WallSlot> walls;
    std::vector<std::uint32_t> wall_offset;
    // Scratch of a build: a copied search (a saved DemSystem) starts with none.
    Previous() = default;
    Previous(const Previous&) {}
    Previous& operator=(const Previous&)
    {
      pairs.reset();
      capacity = 0;
      run_start.clear();
      walls.clear();
      wall_offset.clear();
      return *this;
    }
    Previous(Previous&&) = default;
    Previous& operator=(Previous&&) = default;
  };
  /// True when `lists` are this object's last build for the same particles in the same
  /// storage (then the histories are carried from them directly).
  bool same_particles(const ParticleStore& store, const ContactLists& lists, int threads) const;
  /// The last build's slots, kept in previous_ (its buffers reused from build to build: no
  /// allocation once they have grown to the specimen's size).
  const Previous* keep_previous(ContactLists& lists, int threads);
  /// The storage index at the last build of the particle now at k.
  Index old_index(Index k) const { return permuted_ ? old_of_[k] : k; }
  /// The overlap and spring of slot s (its i and j set) from the kept slots, or from the
  /// archive when `prev` is null.
  void carry_pair(PairSlot& s, const Previous* prev, const std::vector<ParticleId>& id) const;
  void carry_wall(WallSlot& s, const Previous* prev, const std::vector<ParticleId>& id) const;
  void build_pairs(const ParticleStore& store, ContactLists& lists, const Previous* prev, int threads);
  void build_incident(ContactLists& lists, int threads);
  void build_walls(const ParticleStore& store, const std::vector<PlaneWall>& walls, ContactLists& lists,
                   const Previous* prev, int threads);
  void archive(const ParticleStore& store, const ContactLists& lists);
  void archive_memory(const ParticleStore& store, const ContactLists& lists);
  /// Indexes the sorted pair archive by the lower id of its keys (pair_archive_start_).
  void index_pair_archive();
  /// The archived history of a particle pair, or null: a scan of the few entries that
  /// share the pair's lower id, in place of a binary search of the whole archive (whose
  /// probes miss the cache on large specimens).
  const HistoryEntry* find_pair_history(std::uint64_t key) const;

  double skin_ = 0.0;
  bool sort_ = true;
  bool imported_ = false;
  std::size_t n_builds_ = 0;
  CellGrid grid_;
  std::vector<Vec3> x_ref_;
  std::vector<Vec3> wall_ref_;
  std::vector<std::uint32_t> count_;      // scratch of the gather index
  std::vector<std::uint32_t> run_start_;  // particle a's pair slots: [run_start_[a], run_start_[a + 1])
  Previous previous_;                     // the last build's slots while a build carries them
  std::vector<ParticleId> built_ids_;     // the ids in storage order at the last build
  std::vector<Index> old_of_;             // this build's sort: new index k was old_of_[k]
  bool permuted_ = false;                 // this build sorted the storage
  bool carry_ready_ = false;              // the last lists were built here (not read or imported)
  StepProfile* profile_ = nullptr;
  std::vector<HistoryEntry> pair_archive_, wall_archive_;
  /// Entries of lower id k: pair_archive_[start[k] .. start[k+1]) (k beyond: none).
  std::vector<std::uint32_t> pair_archive_start_;
  double reach_ = 0.0;
  bool memory_imported_ = false;
  std::vector<MemoryEntry> pair_memory_archive_, wall_memory_archive_;
  std::vector<std::uint64_t> broken_pairs_, broken_walls_;
};

}  // namespace geocomp::dem
