#include "continuum/models/PiecewiseLinear.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::continuum {

PiecewiseLinear::PiecewiseLinear(double constant) : x_{0.0}, y_{constant} {}

PiecewiseLinear::PiecewiseLinear(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  if (x_.empty() || x_.size() != y_.size())
    throw std::invalid_argument("PiecewiseLinear: need equally many x and y, at least one");
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      throw std::invalid_argument("PiecewiseLinear: non-finite breakpoint");
    if (i > 0 && !(x_[i] > x_[i - 1]))
      throw std::invalid_argument("PiecewiseLinear: x must be strictly increasing");
  }
}

PiecewiseLinear::PiecewiseLinear(const std::vector<std::pair<double, double>> &points) {
  std::vector<double> x, y;
  for (const auto &p : points) {
    x.push_back(p.first);
    y.push_back(p.second);
  }
  *this = PiecewiseLinear(std::move(x), std::move(y));
}

namespace {
// Index i of the segment [x_i, x_{i+1}) containing x, or -1 left of x_0, n-1 right of x_{n-1}.
long segment(const std::vector<double> &x, double v) {
  if (v < x.front())
    return -1;
  const auto it = std::upper_bound(x.begin(), x.end(), v);
  return static_cast<long>(it - x.begin()) - 1;
}
} // namespace

double PiecewiseLinear::value(double v) const {
  const long i = segment(x_, v);
  if (i < 0)
    return y_.front();
  if (i >= static_cast<long>(x_.size()) - 1)
    return y_.back();
  const double t = (v - x_[i]) / (x_[i + 1] - x_[i]);
  return y_[i] + t * (y_[i + 1] - y_[i]);
}

double PiecewiseLinear::slope(double v) const {
  const long i = segment(x_, v);
  if (i < 0 || i >= static_cast<long>(x_.size()) - 1)
    return 0.0;
  return (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]);
}

double PiecewiseLinear::min_value() const { return *std::min_element(y_.begin(), y_.end()); }
double PiecewiseLinear::max_value() const { return *std::max_element(y_.begin(), y_.end()); }

} // namespace geocomp::continuum
