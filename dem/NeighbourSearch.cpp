#include "dem/NeighbourSearch.h"

#include "common/BinaryState.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <new>
#include <string>
#include <stdexcept>

namespace geocomp::dem {

namespace {
const HistoryEntry* find_history(const std::vector<HistoryEntry>& archive, std::uint64_t key)
{
  auto it = std::lower_bound(archive.begin(), archive.end(), key,
                             [](const HistoryEntry& e, std::uint64_t k) { return e.key < k; });
  return (it != archive.end() && it->key == key) ? &*it : nullptr;
}

/// Memory of `key`: the archived one, or a broken bond's mark, or empty.
ContactMemory find_memory(const std::vector<MemoryEntry>& archive, const std::vector<std::uint64_t>& broken,
                          std::uint64_t key)
{
  auto it = std::lower_bound(archive.begin(), archive.end(), key,
                             [](const MemoryEntry& e, std::uint64_t k) { return e.key < k; });
  if (it != archive.end() && it->key == key) return it->memory;
  ContactMemory m;
  if (std::binary_search(broken.begin(), broken.end(), key)) m.state = ContactMemory::bond_broken;
  return m;
}

/// Adds the keys of broken bonds among `entries` to the sorted set `broken`.
void merge_broken(std::vector<std::uint64_t>& broken, const std::vector<MemoryEntry>& entries)
{
  std::vector<std::uint64_t> add;
  for (const MemoryEntry& e : entries)
    if (e.memory.has(ContactMemory::bond_broken)) add.push_back(e.key);
  if (add.empty()) return;
  std::vector<std::uint64_t> merged;
  merged.reserve(broken.size() + add.size());
  std::set_union(broken.begin(), broken.end(), add.begin(), add.end(), std::back_inserter(merged));
  broken.swap(merged);
}

template <class T>
void release(std::vector<T>& v)
{
  std::vector<T>().swap(v);
}
}  // namespace

void NeighbourSearch::set_reach(double r)
{
  if (!(r >= 0.0)) throw std::invalid_argument("NeighbourSearch: reach must be >= 0");
  reach_ = r;
}

void NeighbourSearch::import_memory(std::vector<MemoryEntry> pairs, std::vector<MemoryEntry> walls)
{
  pair_memory_archive_ = std::move(pairs);
  wall_memory_archive_ = std::move(walls);
  std::sort(pair_memory_archive_.begin(), pair_memory_archive_.end());
  std::sort(wall_memory_archive_.begin(), wall_memory_archive_.end());
  merge_broken(broken_pairs_, pair_memory_archive_);
  merge_broken(broken_walls_, wall_memory_archive_);
  memory_imported_ = true;
}

void NeighbourSearch::archive_memory(const ParticleStore& store, const ContactLists& lists)
{
  pair_memory_archive_.clear();
  wall_memory_archive_.clear();
  if (!lists.with_memory) return;
  for (std::size_t c = 0; c < lists.pair_memory.size(); ++c)
    if (lists.pair_memory[c].active()) {
      const PairSlot& s = lists.pairs[c];
      pair_memory_archive_.push_back(
        {pair_key(store.id[s.i], store.id[s.j]), oriented(lists.pair_memory[c], store.id[s.i] < store.id[s.j])});
    }
  for (std::size_t c = 0; c < lists.wall_memory.size(); ++c)
    if (lists.wall_memory[c].active())
      wall_memory_archive_.push_back(
        {wall_key(lists.walls[c].wall, store.id[lists.walls[c].particle]), lists.wall_memory[c]});
  std::sort(pair_memory_archive_.begin(), pair_memory_archive_.end());
  std::sort(wall_memory_archive_.begin(), wall_memory_archive_.end());
  merge_broken(broken_pairs_, pair_memory_archive_);
  merge_broken(broken_walls_, wall_memory_archive_);
}

void NeighbourSearch::set_skin(double s)
{
  if (!(s > 0.0)) throw std::invalid_argument("NeighbourSearch: skin must be positive");
  skin_ = s;
}

bool NeighbourSearch::needs_rebuild(double max_displacement2, const std::vector<PlaneWall>& walls) const
{
  if (wall_ref_.size() != walls.size()) return true;
  const double dp = std::sqrt(max_displacement2);
  if (2.0 * dp > skin_) return true;
  double dw = 0.0;
  for (std::size_t w = 0; w < walls.size(); ++w)
    dw = std::max(dw, std::abs((walls[w].point - wall_ref_[w]).dot(walls[w].normal)));
  return dp + dw > skin_;
}

void NeighbourSearch::import_histories(std::vector<HistoryEntry> pairs, std::vector<HistoryEntry> walls)
{
  pair_archive_ = std::move(pairs);
  wall_archive_ = std::move(walls);
  std::sort(pair_archive_.begin(), pair_archive_.end());
  std::sort(wall_archive_.begin(), wall_archive_.end());
  imported_ = true;
}

void NeighbourSearch::archive(const ParticleStore& store, const ContactLists& lists)
{
  std::size_t active = 0;
  for (const PairSlot& s : lists.pairs) active += (s.overlap > 0.0 || s.shear.squaredNorm() > 0.0) ? 1 : 0;
  pair_archive_.clear();
  if (pair_archive_.capacity() < active) pair_archive_.reserve(active + active / 16);
  for (const PairSlot& s : lists.pairs)  // archived as acting on the higher id (see rebuild)
    if (s.overlap > 0.0 || s.shear.squaredNorm() > 0.0)
      pair_archive_.push_back({pair_key(store.id[s.i], store.id[s.j]), s.overlap,
                               store.id[s.i] < store.id[s.j] ? s.shear : Vec3(-s.shear)});
  std::sort(pair_archive_.begin(), pair_archive_.end());
  wall_archive_.clear();
  for (const WallSlot& s : lists.walls)
    if (s.overlap > 0.0 || s.shear.squaredNorm() > 0.0)
      wall_archive_.push_back({wall_key(s.wall, store.id[s.particle]), s.overlap, s.shear});
  std::sort(wall_archive_.begin(), wall_archive_.end());
}

void NeighbourSearch::index_pair_archive()
{
  // The archive is sorted by key = (lo << 32) | hi: each lower id is one run.
  const std::size_t n_ids = pair_archive_.empty() ? 0 : std::size_t(pair_archive_.back().key >> 32) + 1;
  pair_archive_start_.assign(n_ids + 1, 0);
  for (const HistoryEntry& e : pair_archive_) ++pair_archive_start_[(e.key >> 32) + 1];
  for (std::size_t k = 0; k < n_ids; ++k) pair_archive_start_[k + 1] += pair_archive_start_[k];
}

const HistoryEntry* NeighbourSearch::find_pair_history(std::uint64_t key) const
{
  const std::size_t lo = std::size_t(key >> 32);
  if (lo + 1 >= pair_archive_start_.size()) return nullptr;
  for (std::uint32_t e = pair_archive_start_[lo]; e < pair_archive_start_[lo + 1]; ++e)
    if (pair_archive_[e].key == key) return &pair_archive_[e];
  return nullptr;
}

bool NeighbourSearch::same_particles(const ParticleStore& store, const ContactLists& lists, int threads) const
{
  const std::size_t n = store.size();
  if (!carry_ready_ || built_ids_.size() != n || run_start_.size() != n + 1 || run_start_[n] != lists.pairs.size() ||
      lists.wall_offset.size() != n + 1 || lists.wall_offset[n] != lists.walls.size())
    return false;
  bool same = true;
#pragma omp parallel for schedule(static) reduction(&& : same) num_threads(threads)
  for (std::int64_t p = 0; p < std::int64_t(n); ++p) same = same && store.id[p] == built_ids_[p];
  return same;
}

const NeighbourSearch::Previous* NeighbourSearch::keep_previous(ContactLists& lists, int threads)
{
  const std::size_t n_pairs = lists.pairs.size();
  if (n_pairs > previous_.capacity || !previous_.pairs) {
    // Grown by an eighth beyond the need, as the lists are: a specimen's rebuilds then reuse
    // it (a fresh block per rebuild is a fresh set of pages the kernel zeroes each time).
    const std::size_t capacity = std::max<std::size_t>(1, n_pairs + n_pairs / 8);
    previous_.pairs.reset(static_cast<PairSlot*>(std::malloc(capacity * sizeof(PairSlot))));
    previous_.capacity = previous_.pairs ? capacity : 0;
    if (!previous_.pairs) throw std::bad_alloc();
  }
  // Copied, not swapped: lists.pairs keeps its capacity (and its pages) for the new slots;
  // a new block's pages are first touched by the threads that copy into them.
  const PairSlot* const from = lists.pairs.data();
  PairSlot* const to = previous_.pairs.get();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < std::int64_t(n_pairs); ++k)  // into raw storage: bytes
    std::memcpy(static_cast<void*>(&to[k]), &from[k], sizeof(PairSlot));
  // Swapped: the build refills run_start_, lists.walls and lists.wall_offset in the buffers
  // the previous build's copies used (assign and resize keep their capacity).
  previous_.run_start.swap(run_start_);
  previous_.walls.swap(lists.walls);
  previous_.wall_offset.swap(lists.wall_offset);
  return &previous_;
}

