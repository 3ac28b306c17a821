#include "common/ProgramRunner.h"
#include "HystereticShearEngine.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp;
using geocomp::testing::HystereticShearEngine;
using geocomp::testing::shear_program;

// A kinematic stage ends at the first sample where its condition holds, not later.
TEST(ProgramRunner, StageEndsAtFirstSampleWhereConditionHolds)
{
  LoadingProgram p;
  p.sample_interval = 0.1;
  Stage a;
  a.name = "compress";
  a.axes = {AxisDrive::rate(0), AxisDrive::rate(0), AxisDrive::rate(-0.01)};
  a.stop_any = {parse_condition("eps_zz <= -0.0095", "t")};
  a.max_duration = 100;
  Stage b = a;
  b.name = "stretch";
  b.axes[2] = AxisDrive::rate(0.02);
  b.stop_any = {parse_condition("eps_zz >= 0.0", "t"), parse_condition("stage_time >= 50", "t")};
  p.stages = {a, b};
  HystereticShearEngine engine;
  ProgramRunner runner(p, engine);
  const Response r = runner.run();
  // Stage 1: eps_zz = -0.001 k at sample k: first k with -0.001 k <= -0.0095 is k = 10.
  int last_a = -1;
  for (std::size_t i = 0; i < r.samples.size(); ++i)
    if (r.samples[i].stage == 0)
      last_a = static_cast<int>(i);
  EXPECT_EQ(last_a, 10); // sample 0 is the initial state
  EXPECT_NEAR(r.samples[last_a].strain(2, 2), -0.010, 1e-12);
  // Stage 2 climbs 0.002 per sample from -0.010: 5 samples.
  EXPECT_EQ(r.samples.size(), 16u);
  EXPECT_NEAR(r.samples.back().strain(2, 2), 0.0, 1e-12);
  ASSERT_EQ(r.stage_end_reasons.size(), 2u);
  EXPECT_EQ(r.stage_end_reasons[0], "eps_zz <= -0.0095");
  EXPECT_EQ(r.stage_end_reasons[1], "eps_zz >= 0.0");
}

TEST(ProgramRunner, MaxDurationEndsStageAndSaysSo)
{
  LoadingProgram p = shear_program({}, 10.0);
  p.stages[0].max_duration = 0.5;
  HystereticShearEngine engine;
  const Response r = ProgramRunner(p, engine).run();
  EXPECT_EQ(r.samples.size(), 51u);
  EXPECT_EQ(r.stage_end_reasons[0], "max duration");
}

// Branches are excursions: the main path with branches equals the main path without.
TEST(ProgramRunner, BranchesLeaveTheMainPathUnchanged)
{
  HystereticShearEngine e1, e2;
  const Response plain = ProgramRunner(shear_program({}), e1).run();
  const Response branched =
    ProgramRunner(shear_program({"gamma_max >= 0.02", "gamma_max >= 0.08"}), e2).run();
  const auto a = plain.path(0), b = branched.path(0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]->time, b[i]->time);
    EXPECT_EQ(a[i]->stress, b[i]->stress);
  }
  EXPECT_EQ(branched.branches.size(), 2u);
}

// Unloading from gamma_h returns to tau = 0 (the stage start) along slope K:
// residual gamma = gamma_h - tau_b(gamma_h)/K, to round-off.
TEST(ProgramRunner, UnloadingBranchResidualMatchesElasticUnloading)
{
  HystereticShearEngine engine;
  const Response r = ProgramRunner(shear_program({"gamma_max >= 0.03"}), engine).run();
  ASSERT_EQ(r.branches.size(), 1u);
  const BranchRecord &b = r.branches[0];
  EXPECT_TRUE(b.reached_target);
  EXPECT_EQ(b.tau_target, 0.0);
  const double gh = b.gamma_start;
  EXPECT_GE(gh, 0.03);
  // The runner lands the branch's last sample on the target (unloading is linear here).
  const double expected = gh - engine.backbone(gh) / engine.K;
  EXPECT_NEAR(b.residual_gamma, expected, 1e-9);
  // Every branch sample carries the branch id and unloads monotonically.
  const auto path = r.path(1);
  ASSERT_FALSE(path.empty());
  for (std::size_t i = 1; i < path.size(); ++i)
    EXPECT_LT(tau_max(path[i]->stress), tau_max(path[i - 1]->stress));
}

