// The neighbour search carries each contact's history at a rebuild from the last build's
// slots while the particles are the same (NeighbourSearch.h), and from the archive keyed
// by ids otherwise (after a checkpoint is read, particles added or removed). Both must
// give the same bits, or a restart would not continue the run it was written from.
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <sstream>

namespace geocomp::dem::test {
namespace {

/// Runs `steps` steps; with `through_archive`, the state is written and read back before
/// every step, so every rebuild carries the histories through the archive.
std::vector<double> run(DemSystem& sys, int steps, bool through_archive)
{
  for (int s = 0; s < steps; ++s) {
    if (through_archive) {
      std::stringstream buffer;
      sys.write_state(buffer);
      sys.read_state(buffer);
    }
    sys.step();
  }
  return state_bits(sys, true);
}

TEST(HistoryCarry, KeptSlotsAndTheArchiveGiveTheSameBitsOverManyRebuilds)
{
  for (const int threads : {1, 3}) {
    DemSystem direct, archived;
    compressed_box(direct, linear_law(1e5, 0.5), true, threads);
    compressed_box(archived, linear_law(1e5, 0.5), true, threads);
    const std::vector<double> a = run(direct, 800, false);
    const std::vector<double> b = run(archived, 800, true);
    EXPECT_GE(direct.n_rebuilds(), 5u) << "the run must rebuild often to test the carry";
    EXPECT_EQ(direct.n_rebuilds(), archived.n_rebuilds());
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(double))) << threads << " threads";
  }
}

TEST(HistoryCarry, KeptSlotsFlipTheSpringWhenTheStorageOrderOfAPairReverses)
{
  // Ids in reverse order: the sort at each build reverses the storage order of most
  // pairs relative to the last build's, so the carried springs change sides.
  DemSystem ref;
  compressed_box(ref, linear_law(1e5, 0.5), true, 2);
  DemSystem direct, archived;
  for (DemSystem* sys : {&direct, &archived}) {
    sys->set_contact_model(linear_law(1e5, 0.5));
    sys->set_friction(0.4);
    add_renumbered_backwards(*sys, ref, 0.01);
    for (std::size_t w = 0; w < 6; ++w) sys->set_wall_velocity(w, 0.05 * sys->wall(w).normal);
    sys->set_time_step(ref.time_step());
    sys->set_num_threads(2);
  }
  const std::vector<double> a = run(direct, 800, false);
  const std::vector<double> b = run(archived, 800, true);
  EXPECT_GE(direct.n_rebuilds(), 5u);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(double)));
}

}  // namespace
}  // namespace geocomp::dem::test
