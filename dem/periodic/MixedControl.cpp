#include "dem/periodic/MixedControl.h"

#include <algorithm>
#include <stdexcept>

namespace geocomp::dem {

MixedControl::MixedControl(const Parameters& p)
{
  set_parameters(p);
  mode_.fill(Mode::strain_rate);
  value_.fill(0.0);
}

void MixedControl::set_parameters(const Parameters& p)
{
  if (!(p.gain > 0.0 && p.gain <= 1.0)) throw std::invalid_argument("MixedControl: the gain must be in (0, 1]");
  if (!(p.max_strain_rate > 0.0)) throw std::invalid_argument("MixedControl: the largest strain rate must be positive");
  p_ = p;
}

void MixedControl::set_strain_rate(int a, int b, double rate)
{
  mode_[index(a, b)] = Mode::strain_rate;
  value_[index(a, b)] = rate;
}

void MixedControl::set_stress(int a, int b, double target)
{
  mode_[index(a, b)] = Mode::stress;
  value_[index(a, b)] = target;
}

void MixedControl::set_velocity_gradient(const Mat3& l)
{
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) set_strain_rate(a, b, l(a, b));
}

bool MixedControl::any_stress() const
{
  return std::any_of(mode_.begin(), mode_.end(), [](Mode m) { return m == Mode::stress; });
}

Mat3 MixedControl::velocity_gradient(const CellStress& stress, double dt) const
{
  Mat3 l;
  const Mat3 sigma = stress.elastic;
  const double cap = p_.max_strain_rate;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const int k = index(a, b);
      if (mode_[k] == Mode::strain_rate) {
        l(a, b) = value_[k];
        continue;
      }
      const double error = value_[k] - sigma(a, b);
      const double stiff = stress.stiffness(a, b);
      double rate = (stiff > 0.0) ? p_.gain * error / (stiff * dt) : (error > 0.0 ? cap : (error < 0.0 ? -cap : 0.0));  // servo
      l(a, b) = std::clamp(rate, -cap, cap);
    }
  return l;
}

}  // namespace geocomp::dem
