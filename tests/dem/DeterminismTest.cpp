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

namespace {

/// test::compressed_box run for 1500 steps with `threads` threads under `law`.
std::vector<double> run_with(const ContactModel& law, bool batched, int threads)
{
  DemSystem sys;
  test::compressed_box(sys, law, batched, threads);
  sys.run(1500);
  EXPECT_GT(sys.n_touching_pairs(), 200u);
  std::vector<double> bits = test::state_bits(sys, true);
  for (std::size_t w = 0; w < 6; ++w) bits.insert(bits.end(), sys.wall(w).force.data(), sys.wall(w).force.data() + 3);
  return bits;
}

}  // namespace

// The loads are added into the bodies while the slots are computed, by workers that each
// take a contiguous range of slots; a body met by two workers is gathered afterwards
// (LoadScatter.h). Every body must still get the gather's sum in slot order: the batched
// and scalar linear law, Hertz-Mindlin and a law with rolling moments, at 1 to 4 threads.
TEST(Determinism, OneToFourThreadsGiveTheSameBitsOnEveryPairPath)
{
  const double k = 1e5;
  const ContactModel laws[] = {
    test::linear_law(k, 0.5),
    HertzMindlin(HertzNormal({1e8, 0.25, HertzNormal::Damping::restitution, 0.5, 0.0, true}),
                 MindlinTangential({1e8, 0.25, 1.0})),
    LinearRollingResistance(LinearNormal::with_stiffness(k, 0.5), LinearTangential::with_ratio(2.0 / 7.0),
                            LinearRolling({0.1, 1.0}))};
  struct Case
  {
    const ContactModel* law;
    bool batched;
    const char* name;
  };
  const Case cases[] = {{&laws[0], true, "linear, batched"},
                        {&laws[0], false, "linear, scalar"},
                        {&laws[1], false, "Hertz-Mindlin"},
                        {&laws[2], false, "linear with rolling"}};
  for (const Case& c : cases) {
    const std::vector<double> one = run_with(*c.law, c.batched, 1);
    for (int threads = 2; threads <= 4; ++threads)
      EXPECT_TRUE(test::bitwise_equal(one, run_with(*c.law, c.batched, threads))) << c.name << ", " << threads << " threads";
  }
}
