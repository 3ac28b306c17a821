// The Rudnicki-Rice prediction evaluated along a material-point path agrees with the
// acoustic-tensor onset of the same path when the model is the Drucker-Prager cone the
// prediction is built on: then the theory is exact and only sampling separates the two.
#include "common/ProgramRunner.h"
#include "compare/LocalizationOnsets.h"
#include "continuum/driver/MaterialPointEngine.h"
#include "continuum/models/RudnickiRice.h"
#include "compare/Verdict.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace geocomp;

namespace {
LoadingProgram isochoric(double rate, double interval)
{
  LoadingProgram p;
  p.sample_interval = interval;
  Stage s;
  s.name = "shear";
  s.isochoric = true;
  s.lambda = 0.0;
  s.isochoric_rate = rate;
  s.stop_any = {parse_condition("gamma_max >= 0.08", "test")};
  s.max_duration = 100;
  p.stages = {s};
  return p;
}
} // namespace

namespace {
/// Drucker-Prager cone matched to c, phi, psi with cohesion softening from 50 kPa at
/// kappa = 0.01 to 5 kPa at `kappa_end`.
continuum::MaterialParameters softening_cone(double psi_deg, double kappa_end = 0.05)
{
  continuum::MaterialParameters m;
  m.model = "drucker-prager";
  m.mohr_coulomb.youngs_modulus = 300e6;
  m.mohr_coulomb.poisson_ratio = 0.25;
  m.mohr_coulomb.cohesion = continuum::PiecewiseLinear(std::vector<std::pair<double, double>>{{0.0, 50e3}, {0.01, 50e3}, {kappa_end, 5e3}});
  m.mohr_coulomb.friction_angle = continuum::PiecewiseLinear(std::vector<std::pair<double, double>>{{0.0, 25 * M_PI / 180}, {0.05, 25 * M_PI / 180}});
  m.mohr_coulomb.dilatancy_angle = continuum::PiecewiseLinear(psi_deg * M_PI / 180);
  m.drucker_prager_matching = continuum::DruckerPragerMatching::outer_cone;
  return m;
}
} // namespace

TEST(RudnickiRiceAlongPath, MatchesAcousticTensorOnsetOfDruckerPragerPath)
{
  for (const double psi : {5.0, 15.0}) {
  const continuum::MaterialParameters m = softening_cone(psi, psi > 10 ? 0.02 : 0.05);
  continuum::MaterialPointParameters mp;
  mp.initial_stress = -2e6;
  continuum::MaterialPointEngine engine(m, mp);
  const LoadingProgram program = isochoric(0.1, 0.002);
  const Response r = ProgramRunner(program, engine).run();
  const auto kind = compare::CurveKind::ShearIsochoric;
  const compare::OnsetEstimate theory =
    compare::rudnicki_rice_onset(r, m.mohr_coulomb, m.drucker_prager_matching, compare::KappaMeasure::shear_strain, kind);
  const compare::OnsetEstimate scan = compare::acoustic_tensor_onset(r, "material point", kind);
  ASSERT_TRUE(theory.found) << theory.note << " psi " << psi;
  ASSERT_TRUE(scan.found) << scan.note;
  const double per_sample = 2 * 0.1 * 0.002 * 1.05; // gamma_max per sample, with margin
  EXPECT_NEAR(theory.strain, scan.strain, per_sample) << "psi " << psi;
  EXPECT_NEAR(theory.angle_deg, scan.angle_deg, 1.0) << "psi " << psi;
  }
}

TEST(RudnickiRiceAlongPath, DruckerPragerKappaIsNotRescaledByTheMohrCoulombFactor)
{
  // A Drucker-Prager kappa is Rudnicki and Rice's gamma^p itself, so h = dY/dkappa (omega
  // constant); a Mohr-Coulomb kappa is gamma^p / f(psi). Synthetic plastic samples at
  // constant softening h sweep the deviatoric state N, so h_cr(N) (the closed form of
  // RudnickiRice.h) rises through h gradually and the onset is the first N where
  // h <= h_cr: with the model's own measure at h, with the Mohr-Coulomb factor at h / f.
  const continuum::MaterialParameters m = softening_cone(20.0);
  const auto &mc = m.mohr_coulomb;
  const double G = mc.youngs_modulus / (2 * (1 + mc.poisson_ratio)), p = -2e6, tau = 0.5e6;
  const auto match = continuum::match_mohr_coulomb(mc.friction_angle(0.02), mc.dilatancy_angle(0.02),
                                                   m.drucker_prager_matching);
  const double h = match.y_over_c * (5e3 - 50e3) / (0.05 - 0.01); // dY/dkappa on the softening segment
  const continuum::RudnickiRiceMaterial rr{3 * match.omega, match.lambda, mc.poisson_ratio};
  Response r;
  r.engine = "synthetic";
  r.extras = {{"kappa", "1", ""}, {"state_flag", "1", ""}};
  const int n = 4000;
  auto N_of = [&](int i) { return -0.57 + 0.5 * i / n; };
  for (int i = 0; i <= n; ++i) {
    // Principal deviator (s_I, N tau, s_III): s_I + s_III = -N tau, J2 = tau^2.
    const double N = N_of(i), root = std::sqrt(4 - 3 * N * N);
    ResponseSample s;
    s.time = i;
    s.stress = Vector3(p + tau * (-N + root) / 2, p + N * tau, p + tau * (-N - root) / 2).asDiagonal();
    ASSERT_NEAR(continuum::deviatoric_state(s.stress), N, 1e-9);
    s.strain = Vector3(std::expm1(-1e-5 * i), 0.0, std::expm1(1e-5 * i)).asDiagonal(); // gamma_max = 2e-5 i
    s.extras = {0.02 + 1e-6 * i, 1.0};
    r.samples.push_back(s);
  }
  auto expected = [&](double h_used) { // first sample with h <= h_cr, as a gamma_max
    for (int i = 0; i <= n; ++i)
      if (h_used / G - continuum::rudnicki_rice_prediction(rr, N_of(i)).critical_hardening_over_G <= 0)
        return 2e-5 * i;
    return -1.0;
  };
  // f = gamma^p / kappa on the Mohr-Coulomb main plane: plastic strain rates
  // (1 + sin psi, 0, -(1 - sin psi)) per unit kappa / 2, gamma^p = sqrt(2 e^p:e^p).
  const double sp = std::sin(mc.dilatancy_angle(0.02));
  const Vector3 ep(1 + sp, 0, -(1 - sp));
  const double f = std::sqrt(2 * (ep - Vector3::Constant(ep.sum() / 3)).squaredNorm()) / 2;
  const auto kind = compare::CurveKind::ShearIsochoric;
  const compare::OnsetEstimate own =
    compare::rudnicki_rice_onset(r, mc, m.drucker_prager_matching, compare::KappaMeasure::shear_strain, kind);
  const compare::OnsetEstimate rescaled =
    compare::rudnicki_rice_onset(r, mc, m.drucker_prager_matching, compare::KappaMeasure::mohr_coulomb, kind);
  ASSERT_TRUE(own.found && rescaled.found);
  ASSERT_GT(expected(h), 0.0);
  EXPECT_NEAR(own.strain, expected(h), 2e-5);        // within the sample it crosses in
  EXPECT_NEAR(rescaled.strain, expected(h / f), 2e-5);
  EXPECT_GT(std::abs(own.strain - rescaled.strain), 5 * 2e-5); // the two measures are told apart
  std::printf("onset gamma_max: DP measure %.5f (expected %.5f), rescaled by f %.5f (expected %.5f)\n", own.strain,
              expected(h), rescaled.strain, expected(h / f));
}

