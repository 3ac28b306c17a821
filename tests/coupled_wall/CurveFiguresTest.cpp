// The measures of the comparison, on inputs with known answers: the sampled solid fraction
// of a box, the window means and peak of a triaxial curve.
#include "coupled/wall/CurveMetrics.h"
#include "coupled/wall/PackingState.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geocomp::coupled;
using geocomp::dem::Vec3;

TEST(SampledSolidFraction, CountsOnlyThePartOfEachSphereInsideTheBox)
{
  const double r = 1e-3, h = r / 20.0, sphere = 4.0 / 3.0 * M_PI * r * r * r;
  const Vec3 lo = Vec3::Zero(), hi = Vec3::Constant(4e-3);
  const double box = 64e-9;
  // Whole, cut in half by a face, in a quarter by an edge, an eighth by a corner, outside.
  EXPECT_NEAR(sampled_solid_fraction({Vec3(2e-3, 2e-3, 2e-3)}, {r}, lo, hi, h), sphere / box, 2e-3 * sphere / box);
  EXPECT_NEAR(sampled_solid_fraction({Vec3(0.0, 2e-3, 2e-3)}, {r}, lo, hi, h), 0.5 * sphere / box, 2e-3 * sphere / box);
  EXPECT_NEAR(sampled_solid_fraction({Vec3(4e-3, 4e-3, 2e-3)}, {r}, lo, hi, h), 0.25 * sphere / box, 2e-3 * sphere / box);
  EXPECT_NEAR(sampled_solid_fraction({Vec3(0.0, 0.0, 4e-3)}, {r}, lo, hi, h), 0.125 * sphere / box, 2e-3 * sphere / box);
  EXPECT_EQ(sampled_solid_fraction({Vec3(-1.5e-3, 2e-3, 2e-3)}, {r}, lo, hi, h), 0.0);
  // Two overlapping spheres count their lens once (DEM-NOTES section 8, equal radii r at distance s).
  const double s = 1e-3;
  const double pair = sampled_solid_fraction({Vec3(1.5e-3, 2e-3, 2e-3), Vec3(2.5e-3, 2e-3, 2e-3)}, {r, r}, lo, hi, h);
  const double lens = M_PI * (2.0 * r - s) * (2.0 * r - s) * (s * s + 2.0 * s * 2.0 * r) / (12.0 * s);
  EXPECT_NEAR(pair, (2.0 * sphere - lens) / box, 2e-3 * sphere / box);
}

namespace {
/// q/p rising linearly to 0.8 at 4 % then flat, with +-0.1 alternating on every point;
/// eps_v = -0.1 eps_a; a point every 0.1 % to `end`.
TriaxialCurve synthetic_curve(double end)
{
  TriaxialCurve c;
  for (int k = 0; k * 1e-3 <= end + 1e-12; ++k) {
    TriaxialPoint p;
    p.axial_strain = k * 1e-3;
    p.volumetric_strain = -0.1 * p.axial_strain;
    p.pressure = 1e5;
    p.deviator = p.pressure * (std::min(0.8, 20.0 * p.axial_strain) + (k % 2 == 0 ? 0.1 : -0.1));
    c.push_back(p);
  }
  return c;
}
} // namespace

TEST(CurveMetrics, ReadsEveryFigureAsAWindowMeanSoThatPointToPointNoiseIsNotThePeak)
{
  const CurveMetrics m = curve_metrics(synthetic_curve(0.10));
  // Windows of 0.5 % hold 5 or 6 points: the alternating +-0.1 leaves at most 0.1 / 5.
  EXPECT_NEAR(m.peak_stress_ratio, 0.8, 0.021);
  EXPECT_GT(m.peak_strain, 0.039);
  EXPECT_NEAR(m.stress_ratio_2, 0.4, 0.021);
  EXPECT_NEAR(m.stress_ratio_5, 0.8, 0.021);
  EXPECT_NEAR(m.stress_ratio_10, 0.8, 0.021);
  EXPECT_NEAR(m.volumetric_5, -0.005, 1e-12);
  // The last window is [end - w, end]: its mean strain is 9.75 %.
  EXPECT_NEAR(m.volumetric_10, -0.00975, 1e-12);
  // A curve that ends at 6 % has no figure at 10 %.
  const CurveMetrics short_curve = curve_metrics(synthetic_curve(0.06));
  EXPECT_TRUE(std::isnan(short_curve.stress_ratio_10));
  EXPECT_TRUE(std::isnan(short_curve.volumetric_10));
  EXPECT_NEAR(short_curve.stress_ratio_5, 0.8, 0.021);
}
