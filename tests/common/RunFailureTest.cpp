// A run that cannot be what its case says is never silent (issue 30): an engine failing
// mid-run leaves the samples so far and where and why, which the results file keeps as
// /meta/status; a stage ended by its max duration, or a branch short of its target, is
// named by completion_status(); and a stop condition the program's direction can never
// reach is refused before anything runs. The interval means and the status go through the
// results file unchanged.
#include "common/ProgramRunner.h"
#include "common/ResponseFile.h"
#include "HystereticShearEngine.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <unistd.h>

using namespace geocomp;
using geocomp::testing::HystereticShearEngine;
namespace fs = std::filesystem;

namespace {
/// The shear program to gamma_max = `stop`, without branches.
LoadingProgram shear_program(double stop, double max_duration = 100.0)
{
  return geocomp::testing::shear_program({}, stop, max_duration);
}

/// The closed-form engine, failing in advance_to once its time passes `fail_after`.
class FailingEngine : public HystereticShearEngine
{
public:
  explicit FailingEngine(double fail_after) : fail_after_(fail_after) {}
  void advance_to(double t_end) override
  {
    if (t_end > fail_after_)
      throw std::runtime_error("solver diverged");
    HystereticShearEngine::advance_to(t_end);
  }

private:
  double fail_after_;
};

fs::path scratch(const std::string &name)
{
  const fs::path dir = fs::temp_directory_path() / "geocomp-tests";
  fs::create_directories(dir);
  return dir / (name + "-" + std::to_string(::getpid()) + ".h5");
}

/// The ProgramError of validate(), or none.
std::string refusal(const LoadingProgram &p)
{
  try {
    p.validate();
  } catch (const ProgramError &e) {
    return e.where + ": " + e.what();
  }
  return "";
}
} // namespace

TEST(RunFailure, AnEngineFailingMidRunLeavesTheSamplesSoFarWithWhereAndWhy)
{
  const LoadingProgram p = shear_program(0.1);
  FailingEngine engine(0.055);
  ProgramRunner runner(p, engine);
  try {
    runner.run();
    FAIL() << "the engine's failure was not reported";
  } catch (const ProgramFailed &failed) {
    // Samples at t = 0, 0.01, ..., 0.05; the advance to 0.06 failed.
    ASSERT_EQ(failed.partial.samples.size(), 6u);
    EXPECT_NEAR(failed.partial.samples.back().time, 0.05, 1e-12);
    EXPECT_NE(failed.status.find("failed in stage 1 'shear'"), std::string::npos) << failed.status;
    EXPECT_NE(failed.status.find("after t = 0.05 s"), std::string::npos) << failed.status;
    EXPECT_NE(failed.status.find("solver diverged"), std::string::npos) << failed.status;
    ASSERT_EQ(failed.partial.stage_end_reasons.size(), 1u);
    EXPECT_EQ(failed.partial.stage_end_reasons[0], failed.status);
    // What the command writes: the partial record, readable, with its status.
    const fs::path path = scratch("failed-run");
    RunMeta meta;
    meta.status = failed.status;
    write_response(path, failed.partial, meta);
    RunMeta back;
    const Response q = read_response(path, &back);
    fs::remove(path);
    EXPECT_EQ(back.status, failed.status);
    ASSERT_EQ(q.samples.size(), 6u);
    EXPECT_EQ(q.samples.back().stress, failed.partial.samples.back().stress);
  }
}

TEST(RunFailure, AFailureInsideABranchSaysWhichBranch)
{
  LoadingProgram p = shear_program(0.1);
  p.stages[0].unload_at = {parse_trigger("gamma_max >= 0.004", "test")};
  // gamma_max = 0.1 t: the branch leaves at t = 0.04 and unloads from there; the engine
  // fails on the branch's first advance (to 0.05 on the branch's clock).
  FailingEngine engine(0.045);
  try {
    ProgramRunner(p, engine).run();
    FAIL() << "the engine's failure was not reported";
  } catch (const ProgramFailed &failed) {
    EXPECT_NE(failed.status.find("unloading branch 1"), std::string::npos) << failed.status;
  }
}