void NeighbourSearch::carry_pair(PairSlot& s, const Previous* prev, const std::vector<ParticleId>& id) const
{
  const Index a = s.i, b = s.j;
  s.overlap = 0.0;
  s.shear.setZero();
  if (prev) {
    // The last build's slot of the same two particles, in the run of the one earlier in
    // the old storage; its spring acts on the later one there.
    const Index oa = old_index(a), ob = old_index(b);
    const Index lo = std::min(oa, ob), hi = std::max(oa, ob);
    for (std::uint32_t k = prev->run_start[lo]; k < prev->run_start[lo + 1]; ++k) {
      const PairSlot& o = prev->pairs[k];
      if (o.j != hi) continue;
      if (o.overlap > 0.0 || o.shear.squaredNorm() > 0.0) {  // the archive's rule: active slots only
        s.overlap = o.overlap;
        s.shear = oa == lo ? o.shear : Vec3(-o.shear);
      }
      return;
    }
    return;
  }
  // The archive holds the vectors acting on the higher id, flipped here when that is i
  // (IEEE negation is exact, so both ways give the same bits).
  const HistoryEntry* h = find_pair_history(pair_key(id[a], id[b]));
  if (!h) return;
  s.overlap = h->overlap;
  s.shear = id[a] < id[b] ? h->shear : Vec3(-h->shear);
}

