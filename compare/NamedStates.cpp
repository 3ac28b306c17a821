#include "compare/NamedStates.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geocomp::compare {

namespace {
NamedState elastic_limit(const MetricSet &m)
{
  NamedState b{"B", "elastic limit (S0: residual strain after unloading reaches 1 %), " +
                      (m.elastic_limit_method.empty() ? std::string("not located") : m.elastic_limit_method)};
  b.found = std::isfinite(m.elastic_limit_strain);
  if (!b.found) {
    b.missing = "no elastic limit located on the reference curve";
    return b;
  }
  b.strain = m.elastic_limit_strain;
  b.stress = m.elastic_limit_stress;
  return b;
}

/// D: the first sample past the peak index whose smoothed stress fell by the drop; else the end.
NamedState post_peak(const Curve &c, const std::vector<double> &ys, std::size_t ipk, double y0,
                     const NamedStateOptions &o)
{
  NamedState d{"D", "first sample past the peak whose stress dropped by " + percent_label(o.post_peak_drop) +
                      " of the peak rise"};
  const double limit = ys[ipk] - o.post_peak_drop * (ys[ipk] - y0);
  for (std::size_t i = ipk + 1; i < ys.size(); ++i)
    if (ys[i] <= limit) {
      d.found = true;
      d.strain = c.x[i];
      d.stress = ys[i];
      return d;
    }
  if (ipk + 1 < ys.size()) {
    d.definition = "end of the main path (the stress never dropped by " + percent_label(o.post_peak_drop) +
                   " of the peak rise past the peak)";
    d.found = true;
    d.strain = c.x.back();
    d.stress = ys.back();
    return d;
  }
  d.missing = "the peak is the last sample: nothing past it";
  return d;
}
} // namespace

std::vector<NamedState> named_states(const Curve &c, const MetricSet &m, const OnsetEstimate *onset,
                                     const NamedStateOptions &o)
{
  std::vector<NamedState> out{elastic_limit(m)};
  NamedState peak{"peak", "maximum of the smoothed curve"};
  const std::vector<double> ys = moving_average(c.y, o.smoothing_half_window);
  if (ys.size() < 3 || !(ys.size() == c.x.size())) {
    peak.missing = "fewer than 3 samples on the reference curve";
    out.push_back(peak);
    NamedState d{"D", "past the peak"};
    d.missing = peak.missing;
    out.push_back(d);
  } else {
    const std::size_t ipk = static_cast<std::size_t>(std::max_element(ys.begin(), ys.end()) - ys.begin());
    peak.found = true;
    peak.strain = c.x[ipk];
    peak.stress = ys[ipk];
    if (ipk + 1 == ys.size())
      peak.definition += " (the last sample: the peak may not have been reached)";
    out.push_back(peak);
    out.push_back(post_peak(c, ys, ipk, c.y.front(), o));
  }
  if (onset) {
    NamedState s{"DEM onset", "localization onset, " + onset->source};
    s.found = onset->found && std::isfinite(onset->strain);
    if (s.found)
      s.strain = onset->strain;
    else
      s.missing = "no onset found (" + onset->source + ")";
    out.push_back(s);
  }
  return out;
}

std::string percent_label(double fraction)
{
  std::ostringstream s;
  s.precision(3);
  s << fraction * 100.0 << " %";
  return s.str();
}

} // namespace geocomp::compare