TEST(RunFailure, CompletionStatusNamesAStageEndedOnItsMaxDuration)
{
  const LoadingProgram finished = shear_program(0.01);
  HystereticShearEngine engine;
  EXPECT_EQ(completion_status(ProgramRunner(finished, engine).run(), finished), "complete");
  const LoadingProgram cut = shear_program(0.02, 0.1); // gamma_max reaches 0.01 at t = 0.1
  HystereticShearEngine other;
  const Response r = ProgramRunner(cut, other).run();
  EXPECT_EQ(completion_status(r, cut),
            "stage 1 'shear' ended on its max duration (0.1 s) before its stop condition 'gamma_max >= 0.020000'");
}

TEST(RunFailure, CheckRefusesStopConditionsTheProgramCanNeverReach)
{
  // The case: gamma_max is never negative.
  LoadingProgram p = shear_program(0.1);
  p.stages[0].isochoric_rate = 2.0;
  p.stages[0].max_duration = 1.0;
  p.stages[0].stop_any = {parse_condition("gamma_max <= -0.5", "test")};
  EXPECT_NE(refusal(p).find("program/stage 1/stop when"), std::string::npos);
  EXPECT_NE(refusal(p).find("never negative"), std::string::npos) << refusal(p);
  // A kinematic axis moving away from its threshold, from eps = 0 in the first stage.
  LoadingProgram a;
  a.sample_interval = 0.01;
  Stage s;
  s.axes = {{AxisDrive::stress(-1e5), AxisDrive::stress(-1e5), AxisDrive::rate(0.5)}};
  s.stop_any = {parse_condition("eps_zz <= -0.1", "test")};
  s.max_duration = 1.0;
  a.stages = {s};
  EXPECT_NE(refusal(a).find("does not shorten"), std::string::npos) << refusal(a);
  // ... or moving towards it too slowly to get there within the max duration.
  a.stages[0].axes[2] = AxisDrive::rate(-0.05);
  EXPECT_NE(refusal(a).find("reaches only -0.05"), std::string::npos) << refusal(a);
  // The isochoric box keeps its volume; its z axis lengthens.
  p.stages[0].stop_any = {parse_condition("eps_vol >= 0.01", "test")};
  EXPECT_NE(refusal(p).find("keeps the volume"), std::string::npos) << refusal(p);
  p.stages[0].stop_any = {parse_condition("eps_zz <= -0.01", "test")};
  EXPECT_NE(refusal(p).find("does not shorten"), std::string::npos) << refusal(p);
  // A stage time beyond the max duration.
  p.stages[0].stop_any = {parse_condition("stage_time >= 2", "test")};
  EXPECT_NE(refusal(p).find("max duration"), std::string::npos) << refusal(p);
  // Reachable ones pass: the right direction, fast enough; a later stage, whose start is
  // not known here, is checked only for what no start can change.
  a.stages[0].axes[2] = AxisDrive::rate(-0.5);
  EXPECT_EQ(refusal(a), "");
  p.stages[0].stop_any = {parse_condition("gamma_max >= 0.5", "test")};
  EXPECT_EQ(refusal(p), "");
  Stage back = s;
  back.axes[2] = AxisDrive::rate(0.5);
  back.stop_any = {parse_condition("eps_zz >= -0.05", "test")};
  a.stages.push_back(back);
  EXPECT_EQ(refusal(a), "");
  a.stages[1].stop_any = {parse_condition("tau_max <= -1", "test")};
  EXPECT_NE(refusal(a).find("program/stage 2/stop when"), std::string::npos) << refusal(a);
}

TEST(RunFailure, IntervalMeansAndStatusGoThroughTheResultsFile)
{
  const LoadingProgram p = shear_program(0.02);
  HystereticShearEngine engine;
  Response r = ProgramRunner(p, engine).run();
  // An engine without interval means: the runner copies the instantaneous stress.
  EXPECT_FALSE(r.interval_means);
  EXPECT_EQ(r.samples.back().stress_mean, r.samples.back().stress);
  r.interval_means = true;
  r.samples.back().stress_mean(0, 0) += 123.0;
  const fs::path path = scratch("means");
  RunMeta meta;
  meta.status = "stage 1 ended on its max duration";
  write_response(path, r, meta);
  RunMeta back;
  const Response q = read_response(path, &back);
  fs::remove(path);
  EXPECT_TRUE(q.interval_means);
  EXPECT_EQ(back.status, meta.status);
  ASSERT_EQ(q.samples.size(), r.samples.size());
  for (std::size_t k = 0; k < r.samples.size(); ++k)
    EXPECT_EQ(q.samples[k].stress_mean, r.samples[k].stress_mean);
}
