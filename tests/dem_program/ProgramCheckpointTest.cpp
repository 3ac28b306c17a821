// Program checkpoints (common/ProgramCheckpoint.h): a DEM program stopped at a main-path
// sample - before, between and after its unloading branches, with the running peak state
// stored - and resumed from the checkpoint file in a fresh engine gives the uninterrupted
// run's Response bit for bit (samples, extras, branches).
#include "Specimen.h"

#include "common/ProgramCheckpoint.h"
#include "common/ProgramRunner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;
namespace fs = std::filesystem;

namespace {

LoadingProgram shear_program()
{
  LoadingProgram program;
  Stage stage;
  stage.name = "shear";
  stage.isochoric = true;
  stage.lambda = 0.0;
  stage.isochoric_rate = 1.0;
  stage.stop_any = {parse_condition("gamma_max >= 0.01", "test")};
  stage.max_duration = 0.05;
  stage.unload_at = {parse_trigger("gamma_max >= 0.003", "test"), parse_trigger("gamma_max >= 0.006", "test"),
                     parse_trigger("peak", "test")};
  program.stages = {stage};
  program.sample_interval = 0.0005;
  program.validate();
  return program;
}

::testing::AssertionResult same_response(const Response &a, const Response &b)
{
  if (a.samples.size() != b.samples.size())
    return ::testing::AssertionFailure() << a.samples.size() << " against " << b.samples.size() << " samples";
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    const ResponseSample &x = a.samples[k], &y = b.samples[k];
    if (x.time != y.time || x.strain != y.strain || x.stress != y.stress || x.stage != y.stage ||
        x.branch != y.branch || x.extras != y.extras)
      return ::testing::AssertionFailure() << "sample " << k << " differs (t = " << x.time << ")";
  }
  if (a.branches.size() != b.branches.size())
    return ::testing::AssertionFailure() << "branch counts differ";
  for (std::size_t k = 0; k < a.branches.size(); ++k)
    if (a.branches[k].residual_gamma != b.branches[k].residual_gamma ||
        a.branches[k].first_sample != b.branches[k].first_sample ||
        a.branches[k].last_sample != b.branches[k].last_sample)
      return ::testing::AssertionFailure() << "branch " << k << " differs";
  if (a.stage_end_reasons != b.stage_end_reasons)
    return ::testing::AssertionFailure() << "stage end reasons differ";
  return ::testing::AssertionSuccess();
}

} // namespace

TEST(ProgramCheckpoint, StoppedAndResumedRunEqualsTheUninterruptedRunBitForBit)
{
  const LoadingProgram program = shear_program();
  DemEngine reference_engine(consolidated().system, engine_parameters());
  const Response reference = ProgramRunner(program, reference_engine).run();
  ASSERT_EQ(reference.branches.size(), 2u) << "the program should unload twice before it stops";

  const fs::path file = fs::temp_directory_path() / ("geocomp-program-" + std::to_string(::getpid()) + ".ckpt");
  const std::string key = "test program";
  // Stop after the first main-path samples, between the branches, and after both.
  const std::size_t main_samples = reference.path(0).size();
  for (std::size_t stop_after : {std::size_t(3), main_samples / 2, main_samples - 2}) {
    SCOPED_TRACE("stop after " + std::to_string(stop_after) + " main-path samples");
    DemEngine engine(consolidated().system, engine_parameters());
    ProgramRunner runner(program, engine);
    std::size_t seen = 0;
    runner.on_progress([&](const RunProgress &p) { seen += p.branch == 0 ? 1 : 0; });
    CheckpointPolicy policy;
    policy.stop_requested = [&] { return seen >= stop_after; };
    policy.write = [&](const RunnerState &s, const EngineState &current, const EngineState *peak,
                       const std::vector<const EngineState *> &kept) {
      write_program_checkpoint(file, key, s, engine, current, peak, kept, 7);
    };
    runner.set_checkpoints(policy);
    EXPECT_THROW(runner.run(), ProgramStopped);

    // A fresh engine and runner, as a new process would have them.
    DemEngine fresh(consolidated().system, engine_parameters());
    EXPECT_FALSE(read_program_checkpoint(file, "another case", fresh)) << "a foreign key must not resume";
    std::optional<ProgramCheckpoint> c = read_program_checkpoint(file, key, fresh);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->counter, 7u);
    EXPECT_TRUE(c->runner.has_peak_state);
    fresh.restore(*c->current);
    ProgramRunner again(program, fresh);
    EXPECT_TRUE(same_response(again.resume(std::move(c->runner), std::move(c->peak), std::move(c->kept)), reference));
  }
  fs::remove(file);
}