// "peak" branches start from the state at the running maximum of tau_max.
TEST(ProgramRunner, PeakBranchStartsAtThePeak)
{
  HystereticShearEngine engine;
  const Response r = ProgramRunner(shear_program({"peak", "peak_drop >= 0.2"}), engine).run();
  ASSERT_EQ(r.branches.size(), 2u);
  const BranchRecord &peak = r.branches[0];
  EXPECT_EQ(peak.trigger, "peak");
  // The backbone peaks at g0 = 0.05 with tau = A; the sampled peak is within a sample.
  EXPECT_NEAR(peak.gamma_start, engine.g0, 2 * 0.05 * 0.01);
  EXPECT_NEAR(peak.tau_start, engine.A, 1e-3 * engine.A);
  double tau_main_max = 0;
  for (const auto *s : r.path(0))
    tau_main_max = std::max(tau_main_max, tau_max(s->stress));
  EXPECT_DOUBLE_EQ(peak.tau_start, tau_main_max);
  const BranchRecord &soft = r.branches[1];
  EXPECT_GE((engine.A - soft.tau_start) / engine.A, 0.2);
  EXPECT_GT(soft.residual_gamma, peak.residual_gamma);
}

namespace {
/// Unloads linearly with slope K to a small floor (1e-3 tau_h) just above the target
/// tau = 0, holds it over 2 % more unloading strain, then drops by tau_h: the response of a
/// specimen whose stress sticks and then slips (a force chain giving way). Landing on the
/// target cannot converge there: every secant step stays on the floor.
class StickSlipUnloadingEngine : public HystereticShearEngine {
public:
  ResponseSample measure() override
  {
    ResponseSample s = HystereticShearEngine::measure();
    const double g_hist = s.extras[0], g = gamma();
    if (g < g_hist) {
      const double tau_h = backbone(g_hist), x = (g_hist - g) * K / tau_h;
      const double tau = x < 1.02 ? tau_h * std::max(1.0 - x, 1e-3) : tau_h * (1.0 - x) - tau_h;
      s.stress = Tensor3::Identity() * -p0;
      s.stress(0, 0) -= tau;
      s.stress(2, 2) += tau;
    }
    return s;
  }
};
} // namespace

// The branch ends within one sample of crossing its target even when landing on the
// target does not converge: it must not creep on in ever shorter intervals (it did, on
// the 100 000-sphere specimen: hundreds of samples within one interval).
TEST(ProgramRunner, UnloadingBranchEndsWhenTheLandingDoesNotConverge)
{
  StickSlipUnloadingEngine engine;
  const Response r = ProgramRunner(shear_program({"gamma_max >= 0.03"}), engine).run();
  ASSERT_EQ(r.branches.size(), 1u);
  const BranchRecord &b = r.branches[0];
  EXPECT_TRUE(b.reached_target);
  // Unloading strain 1.02 tau_h/K = 0.0091 at gamma rate 0.1 1/s: 0.09 s, 10 samples of 0.01 s.
  const auto path = r.path(1);
  EXPECT_LE(path.size(), 12u);
  const Tensor3 &last = path.back()->stress;
  EXPECT_LT(last(2, 2) - last(0, 0), 0.0) << "the branch ends past its target (signed deviator)";
  // The main path goes on to its end.
  EXPECT_GE(gamma_max(r.path(0).back()->strain), 0.2);
}

// Two triggers that hold at the same sample both leave from that main-path sample (the
// second once left from the first branch's last sample, at the unloading target, and never
// reached it).
TEST(ProgramRunner, TwoTriggersAtOneSampleBothLeaveFromIt)
{
  HystereticShearEngine engine;
  const Response r = ProgramRunner(shear_program({"gamma_max >= 0.01", "gamma_max >= 0.01"}, 0.05), engine).run();
  ASSERT_EQ(r.branches.size(), 2u);
  EXPECT_EQ(r.branches[0].first_sample, r.branches[1].first_sample);
  EXPECT_EQ(r.samples[r.branches[1].first_sample].branch, 0);
  EXPECT_EQ(r.branches[0].residual_gamma, r.branches[1].residual_gamma);
  EXPECT_TRUE(r.branches[1].reached_target);
}
