// A sphere pressed on a wall and dragged: Coulomb sliding, then rolling (DEM-NOTES 10.4).
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::dem;

TEST(WallFriction, DraggedSphereSlidesWithMuTimesNormalForceThenRolls)
{
  // Sphere at rest, pressed on the floor by gravity; the floor is dragged along x at
  // V. While slipping the tangential force is mu F_n, the sphere accelerates at mu g and
  // spins up at 5 mu g / (2R); it rolls from t* = 2V/(7 mu g) on, at v = 2V/7.
  const double R = 0.01, k = 1e5, g = 9.81, mu = 0.3, V = 0.1;
  const double m = 4.0 / 3.0 * M_PI * R * R * R * 2650.0;
  DemSystem sys;
  // A tangential dashpot (c_t = c_n) damps the stick oscillation once rolling starts.
  sys.set_contact_model(LinearSpringDashpot(LinearNormal::with_stiffness(k, 0.3),
                                            LinearTangential({true, 2.0 / 7.0, true, 1.0})));
  sys.set_gravity(Vec3(0, 0, -g));
  sys.add_sphere(Vec3(0, 0, R - m * g / k), R, 2650.0);  // normal equilibrium
  PlaneWall floor;
  floor.normal = Vec3::UnitZ();
  floor.mu = mu;
  floor.velocity = Vec3(V, 0, 0);
  sys.add_wall(floor);
  const double dt = 0.02 * std::sqrt(m / k);
  sys.set_time_step(dt);
  const double t_star = 2.0 * V / (7.0 * mu * g);
  int checked = 0;
  while (sys.time() < 0.8 * t_star) {
    sys.step();
    if (sys.time() > 0.1 * t_star) {
      const ContactRecord c = sys.contacts().at(0);
      ASSERT_TRUE(c.wall);
      EXPECT_NEAR(c.tangential_force.norm() / (mu * c.normal_force), 1.0, 1e-9);
      EXPECT_GT(c.tangential_force.x(), 0.0);  // drags the sphere along +x
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_NEAR(sys.velocity(0).x() / (mu * g * sys.time()), 1.0, 0.01);
  EXPECT_NEAR(sys.angular_velocity(0).y() / (-2.5 * mu * g * sys.time() / R), 1.0, 0.01);
  // Sliding ends at t*; afterwards the sphere rolls at 2V/7 and friction is below the cap.
  while (sys.time() < 3.0 * t_star) sys.step();
  EXPECT_NEAR(sys.velocity(0).x() / (2.0 * V / 7.0), 1.0, 0.01);
  const ContactRecord c = sys.contacts().at(0);
  EXPECT_LT(c.tangential_force.norm(), 0.5 * mu * c.normal_force);
}

TEST(WallFriction, FrictionlessWallGivesNoTangentialForce)
{
  const double R = 0.01, k = 1e5;
  DemSystem sys;
  sys.set_contact_model(test::linear_law(k, 0.3));
  sys.set_gravity(Vec3(0, 0, -9.81));
  sys.add_sphere(Vec3(0, 0, R * 0.999), R, 2650.0, Vec3(0.1, 0, 0), Vec3(0, 10, 0));
  PlaneWall floor;
  floor.normal = Vec3::UnitZ();
  sys.add_wall(floor);
  sys.set_time_step(1e-6);
  sys.run(1000);
  EXPECT_EQ(sys.torque(0).norm(), 0.0);
  EXPECT_EQ(sys.force(0).x(), 0.0);
  EXPECT_NEAR(sys.angular_velocity(0).y(), 10.0, 1e-12);
}
