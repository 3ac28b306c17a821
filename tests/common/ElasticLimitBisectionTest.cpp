// The elastic limit located by bisection (ProgramRunner, `locate elastic limit`) on the
// closed-form hysteretic engine: its residual after unloading to tau = 0 is known exactly,
//     g_end = g - tau_b(g) / K   (engineering gamma_max, unloading slope K),
// and on S0's isochoric path (lambda = 0) eps_x = -a, eps_z = a / (1 - a), so the
// logarithmic gamma_max the runner bisects on is x = -2 ln(1 - a) with
// g = a (2 - a) / (1 - a). The crossing of 1 % is solved here to round-off and must lie in
// the located bracket, which must be narrower than the tolerance.
#include "common/ElasticLimitBracket.h"
#include "common/ProgramRunner.h"
#include "HystereticShearEngine.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp;
using geocomp::testing::HystereticShearEngine;
using geocomp::testing::shear_program;

namespace {

/// a of the isochoric path at engineering gamma_max g: a^2 - (2 + g) a + g = 0.
double a_of_gamma(double g) { return 0.5 * ((2.0 + g) - std::sqrt((2.0 + g) * (2.0 + g) - 4.0 * g)); }

/// Residual logarithmic gamma_max after unloading from logarithmic start strain x.
double closed_form_residual(const HystereticShearEngine &e, double x)
{
  const double a = 1.0 - std::exp(-0.5 * x);
  const double g = a * (2.0 - a) / (1.0 - a);
  const double g_end = g - e.backbone(g) / e.K;
  return -2.0 * std::log(1.0 - a_of_gamma(g_end));
}

/// The start strain x at which the closed-form residual reaches `threshold`, by bisection.
double closed_form_crossing(const HystereticShearEngine &e, double threshold)
{
  double lo = 0.0, hi = 0.1;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (closed_form_residual(e, mid) < threshold ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

LoadingProgram locating(std::vector<std::string> triggers, double tolerance)
{
  LoadingProgram p = shear_program(std::move(triggers), 0.1);
  p.stages[0].locate_elastic_limit = true;
  p.stages[0].elastic_limit_tolerance = tolerance;
  p.validate();
  return p;
}

int bisection_branches(const Response &r)
{
  int n = 0;
  for (const BranchRecord &b : r.branches)
    n += b.bisection() ? 1 : 0;
  return n;
}

} // namespace

// A tolerance (2e-4) finer than the strain between samples (1e-3): the last steps run the
// main path on from a sample's state to the bracket's midpoint.
TEST(ElasticLimitBisection, BracketHoldsTheClosedFormCrossingAndIsNarrowerThanTheTolerance)
{
  const double tolerance = 2e-4;
  HystereticShearEngine engine;
  const Response r = ProgramRunner(locating({"gamma_max >= 0.005", "gamma_max >= 0.08"}, tolerance), engine).run();
  const LimitSearch s = search_limit(branch_points(r, 0, r.samples.front()), s0_residual_threshold);
  ASSERT_TRUE(s.bracketed());
  const double crossing = closed_form_crossing(engine, s0_residual_threshold);
  EXPECT_LE(s.lower->x, crossing);
  EXPECT_GE(s.upper->x, crossing);
  EXPECT_LE(s.width(), tolerance);
  EXPECT_GT(s.width(), 0.0);
  EXPECT_TRUE(s.lower->bisection || s.upper->bisection);
  // Every branch's residual is the closed form's at its start.
  for (const BranchPoint &b : branch_points(r, 0, r.samples.front()))
    EXPECT_NEAR(b.residual, closed_form_residual(engine, b.x), 1e-9) << "branch " << b.id;
  // Bisection from a bracket of ~0.075 down to 2e-4: about log2(0.075 / 2e-4) = 8.6 branches.
  EXPECT_GE(bisection_branches(r), 8);
  EXPECT_LE(bisection_branches(r), 12);
  bool between_samples = false; // some branch left the main path between two samples
  for (const BranchRecord &b : r.branches)
    between_samples = between_samples || r.samples[b.first_sample].branch == b.id;
  EXPECT_TRUE(between_samples);
  for (const BranchRecord &b : r.branches)
    EXPECT_TRUE(b.reached_target) << "branch " << b.id;
}

// Bisection branches come after the main path: the main path and the planned branches are
// those of the same program without locating, bit for bit, and a second run repeats the
// first bit for bit.
TEST(ElasticLimitBisection, LeavesTheMainPathAndPlannedBranchesUnchangedAndRepeatsBitForBit)
{
  const std::vector<std::string> planned = {"gamma_max >= 0.005", "gamma_max >= 0.08"};
  HystereticShearEngine e0, e1, e2;
  LoadingProgram plain = shear_program(planned, 0.1);
  const Response a = ProgramRunner(plain, e0).run();
  const Response b = ProgramRunner(locating(planned, 1e-3), e1).run();
  const Response c = ProgramRunner(locating(planned, 1e-3), e2).run();
  ASSERT_GT(b.branches.size(), a.branches.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    EXPECT_EQ(a.samples[k].strain, b.samples[k].strain) << "sample " << k;
    EXPECT_EQ(a.samples[k].stress, b.samples[k].stress) << "sample " << k;
  }
  for (std::size_t k = 0; k < a.branches.size(); ++k)
    EXPECT_EQ(a.branches[k].residual_gamma, b.branches[k].residual_gamma);
  ASSERT_EQ(b.samples.size(), c.samples.size());
  for (std::size_t k = 0; k < b.samples.size(); ++k) {
    EXPECT_EQ(b.samples[k].time, c.samples[k].time);
    EXPECT_EQ(b.samples[k].stress, c.samples[k].stress);
  }
  EXPECT_EQ(completion_status(b, locating(planned, 1e-3)), "complete");
}

// A program checkpoint taken while the bracket is open carries the main-path states it keeps
// (RunnerState::kept_samples): a run stopped at any main-path sample and resumed in a fresh
// engine bisects as the uninterrupted run, bit for bit. Before, a run resumed inside the
// bracket had none of them and ran no bisection branch.
TEST(ElasticLimitBisection, ARunStoppedAndResumedInsideTheOpenBracketBisectsAsTheUninterruptedRun)
{
  const LoadingProgram program = locating({"gamma_max >= 0.005", "gamma_max >= 0.08"}, 1e-3);
  HystereticShearEngine reference_engine;
  const Response reference = ProgramRunner(program, reference_engine).run();
  ASSERT_GT(bisection_branches(reference), 0);
  const auto copy = [](const EngineState &s) -> std::unique_ptr<EngineState> {
    return std::make_unique<HystereticShearEngine::State>(dynamic_cast<const HystereticShearEngine::State &>(s));
  };
  int inside = 0;
  for (std::size_t stop_after = 1; stop_after + 1 < reference.path(0).size(); ++stop_after) {
    SCOPED_TRACE("stopped after " + std::to_string(stop_after) + " main-path samples");
    HystereticShearEngine engine;
    ProgramRunner runner(program, engine);
    std::size_t seen = 0;
    runner.on_progress([&](const RunProgress &p) { seen += p.branch == 0 ? 1 : 0; });
    RunnerState stopped;
    std::unique_ptr<EngineState> current, peak;
    std::vector<std::unique_ptr<EngineState>> kept;
    CheckpointPolicy policy;
    policy.stop_requested = [&] { return seen >= stop_after; };
    policy.write = [&](const RunnerState &state, const EngineState &now, const EngineState *at_peak,
                       const std::vector<const EngineState *> &bracket) {
      stopped = state;
      current = copy(now);
      peak = at_peak ? copy(*at_peak) : nullptr;
      for (const EngineState *b : bracket)
        kept.push_back(copy(*b));
    };
    runner.set_checkpoints(policy);
    try {
      runner.run();
      continue; // finished before the stop: nothing to resume
    } catch (const ProgramStopped &) {
    }
    inside += stopped.kept_samples.empty() ? 0 : 1;
    // A fresh engine as a new process has it: following the stage's control (the DEM engine
    // keeps it in its state; this one does not), in the checkpoint's state.
    HystereticShearEngine fresh;
    StageControl control;
    control.stage = &program.stages[0];
    control.t0 = reference.samples.front().time;
    control.eps0 = reference.samples.front().strain.diagonal();
    control.direction = 1.0;
    fresh.begin_control(control);
    fresh.restore(*current);
    const Response r = ProgramRunner(program, fresh).resume(std::move(stopped), std::move(peak), std::move(kept));
    ASSERT_EQ(r.samples.size(), reference.samples.size());
    for (std::size_t k = 0; k < r.samples.size(); ++k) {
      EXPECT_EQ(r.samples[k].time, reference.samples[k].time) << "sample " << k;
      EXPECT_EQ(r.samples[k].stress, reference.samples[k].stress) << "sample " << k;
    }
    ASSERT_EQ(r.branches.size(), reference.branches.size());
    for (std::size_t k = 0; k < r.branches.size(); ++k)
      EXPECT_EQ(r.branches[k].residual_gamma, reference.branches[k].residual_gamma) << "branch " << k;
  }
  EXPECT_GT(inside, 3) << "some stops must fall inside the open bracket";
}

// No planned branch reaches 1 %: nothing to bisect, no branch invented.
TEST(ElasticLimitBisection, NoBranchReachingOnePercentMeansNoBracketAndNoExtraBranch)
{
  HystereticShearEngine engine;
  const Response r = ProgramRunner(locating({"gamma_max >= 0.005", "gamma_max >= 0.01"}, 1e-3), engine).run();
  EXPECT_EQ(r.branches.size(), 2u);
  EXPECT_EQ(bisection_branches(r), 0);
  EXPECT_FALSE(search_limit(branch_points(r, 0, r.samples.front()), s0_residual_threshold).bracketed());
}

TEST(ElasticLimitBisection, LocatingWithoutUnloadingBranchesIsRefusedNamingTheParameter)
{
  LoadingProgram p = shear_program({}, 0.1);
  p.stages[0].locate_elastic_limit = true;
  try {
    p.validate();
    FAIL() << "validate() accepted a stage that locates the elastic limit without branches";
  } catch (const ProgramError &e) {
    EXPECT_EQ(e.where, "program/stage 1/locate elastic limit");
  }
}
