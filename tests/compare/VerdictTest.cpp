// The Rudnicki-Rice verdict: zero crossings along a path and the difference table.
#include "compare/Verdict.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::compare;

// h - h_crit falls linearly through zero: the crossing and its angle are interpolated.
TEST(Verdict, FirstCrossingInterpolatesStrainAndAngle)
{
  std::vector<double> strain, margin, angle;
  for (int i = 0; i <= 10; ++i) {
    strain.push_back(0.001 * i);
    margin.push_back(0.5 - 0.08 * i); // zero at i = 6.25
    angle.push_back(50.0 + i);
  }
  const OnsetEstimate e = first_crossing("Rudnicki-Rice", strain, margin, angle);
  ASSERT_TRUE(e.found);
  EXPECT_NEAR(e.strain, 0.00625, 1e-12);
  EXPECT_NEAR(e.angle_deg, 56.25, 1e-12);
  const OnsetEstimate none = first_crossing("FE", strain, std::vector<double>(11, 1.0), angle);
  EXPECT_FALSE(none.found);
  EXPECT_THROW(first_crossing("x", strain, margin, {1.0}), std::invalid_argument);
}

TEST(Verdict, DifferencesAndAgreementAgainstThePrediction)
{
  OnsetEstimate rr{"Rudnicki-Rice", true, 0.020, 56.5, true, ""};
  OnsetEstimate fe{"FE acoustic tensor", true, 0.021, 55.0, true, ""};
  OnsetEstimate dem{"DEM", true, 0.035, 62.0, true, ""};
  OnsetEstimate none{"other", false, 0.0, 0.0, true, ""};
  const RrVerdict v = rudnicki_rice_verdict(rr, {fe, dem, none});
  ASSERT_EQ(v.rows.size(), 3u);
  EXPECT_NEAR(v.rows[0].strain_difference, 0.001, 1e-15);
  EXPECT_NEAR(v.rows[0].strain_relative, 0.05, 1e-12);
  EXPECT_NEAR(v.rows[0].angle_difference_deg, -1.5, 1e-12);
  EXPECT_EQ(v.rows[0].verdict, "agrees");
  // 75 % late (tolerance 25 %) and 5.5 deg off (tolerance 5 deg).
  EXPECT_EQ(v.rows[1].verdict, "differs");
  EXPECT_FALSE(v.rows[2].comparable);
  EXPECT_EQ(v.rows[2].verdict, "no onset found");
  EXPECT_NE(v.summary.find("FE acoustic tensor only"), std::string::npos) << v.summary;
  VerdictTolerances loose;
  loose.strain_relative = 1.0;
  loose.angle_deg = 6.0;
  EXPECT_EQ(rudnicki_rice_verdict(rr, {dem}, loose).rows[0].verdict, "agrees");
}
