#include "coupled/wall/CurveMetrics.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace geocomp::coupled {

namespace {
double ratio(const TriaxialPoint &p) { return p.stress_ratio(); }
double volumetric(const TriaxialPoint &p) { return p.volumetric_strain; }

/// The window about e, kept inside [0, end]; NaN when the curve ends before e.
double at(const TriaxialCurve &c, double e, double w, double (*value)(const TriaxialPoint &))
{
  const double end = c.back().axial_strain;
  if (end < e - 1e-9)
    return std::numeric_limits<double>::quiet_NaN();
  const double hi = std::min(e + 0.5 * w, end), lo = std::min(e - 0.5 * w, end - w);
  return window_mean(c, lo, hi, value);
}
} // namespace

CurveMetrics curve_metrics(const TriaxialCurve &c, double w)
{
  if (c.empty())
    throw std::invalid_argument("curve_metrics: an empty curve");
  CurveMetrics m;
  m.peak_stress_ratio = -1.0;
  for (const TriaxialPoint &p : c) {
    const double mean = at(c, p.axial_strain, w, ratio);
    if (mean > m.peak_stress_ratio) {
      m.peak_stress_ratio = mean;
      m.peak_strain = p.axial_strain;
    }
  }
  m.stress_ratio_2 = at(c, 0.02, w, ratio);
  m.stress_ratio_5 = at(c, 0.05, w, ratio);
  m.stress_ratio_10 = at(c, 0.10, w, ratio);
  m.volumetric_5 = at(c, 0.05, w, volumetric);
  m.volumetric_10 = at(c, 0.10, w, volumetric);
  return m;
}

} // namespace geocomp::coupled