TEST(RudnickiRiceAlongPath, SnapBackIsFollowedPastTheOnsetAndTheVerdictNamesIt)
{
  // Drucker-Prager cone, cohesion hardening to 120 kPa at kappa = 0.002, then a drop to
  // 10 kPa within 0.005 (|h| ~ 0.9 G): under triaxial compression at 100 kPa lateral stress
  // the homogeneous path reaches a maximum of the axial strain there. Under the program's
  // strain control no increment has a solution (the driver once stopped with exit 1 and no
  // file); plastic-strain control follows the path back, the program resumes where it has a
  // solution again, and the Rudnicki-Rice onset at the start of softening is on the record.
  continuum::MaterialParameters m;
  m.model = "drucker-prager";
  m.mohr_coulomb.youngs_modulus = 100e6;
  m.mohr_coulomb.poisson_ratio = 0.25;
  m.mohr_coulomb.cohesion = continuum::PiecewiseLinear(
    std::vector<std::pair<double, double>>{{0.0, 100e3}, {0.002, 120e3}, {0.007, 10e3}});
  m.mohr_coulomb.friction_angle = continuum::PiecewiseLinear(30 * M_PI / 180);
  m.mohr_coulomb.dilatancy_angle = continuum::PiecewiseLinear(5 * M_PI / 180);
  continuum::MaterialPointParameters mp;
  mp.initial_stress = -100e3;
  continuum::MaterialPointEngine engine(m, mp);
  LoadingProgram p;
  p.sample_interval = 0.05;
  Stage s;
  s.name = "triaxial";
  s.axes = {{AxisDrive::stress(-100e3), AxisDrive::stress(-100e3), AxisDrive::rate(-1e-3)}};
  s.stop_any = {parse_condition("eps_zz <= -0.02", "test")};
  s.max_duration = 100;
  p.stages = {s};
  const Response r = ProgramRunner(p, engine).run();
  ASSERT_EQ(r.stage_end_reasons[0], "eps_zz <= -0.02");
  // Samples under plastic-strain control, along which the axial strain went back.
  const int control = r.extra_index("control");
  int controlled = 0;
  double deepest = 0.0, backed = 0.0;
  for (const auto &x : r.samples) {
    deepest = std::min(deepest, x.strain(2, 2));
    if (x.extras[control] == 1.0) {
      ++controlled;
      backed = std::max(backed, x.strain(2, 2) - deepest);
    }
  }
  EXPECT_GT(controlled, 10);
  EXPECT_GT(backed, 1e-4);
  const auto kind = compare::CurveKind::AxialLateral;
  const compare::AxialAxis axis = *compare::axial_axis_for(p);
  const compare::OnsetEstimate theory = compare::rudnicki_rice_onset(
    r, m.mohr_coulomb, m.drucker_prager_matching, compare::KappaMeasure::shear_strain, kind, -1, axis);
  const compare::OnsetEstimate scan = compare::acoustic_tensor_onset(r, "material point", kind, -1, axis);
  ASSERT_TRUE(theory.found) << theory.note;
  ASSERT_TRUE(scan.found) << scan.note;
  const compare::RrVerdict v = compare::rudnicki_rice_verdict(theory, {scan});
  ASSERT_EQ(v.rows.size(), 1u);
  EXPECT_TRUE(v.rows[0].comparable);
  EXPECT_EQ(v.rows[0].verdict, "agrees") << v.summary;
  std::printf("snap-back: %d samples under plastic-strain control, axial strain back by %.2e; onset %.5f "
              "(theory) %.5f (acoustic tensor): %s\n",
              controlled, backed, theory.strain, scan.strain, v.summary.c_str());
}
