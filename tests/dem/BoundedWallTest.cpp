// Bounded (rectangular) walls for S4's split shear box (PlaneWall.h): a sphere whose
// centre projects inside the rectangle feels exactly the unbounded wall's force, one
// beside it (beyond reach of the rim) feels nothing, one over the rim touches the edge.
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::dem;

namespace {

// One sphere of radius R at x, pressed on the floor z = 0 (plate or plane), one step.
Vec3 floor_force(const Vec3& x, double R, bool bounded)
{
  DemSystem sys;
  sys.set_contact_model(test::linear_law(1e5, 0.3));
  sys.add_sphere(x, R, 2650.0, Vec3(0.05, 0.0, -0.01));
  PlaneWall floor = bounded ? rectangle_wall(Vec3(0.0, 0.0, 0.0), Vec3::UnitZ(), Vec3::UnitX(), 0.02, 0.01, 0.3)
                            : PlaneWall{};
  floor.mu = 0.3;
  sys.add_wall(floor);
  sys.set_time_step(1e-6);
  sys.step();
  sys.step();
  return sys.wall(0).force;
}

}  // namespace

TEST(BoundedWall, InsideTheRectangleFeelsTheUnboundedForce)
{
  const double R = 0.005;
  const Vec3 x(0.012, -0.004, 0.999 * R);
  const Vec3 f_plate = floor_force(x, R, true), f_plane = floor_force(x, R, false);
  ASSERT_GT(f_plane.norm(), 0.0);
  EXPECT_EQ(f_plate, f_plane);  // bitwise: the same branch and arithmetic
}

TEST(BoundedWall, OutsideTheRectangleFeelsNothing)
{
  const double R = 0.005;
  // Beyond the rim by more than R along x, and along y.
  EXPECT_EQ(floor_force(Vec3(0.02 + 1.01 * R, 0.0, 0.5 * R), R, true).norm(), 0.0);
  EXPECT_EQ(floor_force(Vec3(0.0, -0.01 - 1.01 * R, 0.5 * R), R, true).norm(), 0.0);
  // Behind the plane and outside the rectangle: no contact (one-sided plate).
  EXPECT_EQ(floor_force(Vec3(0.03, 0.0, -0.5 * R), R, true).norm(), 0.0);
  // The unbounded plane pushes all of them.
  EXPECT_GT(floor_force(Vec3(0.02 + 1.01 * R, 0.0, 0.5 * R), R, false).norm(), 0.0);
}

TEST(BoundedWall, OverTheRimTheEdgePushesAlongTheBranch)
{
  // Centre 0.6 R beyond the rim along x and 0.6 R above: gap 0.6 sqrt(2) R < R, the force
  // on the wall points from the sphere to the rim, at 45 degrees.
  const double R = 0.005;
  DemSystem sys;
  sys.set_contact_model(test::linear_law(1e5, 0.3));
  sys.add_sphere(Vec3(0.02 + 0.6 * R, 0.0, 0.6 * R), R, 2650.0);
  sys.add_wall(rectangle_wall(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 0.02, 0.01, 0.0));
  sys.set_time_step(1e-7);
  sys.step();
  const Vec3 f = sys.wall(0).force;
  ASSERT_GT(f.norm(), 0.0);
  EXPECT_NEAR(f.x() / f.z(), 1.0, 1e-3);
  EXPECT_LT(f.z(), 0.0);
  const ContactRecord c = sys.contacts().at(0);
  EXPECT_NEAR(c.overlap, R - 0.6 * std::sqrt(2.0) * R, 1e-6 * R);
}

TEST(BoundedWall, RejectsAnAxisAlongTheNormal)
{
  DemSystem sys;
  PlaneWall w = rectangle_wall(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 0.02, 0.01, 0.0);
  w.axis = Vec3::UnitZ();
  EXPECT_THROW(sys.add_wall(w), std::invalid_argument);
}
