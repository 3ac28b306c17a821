// The wall servo holds its goals (issue 30): on S0's constant-lateral-pressure program
// (2 MPa, 3 000 spheres, friction angles 0, 30 and 60 deg), on a 100 kPa triaxial test of a
// loose and of a dense specimen, and on an ordered FCC array under triaxial load, every
// stress-controlled axis stays within 0.5 % of its goal as a mean over each sampling
// interval and within 2 % at the sample instants, from the end of the first 0.5 % of axial
// strain on, and the servo walls do not oscillate (their speed changes sign at fewer than
// 1 % of the steps). The interval mean is the time-weighted mean of the steps' wall
// stresses, and the servo's learned speed survives an unloading branch, so the main path
// after a branch is the main path without it, bit for bit.
#include "Specimen.h"

#include "common/ProgramRunner.h"
#include "compare/case/CaseDescription.h"
#include "dem/program/LatticePacking.h"
#include "dem/program/ServoReport.h"
#include "dem/program/SpecimenPreparation.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace geocomp;
using namespace geocomp::dem;
using namespace geocomp::dem::test;

namespace {
std::string source_dir()
{
  return std::getenv("GEOCOMP_SOURCE_DIR") ? std::getenv("GEOCOMP_SOURCE_DIR") : GEOCOMP_SOURCE_DIR;
}

/// The targets, with the report printed for the log.
void expect_servo_holds(const Response &r, const LoadingProgram &program, const std::string &label)
{
  const ServoReport report = servo_report(r, program);
  std::printf("[servo %s]\n%s", label.c_str(), report.describe().c_str());
  ASSERT_FALSE(report.axes.empty());
  for (const AxisDeviation &a : report.axes)
    EXPECT_GT(a.samples, 5u) << label;
  EXPECT_LE(report.worst_mean(), 0.005) << label;
  EXPECT_LE(report.worst_instantaneous(), 0.02) << label;
  EXPECT_LT(report.reversals, 0.01 * report.steps) << label;
}

/// S0 program 2 on the case's own specimen (radius growth, consolidation to 2 MPa).
void check_s0_lateral_pressure(const std::string &angle)
{
  const CaseDescription c = read_case(source_dir() + "/cases/small/s0_lateral_pressure_phi" + angle + "_n3000.prm");
  PreparedSpecimen s = prepare_specimen(c);
  DemEngineParameters p = DemEngineParameters::from_case(c.dem);
  DemEngine engine(std::move(s.system), p);
  ProgramRunner runner(c.program, engine);
  const Response r = runner.run();
  EXPECT_LE(r.samples.back().strain(2, 2), -0.1 + 1e-9);
  expect_servo_holds(r, c.program, "S0 program 2, friction angle " + angle + " deg");
}

/// A 100 kPa triaxial test to eps_zz = -5 % at 0.5/s (inertial number ~1e-4).
void check_triaxial(const Consolidated &specimen, const std::string &label)
{
  DemEngine engine(specimen.system, engine_parameters());
  LoadingProgram program;
  program.stages = {triaxial_stage(kPressure, 0.5, 0.05)};
  program.sample_interval = 0.001;
  ProgramRunner runner(program, engine);
  const Response r = runner.run();
  expect_servo_holds(r, program, label);
}
} // namespace

TEST(Servo, HoldsS0LateralPressureAtFrictionAngle0) { check_s0_lateral_pressure("0"); }
TEST(Servo, HoldsS0LateralPressureAtFrictionAngle30) { check_s0_lateral_pressure("30"); }
TEST(Servo, HoldsS0LateralPressureAtFrictionAngle60) { check_s0_lateral_pressure("60"); }

// Compacted frictionless, the 2744 spheres reach a packing fraction of 0.617 (walls
// included); compacted with mu_s = 0.4 on, 0.570.
TEST(Servo, Holds100kPaTriaxialOnADenseSpecimen)
{
  const Consolidated &dense = consolidated_large();
  std::printf("[servo] packing fraction of the dense specimen %.4f\n", packing_fraction(dense.system));
  EXPECT_GT(packing_fraction(dense.system), 0.60);
  check_triaxial(dense, "100 kPa triaxial, dense");
}

TEST(Servo, Holds100kPaTriaxialOnALooseSpecimen)
{
  const Consolidated &loose = consolidated_large_loose();
  std::printf("[servo] packing fraction of the loose specimen %.4f\n", packing_fraction(loose.system));
  EXPECT_LT(packing_fraction(loose.system), 0.59);
  check_triaxial(loose, "100 kPa triaxial, loose");
}

