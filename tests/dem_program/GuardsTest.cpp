// The DEM engine's guards (issue 30, GuardLimits): a wall stress that is not finite and a
// particle outside the box stop the run; through the ProgramRunner the failure comes
// back as ProgramFailed with the samples recorded so far and a status that says which
// guard, where and when. (The box-edge and runaway-stress guards, and the results file and
// exit code of `geocomp dem`, are tested end to end in tests/cli/RunGuardsTest.cpp.)
#include "Specimen.h"

#include "common/ProgramRunner.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;

namespace {
/// Lateral 100 kPa, z shortened at 0.5/s to 1 %, sampled every millisecond.
LoadingProgram triaxial()
{
  LoadingProgram p;
  p.stages = {triaxial_stage(kPressure, 0.5, 0.01)};
  p.sample_interval = 0.001;
  return p;
}

/// A particle touching wall `w` of the consolidated specimen.
ParticleId touching_wall(const DemEngine &engine, int w)
{
  DemSystem probe = engine.system();
  probe.record_contact_forces();
  probe.step();
  for (const ContactRecord &c : probe.contacts())
    if (c.wall && int(c.i) == w)
      return c.j;
  ADD_FAILURE() << "no particle touches wall " << w;
  return 0;
}

/// The run of `engine` through the triaxial program, which must fail: its status.
std::string failure_of(DemEngine &engine, std::size_t &samples)
{
  const LoadingProgram p = triaxial();
  try {
    ProgramRunner(p, engine).run();
  } catch (const ProgramFailed &failed) {
    samples = failed.partial.samples.size();
    return failed.status;
  }
  ADD_FAILURE() << "the run did not fail";
  return "";
}
} // namespace

TEST(Guards, ANonFiniteStressStopsTheRunWithTheSamplesSoFar)
{
  DemEngine engine(consolidated().system, engine_parameters());
  // A spin that is not a number on a particle at the x+ wall: its wall contact's tangential
  // force, and with it the wall stress, stops being finite at the first step.
  const ParticleId id = touching_wall(engine, 1);
  DemSystem system = engine.system();
  system.set_angular_velocity(id, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  DemEngine broken(std::move(system), engine_parameters());
  std::size_t samples = 0;
  const std::string status = failure_of(broken, samples);
  EXPECT_EQ(status.rfind("failed in stage 1 'triaxial', after t = 0 s: guard: the wall stress is not finite", 0), 0u)
    << status;
  EXPECT_EQ(samples, 1u); // the first sample, before the step that failed
}

TEST(Guards, AParticleOutsideTheBoxStopsTheRunAtTheNextSample)
{
  // A particle found beyond the z+ wall (tunnelled out, or imported there) fails the run
  // at the next sample, here the first one: nothing was recorded.
  DemEngine engine(consolidated().system, engine_parameters());
  const ParticleId id = touching_wall(engine, 5);
  DemSystem system = engine.system();
  Vec3 x = system.particles().x[system.index_of(id)];
  x.z() = system.wall(5).point.z() + 0.02;
  system.set_position(id, x);
  DemEngine broken(std::move(system), engine_parameters());
  std::size_t samples = 1;
  const std::string status = failure_of(broken, samples);
  EXPECT_NE(status.find("guard: particle " + std::to_string(id) + " has left the box along z"), std::string::npos)
    << status;
  EXPECT_EQ(samples, 0u);
}

TEST(Guards, ACarefulRunMeetsNoGuard)
{
  // The same program on the untouched specimen runs to its stop condition.
  DemEngine engine(consolidated().system, engine_parameters());
  const LoadingProgram p = triaxial();
  const Response r = ProgramRunner(p, engine).run();
  EXPECT_EQ(completion_status(r, p), "complete");
  EXPECT_LE(r.samples.back().strain(2, 2), -0.01 + 1e-9);
}
