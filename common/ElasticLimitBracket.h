#pragma once
// @sect3{The elastic limit bracketed by unloading branches}
//
// Why it exists: S0 defines the elastic limit B of a shear test as the strain up to which an
// unloading branch gives back all but 1 % of the shear strain (residual gamma_max < 1 %).
// Branches placed at a few planned strains only bracket B coarsely (S0's own run: 3.0 % and
// 17.6 %); ProgramRunner narrows the bracket by bisection (more branches between its ends).
// This file says, from the branches recorded so far, where the bracket is.
//
// Measures, the same as the metrics' shear curve (compare/Metrics.h): the start of a branch
// is x = gamma_max of the logarithmic strain of the main-path state it left from, relative to
// the stage start, and its residual is gamma_max of the logarithmic strain at its last sample,
// relative to the stage start:
//     x = gamma_max(ln(I + eps_origin) - ln(I + eps_stage)),  r = gamma_max(ln(I + eps_end) - ln(I + eps_stage)).
// Branches are ordered by the time at which they left the main path (the main path's strain
// grows with time); only branches that reached their unloading target count.
#include "common/Response.h"

#include <optional>

namespace geocomp {

/// One branch as the bracket reads it.
struct BranchPoint {
  int id = 0;
  double time = 0.0;        ///< program time at which it left the main path
  double x = 0.0;           ///< its start strain (see the file comment)
  double residual = 0.0;    ///< its residual strain
  std::size_t origin = 0;   ///< Response sample it left from
  bool bisection = false;
};

/// The first crossing of the threshold along the main path: `upper` is the earliest branch
/// whose residual reaches the threshold, `lower` the latest branch before it whose residual
/// is below (either may be missing). A bracket exists when both do.
struct LimitSearch {
  std::optional<BranchPoint> lower, upper;
  bool bracketed() const { return lower && upper; }
  double width() const { return bracketed() ? upper->x - lower->x : 0.0; }
};

/// The branches of `stage` in main-path order, measured as in the file comment.
std::vector<BranchPoint> branch_points(const Response &response, int stage, const ResponseSample &stage_start);
/// Where the residual of those branches first reaches `threshold`.
LimitSearch search_limit(const std::vector<BranchPoint> &points, double threshold);

} // namespace geocomp
