// The thread count from the problem size (dem/ThreadCount.h): set_num_threads(0) gives the
// step one thread per kMinParticlesPerThread particles, at most the OpenMP maximum, and
// follows the particles; a count given is kept whatever the size, and a checkpoint keeps
// the setting, not the count it gave.
#include "TestSystems.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <sstream>

using namespace geocomp::dem;
using namespace geocomp::dem::test;

namespace {

/// Sets the OpenMP maximum for one test and puts the old one back.
struct OmpMaxThreads {
  explicit OmpMaxThreads(int n) : old(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~OmpMaxThreads() { omp_set_num_threads(old); }
  int old;
};

/// n spheres of radius 1 mm in a row, far enough apart to touch nothing.
void add_spheres(DemSystem& sys, std::size_t n)
{
  const std::size_t first = sys.n_particles();
  for (std::size_t k = first; k < first + n; ++k) sys.add_sphere(Vec3(0.003 * double(k), 0.0, 0.0), 0.001, 2650.0);
}

}  // namespace

TEST(DemSystem, AutomaticThreadsNeverExceedWhatTheSizePaysFor)
{
  const std::size_t k = kMinParticlesPerThread;
  EXPECT_EQ(threads_for(0, 16), 1);
  EXPECT_EQ(threads_for(k - 1, 16), 1);
  EXPECT_EQ(threads_for(2 * k - 1, 16), 1);
  EXPECT_EQ(threads_for(2 * k, 16), 2);
  EXPECT_EQ(threads_for(5 * k + k / 2, 16), 5);
  EXPECT_EQ(threads_for(100 * k, 16), 16);  // never more than OpenMP allows
  EXPECT_EQ(threads_for(100 * k, 2), 2);
  EXPECT_EQ(threads_for(100 * k, 0), 1);    // at least one
}

TEST(DemSystem, AutomaticThreadsFollowTheParticlesAsTheyAreAdded)
{
  const OmpMaxThreads four(4);
  DemSystem sys;
  sys.set_num_threads(0);
  EXPECT_TRUE(sys.automatic_threads());
  EXPECT_EQ(sys.num_threads(), 1);  // no particles yet
  add_spheres(sys, 200);
  EXPECT_EQ(sys.num_threads(), 1);  // a small specimen: one thread
  add_spheres(sys, 2 * kMinParticlesPerThread - 200);
  EXPECT_EQ(sys.num_threads(), 2);  // a large one: more
  add_spheres(sys, 10 * kMinParticlesPerThread);
  EXPECT_EQ(sys.num_threads(), 4);  // at most the OpenMP maximum
  omp_set_num_threads(3);
  EXPECT_EQ(sys.num_threads(), 3);  // which is read as the step starts
}

TEST(DemSystem, AGivenThreadCountIsKeptWhateverTheSize)
{
  const OmpMaxThreads two(2);
  DemSystem sys;
  add_spheres(sys, 10);
  sys.set_num_threads(3);
  EXPECT_FALSE(sys.automatic_threads());
  EXPECT_EQ(sys.num_threads(), 3);  // more than the size pays for and than OpenMP's maximum
  add_spheres(sys, 10 * kMinParticlesPerThread);
  sys.set_num_threads(1);
  EXPECT_EQ(sys.num_threads(), 1);
  sys.set_num_threads(-1);  // n <= 0: automatic
  EXPECT_TRUE(sys.automatic_threads());
  EXPECT_EQ(sys.num_threads(), 2);
}

// A checkpoint stores the setting: the automatic mode read back on a machine with other
// cores, or for other particles, chooses again; a count given comes back as given.
TEST(DemSystem, ACheckpointKeepsTheThreadSettingNotTheCountItGave)
{
  const OmpMaxThreads two(2);
  DemSystem sys;
  compressed_box(sys, linear_law(1e5, 0.5), true, 0);
  sys.run(3);
  EXPECT_EQ(sys.num_threads(), 1);  // 512 spheres
  std::stringstream state;
  sys.write_state(state);
  DemSystem copy;
  copy.set_num_threads(5);
  copy.read_state(state);
  EXPECT_TRUE(copy.automatic_threads());
  EXPECT_EQ(copy.num_threads(), 1);
  copy.run(2);
  sys.run(2);
  EXPECT_EQ(state_bits(copy, true), state_bits(sys, true));

  sys.set_num_threads(3);
  std::stringstream given;
  sys.write_state(given);
  copy.read_state(given);
  EXPECT_FALSE(copy.automatic_threads());
  EXPECT_EQ(copy.num_threads(), 3);
}
