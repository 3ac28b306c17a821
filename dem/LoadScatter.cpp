#include "dem/LoadScatter.h"

namespace geocomp::dem {

void LoadScatter::plan(const ContactLists& lists, std::size_t n, std::size_t block, int workers,
                       std::uint64_t generation)
{
  const std::size_t n_pairs = lists.pairs.size();
  if (planned_ && generation == generation_ && n == n_ && n_pairs == n_pairs_ && block == block_ &&
      workers == workers_)
    return;
  planned_ = true;
  generation_ = generation;
  n_ = n;
  n_pairs_ = n_pairs;
  block_ = block;
  workers_ = workers;

  // First pass: target_ holds the first worker that meets each body, kShared once a
  // second worker meets it, kUnmet for bodies without pair slots.
  constexpr std::uint32_t kUnmet = kShared - 1;
  target_.assign(n, kUnmet);
  const std::size_t nb = (n_pairs + block - 1) / block;
  for (int w = 0; w < workers; ++w) {
    const auto [b0, b1] = blocks_of(w, workers, nb);
    const std::size_t end = std::min(n_pairs, b1 * block);
    for (std::size_t c = b0 * block; c < end; ++c) {
      for (const Index p : {lists.pairs[c].i, lists.pairs[c].j}) {
        std::uint32_t& t = target_[p];
        if (t == kUnmet) t = std::uint32_t(w);
        else if (t != std::uint32_t(w)) t = kShared;
      }
    }
  }
  // Second pass: a private body's row is its own index.
  shared_.clear();
  for (std::size_t p = 0; p < n; ++p) {
    if (target_[p] == kShared) shared_.push_back(Index(p));
    else target_[p] = std::uint32_t(p);
  }
  rows_.resize(n + kJunkRows * std::size_t(workers));
}

}  // namespace geocomp::dem
