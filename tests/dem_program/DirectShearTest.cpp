// S4's direct shear box (dem/program/DirectShearBox.h) on a small box: the S4 eq. (22)-(24)
// bookkeeping against the wall forces, the corrected area, the lid servo, and a short
// shear run that first contracts and then dilates.
#include "dem/program/DirectShearBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace geocomp::dem;

namespace {

// A 3 x 3 cm box with grains of 1/8 of S4's mass (half the size), so that ~200 clumps
// fill it; modulus scaled by 1/100 (S4's rubble modulus is 58.54 GPa).
DirectShearParameters small_box()
{
  DirectShearParameters p;
  p.length = p.width = 0.03;
  p.half_height = 0.009;
  p.clumps.log_mass_mean -= std::log(8.0);
  p.clumps.mass_min /= 8.0;
  p.clumps.mass_max /= 8.0;
  p.modulus_scale = 0.01;
  p.normal_stress = 100e3;
  p.shear_speed = 0.05;
  p.max_shear = 0.003;
  p.output_points = 30;
  p.growth_stages = 8;
  p.settle_steps = 600;
  p.load_max_time = 0.05;
  p.seed = 7;
  return p;
}

struct Prepared
{
  DirectShearBox box;
  explicit Prepared(const DirectShearParameters& p) : box(p) { box.prepare(); }
};

Prepared& prepared()
{
  static Prepared s(small_box());
  return s;
}

}  // namespace

TEST(DirectShear, CorrectedAreaIsBTimesLMinusU)
{
  EXPECT_DOUBLE_EQ(corrected_area(0.1, 0.1, 0.0), 0.01);            // S4 eq. (23)
  EXPECT_DOUBLE_EQ(corrected_area(0.1, 0.08, 0.015), 0.08 * 0.085);
}

TEST(DirectShear, ServoHoldsTheNormalStressAfterLoading)
{
  DirectShearBox& box = prepared().box;
  const double P = box.system().wall(box.lid()).force.z();
  EXPECT_NEAR(P / box.target_load(), 1.0, 0.05);
  EXPECT_GT(box.system().n_clumps(), 100u);
}

TEST(DirectShear, ForceAccountingMatchesTheWallForces)
{
  DirectShearBox& box = prepared().box;
  const DemSystem& sys = box.system();
  const ShearRecord r = box.measure(0.001);
  // S4 eq. (22): the lid and the four sides (N_wall = 5); the rim (last) is not in F_S.
  const auto& up = box.upper_walls();
  ASSERT_EQ(up.size(), 6u);
  double fs = 0.0;
  for (std::size_t j = 0; j < 5; ++j) fs += sys.wall(up[j]).force.x();
  // Independently: the x forces of the wall contacts of the upper walls (ContactRecord
  // holds the force on the particle; the wall receives the opposite).
  double fs_contacts = 0.0, fn_contacts = 0.0;
  for (const ContactRecord& c : sys.contacts()) {
    if (!c.wall) continue;
    if (std::find(up.begin(), up.end() - 1, std::size_t(c.i)) != up.end() - 1) fs_contacts -= c.force.x();
    if (c.i == box.lid()) fn_contacts -= c.force.z();
  }
  EXPECT_DOUBLE_EQ(r.shear_force, fs);
  EXPECT_NEAR(r.shear_force, fs_contacts, 1e-9 * (1.0 + std::abs(fn_contacts)));
  EXPECT_NEAR(r.normal_force, fn_contacts, 1e-9 * fn_contacts);
  EXPECT_DOUBLE_EQ(r.area, 0.03 * (0.03 - 0.001));
  EXPECT_DOUBLE_EQ(r.sigma_z, r.normal_force / r.area);
  EXPECT_DOUBLE_EQ(r.tau_x, r.shear_force / r.area);
  EXPECT_DOUBLE_EQ(r.mu_b, r.shear_force / r.normal_force);
}

TEST(DirectShear, ShortShearContractsThenDilates)
{
  DirectShearBox& box = prepared().box;
  const std::vector<ShearRecord> curve = box.shear();
  const ShearSummary s = box.summary(curve);
  ASSERT_GT(curve.size(), 10u);
  EXPECT_GT(s.max_contraction, 0.0);                           // the lid first goes down
  EXPECT_GT(curve.back().lid_rise, -s.max_contraction);        // then comes back up
  EXPECT_GT(s.peak_mu_b, 0.2);
  EXPECT_LT(s.inertial_number, 1e-3);
  for (const ShearRecord& r : curve) EXPECT_NEAR(r.sigma_z * r.area, r.normal_force, 1e-9 * r.normal_force);
}

// S4's normal-stress trends (section 3.3, Fig. 5 and 7a) on one dense specimen (seated
// without friction, S4's vibration compaction, then loaded): sheared at 100 and 300 kPa,
// it first contracts more and then dilates less at 300 kPa, and its effective friction
// mu_b (S4 eq. 24) peaks lower there.
TEST(DirectShear, LowNormalStressDilatesMoreContractsLessAndHasHigherMuB)
{
  auto run = [](double normal_stress) {
    DirectShearParameters p = small_box();
    p.normal_stress = normal_stress;
    DirectShearBox box(p);
    box.prepare();
    return box.summary(box.shear());
  };
  const ShearSummary lo = run(100e3), hi = run(300e3);
  // The same seated specimen for both loads, denser than a frictional growth (e ~ 1.0 in
  // the S4 cases, a loose specimen that only contracts; S4: e = 0.46).
  EXPECT_DOUBLE_EQ(lo.void_ratio_seated, hi.void_ratio_seated);
  EXPECT_LT(lo.void_ratio_seated, 0.9);
  // At rest under sigma_n before the shear.
  EXPECT_LT(lo.rest_kinetic_ratio, 1e-4);
  EXPECT_LT(hi.rest_kinetic_ratio, 1e-4);
  EXPECT_GT(hi.max_contraction, lo.max_contraction);  // contraction grows with the load
  EXPECT_GT(hi.final_dilation, 0.0);                   // net dilation at both loads
  EXPECT_GT(lo.final_dilation, hi.final_dilation);     // more dilation at low load
  EXPECT_GT(lo.peak_mu_b, hi.peak_mu_b);               // mu_b falls with normal stress
  EXPECT_LT(hi.inertial_number, lo.inertial_number);
  EXPECT_LT(lo.inertial_number, 1e-3);
}
