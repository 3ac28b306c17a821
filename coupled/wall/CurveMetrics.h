#pragma once
// @sect3{The figures of a triaxial curve: peak stress ratio, values at set strains}
//
// Why it exists: a DEM curve fluctuates from point to point (a 500-sphere cell's q/p jumps
// by 0.1 between points 0.1 % of strain apart, as contacts slip), so a figure read at one
// point is as much noise as curve. Every figure here is a window mean: the mean over the
// points with axial strain in [e - w/2, e + w/2] (w = `window`, 0.5 % by default), the last
// window of a curve ending at e_end taken as [e_end - w, e_end]:
//  - the peak stress ratio: the largest window mean of q/p over window centres at the
//    points, and the axial strain of that centre;
//  - q/p at 2, 5 and 10 % and the volumetric strain at 5 and 10 % (NaN where the curve
//    ends before that strain).
#include "coupled/wall/TriaxialCurve.h"

#include <cstddef>
#include <stdexcept>

namespace geocomp::coupled {

struct CurveMetrics {
  double peak_stress_ratio = 0.0;
  double peak_strain = 0.0;          ///< axial strain of the peak's window centre
  double stress_ratio_2 = 0.0, stress_ratio_5 = 0.0, stress_ratio_10 = 0.0;
  double volumetric_5 = 0.0, volumetric_10 = 0.0;  ///< tension positive
};

/// Mean of `value(point)` over the points with axial strain in [lo, hi]; throws
/// std::invalid_argument when none lies there.
template <class Value>
double window_mean(const TriaxialCurve &curve, double lo, double hi, Value value)
{
  double sum = 0.0;
  std::size_t n = 0;
  for (const TriaxialPoint &p : curve)
    if (p.axial_strain >= lo && p.axial_strain <= hi) {
      sum += value(p);
      ++n;
    }
  if (n == 0)
    throw std::invalid_argument("window_mean: no point of the curve between these axial strains");
  return sum / double(n);
}

/// The figures above; an empty curve throws std::invalid_argument.
CurveMetrics curve_metrics(const TriaxialCurve &curve, double window = 0.005);

} // namespace geocomp::coupled
