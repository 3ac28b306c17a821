// See PlasticReach.h: plastic sample intervals within each free knot's reach.
#include "compare/calibrate/PlasticReach.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace geocomp::calibration {

namespace {
const HardeningTable &table_of(const ContinuumParameters &p, FreeParameter::Family f)
{
  return f == FreeParameter::Family::Cohesion ? p.cohesion
         : f == FreeParameter::Family::Friction ? p.friction_angle
                                                 : p.dilatancy_angle;
}

} // namespace

std::vector<std::string> unconstrained_strength(const std::vector<FreeParameter> &free,
                                                const ContinuumParameters &calibrated,
                                                const std::vector<Response> &fitted, std::size_t min_intervals)
{
  std::vector<std::string> warnings;
  double kappa_max = 0.0;
  for (const Response &r : fitted) {
    const int k = r.extra_index("kappa");
    for (const ResponseSample *s : r.path(0))
      if (k >= 0)
        kappa_max = std::max(kappa_max, s->extras[std::size_t(k)]);
  }
  for (const FreeParameter &p : free) {
    using Family = FreeParameter::Family;
    if (p.family != Family::Cohesion && p.family != Family::Friction && p.family != Family::Dilatancy)
      continue; // not a table knot (E, nu, the Nikolaevsky model's numbers)
    const auto &knots = table_of(calibrated, p.family).points;
    const std::size_t k = std::size_t(p.knot);
    const double lower = k == 0 ? -std::numeric_limits<double>::infinity() : knots[k - 1].first;
    const double upper = k + 1 == knots.size() ? std::numeric_limits<double>::infinity() : knots[k + 1].first;
    std::size_t intervals = 0;
    for (const Response &r : fitted) {
      const int e = r.extra_index("kappa");
      if (e < 0)
        continue;
      const std::vector<const ResponseSample *> path = r.path(0);
      for (std::size_t i = 1; i < path.size(); ++i) {
        const double a = path[i - 1]->extras[std::size_t(e)], b = path[i]->extras[std::size_t(e)];
        if (b > a && b > lower && a < upper)
          ++intervals;
      }
    }
    if (intervals >= min_intervals)
      continue;
    std::ostringstream w;
    w.precision(3);
    w << p.name << ": the calibrated material point flows plastically in " << intervals
      << (intervals == 1 ? " sample interval" : " sample intervals") << " within this knot's reach (kappa ";
    if (k == 0)
      w << "from the onset of yield";
    else
      w << "above " << lower;
    if (k + 1 < knots.size())
      w << " and below " << upper;
    w << "; the targets reach kappa = " << kappa_max << "), so the targets cannot constrain it: its value and standard error bound the strength rather than "
         "measure it. Fix it, or add a target that yields there (a longer path, another confinement).";
    warnings.push_back(w.str());
  }
  return warnings;
}

} // namespace geocomp::calibration
