// The elastic limit located by bisection on a tiny DEM specimen (343 spheres, Specimen.h)
// in S0's isochoric shear: the runner's extra branches narrow the bracket of the planned
// branches to below the tolerance, the branches at its two ends have residuals on either
// side of 1 %, and a second run gives the same bits (one thread, same specimen).
#include "Specimen.h"

#include "common/ElasticLimitBracket.h"
#include "common/ProgramRunner.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;

namespace {

LoadingProgram locating_program()
{
  LoadingProgram program;
  Stage stage;
  stage.name = "isochoric";
  stage.isochoric = true;
  stage.lambda = 0.0;
  stage.isochoric_rate = 1.0;
  stage.stop_any = {parse_condition("gamma_max >= 0.05", "test")};
  stage.max_duration = 0.1;
  stage.unload_at = {parse_trigger("gamma_max >= 0.002", "test"), parse_trigger("gamma_max >= 0.04", "test")};
  stage.locate_elastic_limit = true;
  stage.elastic_limit_tolerance = 0.001;
  program.stages = {stage};
  program.sample_interval = 0.0005; // gamma_max grows by about 0.001 per sample
  program.validate();
  return program;
}

} // namespace

TEST(ElasticLimitBisection, TinyDemSpecimenBracketIsNarrowerThanTheToleranceAndRepeatsBitForBit)
{
  const LoadingProgram program = locating_program();
  const auto start = std::chrono::steady_clock::now();
  DemEngine engine(consolidated().system, engine_parameters());
  const Response r = ProgramRunner(program, engine).run();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::vector<BranchPoint> points = branch_points(r, 0, r.samples.front());
  const LimitSearch s = search_limit(points, s0_residual_threshold);
  ASSERT_TRUE(s.bracketed()) << "the planned branches should straddle 1 %";
  EXPECT_LT(s.lower->residual, 0.01);
  EXPECT_GE(s.upper->residual, 0.01);
  EXPECT_LE(s.width(), program.stages[0].elastic_limit_tolerance);
  EXPECT_GT(s.width(), 0.0);
  int bisections = 0;
  for (const BranchRecord &b : r.branches) {
    bisections += b.bisection() ? 1 : 0;
    EXPECT_TRUE(b.reached_target) << "branch " << b.id;
  }
  EXPECT_GE(bisections, 3);
  std::printf("[dem bisection] bracket [%.4f, %.4f] %% (residuals %.3f, %.3f %%), %d bisection branches, "
              "%zu samples, %.2f s\n", s.lower->x * 100, s.upper->x * 100, s.lower->residual * 100,
              s.upper->residual * 100, bisections, r.samples.size(), seconds);
  for (const BranchPoint &p : points)
    std::printf("  branch %d: start %.4f %%, residual %.4f %%%s\n", p.id, p.x * 100, p.residual * 100,
                p.bisection ? " (bisection)" : "");

  DemEngine again(consolidated().system, engine_parameters());
  const Response r2 = ProgramRunner(program, again).run();
  ASSERT_EQ(r.samples.size(), r2.samples.size());
  for (std::size_t k = 0; k < r.samples.size(); ++k)
    ASSERT_TRUE(r.samples[k].time == r2.samples[k].time && r.samples[k].strain == r2.samples[k].strain &&
                r.samples[k].stress == r2.samples[k].stress && r.samples[k].extras == r2.samples[k].extras)
      << "sample " << k;
  ASSERT_EQ(r.branches.size(), r2.branches.size());
  for (std::size_t k = 0; k < r.branches.size(); ++k)
    EXPECT_EQ(r.branches[k].residual_gamma, r2.branches[k].residual_gamma) << "branch " << k;
}
