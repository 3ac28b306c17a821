#include "common/LoadingProgram.h"

#include <gtest/gtest.h>

using namespace geocomp;

namespace {
Stage isochoric_stage(double lambda)
{
  Stage s;
  s.name = "shear";
  s.isochoric = true;
  s.lambda = lambda;
  s.isochoric_rate = 0.2;
  s.stop_any = {parse_condition("gamma_max >= 0.3", "test")};
  s.max_duration = 10;
  return s;
}
} // namespace

class IsochoricProgram : public ::testing::TestWithParam<double> {};

// S0 eq. (3) imposed as positions keeps the box volume constant to round-off.
TEST_P(IsochoricProgram, BoxVolumeConstantToRoundOff)
{
  const Stage s = isochoric_stage(GetParam());
  StageControl c;
  c.stage = &s;
  c.t0 = 0.3;
  c.eps0 = Vector3(-0.01, 0.002, 0.004); // any start: the volume at t0 is kept
  const double v0 = (1 + c.eps0[0]) * (1 + c.eps0[1]) * (1 + c.eps0[2]);
  for (double t = c.t0; t < c.t0 + 1.5; t += 0.01) {
    const double v = (1 + c.strain(0, t)) * (1 + c.strain(1, t)) * (1 + c.strain(2, t));
    EXPECT_NEAR(v, v0, 4e-16 * v0) << "t = " << t;
  }
  // eq. (3): x moves in at v0, y at lambda v0.
  EXPECT_NEAR(c.strain(0, c.t0 + 1.0), c.eps0[0] - 0.2, 1e-15);
  EXPECT_NEAR(c.strain(1, c.t0 + 1.0), c.eps0[1] - 0.2 * GetParam(), 1e-15);
}

// The z rate handed to engines is the time derivative of the imposed position.
TEST_P(IsochoricProgram, StrainRateIsDerivativeOfStrain)
{
  const Stage s = isochoric_stage(GetParam());
  for (double direction : {1.0, -1.0}) {
    StageControl c;
    c.stage = &s;
    c.direction = direction;
    for (double t : {0.1, 0.5, 1.0}) {
      const double h = 1e-6;
      for (int a = 0; a < 3; ++a) {
        const double fd = (c.strain(a, t + h) - c.strain(a, t - h)) / (2 * h);
        EXPECT_NEAR(c.strain_rate(a, t), fd, 1e-7) << "axis " << a;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Lambdas, IsochoricProgram, ::testing::Values(-1.0, -0.5, 0.0, 0.5, 1.0));

TEST(LoadingProgramValidation, RejectsLambdaOutsideUnitInterval)
{
  LoadingProgram p;
  p.sample_interval = 0.01;
  p.stages.push_back(isochoric_stage(1.5));
  try {
    p.validate();
    FAIL() << "lambda = 1.5 accepted";
  } catch (const ProgramError &e) {
    EXPECT_EQ(e.where, "program/stage 1/lambda");
  }
}

TEST(LoadingProgramValidation, RejectsEmptyProgram)
{
  LoadingProgram p;
  p.sample_interval = 0.01;
  EXPECT_THROW(p.validate(), ProgramError);
}

TEST(Conditions, ParseQuantityComparisonAndValue)
{
  const Condition c = parse_condition(" eps_zz <= -0.1 ", "w");
  EXPECT_EQ(c.quantity, Quantity::EpsZZ);
  EXPECT_FALSE(c.at_least);
  EXPECT_DOUBLE_EQ(c.value, -0.1);
  EXPECT_THROW(parse_condition("eps_zz < -0.1", "w"), ProgramError);
  EXPECT_THROW(parse_condition("foo >= 1", "w"), ProgramError);
  EXPECT_THROW(parse_condition("time >= abc", "w"), ProgramError);
  EXPECT_THROW(parse_condition("time >= 1 <= 2", "w"), ProgramError);
}
