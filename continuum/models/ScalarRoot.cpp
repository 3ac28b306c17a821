#include "continuum/models/ScalarRoot.h"

#include <cmath>

namespace geocomp::continuum {

ScalarRootResult bracketed_root(const std::function<double(double)> &f, double lo, double f_lo,
                                double width, double x_tol, double f_tol) {
  ScalarRootResult r;
  if (!(f_lo < 0.0)) {
    r.x = lo;
    r.f = f_lo;
    r.converged = std::abs(f_lo) <= f_tol;
    return r;
  }
  double hi = lo + width, f_hi = f(hi);
  ++r.evaluations;
  for (int k = 0; k < 200 && f_hi < 0.0; ++k) {
    lo = hi;
    f_lo = f_hi;
    width *= 2.0;
    hi = lo + width;
    f_hi = f(hi);
    ++r.evaluations;
  }
  if (f_hi < 0.0 || !std::isfinite(f_hi))
    return r;
  // Illinois: regula falsi, halving the retained end's value when the same end is kept twice.
  int side = 0;
  for (int k = 0; k < 300; ++k) {
    double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(x > lo && x < hi))
      x = 0.5 * (lo + hi);
    const double fx = f(x);
    ++r.evaluations;
    r.x = x;
    r.f = fx;
    if (std::abs(fx) <= f_tol || hi - lo <= x_tol) {
      r.converged = true;
      return r;
    }
    if (fx < 0.0) {
      lo = x;
      f_lo = fx;
      if (side == -1)
        f_hi *= 0.5;
      side = -1;
    } else {
      hi = x;
      f_hi = fx;
      if (side == 1)
        f_lo *= 0.5;
      side = 1;
    }
  }
  return r;
}

} // namespace geocomp::continuum
