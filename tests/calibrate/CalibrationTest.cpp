// Calibration over the material point: curves made by the driver with known parameters
// are recovered (exactly without noise, to 1 % with noise; psi from the mean stress of
// isochoric shear), the closed-form starting values land near the truth (E and nu exactly
// from an unloading branch), and a target that cannot identify a parameter names it.
#include "compare/calibrate/Calibration.h"
#include "compare/calibrate/FitReport.h"
#include "compare/calibrate/StartingValues.h"
#include "continuum/driver/CaseMaterial.h"
#include "tests/calibrate/SyntheticTargets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

using namespace geocomp;
using namespace geocomp::calibration;
using namespace geocomp::calibration::synthetic;

namespace {
/// Isochoric shear to gamma_max = 0.2 %: elastic for the truth (yield near 0.3 %).
LoadingProgram isochoric()
{
  LoadingProgram program;
  program.sample_interval = 0.0001;
  Stage s;
  s.name = "isochoric";
  s.isochoric = true;
  s.lambda = 0.0;
  s.isochoric_rate = 1.0;
  s.stop_any = {parse_condition("gamma_max >= 0.002", "test")};
  s.max_duration = 1.0;
  program.stages = {s};
  return program;
}

/// Isochoric shear (S0 eq. (3), lambda = 0) past yield, to gamma_max = 3 %.
LoadingProgram isochoric_past_yield()
{
  LoadingProgram program = isochoric();
  program.sample_interval = 0.0005;
  program.stages[0].stop_any = {parse_condition("gamma_max >= 0.03", "test")};
  return program;
}

std::vector<FitTarget> three_confinements(double noise)
{
  return {made_target(axial(1e5), 1e5, noise, 1), made_target(axial(2e5), 2e5, noise, 2),
          made_target(axial(4e5), 4e5, noise, 3)};
}

CalibrationParameters free_five()
{
  CalibrationParameters c;
  c.free_parameters = {"E", "nu", "cohesion", "friction[1]", "dilatancy[1]"};
  c.starting_values = "case";
  return c;
}

ContinuumParameters perturbed()
{
  ContinuumParameters p = truth();
  p.youngs_modulus *= 1.3;
  p.poisson_ratio = 0.22;
  p.cohesion.points[0].second = 10e3;
  p.friction_angle.points[1].second = 28.0;
  p.dilatancy_angle.points[1].second = 3.0;
  return p;
}
} // namespace

TEST(CalibrationRoundTrip, RecoversFiveParametersFromThreeCurvesWithoutNoise)
{
  const auto targets = three_confinements(0.0);
  const CalibrationResult r = calibrate(perturbed(), targets, free_five());
  const std::vector<double> expected = {80e6, 0.3, 30e3, 32.0, 8.0};
  ASSERT_EQ(r.value.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(r.value[i] / expected[i], 1.0, 1e-6) << r.parameters[i].name;
  EXPECT_LT(r.final_cost, 1e-12 * r.initial_cost);
  std::printf("[calibration] noise-free: %d iterations, %.2f s, cost %.3g -> %.3g\n", r.iterations, r.seconds,
              r.initial_cost, r.final_cost);
}

TEST(CalibrationRoundTrip, AKnotThatStartsOnItsBoundIsFittedNotRefused)
{
  // The truth's dilatancy is 0 at kappa = 0, the lower bound: the differences of a Jacobian
  // there must not step outside the bounds (central ones did: "the material point fails at
  // the starting values", then "Residual and Jacobian evaluation failed" where a fit ended).
  CalibrationParameters c = free_five();
  c.free_parameters = {"dilatancy"};
  ContinuumParameters start = truth();
  start.dilatancy_angle.points[1].second = 3.0;
  ASSERT_EQ(start.dilatancy_angle.points[0].second, 0.0);
  const CalibrationResult r = calibrate(start, three_confinements(0.0), c);
  const std::vector<double> expected = {0.0, 8.0};
  ASSERT_EQ(r.value.size(), expected.size());
  // The knot ends on (or within round-off of) its bound, differentiated one-sidedly there.
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(r.value[i], expected[i], expected[i] == 0.0 ? 1e-4 : 1e-5 * std::abs(expected[i]))
      << r.parameters[i].name;
}

TEST(CalibrationRoundTrip, AFreeDilatancyStopsAtTheFrictionAngleWhereTheCurvesAskForMore)
{
  // Curves whose dilatancy (30 deg) the fitted section's friction table cannot hold: phi falls
  // to 27 deg at kappa = 0.08 there. Mohr-Coulomb needs psi <= phi at every kappa, so the fit
  // ends at psi = 27 deg (steps past it refused, the trust region shrinks), never past it -
  // where the case reader would refuse the calibrated section.
  ContinuumParameters made = truth();
  made.friction_angle.points = {{0.0, 20.0}, {0.02, 32.0}, {0.08, 35.0}};
  made.dilatancy_angle.points = {{0.0, 0.0}, {0.02, 30.0}};
  const std::vector<FitTarget> targets = {made_target(axial(1e5), 1e5, 0.0, 1, made),
                                          made_target(axial(4e5), 4e5, 0.0, 3, made)};
  CalibrationParameters c = free_five();
  c.free_parameters = {"dilatancy[1]"};
  ContinuumParameters start = truth(); // phi: 20, 32, 27 deg at kappa 0, 0.02, 0.08
  start.dilatancy_angle.points[1].second = 10.0;
  const CalibrationResult r = calibrate(start, targets, c);
  ASSERT_EQ(r.value.size(), 1u);
  EXPECT_LE(r.value[0], 27.0 + 1e-9);
  EXPECT_GT(r.value[0], 26.0) << "the curves pull psi up to the friction angle";
  EXPECT_NO_THROW(continuum::material_from_case(r.calibrated));
  std::printf("[calibration] psi capped by phi: %.6f deg after %d iterations\n", r.value[0], r.iterations);
}

TEST(CalibrationRoundTrip, RecoversFiveParametersToOnePercentWithNoise)
{
  const auto targets = three_confinements(0.002);
  const CalibrationResult r = calibrate(perturbed(), targets, free_five());
  const std::vector<double> expected = {80e6, 0.3, 30e3, 32.0, 8.0};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(r.value[i] / expected[i], 1.0, 0.01) << r.parameters[i].name;
    // The standard error is an honest scale of the error: the truth within 4 of them.
    EXPECT_LT(std::abs(r.value[i] - expected[i]), 4.0 * r.standard_error[i] + 1e-12 * expected[i])
      << r.parameters[i].name;
    EXPECT_GT(r.standard_error[i], 0.0) << r.parameters[i].name;
  }
  for (std::size_t i = 0; i < r.value.size(); ++i)
    EXPECT_NEAR(r.correlation(i, i), 1.0, 1e-9);
}

