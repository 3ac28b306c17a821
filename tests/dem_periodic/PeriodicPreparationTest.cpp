// RVE preparation: the random placement (no overlap through the images, the asked packing
// fraction, the same spheres for the same seed) and a Packing turned into a cell.
#include "dem/periodic/PeriodicPreparation.h"
#include "TestCells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace geocomp::dem;

TEST(PeriodicPreparation, TheRandomPlacementHasNoOverlapThroughTheImagesAndTheAskedPackingFraction)
{
  RandomPlacement p;
  p.particles = 400;
  p.packing_fraction = 0.32;
  p.seed = 3;
  PeriodicCell::Parameters cp;
  cp.time_step = 1e-6;
  const PeriodicCell a = place_spheres(p, test::periodic_linear_law(1e5, 0.5), cp);
  ASSERT_EQ(a.n_particles(), 400u);
  EXPECT_NEAR(a.packing_fraction(), 0.32, 1e-12);
  double r_min = 1.0, r_max = 0.0;
  for (double r : a.particles().radius) {
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
  }
  EXPECT_GE(r_min, 0.8e-3);
  EXPECT_LE(r_max, 1.2e-3);
  EXPECT_GT(r_max - r_min, 0.3e-3);
  PeriodicCell c = a;
  c.evaluate();
  EXPECT_EQ(c.stress().contacts, 0u);  // no pair overlaps, images included
  const PeriodicCell b = place_spheres(p, test::periodic_linear_law(1e5, 0.5), cp);
  EXPECT_EQ(0, std::memcmp(a.particles().x.data(), b.particles().x.data(), 400 * sizeof(Vec3)));
  p.seed = 4;
  const PeriodicCell d = place_spheres(p, test::periodic_linear_law(1e5, 0.5), cp);
  EXPECT_NE(0, std::memcmp(a.particles().x.data(), d.particles().x.data(), 400 * sizeof(Vec3)));
}

TEST(PeriodicPreparation, APackingBecomesACellWithItsBoxAsTheCellMatrix)
{
  Packing pk;
  pk.box_min = Eigen::Vector3d(1.0, 2.0, 3.0);
  pk.box_max = Eigen::Vector3d(1.5, 2.6, 3.7);
  pk.density = 2000.0;
  pk.position = {{1.01, 2.3, 3.35}, {1.49, 2.3, 3.35}, {1.25, 2.1, 3.6}};
  pk.radius = {0.02, 0.03, 0.04};
  PeriodicCell::Parameters cp;
  cp.time_step = 1e-6;
  PeriodicCell cell = cell_from_packing(pk, test::periodic_linear_law(1e5, 0.5), cp);
  EXPECT_EQ(cell.cell().h(), Mat3(Vec3(pk.box_max - pk.box_min).asDiagonal()));
  ASSERT_EQ(cell.n_particles(), 3u);
  for (Index p = 0; p < 3; ++p) {
    EXPECT_LT((cell.position(p) - (pk.position[p] - pk.box_min)).norm(), 1e-15);
    EXPECT_EQ(cell.particles().radius[p], pk.radius[p]);
    EXPECT_NEAR(cell.particles().mass[p], 2000.0 * 4.0 / 3.0 * M_PI * std::pow(pk.radius[p], 3), 1e-15);
  }
  EXPECT_NEAR(cell.packing_fraction(), pk.packing_fraction(), 1e-12);
  // Spheres 0 and 1 (x = 0.01 and 0.49 in a 0.5 m cell) touch across the face x = 0.
  cell.evaluate();
  EXPECT_EQ(cell.stress().contacts, 1u);
  EXPECT_GT(cell.force(0).x(), 0.0);  // pushed away from its image partner at x = -0.01
}