void NeighbourSearch::carry_wall(WallSlot& s, const Previous* prev, const std::vector<ParticleId>& id) const
{
  s.overlap = 0.0;
  s.shear.setZero();
  if (prev) {
    const Index op = old_index(s.particle);
    for (std::uint32_t k = prev->wall_offset[op]; k < prev->wall_offset[op + 1]; ++k) {
      const WallSlot& o = prev->walls[k];
      if (o.wall != s.wall) continue;
      if (o.overlap > 0.0 || o.shear.squaredNorm() > 0.0) {
        s.overlap = o.overlap;
        s.shear = o.shear;
      }
      return;
    }
    return;
  }
  const HistoryEntry* h = find_history(wall_archive_, wall_key(s.wall, id[s.particle]));
  if (h) {
    s.overlap = h->overlap;
    s.shear = h->shear;
  }
}

bool NeighbourSearch::rebuild(ParticleStore& store, const std::vector<PlaneWall>& walls, ContactLists& lists,
                              int threads)
{
  if (!(skin_ > 0.0)) throw std::logic_error("NeighbourSearch: skin not set");
  // (1) Histories: straight from the last build's slots while the particles are the same
  // ones in the same storage (the usual case), else archived by stable key, before any
  // index changes (checkpoint imports, particles added or removed).
  PhaseClock clock(profile_ ? profile_->build_seconds.data() : nullptr);
  const bool direct = !imported_ && same_particles(store, lists, threads);
  if (!direct && !imported_) archive(store, lists);
  imported_ = false;
  if (!direct) index_pair_archive();
  if (!memory_imported_) archive_memory(store, lists);
  memory_imported_ = false;
  const Previous* const prev = direct ? keep_previous(lists, threads) : nullptr;
  clock.mark(StepProfile::keep);

  const std::size_t n = store.size();
  double r_max = 0.0;
  for (double r : store.radius) r_max = std::max(r_max, r);
  grid_.build(store.x, 2.0 * r_max + reach_ + skin_);
  clock.mark(StepProfile::grid);

  // (2) Spatial sorting.
  permuted_ = false;
  if (sort_ && n > 1) {
    const auto& order = grid_.sorted();
    bool identity = true;
#pragma omp parallel for schedule(static) reduction(&& : identity) num_threads(threads)
    for (std::int64_t k = 0; k < std::int64_t(n); ++k) identity = identity && order[k] == Index(k);
    if (!identity) {
      old_of_ = order;  // new index k was old order[k]
      store.permute(order, threads);
      grid_.adopt_sorted_order();
      permuted_ = true;
    }
  }

  clock.mark(StepProfile::sort);
  build_pairs(store, lists, prev, threads);  // (3), (4)
  clock.mark(StepProfile::pair_lists);
  build_incident(lists, threads);            // (5)
  clock.mark(StepProfile::gather_index);
  build_walls(store, walls, lists, prev, threads);
  clock.mark(StepProfile::wall_lists);

  x_ref_.resize(n);
  built_ids_.resize(n);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t p = 0; p < std::int64_t(n); ++p) {
    x_ref_[p] = store.x[p];
    built_ids_[p] = store.id[p];
    store.orientation[p].normalize();  // unit quaternions drift by round-off only
  }
  wall_ref_.resize(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) wall_ref_[w] = walls[w].point;
  // The archives served this build only (the next one archives the lists anew, or reads
  // the lists themselves): give their memory back, about 40 bytes per contact.
  release(pair_archive_);
  release(pair_archive_start_);
  release(wall_archive_);
  release(pair_memory_archive_);
  release(wall_memory_archive_);
  carry_ready_ = true;
  ++n_builds_;
  clock.mark(StepProfile::references);
  return permuted_;
}

