#include "dem/program/ServoControl.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

void ServoParameters::validate() const
{
  if (!(proportional_gain > 0.0) || !std::isfinite(proportional_gain))
    throw std::invalid_argument("servo: the proportional gain must be positive");
  if (!(integral_gain >= 0.0) || !std::isfinite(integral_gain))
    throw std::invalid_argument("servo: the integral gain must be >= 0");
  if (!(max_velocity > 0.0) || !std::isfinite(max_velocity))
    throw std::invalid_argument("servo: the maximum wall velocity must be positive");
  if (!(kinematic_speed_ratio >= 0.0) || !std::isfinite(kinematic_speed_ratio))
    throw std::invalid_argument("servo: the kinematic speed ratio must be >= 0");
}

double ServoParameters::cap(double kinematic_speed) const
{
  return std::max(max_velocity, kinematic_speed_ratio * kinematic_speed);
}

double AxisServo::velocity(const ServoParameters &p, const ServoInput &in)
{
  const double error = in.goal - in.stress; // > 0: too compressed, the walls move out
  const double v_max = p.cap(in.kinematic_speed);
  if (!(in.stiffness > 0.0)) { // no wall contact: towards the goal at the cap
    integral_velocity_ = 0.0;
    return error > 0.0 ? v_max : (error < 0.0 ? -v_max : 0.0);
  }
  const double G = in.area / (in.stiffness * in.dt); // speed per unit stress error, one-step correction
  const double proportional = p.proportional_gain * G * error;
  const double integral = integral_velocity_ + p.integral_gain * G * error;
  const double v = proportional + integral;
  // Anti-windup: the integral grows only while the wall is not held at the cap, or when
  // the new error pulls it back.
  if (std::abs(v) < v_max || std::abs(integral) < std::abs(integral_velocity_))
    integral_velocity_ = std::clamp(integral, -v_max, v_max);
  return std::clamp(v, -v_max, v_max);
}

} // namespace geocomp::dem
