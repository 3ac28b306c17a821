// S4's direct shear box (dem/program/DirectShearBox.h) on a small box: the S4 eq. (22)-(24)
// bookkeeping against the wall forces, the corrected area, the lid servo, a short shear
// run that first contracts and then dilates, and the free upper box carried by the
// specimen (its side friction bounded by its weight, F_N = P + W_P + W_B).
#include "SmallShearBox.h"
#include "dem/program/DirectShearBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

using namespace geocomp::dem;

namespace {

DirectShearParameters small_box() { return geocomp::dem::test::small_shear_box(7); }

struct Prepared
{
  DirectShearBox box;
  std::vector<ShearRecord> curve;  ///< filled by sheared()
  explicit Prepared(const DirectShearParameters& p) : box(p) { box.prepare(); }
};

Prepared& prepared()
{
  static Prepared s(small_box());
  return s;
}

// The fixture's specimen sheared 3 mm (once, shared by the tests of the shear).
Prepared& sheared()
{
  Prepared& s = prepared();
  if (s.curve.empty()) s.curve = s.box.shear();
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
  ASSERT_EQ(up.size(), 9u);  // lid, four sides, rim, three skirts
  double fs = 0.0;
  for (std::size_t j = 0; j < 5; ++j) fs += sys.wall(up[j]).force.x();
  // Independently: the forces of the wall contacts of the upper walls (ContactRecord holds
  // the force on the particle; the wall receives the opposite).
  double fs_contacts = 0.0, lid_contacts = 0.0, box_contacts = 0.0;
  for (const ContactRecord& c : sys.contacts()) {
    if (!c.wall) continue;
    const auto at = std::find(up.begin(), up.end(), std::size_t(c.i));
    if (at == up.end()) continue;
    if (at - up.begin() < 5) fs_contacts -= c.force.x();
    if (at == up.begin()) lid_contacts -= c.force.z();
    else box_contacts -= c.force.z();
  }
  const double W_B = 2.0;
  EXPECT_DOUBLE_EQ(r.shear_force, fs);
  EXPECT_NEAR(r.shear_force, fs_contacts, 1e-9 * (1.0 + std::abs(lid_contacts)));
  // S4 eq. (22): F_N = P + W_P + W_B with P the lid's force and W_P the upper grains' weight.
  EXPECT_GT(r.grain_weight, 0.0);
  EXPECT_LT(r.grain_weight, 0.03 * 0.03 * 0.018 * 2550.0 * 9.81);  // below the box full of rock
  EXPECT_NEAR(r.normal_force, lid_contacts + r.grain_weight + W_B, 1e-9 * lid_contacts);
  EXPECT_NEAR(r.box_vertical_force, box_contacts, 1e-9 * (1.0 + std::abs(lid_contacts)));
  EXPECT_DOUBLE_EQ(r.area, 0.03 * (0.03 - 0.001));
  EXPECT_DOUBLE_EQ(r.sigma_z, r.normal_force / r.area);
  EXPECT_DOUBLE_EQ(r.tau_x, r.shear_force / r.area);
  EXPECT_DOUBLE_EQ(r.mu_b, r.shear_force / r.normal_force);
}

TEST(DirectShear, ShortShearContractsThenDilates)
{
  Prepared& sh = sheared();
  const std::vector<ShearRecord>& curve = sh.curve;
  const ShearSummary s = sh.box.summary(curve);
  ASSERT_GT(curve.size(), 10u);
  EXPECT_GT(s.max_contraction, 0.0);                           // the lid first goes down
  EXPECT_GT(curve.back().lid_rise, -s.max_contraction);        // then comes back up
  EXPECT_GT(s.peak_mu_b, 0.2);
  EXPECT_LT(s.inertial_number, 1e-3);
  for (const ShearRecord& r : curve) EXPECT_NEAR(r.sigma_z * r.area, r.normal_force, 1e-9 * r.normal_force);
}

// S4: the upper box is fixed horizontally and free vertically, so the specimen carries its
// weight and F_N = P + W_P + W_B (eq. 22). The box (m_B dv/dt = F_Bz - W_B + R, R the seat's
// or top stop's reaction) is carried by the specimen through the side friction F_Bz: over the
// shear its mean equals W_B - mean(R) + m_B (v_end - v_0)/T, so it cannot press the dilating
// specimen down by more than its weight (the former fixed box did so with 0.6-0.8 F_N); the
// box rises with the dilating specimen, and the skirts keep the grains in the opened gap.
TEST(DirectShear, FreeUpperBoxIsCarriedBySpecimenAndBoundsTheSideFriction)
{
  Prepared& sh = sheared();
  const ShearSummary s = sh.box.summary(sh.curve);
  const double W_B = 2.0, P = sh.box.target_load();
  RecordProperty("box_force_mean_N", std::to_string(s.box_force_mean));
  RecordProperty("box_force_max_row_N", std::to_string(s.box_force_max));
  RecordProperty("box_rise_final_m", std::to_string(s.box_rise_final));
  RecordProperty("lid_rise_final_m", std::to_string(s.final_dilation));
  RecordProperty("box_seated_share", std::to_string(s.box_seated_share));
  ASSERT_GT(s.box_force_mean, 0.0);
  EXPECT_EQ(s.box_top_share, 0.0);                       // never held by the top stop
  EXPECT_LT(s.box_seated_share, 0.5);                    // mostly off its seat: carried
  // Side friction bounded by W_B: mean F_Bz + mean R = W_B + m_B v_end / T, the box rising at
  // most at the shear speed (a dilation rate below 1), T = 3 mm / 0.05 m/s.
  const double momentum = 0.2 * 0.05 / (0.003 / 0.05);
  EXPECT_LT(s.box_force_mean, W_B * 1.05 + momentum);
  EXPECT_GT(s.box_force_mean + s.box_stop_mean, 0.95 * W_B);
  EXPECT_LT(s.box_force_max, W_B + 0.2 * P);             // every row: far below the fixed box's
  EXPECT_GT(s.box_rise_final, 0.5 * s.final_dilation);   // it rides up with the specimen
  EXPECT_EQ(s.escaped, 0u);                              // no grain lost through the gap
  // The vertical load of the walls on the specimen (lid + box plates, from the wall forces)
  // plus W_P is F_N = P + W_P + W_B on average over the shear.
  double load = 0.0, fn = 0.0;
  for (const ShearRecord& r : sh.curve) {
    load += r.normal_force - W_B + r.box_vertical_force;
    fn += P + r.grain_weight + W_B;
  }
  RecordProperty("load_over_F_N", std::to_string(load / fn));
  EXPECT_NEAR(load / fn, 1.0, 0.05);
}

// One seed of the small box at a normal stress and contact friction, prepared and sheared.
ShearSummary shear_run(std::uint64_t seed, double normal_stress, double mu_contact)
{
  DirectShearParameters p = geocomp::dem::test::small_shear_box(seed);
  p.normal_stress = normal_stress;
  p.mu_contact = mu_contact;
  DirectShearBox box(p);
  box.prepare();
  return box.summary(box.shear());
}

// The seeds every trend is checked over (not one lucky seed): each trend must hold for each.
constexpr std::uint64_t trend_seeds[] = {7, 8, 9};

// S4's normal-stress trends (section 3.3, Fig. 5 and 7a) on dense specimens (seated
// without friction, S4's vibration compaction, then loaded): the same specimen sheared at
// 100 and 300 kPa first contracts more and then dilates less at 300 kPa, and its effective
// friction mu_b (S4 eq. 24) peaks lower there. Checked for each of three seeds; the
// margins (the difference that must stay positive) are printed.
TEST(DirectShear, OverThreeSeedsLowNormalStressDilatesMoreContractsLessAndHasHigherMuB)
{
  for (std::uint64_t seed : trend_seeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const ShearSummary lo = shear_run(seed, 100e3, 0.7), hi = shear_run(seed, 300e3, 0.7);
    std::printf("[S4 trends, seed %llu] contraction 300 - 100 kPa %+.4f mm, dilation 100 - 300 kPa %+.4f mm "
                "(final %.4f / %.4f mm), peak mu_b 100 - 300 kPa %+.3f (%.3f / %.3f)\n",
                (unsigned long long)seed, 1e3 * (hi.max_contraction - lo.max_contraction),
                1e3 * (lo.final_dilation - hi.final_dilation), 1e3 * lo.final_dilation, 1e3 * hi.final_dilation,
                lo.peak_mu_b - hi.peak_mu_b, lo.peak_mu_b, hi.peak_mu_b);
    // The same seated specimen for both loads, denser than a frictional growth (e ~ 1.0).
    EXPECT_DOUBLE_EQ(lo.void_ratio_seated, hi.void_ratio_seated);
    EXPECT_LT(lo.void_ratio_seated, 0.9);
    EXPECT_LT(lo.rest_kinetic_ratio, 1e-4);  // at rest under sigma_n before the shear
    EXPECT_LT(hi.rest_kinetic_ratio, 1e-4);
    EXPECT_GT(hi.max_contraction, lo.max_contraction);  // contraction grows with the load
    EXPECT_GT(hi.final_dilation, 0.0);                   // net dilation at both loads
    EXPECT_GT(lo.final_dilation, hi.final_dilation);     // more dilation at low load
    EXPECT_GT(lo.peak_mu_b, hi.peak_mu_b);               // mu_b falls with normal stress
    EXPECT_LT(hi.inertial_number, lo.inertial_number);
    EXPECT_LT(lo.inertial_number, 1e-3);
  }
}

// S4 Fig. 7(b): the effective friction rises with the contact friction. The same specimen
// (the preparation is frictionless up to the seating, so it does not depend on the contact
// friction) sheared at 100 kPa with contact friction 0.3 and 1.0 peaks higher at 1.0, for
// each of three seeds; margins printed.
TEST(DirectShear, OverThreeSeedsPeakMuBRisesWithTheContactFriction)
{
  for (std::uint64_t seed : trend_seeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const ShearSummary lo = shear_run(seed, 100e3, 0.3), hi = shear_run(seed, 100e3, 1.0);
    std::printf("[S4 friction, seed %llu] peak mu_b at contact mu 1.0 - 0.3: %+.3f (%.3f / %.3f)\n",
                (unsigned long long)seed, hi.peak_mu_b - lo.peak_mu_b, hi.peak_mu_b, lo.peak_mu_b);
    EXPECT_DOUBLE_EQ(lo.void_ratio_seated, hi.void_ratio_seated);
    EXPECT_GT(hi.peak_mu_b, lo.peak_mu_b);
  }
}
