// Template body of monotone_root (included by PlaneStress.h).
#include <cmath>

namespace geocomp::kinetic {

template <class F>
double monotone_root(F &&f, double x0, double slope, double tol, int max_iter)
{
  double xa = x0, fa = f(xa);
  if (std::abs(fa) <= tol)
    return xa;
  double lo = 0, hi = 0, flo = 0, fhi = 0;
  bool has_lo = false, has_hi = false;
  auto record = [&](double x, double fx) {
    if (fx < 0.0 && (!has_lo || x > lo)) {
      lo = x, flo = fx, has_lo = true;
    }
    if (fx > 0.0 && (!has_hi || x < hi)) {
      hi = x, fhi = fx, has_hi = true;
    }
  };
  record(xa, fa);
  double xb = xa - fa / slope;
  for (int it = 0; it < max_iter; ++it) {
    if (has_lo && has_hi && !(xb > lo && xb < hi))
      xb = 0.5 * (lo + hi); // secant left the bracket: bisect
    const double fb = f(xb);
    if (std::abs(fb) <= tol)
      return xb;
    record(xb, fb);
    double s = (fb - fa) / (xb - xa);
    if (!(s > 0.0) || !std::isfinite(s))
      s = slope;
    xa = xb, fa = fb;
    xb = xa - fa / s;
    if (!has_lo || !has_hi) {
      // Not bracketed yet: make sure the next point moves at least past the current one.
      if (std::abs(xb - xa) < 1e-300)
        xb = xa - fa / slope;
    } else if (std::abs(hi - lo) < 1e-18 * (std::abs(hi) + std::abs(lo)) + 1e-300) {
      return std::abs(flo) < std::abs(fhi) ? lo : hi;
    }
  }
  if (has_lo && has_hi)
    return std::abs(flo) < std::abs(fhi) ? lo : hi;
  return xa;
}

} // namespace geocomp::kinetic
