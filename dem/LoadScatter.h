// @sect3{The LoadScatter class: contact loads added into the bodies during pass A}
//
// Why it exists: the gather of pass B (ContactLists.h) read every pair slot twice, once
// for each body, and the j side's reads jump through the whole slot array (88-byte slots
// then, a random cache line each; out of the last-level cache at 100 000 spheres). It was a
// third of the step. Here each slot's loads are added into both bodies as soon as the
// slot is computed, in slot order, into a row of 8 doubles per body (force, torque; one
// cache line), so the slots are streamed once.
//
// Determinism (DEM-NOTES section 5): the gather summed a body's slots in ascending slot
// order, starting from its weight $m\,g$. The pair slots are split into W contiguous
// ranges of blocks, one per worker (W = the thread count; worker w is run by thread
// w mod T). A body whose slots all fall into one worker's range is *private* to it:
// that worker adds its slots into the body's row in slot order, starting from $m\,g$,
// which is the gather's sum, operation for operation. A body with slots in two ranges is
// *shared*: its slots go to the worker's junk row and keep their loads beside the slots
// (ContactLists::pair_loads), and the gather (incident slots in ascending order) computes
// it after pass A, the shared bodies split evenly among the
// threads (they lie in one layer of storage). Every body gets the gather's bits, so the
// trajectories do not depend on W or on the threads (test `Determinism.*`); the share of
// shared bodies is the layer where two workers' storage ranges meet (none for W = 1).
//
// Slot loads (DEM-NOTES section 1, as pass B): $F_j \mathrel{+}= F$, $F_i \mathrel{-}= F$,
// $T_k \mathrel{-}= (R_k - \delta/2)\,(n\times F_t)$ for both bodies, the rolling moment
// $+M_r$ on j and $-M_r$ on i.
#pragma once

#include "dem/ContactLists.h"
#include "dem/Types.h"

#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace geocomp::dem {

/// A body's summed contact loads, padded to one 64-byte cache line (the kernel adds
/// 4-double rows).
struct alignas(64) LoadRow
{
  double f[4] = {0.0, 0.0, 0.0, 0.0};
  double t[4] = {0.0, 0.0, 0.0, 0.0};
};

class LoadScatter
{
public:
  /// `target[p]` of a shared body.
  static constexpr std::uint32_t kShared = ~std::uint32_t(0);
  /// Junk rows per worker: the batched kernel sends each lane's loads of shared bodies to
  /// a row of its own, so consecutive slots do not wait on one row's read-modify-write.
  static constexpr std::size_t kJunkRows = 8;

  /// Blocks [first, second) of worker w in the current plan.
  std::pair<std::size_t, std::size_t> blocks_of(int w) const { return {bounds_[w], bounds_[w + 1]}; }

  /// Marks private and shared bodies for these lists, `n` bodies, blocks of `block`
  /// slots and `workers` workers, unless already planned for the same `generation` (the
  /// neighbour search's build count) and sizes. Sizes the rows (n bodies + kJunkRows
  /// junk rows per worker).
  void plan(const ContactLists& lists, std::size_t n, std::size_t block, int workers, std::uint64_t generation);
  /// Forgets the plan (the lists were replaced, e.g. read from a checkpoint).
  void invalidate() { planned_ = false; }
  /// Plans anew at the next plan() with the workers' ranges moved so that each gets the
  /// same share of `seconds` (each worker's measured time on its current range, the cost
  /// taken as even within a range). The ranges only balance the threads: a body's load
  /// has the gather's bits whatever they are (above), so the bits do not depend on them.
  void rebalance(const std::vector<double>& seconds);

  /// The row body p's slots go to when worker w adds them.
  std::uint32_t row_of(Index p, int w) const
  {
    const std::uint32_t r = target_[p];
    return r == kShared ? junk_row(w) : r;
  }
  /// The first of worker w's kJunkRows junk rows.
  std::uint32_t junk_row(int w) const { return std::uint32_t(n_ + kJunkRows * std::size_t(w)); }
  /// The shared bodies, ascending.
  const std::vector<Index>& shared_bodies() const { return shared_; }

  LoadRow* rows() { return rows_.data(); }
  const std::uint32_t* targets() const { return target_.data(); }

  /// True when body p is shared (gathered in pass B1, not added into a row in pass A).
  bool shared(Index p) const { return target_[p] == kShared; }

  /// A slot's loads into rows ri (body i) and rj (body j), as the gather sums them.
  void add_pair(std::uint32_t ri, std::uint32_t rj, const SlotLoad& load, double overlap, double R_i, double R_j)
  {
    LoadRow& a = rows_[ri];
    LoadRow& b = rows_[rj];
    for (int k = 0; k < 3; ++k) {
      a.f[k] -= load.force[k];
      b.f[k] += load.force[k];
    }
    const double arm_i = R_i - 0.5 * overlap, arm_j = R_j - 0.5 * overlap;
    for (int k = 0; k < 3; ++k) {
      a.t[k] -= arm_i * load.lever[k];
      b.t[k] -= arm_j * load.lever[k];
    }
  }
  /// The rolling moment of a slot: +M_r on j, -M_r on i (after add_pair, as the gather).
  void add_rolling(std::uint32_t ri, std::uint32_t rj, const Vec3& m)
  {
    for (int k = 0; k < 3; ++k) {
      rows_[ri].t[k] -= m[k];
      rows_[rj].t[k] += m[k];
    }
  }

  std::size_t memory_bytes() const
  {
    return rows_.capacity() * sizeof(LoadRow) + target_.capacity() * sizeof(std::uint32_t) +
           shared_.capacity() * sizeof(Index);
  }

private:
  /// The workers' block ranges for n_pairs slots: even, or at the cuts rebalance() set.
  void set_bounds(std::size_t n_pairs, std::size_t block, int workers);

  bool planned_ = false;
  std::uint64_t generation_ = 0;
  std::size_t n_ = 0, n_pairs_ = 0, block_ = 0;
  int workers_ = 0;
  std::vector<std::size_t> bounds_;  // worker w: blocks [bounds_[w], bounds_[w + 1])
  std::vector<double> cut_;          // the next plan's range ends as fractions of the slots (empty: even)
  std::vector<Index> shared_;
  std::vector<LoadRow> rows_;
  std::vector<std::uint32_t> target_;
};

}  // namespace geocomp::dem
