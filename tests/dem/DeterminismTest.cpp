// Deterministic force accumulation: same input -> same bits, for any thread count.
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

using namespace geocomp::dem;

namespace {

/// A compressed frictional specimen of 6^3 spheres with inward-moving walls.
void make_specimen(DemSystem& sys, int threads)
{
  sys.set_contact_model(test::linear_law(1e5, 0.5, 2.0 / 7.0));
  sys.set_friction(0.4);
  test::fill_box(sys, 6, 0.01, 0.3, 42u, 0.2);
  for (std::size_t w = 0; w < 6; ++w) sys.set_wall_velocity(w, 0.05 * sys.wall(w).normal);
  const double m = 4.0 / 3.0 * M_PI * 1e-6 * 2650.0;
  sys.set_time_step(0.1 * std::sqrt(m / 1e5));
  sys.set_num_threads(threads);
  sys.set_energy_tracking(true);
}

}  // namespace

TEST(Determinism, SameRunTwiceIsBitwiseIdentical)
{
  DemSystem a, b;
  make_specimen(a, 2);
  make_specimen(b, 2);
  a.run(1500);
  b.run(1500);
  ASSERT_GT(a.n_touching_pairs(), 50u);
  EXPECT_TRUE(test::bitwise_equal(test::state_bits(a), test::state_bits(b)));
  EXPECT_EQ(a.energy().dissipated_friction, b.energy().dissipated_friction);
}

TEST(Determinism, OneAndTwoThreadsAreBitwiseIdentical)
{
  DemSystem a, b;
  make_specimen(a, 1);
  make_specimen(b, 2);
  a.run(1500);
  b.run(1500);
  ASSERT_GT(a.n_rebuilds(), 1u);
  EXPECT_TRUE(test::bitwise_equal(test::state_bits(a), test::state_bits(b)));
  const EnergyLedger ea = a.energy(), eb = b.energy();
  EXPECT_EQ(ea.dissipated_damping, eb.dissipated_damping);
  EXPECT_EQ(ea.wall_work, eb.wall_work);
  for (std::size_t w = 0; w < 6; ++w) EXPECT_EQ(a.wall(w).force, b.wall(w).force);
}