TEST(CalibrationStart, ClosedFormsLandNearTheTruth)
{
  const auto targets = three_confinements(0.0);
  const StartingValues s = closed_form_start(perturbed(), targets);
  // E from the initial slope at constant lateral stress, nu from the lateral strain.
  EXPECT_NEAR(s.parameters.youngs_modulus / 80e6, 1.0, 0.1);
  EXPECT_NEAR(s.parameters.poisson_ratio, 0.3, 0.01);
  // The peak envelope through three confinements: phi and c of the peak (32 deg, 30 kPa).
  double phi_max = 0.0;
  for (const auto &p : s.parameters.friction_angle.points)
    phi_max = std::max(phi_max, p.second);
  EXPECT_NEAR(phi_max, 32.0, 1.0);
  EXPECT_NEAR(s.parameters.cohesion.points[0].second, 30e3, 6e3);
  // psi from the plastic volumetric slope at the peak (N_psi - 1): 8 deg past kappa = 0.02.
  EXPECT_NEAR(s.parameters.dilatancy_angle.points[1].second, 8.0, 0.5);
  EXPECT_GE(s.notes.size(), 4u);
}

TEST(CalibrationStart, UnloadingBranchesGiveTheElasticConstants)
{
  // One unloading branch from 1 % axial strain (past yield): the material point unloads
  // elastically, so Hooke's law in increments returns E and nu of the truth.
  LoadingProgram program = axial(2e5);
  program.stages[0].unload_at = {parse_trigger("eps_zz <= -0.01", "test")};
  FitTarget probe;
  probe.program = program;
  probe.initial_stress = -2e5;
  probe.substeps = 10;
  const Response r = simulate(probe, continuum::material_from_case(truth()));
  ASSERT_EQ(r.branches.size(), 1u);
  const StartingValues s = closed_form_start(perturbed(), {make_target("unloading", r, program, -2e5, 10, 1.0)});
  EXPECT_NEAR(s.parameters.youngs_modulus / 80e6, 1.0, 1e-6);
  EXPECT_NEAR(s.parameters.poisson_ratio, 0.3, 1e-6);
  EXPECT_NE(s.notes.front().find("unloading"), std::string::npos) << s.notes.front();
}

TEST(CalibrationIdentifiability, IsochoricShearAloneNamesEAndNu)
{
  // Elastic constant-volume shear sees only G = E/(2(1 + nu)): E and nu cannot both be
  // fitted. (Past yield, dilatancy changes the mean stress through K and both show.)
  const std::vector<FitTarget> targets = {made_target(isochoric(), 2e5, 0.0, 1)};
  CalibrationParameters c;
  c.free_parameters = {"E", "nu"};
  c.starting_values = "case";
  try {
    calibrate(perturbed(), targets, c);
    FAIL() << "expected a CalibrationError";
  } catch (const CalibrationError &e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("E"), std::string::npos) << m;
    EXPECT_NE(m.find("nu"), std::string::npos) << m;
    EXPECT_TRUE(e.parameter == "E" || e.parameter == "nu") << e.parameter;
  }
}

