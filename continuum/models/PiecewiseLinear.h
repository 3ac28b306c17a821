#pragma once
// A piecewise-linear function y(x) given by a table of breakpoints, used for the
// hardening/softening laws c(kappa), phi(kappa), psi(kappa), Y(kappa): rise to a peak,
// fall to a residual. Beyond the last breakpoint the function stays at its last value
// (the residual); before the first it stays at the first value.
//
// `slope(x)` is the right derivative (at a breakpoint, the slope of the segment that
// starts there), which is the one a return map that moves kappa forward needs.
#include <utility>
#include <vector>

namespace geocomp::continuum {

class PiecewiseLinear {
public:
  /// A constant function.
  explicit PiecewiseLinear(double constant = 0.0);
  /// Breakpoints (x_i, y_i), x strictly increasing, at least one point.
  PiecewiseLinear(std::vector<double> x, std::vector<double> y);
  explicit PiecewiseLinear(const std::vector<std::pair<double, double>> &points);

  double value(double x) const;
  double slope(double x) const;
  double operator()(double x) const { return value(x); }

  const std::vector<double> &breakpoints() const { return x_; }
  const std::vector<double> &values() const { return y_; }
  double min_value() const;
  double max_value() const;

private:
  std::vector<double> x_, y_;
};

} // namespace geocomp::continuum
