#include "dem/LoadScatter.h"

#include <algorithm>
#include <cmath>

namespace geocomp::dem {

namespace {
/// Worker w meets a body whose target is t: the first worker's index, kShared after two.
inline void meet(std::uint32_t& t, std::uint32_t w)
{
  std::uint32_t seen = __atomic_load_n(&t, __ATOMIC_RELAXED);
  while (seen != w && seen != LoadScatter::kShared) {
    const std::uint32_t want = seen == LoadScatter::kShared - 1 ? w : LoadScatter::kShared;
    if (__atomic_compare_exchange_n(&t, &seen, want, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) return;
  }
}
}  // namespace

void LoadScatter::rebalance(const std::vector<double>& seconds)
{
  const int workers = int(seconds.size());
  if (workers != workers_ || workers < 2 || bounds_.size() != std::size_t(workers) + 1) return;
  double total = 0.0;
  for (double t : seconds) total += t;
  const double n_blocks = double(bounds_.back());
  if (!(total > 0.0) || !(n_blocks > 0.0)) return;
  // The cost as a function of the slot fraction u: piecewise even over the current
  // ranges; the new range ends where its integral reaches k / workers of the total.
  cut_.assign(std::size_t(workers), 1.0);
  double below = 0.0;  // cost of the ranges before w
  int w = 0;
  for (int k = 1; k < workers; ++k) {
    const double goal = total * double(k) / double(workers);
    while (w < workers - 1 && below + seconds[w] < goal) below += seconds[w++];
    const double u0 = double(bounds_[w]) / n_blocks, u1 = double(bounds_[w + 1]) / n_blocks;
    const double inside = seconds[w] > 0.0 ? (goal - below) / seconds[w] : 0.0;
    cut_[std::size_t(k - 1)] = u0 + std::clamp(inside, 0.0, 1.0) * (u1 - u0);
  }
  planned_ = false;
}

void LoadScatter::set_bounds(std::size_t n_pairs, std::size_t block, int workers)
{
  const std::size_t nb = (n_pairs + block - 1) / block;
  bounds_.assign(std::size_t(workers) + 1, nb);
  bounds_[0] = 0;
  const bool cut = cut_.size() == std::size_t(workers);
  for (int w = 1; w < workers; ++w) {
    const std::size_t even = nb * std::size_t(w) / std::size_t(workers);
    const std::size_t at = cut ? std::size_t(std::llround(cut_[std::size_t(w - 1)] * double(nb))) : even;
    bounds_[std::size_t(w)] = std::clamp(at, bounds_[std::size_t(w - 1)], nb);
  }
  if (!cut) cut_.clear();
}

void LoadScatter::plan(const ContactLists& lists, std::size_t n, std::size_t block, int workers,
                       std::uint64_t generation)
{
  const std::size_t n_pairs = lists.pairs.size();
  if (planned_ && generation == generation_ && n == n_ && n_pairs == n_pairs_ && block == block_ &&
      workers == workers_)
    return;
  planned_ = true;
  generation_ = generation;
  set_bounds(n_pairs, block, workers);
  n_ = n;
  n_pairs_ = n_pairs;
  block_ = block;
  workers_ = workers;

  // First pass, one thread per worker: target_ holds the first worker that meets each
  // body, kShared once a second worker meets it, kUnmet for bodies without pair slots
  // (compare-and-swap: the final value does not depend on which worker came first).
  constexpr std::uint32_t kUnmet = kShared - 1;
  target_.resize(n);
  std::uint32_t* const target = target_.data();
  const PairSlot* const pairs = lists.pairs.data();
#pragma omp parallel num_threads(workers)
  {
#pragma omp for schedule(static)
    for (std::int64_t p = 0; p < std::int64_t(n); ++p) target[p] = kUnmet;
#pragma omp for schedule(static, 1)
    for (int w = 0; w < workers; ++w) {
      const auto [b0, b1] = blocks_of(w);
      const std::size_t end = std::min(n_pairs, b1 * block);
      for (std::size_t c = b0 * block; c < end; ++c)
        for (const Index p : {pairs[c].i, pairs[c].j}) meet(target[p], std::uint32_t(w));
    }
    // Second pass: a private body's row is its own index.
#pragma omp for schedule(static)
    for (std::int64_t p = 0; p < std::int64_t(n); ++p)
      if (target[p] != kShared) target[p] = std::uint32_t(p);
  }
  shared_.clear();
  for (std::size_t p = 0; p < n; ++p)
    if (target[p] == kShared) shared_.push_back(Index(p));
  rows_.resize(n + kJunkRows * std::size_t(workers));
}

}  // namespace geocomp::dem