void NeighbourSearch::build_pairs(const ParticleStore& store, ContactLists& lists, const Previous* prev, int threads)
{
  const std::size_t n = store.size();
  const auto& x = store.x;
  const auto& R = store.radius;
  const auto& body = store.body;
  const auto& inv_m = store.inv_mass;
  auto listed = [&](Index a, Index b) {
    if (b <= a) return false;
    if (body[a] != kOwnBody && body[a] == body[b]) return false;
    if (inv_m[a] == 0.0 && inv_m[b] == 0.0) return false;
    const double range = R[a] + R[b] + reach_ + skin_;
    return (x[b] - x[a]).squaredNorm() < range * range;
  };
  // Storage in cell order (sorting on): only the cells after a's can hold b > a, and
  // they are met in the same order as in the full stencil, so the slots are the same.
  const bool cell_order = sort_;
  const auto for_each_candidate = [&](Index a, auto&& f) {
    if (cell_order) grid_.for_each_after(a, f);
    else grid_.for_each_near(grid_.cell_of_particle(a), f);
  };
  // Two passes (count, fill) over particles, each in its own range; particle a's slots
  // are the run [run_start_[a], run_start_[a + 1]).
  run_start_.assign(n + 1, 0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t a = 0; a < std::int64_t(n); ++a) {
    std::uint32_t c = 0;
    for_each_candidate(Index(a), [&](Index b) { c += listed(Index(a), b) ? 1u : 0u; });
    run_start_[a + 1] = c;
  }
  for (std::size_t a = 0; a < n; ++a) run_start_[a + 1] += run_start_[a];
  const std::size_t n_pairs = run_start_[n];
  const bool memory = lists.with_memory;
  // Grown by an eighth when short (resize alone would double the capacity).
  if (lists.pairs.capacity() < n_pairs) lists.pairs.reserve(n_pairs + n_pairs / 8);
  if (lists.pair_loads.capacity() < n_pairs) lists.pair_loads.reserve(n_pairs + n_pairs / 8);
  lists.pairs.resize(n_pairs);
  lists.pair_memory.resize(memory ? n_pairs : 0);
  lists.pair_loads.resize(n_pairs);
  const auto& id = store.id;
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t a = 0; a < std::int64_t(n); ++a) {
    std::uint32_t k = run_start_[a];
    for_each_candidate(Index(a), [&](Index b) {
      if (!listed(Index(a), b)) return;
      // i is the particle earlier in storage (the slots of a particle's run are its own,
      // so pass A and pass B read i sequentially).
      PairSlot& s = lists.pairs[k];
      s.i = Index(a);
      s.j = b;
      carry_pair(s, prev, id);  // (4) the history carried over
      lists.pair_loads[k] = SlotLoad{};  // the next force pass writes them
      if (memory)
        lists.pair_memory[k] =
          oriented(find_memory(pair_memory_archive_, broken_pairs_, pair_key(id[a], id[b])), id[a] < id[b]);
      ++k;
    });
  }
}

