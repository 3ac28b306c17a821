// The cross-engine rms (compare/CrossEngine.h) against closed forms: a stress ratio offset by
// a constant differs by that constant over the reference's largest ratio, whatever the other
// curve's sampling (linear interpolation of a linear curve is exact); an isochoric eps_v of
// round-off is divided by the 1e-3 floor, not by itself; samples outside the other's strain
// range are left out; the verdict rounds the larger rms up to 0.1 %.
#include "compare/CrossEngine.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::compare;

namespace {
/// A curve with x in [0, x_max] on n samples: p' = 1e5 Pa, q = (a + b x) p', eps_v = c x.
Curve linear_curve(int n, double x_max, double a, double b, double c)
{
  Curve k;
  for (int i = 0; i < n; ++i) {
    const double x = x_max * i / (n - 1);
    k.x.push_back(x);
    k.y.push_back(1e5 * (a + b * x));
    k.p.push_back(-1e5);
    k.q.push_back(1e5 * (a + b * x));
    k.eps_v.push_back(c * x);
  }
  return k;
}
} // namespace

TEST(CrossEngine, AnOffsetStressRatioGivesTheOffsetOverTheLargestRatioOnEveryCommonSample)
{
  const Curve ref = linear_curve(21, 0.02, 0.0, 30.0, -0.5);  // eta up to 0.6, eps_v down to -0.01
  const Curve other = linear_curve(7, 0.03, 0.012, 30.0, -0.5); // coarser, longer, eta + 0.012
  const CrossEngineTable t = cross_engine_table({"DEM", ref}, {"LIGGGHTS", other}, {});
  EXPECT_EQ(t.common_samples, 21u);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_NEAR(t.rows[0].engines, 0.012 / 0.6, 1e-12);
  EXPECT_NEAR(t.rows[0].scale, 0.6, 1e-12);
  EXPECT_NEAR(t.rows[1].engines, 0.0, 1e-12);
  EXPECT_NEAR(t.rows[2].engines, 0.012e5 / 0.6e5, 1e-12);
  EXPECT_EQ(t.verdict.rfind("engines agree within 2.0 %", 0), 0u) << t.verdict;
  EXPECT_TRUE(t.scatter_note.empty());
}

TEST(CrossEngine, OnlyTheReferencesSamplesInsideTheOtherCurvesRangeCount)
{
  const Curve ref = linear_curve(21, 0.02, 0.0, 30.0, 0.0);
  const Curve other = linear_curve(11, 0.0105, 0.0, 30.0, 0.0);
  const auto [rms, n] = relative_rms(ref, other, "stress_ratio");
  EXPECT_EQ(n, 11u);
  EXPECT_NEAR(rms, 0.0, 1e-12);
}

TEST(CrossEngine, AnIsochoricVolumetricStrainIsMeasuredAgainstTheFloorAndSpecimensSitBeside)
{
  const Curve ref = linear_curve(11, 0.1, 0.2, 5.0, 1e-9);   // eps_v: round-off
  const Curve other = linear_curve(11, 0.1, 0.2, 5.0, 3e-9);
  const Curve seed = linear_curve(11, 0.1, 0.25, 5.0, 0.0); // eta + 0.05 over a largest 0.7
  const CrossEngineTable t = cross_engine_table({"DEM", ref}, {"LIGGGHTS", other}, {{"seed 2", seed}});
  EXPECT_NEAR(t.rows[1].scale, 1e-3, 1e-15);
  const double ev = std::sqrt((4.0 + 16.0 + 36.0 + 64.0 + 100.0 + 144.0 + 196.0 + 256.0 + 324.0 + 400.0) / 11.0) *
                    1e-11 / 1e-3; // (3e-9 - 1e-9) x_i / 0.1 on x_i = 0, 0.01, ..., 0.1
  EXPECT_NEAR(t.rows[1].engines, ev, 1e-12);
  ASSERT_EQ(t.rows[0].specimens.size(), 1u);
  EXPECT_NEAR(t.rows[0].specimens[0], 0.05 / 0.7, 1e-12);
  EXPECT_NE(t.scatter_note.find("within the specimen-to-specimen scatter"), std::string::npos) << t.scatter_note;
}
