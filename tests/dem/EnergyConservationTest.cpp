// Energy: conservation without losses, and the ledger closing with losses and moving walls.
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::dem;

TEST(EnergyConservation, UndampedFrictionlessClusterConservesEnergyOver1e5Steps)
{
  DemSystem sys;
  sys.set_contact_model(test::linear_law(1e4, 1.0));  // e = 1: no dashpot
  sys.set_friction(0.0);
  test::fill_box(sys, 2, 0.01, 0.2, 7u);  // 8 spheres, 6 frictionless walls
  const double m = 4.0 / 3.0 * M_PI * 1e-6 * 2650.0;
  sys.set_time_step(1e-3 * std::sqrt(m / 1e4));
  sys.set_energy_tracking(true);
  sys.step();
  const double e0 = sys.energy().mechanical();
  ASSERT_GT(e0, 0.0);
  double worst = 0.0;
  std::size_t touching_steps = 0;
  for (int s = 0; s < 100000; ++s) {
    sys.step();
    if (s % 10 == 0) {
      const EnergyLedger e = sys.energy();
      worst = std::max(worst, std::abs(e.mechanical() - e0) / e0);
      touching_steps += (e.elastic() > 0.0) ? 1 : 0;
    }
  }
  EXPECT_GT(touching_steps, 100u);  // collisions did happen
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(sys.energy().dissipated(), 0.0);
}

TEST(EnergyConservation, UndampedHertzClusterConservesEnergy)
{
  DemSystem sys;
  sys.set_contact_model(HertzMindlin(HertzNormal({1e8, 0.25, HertzNormal::Damping::restitution, 1.0, 0.0, true}),
                                     MindlinTangential({1e8, 0.25, 1.0})));
  test::fill_box(sys, 2, 0.01, 0.2, 11u);
  sys.set_time_step(2e-3 * sys.critical_time_step());
  sys.step();
  const double e0 = sys.energy().mechanical();
  double worst = 0.0;
  for (int s = 0; s < 50000; ++s) {
    sys.step();
    if (s % 10 == 0) worst = std::max(worst, std::abs(sys.energy().mechanical() - e0) / e0);
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(EnergyLedger, DampingFrictionAndWallWorkCloseTheBalance)
{
  // Dashpots, friction, gravity and a moving wall: stored + dissipated - wall work stays
  // constant (to the O(dt) accuracy of the bookkeeping) while the losses are large.
  DemSystem sys;
  sys.set_contact_model(test::linear_law(1e4, 0.6, 2.0 / 7.0));
  sys.set_friction(0.4);
  test::fill_box(sys, 3, 0.01, 0.3, 3u, 0.3);
  sys.set_gravity(Vec3(0, 0, -9.81));
  const double m = 4.0 / 3.0 * M_PI * 1e-6 * 2650.0;
  sys.set_time_step(0.01 * std::sqrt(m / 1e4));
  sys.set_energy_tracking(true);
  sys.set_wall_velocity(5, Vec3(0, 0, -0.05));  // lid moves down
  sys.step();
  const double b0 = sys.energy().balance();
  sys.run(20000);
  const EnergyLedger e = sys.energy();
  EXPECT_GT(e.dissipated_damping, 0.0);
  EXPECT_GT(e.dissipated_friction, 0.0);
  EXPECT_GT(e.wall_work, 0.0);
  const double scale = e.dissipated() + std::abs(e.wall_work);
  EXPECT_LT(std::abs(e.balance() - b0) / scale, 5e-3)
    << "mech " << e.mechanical() << " diss " << e.dissipated() << " wall " << e.wall_work;
}

TEST(LocalDamping, OffByDefaultAndDissipatesWhenOn)
{
  auto run = [](double lambda) {
    DemSystem sys;
    sys.set_contact_model(test::linear_law(1e4, 1.0));
    test::fill_box(sys, 2, 0.01, 0.2, 5u);
    const double m = 4.0 / 3.0 * M_PI * 1e-6 * 2650.0;
    sys.set_time_step(0.01 * std::sqrt(m / 1e4));
    sys.set_local_damping(lambda);
    sys.step();
    const double e0 = sys.energy().mechanical();
    sys.run(20000);
    const EnergyLedger e = sys.energy();
    return std::pair<double, EnergyLedger>(e0, e);
  };
  const auto [e0_off, off] = run(0.0);
  EXPECT_NEAR(off.mechanical() / e0_off, 1.0, 1e-4);
  EXPECT_EQ(off.dissipated_local, 0.0);
  const auto [e0_on, on] = run(0.3);
  EXPECT_LT(on.mechanical(), 0.5 * e0_on);
  EXPECT_NEAR((on.mechanical() + on.dissipated_local) / e0_on, 1.0, 0.02);
}
