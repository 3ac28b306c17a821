#pragma once
// A safeguarded scalar root finder for the local problems of the return maps.
//
// Why: with piecewise-linear hardening tables the local residual has kinks, and a plain
// Newton iteration can cycle across a kink. The returns therefore try Newton first
// (quadratic, usually 2-4 iterations) and fall back to this bracketing solver, which
// cannot fail once a sign change is bracketed: it expands an upper bound until the sign
// changes, then runs the Illinois variant of regula falsi with bisection steps.
#include <cmath>
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

/// The Newton part of the scalar returns (Drucker-Prager cone and apex, Mohr-Coulomb
/// apex), shared so that all three stop by the same rules: at most 25 steps from `x`, done
/// when |r| <= 1e-14 scale, or when a step is below 1e-15 |x| and |r| <= 1e-11 scale; a
/// zero slope gives up. `evaluate(x)` returns a value with members r (residual) and dr
/// (its slope); `value` holds evaluate(x) on entry. On return `x` and `value` are the last
/// iterate and its evaluation, and `iterations` has been incremented once per step. Returns
/// whether it converged; the caller falls back to bracketed_root when not.
template <class Evaluate, class Value>
bool newton_root(const Evaluate &evaluate, double &x, Value &value, double scale, int &iterations)
{
  for (int it = 0; it < 25; ++it) {
    if (std::abs(value.r) <= 1e-14 * scale)
      return true;
    if (value.dr == 0.0)
      return false;
    const double step = -value.r / value.dr;
    x += step;
    value = evaluate(x);
    ++iterations;
    if (std::abs(step) <= 1e-15 * std::abs(x) && std::abs(value.r) <= 1e-11 * scale)
      return true;
  }
  return false;
}

} // namespace geocomp::continuum