void NeighbourSearch::build_incident(ContactLists& lists, int threads)
{
  // Incident slots of every particle in ascending slot order: those where it is j (from
  // the runs of earlier particles, so before its own run), sorted, then its own run.
  const std::size_t n = run_start_.size() - 1, n_pairs = lists.pairs.size();
  const PairSlot* const pairs = lists.pairs.data();
  count_.assign(n, 0);
  std::uint32_t* const cursor = count_.data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < std::int64_t(n_pairs); ++k) {
#pragma omp atomic update
    ++cursor[pairs[k].j];
  }
  auto& off = lists.incident_offset;
  off.resize(n + 1);
  off[0] = 0;
  for (std::size_t p = 0; p < n; ++p) off[p + 1] = off[p] + cursor[p] + (run_start_[p + 1] - run_start_[p]);
  if (lists.incident.capacity() < 2 * n_pairs) lists.incident.reserve(2 * n_pairs + n_pairs / 4);
  lists.incident.resize(2 * n_pairs);
  std::uint32_t* const inc = lists.incident.data();
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (std::int64_t p = 0; p < std::int64_t(n); ++p) cursor[p] = off[p];
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < std::int64_t(n_pairs); ++k) {
      std::uint32_t at;
#pragma omp atomic capture
      at = cursor[pairs[k].j]++;
      inc[at] = std::uint32_t(k << 1) | 1u;
    }
#pragma omp for schedule(static)
    for (std::int64_t p = 0; p < std::int64_t(n); ++p) {
      std::sort(inc + off[p], inc + cursor[p]);  // the j entries, (k << 1) | 1: by slot
      std::uint32_t at = cursor[p];
      for (std::uint32_t k = run_start_[p]; k < run_start_[p + 1]; ++k) inc[at++] = std::uint32_t(k << 1);
    }
  }
}

void NeighbourSearch::build_walls(const ParticleStore& store, const std::vector<PlaneWall>& walls,
                                  ContactLists& lists, const Previous* prev, int threads)
{
  // Wall candidates, sorted by particle: count, then fill, each particle in its range.
  const std::size_t n = store.size();
  const auto& x = store.x;
  const auto& R = store.radius;
  const auto& id = store.id;
  const bool memory = lists.with_memory;
  auto near = [&](std::size_t p, std::size_t w) {
    return store.inv_mass[p] != 0.0 && walls[w].distance(x[p]) < R[p] + reach_ + skin_;
  };
  auto& off = lists.wall_offset;
  off.assign(n + 1, 0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t p = 0; p < std::int64_t(n); ++p) {
    std::uint32_t c = 0;
    for (std::size_t w = 0; w < walls.size(); ++w) c += near(std::size_t(p), w) ? 1u : 0u;
    off[p + 1] = c;
  }
  for (std::size_t p = 0; p < n; ++p) off[p + 1] += off[p];
  if (lists.wall_loads.capacity() < off[n]) lists.wall_loads.reserve(off[n] + off[n] / 8);
  lists.walls.resize(off[n]);
  lists.wall_memory.resize(memory ? off[n] : 0);
  lists.wall_loads.resize(off[n]);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t p = 0; p < std::int64_t(n); ++p) {
    std::uint32_t k = off[p];
    for (std::size_t w = 0; w < walls.size(); ++w) {
      if (!near(std::size_t(p), w)) continue;
      WallSlot& s = lists.walls[k];
      s.wall = Index(w);
      s.particle = Index(p);
      carry_wall(s, prev, id);
      lists.wall_loads[k] = SlotLoad{};
      if (memory)
        lists.wall_memory[k] = find_memory(wall_memory_archive_, broken_walls_, wall_key(std::uint32_t(w), id[p]));
      ++k;
    }
  }
}

