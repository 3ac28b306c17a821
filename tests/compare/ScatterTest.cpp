// The specimen-to-specimen band of a metric and the verdict on an engine's value
// (compare/Scatter.h): inside the band, outside it, at its edge within the tolerance, and
// undefined where the value or the band is.
#include "compare/Scatter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace geocomp::compare;

namespace {
MetricSet with_peak(double peak_stress)
{
  MetricSet m;
  m.peak_stress = peak_stress;
  return m;
}

const ScatterRow &row(const ScatterTable &t, const std::string &key)
{
  for (const auto &r : t.rows)
    if (r.key == key)
      return r;
  throw std::runtime_error("no row " + key);
}
} // namespace

TEST(SpecimenScatter, AValueInsideTheSpecimensBandIsWithinItAndOneBeyondItIsOutside)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const ScatterTable t =
    scatter_table({"seed 7", "seed 8", "seed 9"}, {with_peak(1e6), with_peak(3e6), with_peak(2.5e6)},
                  {"inside", "above", "at the edge", "past the edge", "undefined"},
                  {with_peak(2e6), with_peak(4e6), with_peak(3e6 * (1 + 1e-7)), with_peak(3e6 * (1 + 1e-5)), with_peak(nan)});
  const ScatterRow &peak = row(t, "peak_stress_MPa");
  EXPECT_DOUBLE_EQ(peak.low, 1.0); // MPa, as the report shows it
  EXPECT_DOUBLE_EQ(peak.high, 3.0);
  ASSERT_EQ(peak.verdicts.size(), 5u);
  EXPECT_EQ(peak.verdicts[0], "within scatter");
  EXPECT_EQ(peak.verdicts[1], "outside");
  EXPECT_EQ(peak.verdicts[2], "within scatter");
  EXPECT_EQ(peak.verdicts[3], "outside");
  EXPECT_EQ(peak.verdicts[4], "n/a");
  // A metric no specimen defines has no band: every verdict is n/a.
  const ScatterRow &softening = row(t, "softening_modulus_MPa");
  EXPECT_TRUE(std::isnan(softening.low));
  for (const auto &v : softening.verdicts)
    EXPECT_EQ(v, "n/a");
}
