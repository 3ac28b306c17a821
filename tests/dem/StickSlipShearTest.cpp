// S3's anchor-spring friction (S3 eq. (9)) in a wall shear, where its saw-tooth has a closed
// form: a sphere held in place pressed by a plane wall (normal force F_n = k_n delta0), the wall
// dragged tangentially at a constant speed. The friction force on the wall rises as
// mu F_n xi / delta*_tau with the anchor spring xi; at xi = delta*_tau the anchors are
// re-placed at k_phi delta*_tau. With k_phi = 0 the force drops to zero once every
// delta*_tau of travel (stick-slip); with k_phi = 1 it stays at mu F_n (Coulomb sliding).
// In a sheared packing the contacts slip out of step and the saw-tooth averages out
// (docs/s3-bonded.md); this is the single contact's, in a loaded system.
#include "dem/DemSystem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace geocomp::dem;

namespace {
constexpr double kR = 0.005, kKn = 5e6, kDelta0 = 1e-6, kMu = 0.5, kSlip = 2e-6;

struct Drag {
  double peak = 0.0;  ///< largest friction force on the wall [N]
  int drops = 0;      ///< steps at which it fell by more than half of mu F_n
  double last = 0.0;  ///< at the end
};

/// Drags the top wall over `travel` along x; friction force = |F_x| on the wall.
Drag drag(double retention, double travel)
{
  DemSystem sys;
  sys.set_contact_model(S3Soil(LinearNormal::with_stiffness(kKn, 1.0), StickSlipTangential({kSlip, retention}),
                               LinearRolling({0.0, 1.0}), S3Bonding()));
  sys.add_box(Vec3(-0.1, -0.1, -0.1), Vec3(0.1, 0.1, kR - kDelta0), kMu);  // z+ wall (5) presses the sphere
  sys.add_sphere(Vec3::Zero(), kR, 1e15);  // so heavy that it stays where it is
  sys.set_time_step(1e-6);
  const double v = 1e-3;  // 1 nm per step: 2 000 steps per delta*_tau
  sys.set_wall_velocity(5, Vec3(v, 0.0, 0.0));
  const double limit = kMu * kKn * kDelta0;
  Drag d;
  double previous = 0.0;
  for (double x = 0.0; x < travel; x += v * sys.time_step()) {
    sys.step();
    const double f = std::abs(sys.wall(5).force.x());
    d.drops += f < previous - 0.5 * limit ? 1 : 0;
    d.peak = std::max(d.peak, f);
    previous = f;
  }
  d.last = previous;
  return d;
}
}  // namespace

TEST(StickSlipShear, KPhiZeroDropsTheFrictionToZeroOnceEverySlipDisplacement)
{
  const double limit = kMu * kKn * kDelta0;
  const Drag d = drag(0.0, 10.5 * kSlip);
  EXPECT_NEAR(d.peak, limit, 0.01 * limit) << "the spring reaches the Coulomb limit before it slips";
  EXPECT_EQ(d.drops, 10) << "one drop per delta*_tau of travel";
}

TEST(StickSlipShear, KPhiOneSlidesAtTheCoulombLimitWithoutDrops)
{
  const double limit = kMu * kKn * kDelta0;
  const Drag d = drag(1.0, 10.5 * kSlip);
  EXPECT_EQ(d.drops, 0);
  EXPECT_NEAR(d.last, limit, 0.01 * limit);
}