std::size_t NeighbourSearch::memory_bytes() const
{
  return grid_.memory_bytes() + (x_ref_.capacity() + wall_ref_.capacity()) * sizeof(Vec3) +
         (count_.capacity() + pair_archive_start_.capacity() + run_start_.capacity() + old_of_.capacity()) *
           sizeof(std::uint32_t) +
         built_ids_.capacity() * sizeof(ParticleId) +
         (pair_archive_.capacity() + wall_archive_.capacity()) * sizeof(HistoryEntry) +
         (pair_memory_archive_.capacity() + wall_memory_archive_.capacity()) * sizeof(MemoryEntry) +
         (broken_pairs_.capacity() + broken_walls_.capacity()) * sizeof(std::uint64_t) +
         previous_.capacity * sizeof(PairSlot) + previous_.walls.capacity() * sizeof(WallSlot) +
         (previous_.run_start.capacity() + previous_.wall_offset.capacity()) * sizeof(std::uint32_t);
}

void NeighbourSearch::write_state(std::ostream& out) const
{
  binary::put_tag(out, "NBSEARCH", 2);
  binary::put(out, skin_);
  binary::put(out, sort_);
  binary::put(out, imported_);
  binary::put<std::uint64_t>(out, n_builds_);
  binary::put_vector(out, x_ref_);
  binary::put_vector(out, wall_ref_);
  binary::put_vector(out, pair_archive_);
  binary::put_vector(out, wall_archive_);
  binary::put(out, reach_);
  binary::put(out, memory_imported_);
  binary::put_vector(out, pair_memory_archive_);
  binary::put_vector(out, wall_memory_archive_);
  binary::put_vector(out, broken_pairs_);
  binary::put_vector(out, broken_walls_);
}

void NeighbourSearch::read_state(std::istream& in)
{
  // Version 1 (before contact memory): no reach, memory archives or broken bonds.
  char tag[8];
  in.read(tag, 8);
  std::uint32_t version = 0;
  if (in) binary::get(in, version);
  if (!in || std::string(tag, 8) != "NBSEARCH" || (version != 1 && version != 2))
    throw binary::StateError("checkpoint: section 'NBSEARCH' not found or of another version");
  carry_ready_ = false;  // the lists read beside this state were not built here
  binary::get(in, skin_);
  binary::get(in, sort_);
  binary::get(in, imported_);
  std::uint64_t builds = 0;
  binary::get(in, builds);
  n_builds_ = std::size_t(builds);
  binary::get_vector(in, x_ref_);
  binary::get_vector(in, wall_ref_);
  binary::get_vector(in, pair_archive_);
  binary::get_vector(in, wall_archive_);
  if (version == 1) {
    reach_ = 0.0;
    memory_imported_ = false;
    pair_memory_archive_.clear();
    wall_memory_archive_.clear();
    broken_pairs_.clear();
    broken_walls_.clear();
    return;
  }
  binary::get(in, reach_);
  binary::get(in, memory_imported_);
  binary::get_vector(in, pair_memory_archive_);
  binary::get_vector(in, wall_memory_archive_);
  binary::get_vector(in, broken_pairs_);
  binary::get_vector(in, broken_walls_);
}

}  // namespace geocomp::dem
