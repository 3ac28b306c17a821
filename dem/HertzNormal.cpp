#include "dem/HertzNormal.h"

#include <stdexcept>

namespace geocomp::dem {

HertzNormal::HertzNormal(const Parameters& p) : p_(p)
{
  if (!(p_.youngs_modulus > 0.0) || !(p_.poisson_ratio > -1.0) || !(p_.poisson_ratio < 0.5))
    throw std::invalid_argument("HertzNormal: need E > 0 and -1 < nu < 0.5");
  if (p_.damping_input == Damping::restitution && !(p_.restitution >= 0.0 && p_.restitution <= 1.0))
    throw std::invalid_argument("HertzNormal: restitution must lie in [0, 1]");
  if (p_.damping_input == Damping::brilliantov && !(p_.brilliantov_a >= 0.0))
    throw std::invalid_argument("HertzNormal: Brilliantov A must be >= 0");
  e_star_ = p_.youngs_modulus / (2.0 * (1.0 - p_.poisson_ratio * p_.poisson_ratio));  // like materials
  if (p_.restitution <= 0.0) beta_ = -1.0;
  else if (p_.restitution >= 1.0) beta_ = 0.0;
  else {
    const double l = std::log(p_.restitution);
    beta_ = l / std::sqrt(l * l + M_PI * M_PI);
  }
}

}  // namespace geocomp::dem
