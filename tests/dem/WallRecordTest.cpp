// A wall's record (force, torque, servo stiffness, contact count: PlaneWall.h) is what the
// loading programs read every step: the lid's servo, the direct-shear box, the stresses of
// the true-triaxial cube. It must be the sum over the wall's contacts as contacts() lists
// them, on the batched and the scalar paths and at any thread count, with the wall slots
// spread over more than one block of 256 (test::compressed_box).
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <vector>

using namespace geocomp::dem;

namespace {

struct WallSums
{
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  std::size_t touching = 0;
};

/// The records rebuilt from the listed contacts: the wall receives -F at the contact point.
std::vector<WallSums> sums_from_contacts(const DemSystem& sys)
{
  std::vector<WallSums> sums(sys.n_walls());
  for (const ContactRecord& c : sys.contacts()) {
    if (!c.wall) continue;
    WallSums& s = sums[c.i];
    s.force -= c.force;
    s.torque += (c.point - sys.wall(c.i).point).cross(-c.force);
    if (c.overlap > 0.0) ++s.touching;
  }
  return sums;
}

void expect_records_are_sums(const ContactModel& law, bool batched, int threads, double k_n)
{
  DemSystem sys;
  test::compressed_box(sys, law, batched, threads);
  sys.run(900);
  const std::vector<WallSums> sums = sums_from_contacts(sys);
  std::size_t touching = 0;
  for (std::size_t w = 0; w < sys.n_walls(); ++w) {
    const PlaneWall& wall = sys.wall(w);
    const double scale = 1e-12 * (1.0 + sums[w].force.norm());
    EXPECT_LT((wall.force - sums[w].force).norm(), scale) << "wall " << w;
    EXPECT_LT((wall.torque - sums[w].torque).norm(), scale) << "wall " << w;
    EXPECT_EQ(wall.n_contacts, sums[w].touching) << "wall " << w;
    if (k_n > 0.0) EXPECT_NEAR(wall.stiffness, k_n * double(sums[w].touching), 1e-9 * k_n) << "wall " << w;
    EXPECT_LT(wall.force.dot(wall.normal), 0.0) << "wall " << w;  // pushed outwards by the specimen
    touching += sums[w].touching;
  }
  EXPECT_GT(touching, 150u);  // of the 6 x 64 boundary spheres' wall slots (two blocks of 256)
}

}  // namespace

TEST(WallRecord, IsTheSumOfItsContactsOnTheBatchedPathAtOneAndThreeThreads)
{
  expect_records_are_sums(test::linear_law(1e5, 0.5), true, 1, 1e5);
  expect_records_are_sums(test::linear_law(1e5, 0.5), true, 3, 1e5);
}

TEST(WallRecord, IsTheSumOfItsContactsOnTheScalarPathWithHertzMindlin)
{
  const HertzMindlin law(HertzNormal({1e8, 0.25, HertzNormal::Damping::restitution, 0.5, 0.0, true}),
                         MindlinTangential({1e8, 0.25, 1.0}));
  expect_records_are_sums(law, false, 2, 0.0);
}
