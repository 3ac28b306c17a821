// S4's floating upper box (dem/program/DirectShearBox.h): "the upper box is fixed
// horizontally and free vertically" (S4 section 3.2). Its equations of motion, and the
// lid's, are integrated by drive_box() and drive_lid():
//   m_lid dv_lid/dt = F_lid - P - W_lid         (the loaded lid, P = sigma_n L B)
//   m_B   dv_B/dt   = F_Bz  - W_B + R           (the box: sides, rim, skirts; R the seat/stop)
// so that the specimen carries F_N = P + W_P + W_B (S4 eq. 22). These tests check the
// physics on a 3 x 3 cm box of small clumps: at rest the lid and the box settle where
// their loads balance the grains' forces on them; during shear the upper box does not move
// horizontally while the lower box moves by U; and the specimen's dilation shows up as
// vertical lid motion that the upper grains follow.
#include "SmallShearBox.h"
#include "dem/program/DirectShearBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace geocomp::dem;

namespace {

// Mass-weighted mean height of the clumps listed in `which` [m].
double mean_height(const DemSystem& sys, const std::vector<std::size_t>& which)
{
  const ClumpSet& c = sys.clumps();
  double mz = 0.0, m = 0.0;
  for (std::size_t k : which) {
    mz += c.mass[k] * c.x[k].z();
    m += c.mass[k];
  }
  return mz / m;
}

struct FloatingRun
{
  DirectShearBox box;
  // At rest (after prepare): time means over the balance window.
  double lid_force_mean = 0.0, box_force_mean = 0.0, box_stop_mean = 0.0, lid_travel = 0.0;
  double box_stop_min = 1e300, box_rise_max = 0.0;  ///< seat reaction and |rise| over the window
  // Shear.
  std::vector<Vec3> upper_before, upper_after, lower_before, lower_after;
  std::vector<ShearRecord> curve;
  double upper_grains_rise = 0.0;  ///< rise of the grains above mid-gap at the shear start

  explicit FloatingRun(const DirectShearParameters& p) : box(p)
  {
    box.prepare();
    rest(4000);
    for (std::size_t w : box.upper_walls()) upper_before.push_back(box.system().wall(w).point);
    for (std::size_t w : box.lower_walls()) lower_before.push_back(box.system().wall(w).point);
    const DemSystem& sys = box.system();
    std::vector<std::size_t> upper;
    const double z_mid = p.half_height + 0.5 * box.gap();
    for (std::size_t k = 0; k < sys.n_clumps(); ++k)
      if (sys.clumps().x[k].z() > z_mid) upper.push_back(k);
    const double z0 = mean_height(sys, upper);
    curve = box.shear();
    upper_grains_rise = mean_height(sys, upper) - z0;
    for (std::size_t w : box.upper_walls()) upper_after.push_back(box.system().wall(w).point);
    for (std::size_t w : box.lower_walls()) lower_after.push_back(box.system().wall(w).point);
  }

  // The dynamics of the rest and the shear without shear: the lid and the box under their
  // loads; sums of the forces on them over every step.
  void rest(std::size_t steps)
  {
    DemSystem& sys = box.system();
    const double z0 = sys.wall(box.lid()).point.z();
    for (std::size_t s = 0; s < steps; ++s) {
      box.drive_lid();
      box.drive_box();
      sys.step();
      const ShearRecord r = box.measure(0.0);
      lid_force_mean += sys.wall(box.lid()).force.z();
      box_force_mean += r.box_vertical_force;
      box_stop_mean += r.box_stop_force;
      box_stop_min = std::min(box_stop_min, r.box_stop_force);
      box_rise_max = std::max(box_rise_max, std::abs(r.box_rise));
    }
    lid_force_mean /= double(steps);
    box_force_mean /= double(steps);
    box_stop_mean /= double(steps);
    lid_travel = sys.wall(box.lid()).point.z() - z0;
  }
};

FloatingRun& run()
{
  static FloatingRun r(geocomp::dem::test::small_shear_box(11));
  return r;
}

}  // namespace

