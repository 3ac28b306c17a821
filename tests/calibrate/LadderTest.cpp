// The model ladder (compare/calibrate/Ladder.h): curves made by the material point with a
// known Mohr-Coulomb model of constant parameters are recovered by the constant rung, whose
// BIC is the smallest (the richer rungs fit the noise no better than their extra parameters
// cost); curves made with hardening/softening tables are fitted better by the tables rung,
// by RSS and by AIC. The criteria are the formula, and the table round-trips through JSON.
#include "compare/calibrate/Ladder.h"
#include "tests/calibrate/SyntheticTargets.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp;
using namespace geocomp::calibration;
using namespace geocomp::calibration::synthetic;

namespace {
/// Mohr-Coulomb with constant c = 30 kPa, phi = 30 deg, psi = 6 deg.
ContinuumParameters constant_truth()
{
  ContinuumParameters p = truth();
  p.cohesion.points = {{0.0, 30e3}};
  p.friction_angle.points = {{0.0, 30.0}};
  p.dilatancy_angle.points = {{0.0, 6.0}};
  return p;
}

/// The case's section: tables of the truth()'s shape, their values off.
ContinuumParameters case_section()
{
  ContinuumParameters p = truth();
  p.youngs_modulus = 100e6;
  p.poisson_ratio = 0.25;
  p.cohesion.points = {{0.0, 20e3}};
  p.friction_angle.points = {{0.0, 25.0}, {0.02, 28.0}, {0.08, 26.0}};
  p.dilatancy_angle.points = {{0.0, 2.0}, {0.02, 4.0}};
  return p;
}

/// Axial compression at lateral pressure p to 6 %, sampled every 0.3 % (20 samples: the
/// ladder fits every rung, so the curves are kept short).
FitTarget curve(double p, double noise, unsigned seed, const ContinuumParameters &material)
{
  LoadingProgram program = axial(p);
  program.sample_interval = 0.003;
  return made_target(program, p, noise, seed, material);
}

/// Two confinements: enough to separate c from phi.
std::vector<FitTarget> two_confinements(double noise, const ContinuumParameters &material)
{
  return {curve(1e5, noise, 11, material), curve(4e5, noise, 13, material)};
}

CalibrationParameters options(std::vector<std::string> ladder)
{
  CalibrationParameters c;
  c.starting_values = "case";
  c.ladder = std::move(ladder);
  return c;
}

const compare::LadderRung &rung(const std::vector<compare::LadderRung> &rows, const std::string &name)
{
  for (const auto &r : rows)
    if (r.name == name)
      return r;
  throw std::runtime_error("no rung " + name);
}

void print(const std::vector<compare::LadderRung> &rows) { std::printf("%s", ladder_summary(rows).c_str()); }
} // namespace

