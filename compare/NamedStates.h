#pragma once
// The named states of a stress-strain curve at which the report draws its maps (S0 Fig. 2:
// O-A-B-C-D-E, B the elastic limit, then the peak and softening): where, on the reference
// engine's curve (the DEM's), the maps of every engine are drawn side by side.
//
//   B       the elastic limit of the metrics (S0: residual strain after unloading reaches 1 %),
//           located by bisection or interpolated between branches (Metrics.h)
//   peak    the maximum of the smoothed curve (Metrics.h)
//   D       past the peak: the first main-path sample after the peak whose smoothed stress has
//           dropped by `post_peak_drop` of the peak rise,
//               y_D <= y_peak - f (y_peak - y_0),                          f = 0.05,
//           which on an isochoric program (y_0 = 0) is the program's own `peak_drop >= f`;
//           without such a drop, the end of the main path (when it lies past the peak)
//   onset   the DEM localization onset (particle local strain, Localization.h) when found
//
// A state that does not exist on the curve (no elastic limit located, no sample past the
// peak, no onset found) is kept with found = false and the reason, so that the report says
// so instead of leaving it out. Strains are in the curve's measure x (Metrics.h).
#include "compare/Metrics.h"
#include "compare/Verdict.h"

#include <string>
#include <vector>

namespace geocomp::compare {

struct NamedState {
  std::string name;        ///< "B", "peak", "D", "DEM onset"
  std::string definition;  ///< how it was found, for the report
  bool found = false;
  double strain = nan;     ///< in the curve's measure x (fraction)
  double stress = nan;     ///< y there [Pa], NaN for an onset between samples
  std::string missing;     ///< why it was not found
};

struct NamedStateOptions {
  double post_peak_drop = 0.05; ///< D: drop of the smoothed stress past the peak, fraction of the peak rise
  int smoothing_half_window = 2; ///< as MetricOptions: the smoothing the peak was found on
};

/// B, peak, D and (when `onset` is given) the onset, in that order, from a curve and its
/// metrics (compute_metrics with the same smoothing).
std::vector<NamedState> named_states(const Curve &curve, const MetricSet &metrics, const OnsetEstimate *onset,
                                     const NamedStateOptions &options = {});

/// A strain fraction as a label with three significant digits ("5.81 %").
std::string percent_label(double fraction);

} // namespace geocomp::compare
