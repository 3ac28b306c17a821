// @sect3{The ParticleIndex class: stable particle ids over a reordered store}
//
// Why it exists: the store (ParticleStore.h) is reordered by cell at neighbour-list
// builds (spatial sorting) and compacted when a broken sphere leaves it, but drivers,
// contact histories and checkpoints name particles by id. This map keeps
// $\mathrm{id} \mapsto k$ (storage index), with kNoIndex for the ids of removed spheres;
// ids are handed out in order and never reused, so `size()` is one past the largest id.
// Adding and removing spheres go through here, so that the store and the map change
// together: the invariant is store.id[index[id]] == id for every live id.
#pragma once

#include "dem/ParticleStore.h"

#include <cstddef>
#include <vector>

namespace geocomp::dem {

class ParticleIndex
{
public:
  /// One past the largest id handed out (ids of removed particles included).
  std::size_t size() const { return index_.size(); }
  /// False for an id whose sphere was removed.
  bool alive(ParticleId id) const { return id < index_.size() && index_[id] != kNoIndex; }
  Index operator[](ParticleId id) const { return index_[id]; }
  /// With range check (std::out_of_range).
  Index at(ParticleId id) const { return index_.at(id); }
  void reserve(std::size_t n) { index_.reserve(n); }

  /// Appends a sphere to the store under the next id; returns the id.
  ParticleId add_sphere(ParticleStore& store, const Vec3& x, double radius, double mass)
  {
    const ParticleId id = ParticleId(index_.size());
    index_.push_back(store.add_sphere(id, x, radius, mass));
    return id;
  }
  /// Removes particle `id` from the store (the last particle moves into its slot).
  void remove(ParticleStore& store, ParticleId id)
  {
    const Index k = index_[id];
    store.remove(k);
    index_[id] = kNoIndex;
    if (k < store.size()) index_[store.id[k]] = k;
  }
  /// The map after the store was reordered (ParticleStore::permute).
  void refresh(const ParticleStore& store)
  {
    for (Index k = 0; k < store.size(); ++k) index_[store.id[k]] = k;
  }

  /// The map itself (checkpoints).
  const std::vector<Index>& map() const { return index_; }
  std::vector<Index>& map() { return index_; }
  std::size_t memory_bytes() const { return index_.capacity() * sizeof(Index); }

private:
  std::vector<Index> index_;  // id -> storage index (kNoIndex: removed)
};

}  // namespace geocomp::dem
