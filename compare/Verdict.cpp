#include "compare/Verdict.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace geocomp::compare {

OnsetEstimate first_crossing(const std::string &source, const std::vector<double> &strain,
                             const std::vector<double> &indicator, const std::vector<double> &angle_deg)
{
  if (strain.size() != indicator.size() || (!angle_deg.empty() && angle_deg.size() != strain.size()))
    throw std::invalid_argument("first_crossing: strain, indicator and angle need equal lengths");
  OnsetEstimate e;
  e.source = source;
  e.has_angle = !angle_deg.empty();
  for (std::size_t i = 0; i < strain.size(); ++i) {
    if (!std::isfinite(indicator[i]) || indicator[i] > 0.0)
      continue;
    e.found = true;
    if (i == 0 || !std::isfinite(indicator[i - 1])) {
      e.strain = strain[i];
      e.angle_deg = e.has_angle ? angle_deg[i] : 0.0;
      e.note = i == 0 ? "indicator already <= 0 at the first point" : "";
    } else {
      const double t = indicator[i - 1] / (indicator[i - 1] - indicator[i]);
      e.strain = strain[i - 1] + t * (strain[i] - strain[i - 1]);
      e.angle_deg = e.has_angle ? angle_deg[i - 1] + t * (angle_deg[i] - angle_deg[i - 1]) : 0.0;
    }
    return e;
  }
  e.note = "no crossing along the path";
  return e;
}

RrVerdict rudnicki_rice_verdict(const OnsetEstimate &predicted, const std::vector<OnsetEstimate> &engines,
                                const VerdictTolerances &tol)
{
  RrVerdict v;
  v.predicted = predicted;
  v.tolerances = tol;
  int agree = 0, compared = 0;
  std::ostringstream names;
  for (const auto &e : engines) {
    VerdictRow r;
    r.onset = e;
    r.comparable = predicted.found && e.found;
    if (!r.comparable) {
      r.verdict = !e.found && predicted.found   ? "no onset found"
                  : e.found && !predicted.found ? "localized, not predicted"
                                                : "neither localizes";
      v.rows.push_back(r);
      continue;
    }
    ++compared;
    r.strain_difference = e.strain - predicted.strain;
    r.strain_relative = predicted.strain != 0.0 ? r.strain_difference / predicted.strain : NAN;
    const double allowed = std::max(tol.strain_absolute, tol.strain_relative * std::abs(predicted.strain));
    r.strain_agrees = std::abs(r.strain_difference) <= allowed;
    const bool angles = e.has_angle && predicted.has_angle;
    r.angle_difference_deg = angles ? e.angle_deg - predicted.angle_deg : NAN;
    r.angle_agrees = !angles || std::abs(r.angle_difference_deg) <= tol.angle_deg;
    r.verdict = r.strain_agrees && r.angle_agrees ? "agrees"
                : r.strain_agrees                 ? "angle differs"
                : r.angle_agrees                  ? "onset differs"
                                                  : "differs";
    if (r.verdict == "agrees") {
      ++agree;
      names << (agree > 1 ? ", " : "") << e.source;
    }
    v.rows.push_back(r);
  }
  std::ostringstream s;
  if (!predicted.found)
    s << "Rudnicki-Rice predicts no localization along this path.";
  else if (compared == 0)
    s << "No engine localized, so the prediction cannot be checked.";
  else if (agree == compared)
    s << "Rudnicki-Rice predicts the onset within tolerance for every engine that localized (" << names.str()
      << ").";
  else if (agree > 0)
    s << "Rudnicki-Rice agrees with " << names.str() << " only.";
  else
    s << "Rudnicki-Rice agrees with no engine within tolerance.";
  v.summary = s.str();
  return v;
}

} // namespace geocomp::compare