// On a specimen at rest the loaded lid settles where the grains push it up with P (its
// weight W_lid = 0 here): m_lid dv/dt = F_lid - P has zero mean over the window up to the
// momentum change m_lid dv/T, tiny at rest, and the lid does not creep. The box at rest
// sits on its seat (the spacers at the set gap): the loaded specimen settles and drags its
// sides down (F_Bz < W_B, measured -3 N against W_B = 2 N), the seat pushes up only (R >= 0)
// and carries the rest, F_Bz + R = W_B, and the box does not move. (Off the seat, during
// shear, the specimen alone carries it: DirectShear.FreeUpperBoxIsCarriedBySpecimen...)
TEST(FloatingBox, LidOnARestingSpecimenSettlesWhereItsLoadBalancesTheGrainForcesAndTheBoxRestsOnItsSeat)
{
  FloatingRun& r = run();
  const double P = r.box.target_load(), W_B = 2.0;
  std::printf("[floating box] at rest: mean F_lid / P = %.5f (margin %.2e of 0.01), mean (F_Bz + R) / W_B = %.4f "
              "(margin %.2e of 0.05), F_Bz %.3f N, R %.3f N (min %.3f N), box rise %.2e m, lid travel %.3e m\n",
              r.lid_force_mean / P, 0.01 - std::abs(r.lid_force_mean / P - 1.0),
              (r.box_force_mean + r.box_stop_mean) / W_B,
              0.05 - std::abs((r.box_force_mean + r.box_stop_mean) / W_B - 1.0), r.box_force_mean, r.box_stop_mean, r.box_stop_min, r.box_rise_max,
              r.lid_travel);
  EXPECT_NEAR(r.lid_force_mean / P, 1.0, 0.01);
  EXPECT_NEAR((r.box_force_mean + r.box_stop_mean) / W_B, 1.0, 0.05);
  EXPECT_GE(r.box_stop_min, 0.0);   // a seat pushes, never pulls
  EXPECT_LT(r.box_rise_max, 1e-9);  // seated: the box stays at the set gap
  EXPECT_LT(std::abs(r.lid_travel), 0.01 * r.box.gap());  // at rest: no creep of the lid
}

// S4: "the upper box is fixed horizontally": its plates (lid, sides, rim, skirts) keep their
// x and y through the shear, while the lower box is carried by U = v t.
TEST(FloatingBox, UpperBoxDoesNotMoveHorizontallyWhileTheLowerBoxShears)
{
  FloatingRun& r = run();
  ASSERT_EQ(r.upper_before.size(), r.upper_after.size());
  for (std::size_t j = 0; j < r.upper_before.size(); ++j) {
    EXPECT_EQ(r.upper_after[j].x(), r.upper_before[j].x()) << "upper wall " << j;
    EXPECT_EQ(r.upper_after[j].y(), r.upper_before[j].y()) << "upper wall " << j;
  }
  const double U = r.curve.back().shear;
  EXPECT_NEAR(U, 0.003, 1e-6);
  for (std::size_t j = 0; j < r.lower_before.size(); ++j) {
    EXPECT_NEAR(r.lower_after[j].x() - r.lower_before[j].x(), U, 0.002 * U) << "lower wall " << j;
    EXPECT_EQ(r.lower_after[j].z(), r.lower_before[j].z()) << "lower wall " << j;  // fixed vertically
  }
  // And the box did move vertically: free on z, it rode up with the specimen.
  EXPECT_GT(r.curve.back().box_rise, 0.0);
}

// Contraction and dilation are the lid's vertical motion: the lid first goes down, then up,
// and the grains of the upper half (those above mid-gap at the start of shear) rise with it:
// their mean height changes by the lid's final rise within a third of it (the upper half
// rides on the shear zone as a block, the lid on top of it).
TEST(FloatingBox, ContractionAndDilationAppearAsVerticalLidMotionThatTheUpperGrainsFollow)
{
  FloatingRun& r = run();
  double lowest = 0.0;
  for (const ShearRecord& row : r.curve) lowest = std::min(lowest, row.lid_rise);
  const double final_rise = r.curve.back().lid_rise;
  std::printf("[floating box] lid lowest %.4f mm, final %.4f mm, upper grains' rise %.4f mm (ratio %.3f)\n",
              1e3 * lowest, 1e3 * final_rise, 1e3 * r.upper_grains_rise, r.upper_grains_rise / final_rise);
  EXPECT_LT(lowest, 0.0);      // contraction: the lid went down first
  EXPECT_GT(final_rise, 0.0);  // then dilation: it ends above its start
  EXPECT_NEAR(r.upper_grains_rise / final_rise, 1.0, 1.0 / 3.0);
  for (const ShearRecord& row : r.curve) EXPECT_GT(row.normal_force, 0.0);  // the lid stays on the grains
}