namespace {
/// An FCC array of 1099 touching spheres: the servo first brings every axis to 100 kPa,
/// then holds x and y there while z is shortened through the array's collapse.
Response fcc_triaxial(const DemEngineParameters &p, LoadingProgram &program)
{
  DemSystem system = make_system(fcc_lattice(6, 0.005, 2650.0), contact_parameters(), dem_parameters());
  DemEngine engine(std::move(system), p);
  Stage iso;
  iso.name = "isotropic";
  iso.axes = {{AxisDrive::stress(-kPressure), AxisDrive::stress(-kPressure), AxisDrive::stress(-kPressure)}};
  iso.stop_any = {parse_condition("stage_time >= 0.02", "test")};
  iso.max_duration = 0.02;
  program.stages = {iso, triaxial_stage(kPressure, 0.5, 0.05)};
  program.sample_interval = 0.001;
  return ProgramRunner(program, engine).run();
}
} // namespace

TEST(Servo, HoldsAnFccArrayUnderTriaxialLoad)
{
  LoadingProgram program;
  const Response r = fcc_triaxial(engine_parameters(), program);
  double peak = 0.0;
  for (const ResponseSample &s : r.samples)
    peak = std::max(peak, -s.stress(2, 2));
  std::printf("[servo fcc] largest axial stress %.4g Pa (the array collapses after it)\n", peak);
  EXPECT_GT(peak, 3.0 * kPressure);
  expect_servo_holds(r, program, "FCC array, 100 kPa triaxial");
}

TEST(Servo, ProportionalPartAloneLagsBehindTheFccCollapse)
{
  // The same test with the integral part off and the cap at 0.05 m/s (the servo before
  // issue 30): the lateral walls fall behind when the array collapses.
  DemEngineParameters p = engine_parameters();
  p.servo.integral_gain = 0.0;
  p.servo.kinematic_speed_ratio = 0.0;
  LoadingProgram program;
  const ServoReport report = servo_report(fcc_triaxial(p, program), program);
  std::printf("[servo fcc, proportional only]\n%s", report.describe().c_str());
  EXPECT_GT(report.worst_mean(), 0.005);
}

TEST(Servo, IntervalMeanIsTheTimeWeightedMeanOfTheStepStresses)
{
  DemEngine engine(consolidated().system, engine_parameters());
  const Stage stage = triaxial_stage(kPressure, 0.5, 0.01);
  StageControl control;
  control.stage = &stage;
  engine.begin_control(control);
  engine.measure(); // the interval starts here
  const double dt = engine.system().time_step();
  Tensor3 sum = Tensor3::Zero();
  double time = 0.0;
  for (int k = 0; k < 37; ++k) {
    const double t0 = engine.time();
    engine.advance_to(t0 + (k == 36 ? 0.4 : 1.0) * dt); // the last step shortened, as at a sample
    sum += (engine.time() - t0) * engine.wall_stress();
    time += engine.time() - t0;
  }
  const ResponseSample s = engine.measure();
  const Tensor3 expected = sum / time;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(s.stress_mean(i, j), expected(i, j), 1e-9 * kPressure) << i << j;
  EXPECT_GT((s.stress_mean - s.stress).norm(), 1e-6 * kPressure); // a mean, not the last value
  // The next interval starts afresh: right after a sample the mean is the instantaneous stress.
  const ResponseSample again = engine.measure();
  EXPECT_EQ(again.stress_mean, again.stress);
}

TEST(Servo, MainPathAfterABranchEqualsTheMainPathWithoutItBitForBit)
{
  // The servo's learned wall speed belongs to the drive: the branch reverses the drive and
  // starts its own, and the main path takes up its own again where it left it.
  LoadingProgram program;
  Stage stage = triaxial_stage(kPressure, 0.5, 0.006);
  program.stages = {stage};
  program.sample_interval = 0.001;
  DemEngine plain_engine(consolidated().system, engine_parameters());
  const Response plain = ProgramRunner(program, plain_engine).run();
  program.stages[0].unload_at = {parse_trigger("eps_zz <= -0.003", "test")};
  DemEngine branched_engine(consolidated().system, engine_parameters());
  const Response branched = ProgramRunner(program, branched_engine).run();
  ASSERT_EQ(branched.branches.size(), 1u);
  const auto a = plain.path(0), b = branched.path(0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k]->stress, b[k]->stress) << "sample " << k;
    EXPECT_EQ(a[k]->stress_mean, b[k]->stress_mean) << "sample " << k;
  }
}
