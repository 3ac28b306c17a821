// The scatter plan's worker ranges (LoadScatter.h): even at first, then moved to equal
// shares of the measured time; a body met by two ranges is shared, any other private.
#include "dem/LoadScatter.h"

#include <gtest/gtest.h>

#include <set>

namespace geocomp::dem {
namespace {

/// n_pairs slots on a chain of bodies: slot c joins bodies c and c + 1.
ContactLists chain(std::size_t n_pairs)
{
  ContactLists lists;
  lists.pairs.resize(n_pairs);
  for (std::size_t c = 0; c < n_pairs; ++c) {
    lists.pairs[c].i = Index(c);
    lists.pairs[c].j = Index(c + 1);
  }
  return lists;
}

TEST(LoadScatter, RangesStartEvenAndMoveToEqualSharesOfTheMeasuredTime)
{
  const ContactLists lists = chain(1200 * 4);  // 1200 blocks of 4 slots
  LoadScatter scatter;
  scatter.plan(lists, 1200 * 4 + 1, 4, 2, 1);
  EXPECT_EQ(scatter.blocks_of(0), std::make_pair(std::size_t(0), std::size_t(600)));
  EXPECT_EQ(scatter.blocks_of(1), std::make_pair(std::size_t(600), std::size_t(1200)));
  // The first range took three times the second's time: its blocks cost 3 units each,
  // the others 1, so the halves of the total (3 * 600 + 600 = 2400) meet at block 400.
  scatter.rebalance({3.0, 1.0});
  scatter.plan(lists, 1200 * 4 + 1, 4, 2, 1);
  EXPECT_EQ(scatter.blocks_of(0), std::make_pair(std::size_t(0), std::size_t(400)));
  EXPECT_EQ(scatter.blocks_of(1), std::make_pair(std::size_t(400), std::size_t(1200)));
  // The cut is kept as a fraction of the slots for the next lists (a rebuild).
  const ContactLists longer = chain(2400 * 4);
  scatter.plan(longer, 2400 * 4 + 1, 4, 2, 2);
  EXPECT_EQ(scatter.blocks_of(0).second, 800u);
}

TEST(LoadScatter, ABodyIsSharedExactlyWhenTwoRangesMeetIt)
{
  const ContactLists lists = chain(64 * 4);
  LoadScatter scatter;
  scatter.plan(lists, 64 * 4 + 1, 4, 3, 1);
  scatter.rebalance({1.0, 5.0, 2.0});
  scatter.plan(lists, 64 * 4 + 1, 4, 3, 1);
  std::set<Index> expected;
  for (int w = 1; w < 3; ++w) {
    const std::size_t b = scatter.blocks_of(w).first;
    if (b > 0 && b < 64) expected.insert(Index(b * 4));  // body b*4: slot b*4-1 (range w-1) and b*4 (range w)
  }
  EXPECT_EQ(expected.size(), 2u);
  const std::vector<Index>& shared = scatter.shared_bodies();
  EXPECT_EQ(std::set<Index>(shared.begin(), shared.end()), expected);
  for (std::size_t p = 0; p <= 64 * 4; ++p)
    EXPECT_EQ(scatter.shared(Index(p)), expected.count(Index(p)) == 1) << "body " << p;
}

}  // namespace
}  // namespace geocomp::dem
