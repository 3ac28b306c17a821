#include "common/ElasticLimitBracket.h"

#include <algorithm>

namespace geocomp {

std::vector<BranchPoint> branch_points(const Response &response, int stage, const ResponseSample &stage_start)
{
  const Tensor3 e0 = logarithmic_strain(stage_start.strain);
  auto x_of = [&](const ResponseSample &s) { return gamma_max(logarithmic_strain(s.strain) - e0); };
  std::vector<BranchPoint> points;
  for (const BranchRecord &b : response.branches) {
    if (b.stage != stage || !b.reached_target || b.first_sample >= response.samples.size() ||
        b.last_sample >= response.samples.size())
      continue;
    const ResponseSample &origin = response.samples[b.first_sample];
    points.push_back({b.id, origin.time, x_of(origin), x_of(response.samples[b.last_sample]), b.first_sample,
                      b.bisection()});
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const BranchPoint &a, const BranchPoint &b) { return a.time < b.time; });
  return points;
}

LimitSearch search_limit(const std::vector<BranchPoint> &points, double threshold)
{
  LimitSearch s;
  for (const BranchPoint &p : points) {
    if (p.residual >= threshold) {
      s.upper = p;
      break;
    }
    s.lower = p;
  }
  return s;
}

} // namespace geocomp