TEST(CalibrationRoundTrip, MeanStressRecoversDilatancyFromIsochoricShear)
{
  // At constant volume dilatancy shows as the rise of the mean stress, not as eps_v.
  const std::vector<FitTarget> targets = {made_target(isochoric_past_yield(), 2e5, 0.0, 1)};
  CalibrationParameters c;
  c.free_parameters = {"friction[1]", "dilatancy[1]"};
  c.quantities = {{"q", 1.0}, {"p", 1.0}};
  c.starting_values = "case";
  ContinuumParameters start = truth(); // E, nu, c known: only the friction and dilatancy knots are off
  start.friction_angle.points[1].second = 28.0;
  start.dilatancy_angle.points[1].second = 3.0;
  const CalibrationResult r = calibrate(start, targets, c);
  EXPECT_NEAR(r.value[0] / 32.0, 1.0, 1e-6);
  EXPECT_NEAR(r.value[1] / 8.0, 1.0, 1e-6);
  ASSERT_EQ(r.residual_summary.size(), 1u);
  ASSERT_EQ(r.residual_summary[0].size(), 3u);
  EXPECT_TRUE(r.residual_summary[0][1].fitted);   // p
  EXPECT_FALSE(r.residual_summary[0][2].fitted);  // eps_v
  EXPECT_LT(r.residual_summary[0][0].max_abs, 1e-6);
}

TEST(CalibrationIdentifiability, VolumeAloneCannotSeeDilatancyInIsochoricShear)
{
  // eps_v = 0 along the whole isochoric path whatever psi is: the residuals do not move.
  const std::vector<FitTarget> targets = {made_target(isochoric_past_yield(), 2e5, 0.0, 1)};
  CalibrationParameters c;
  c.free_parameters = {"friction[1]", "dilatancy[1]"};
  c.quantities = {{"eps_v", 1.0}};
  c.starting_values = "case";
  try {
    calibrate(perturbed(), targets, c);
    FAIL() << "expected a CalibrationError";
  } catch (const CalibrationError &e) {
    EXPECT_NE(std::string(e.what()).find("dilatancy[1]"), std::string::npos) << e.what();
  }
}

TEST(CalibrationIdentifiability, AKnotTheCurvesNeverReachIsNamed)
{
  // Friction knots at kappa = 5 and 10, far beyond the plastic strains the curves reach:
  // the residuals do not depend on the second (it only shapes phi for kappa > 5).
  ContinuumParameters start = perturbed();
  start.friction_angle.points.push_back({5.0, 27.0});
  start.friction_angle.points.push_back({10.0, 20.0});
  CalibrationParameters c;
  c.free_parameters = {"E", "friction[4]"};
  c.starting_values = "case";
  try {
    calibrate(start, three_confinements(0.0), c);
    FAIL() << "expected a CalibrationError";
  } catch (const CalibrationError &e) {
    EXPECT_EQ(e.parameter, "friction[4]") << e.what();
  }
}

TEST(CalibrationOutput, FragmentRoundTripsThroughTheCaseReader)
{
  const std::string fragment = continuum_fragment(truth(), "test");
  const CaseDescription c = parse_case(
    "set engines = material-point\n" + fragment +
      "subsection program\n  subsection stage 1\n    set z = rate -1\n    set stop when = eps_zz <= -0.01\n    set max duration = 1\n  end\nend\n",
    "fragment.prm");
  EXPECT_EQ(c.continuum.youngs_modulus, 80e6);
  EXPECT_EQ(c.continuum.poisson_ratio, 0.3);
  ASSERT_EQ(c.continuum.friction_angle.points.size(), 3u);
  EXPECT_EQ(c.continuum.friction_angle.points[1].second, 32.0);
  EXPECT_EQ(c.continuum.dilatancy_angle.points[1].first, 0.02);
}

TEST(CalibrationOutput, CaseFilesIncludeTheCalibratedSection)
{
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "geocomp-calibrated-test.prm";
  {
    std::ofstream out(file);
    out << continuum_fragment(truth(), "test");
  }
  const CaseDescription c = parse_case(
    "set engines = material-point\nsubsection continuum\n  set youngs modulus = 1e9\nend\ninclude " + file.string() +
      "\nsubsection program\n  subsection stage 1\n    set z = rate -1\n    set stop when = eps_zz <= -0.01\n"
      "    set max duration = 1\n  end\nend\n",
    "includes.prm");
  EXPECT_EQ(c.continuum.youngs_modulus, 80e6);
  EXPECT_EQ(c.continuum.friction_angle.points.size(), 3u);
  std::filesystem::remove(file);
}