TEST(ModelLadder, TheConstantRungRecoversAConstantModelExactly)
{
  const ContinuumParameters section = case_section();
  const std::vector<FitTarget> targets = two_confinements(0.0, constant_truth());
  const CalibrationParameters o = options({"mohr-coulomb constant"});
  const RungProblem problem = rung_problem("mohr-coulomb constant", {&section, &targets, &o, nullptr}, nullptr);
  EXPECT_EQ(problem.start.friction_angle.points.size(), 1u) << "each freed table is one number";
  const CalibrationResult r = calibrate(problem.start, targets, problem.options);
  const std::vector<double> expected = {80e6, 0.3, 30e3, 30.0, 6.0};
  ASSERT_EQ(r.value.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(r.value[i] / expected[i], 1.0, 1e-6) << r.parameters[i].name;
}

TEST(ModelLadder, OnAConstantModelWithNoiseTheConstantRungHasTheSmallestBic)
{
  const ContinuumParameters section = case_section();
  const std::vector<FitTarget> targets = two_confinements(0.002, constant_truth());
  const CalibrationParameters o = options(ladder_rung_names());
  const std::vector<compare::LadderRung> rows = run_ladder({&section, &targets, &o, nullptr});
  print(rows);
  ASSERT_EQ(rows.size(), 4u);
  const compare::LadderRung &constant = rung(rows, "mohr-coulomb constant");
  const compare::LadderRung &tables = rung(rows, "mohr-coulomb tables");
  ASSERT_TRUE(constant.failure.empty()) << constant.failure;
  ASSERT_TRUE(tables.failure.empty()) << tables.failure;
  EXPECT_EQ(constant.k, 5u);
  EXPECT_EQ(tables.k, 8u); // E, nu, c[0], phi[0..2], psi[0..1]
  EXPECT_EQ(constant.n, tables.n);
  // The tables nest the constant model: their RSS is no larger, but not smaller by enough.
  EXPECT_LE(tables.rss, constant.rss * (1.0 + 1e-9));
  EXPECT_EQ(constant.delta_bic, 0.0);
  for (const auto &r : rows) {
    if (r.name != constant.name && r.failure.empty()) {
      EXPECT_GT(r.bic, constant.bic) << r.name;
    }
  }
}

TEST(ModelLadder, OnATablesModelTheTablesRungWinsByRssAndAic)
{
  // The truth's table shape with E, nu, c, the peak friction and dilatancy off; these five
  // are freed: one value each (constant) or one knot each (tables).
  ContinuumParameters section = truth();
  section.youngs_modulus = 100e6;
  section.poisson_ratio = 0.25;
  section.cohesion.points = {{0.0, 20e3}};
  section.friction_angle.points[1].second = 28.0;
  section.dilatancy_angle.points[1].second = 4.0;
  const std::vector<FitTarget> targets = two_confinements(0.002, truth());
  CalibrationParameters o = options({"mohr-coulomb constant", "mohr-coulomb tables"});
  o.free_parameters = {"E", "nu", "cohesion", "friction[1]", "dilatancy[1]"};
  const std::vector<compare::LadderRung> rows = run_ladder({&section, &targets, &o, nullptr});
  print(rows);
  const compare::LadderRung &constant = rung(rows, "mohr-coulomb constant");
  const compare::LadderRung &tables = rung(rows, "mohr-coulomb tables");
  ASSERT_TRUE(constant.failure.empty()) << constant.failure;
  ASSERT_TRUE(tables.failure.empty()) << tables.failure;
  EXPECT_EQ(tables.k, constant.k);
  EXPECT_LT(tables.rss, constant.rss);
  EXPECT_LT(tables.aic, constant.aic);
  EXPECT_EQ(tables.delta_aic, 0.0);
  EXPECT_GT(constant.delta_aic, 10.0) << "the softening is not noise";
}

TEST(ModelLadder, AHeldOutCurveIsPredictedByEachRung)
{
  // Fitted at 100 and 400 kPa, the 200 kPa curve predicted: the constant model's prediction
  // of a constant model's curve is exact up to the fit's convergence.
  const ContinuumParameters section = case_section();
  const std::vector<FitTarget> all = {curve(1e5, 0.0, 0, constant_truth()), curve(2e5, 0.0, 0, constant_truth()),
                                      curve(4e5, 0.0, 0, constant_truth())};
  const std::vector<FitTarget> fitted = {all[0], all[2]};
  const CalibrationParameters o = options({"mohr-coulomb constant"});
  const std::vector<compare::LadderRung> rows = run_ladder({&section, &fitted, &o, &all[1]});
  ASSERT_TRUE(rows[0].failure.empty()) << rows[0].failure;
  EXPECT_LT(rows[0].held_out_q, 1e-6);
  EXPECT_LT(rows[0].held_out_eps_v, 1e-6);
}

TEST(ModelLadderReport, CriteriaAreTheFormulaAndTheTableRoundTripsThroughJson)
{
  std::vector<compare::LadderRung> rows(3);
  rows[0].name = "mohr-coulomb constant";
  rows[0].k = 5;
  rows[0].n = 120;
  rows[0].rss = 0.25;
  rows[1].name = "mohr-coulomb tables";
  rows[1].k = 8;
  rows[1].n = 120;
  rows[1].rss = 0.2;
  rows[1].parameters = {"E = 8e+07"};
  rows[2].name = "nikolaevsky";
  rows[2].failure = "parameter 'lambda': cannot identify <it>";
  compare::rank_rungs(rows);
  EXPECT_DOUBLE_EQ(rows[0].aic, 120.0 * std::log(0.25 / 120.0) + 10.0);
  EXPECT_DOUBLE_EQ(rows[1].bic, 120.0 * std::log(0.2 / 120.0) + 8.0 * std::log(120.0));
  EXPECT_DOUBLE_EQ(std::min(rows[0].delta_aic, rows[1].delta_aic), 0.0);
  EXPECT_TRUE(std::isnan(rows[2].aic));
  const auto back = compare::ladder_from_fit_json("{\"ladder\": " + compare::ladder_json(rows, "") + "}");
  ASSERT_EQ(back.size(), 3u);
  EXPECT_EQ(back[1].parameters, rows[1].parameters);
  EXPECT_EQ(back[1].rss, rows[1].rss);
  EXPECT_EQ(back[0].aic, rows[0].aic);
  EXPECT_EQ(back[2].failure, rows[2].failure);
  const std::string html = compare::ladder_html(rows);
  EXPECT_NE(html.find("Model ladder"), std::string::npos);
  EXPECT_NE(html.find("&lt;it&gt;"), std::string::npos) << "the failure is escaped";
}
