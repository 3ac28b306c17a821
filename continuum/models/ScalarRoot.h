#pragma once
// A safeguarded scalar root finder for the local problems of the return maps.
//
// Why: with piecewise-linear hardening tables the local residual has kinks, and a plain
// Newton iteration can cycle across a kink. The returns therefore try Newton first
// (quadratic, usually 2-4 iterations) and fall back to this bracketing solver, which
// cannot fail once a sign change is bracketed: it expands an upper bound until the sign
// changes, then runs the Illinois variant of regula falsi with bisection steps.
#include <functional>

namespace geocomp::continuum {

struct ScalarRootResult {
  double x = 0.0;
  double f = 0.0;
  int evaluations = 0;
  bool converged = false;
};

/// Root of f on [lo, lo + expanding), given f(lo) < 0 and f increasing towards the root.
/// The interval grows from `initial_width` by doubling (at most 200 times). Stops when the
/// bracket is below x_tolerance or |f| <= f_tolerance.
ScalarRootResult bracketed_root(const std::function<double(double)> &f, double lo, double f_lo,
                                double initial_width, double x_tolerance, double f_tolerance);

} // namespace geocomp::continuum
