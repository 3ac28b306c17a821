#include "dem/LinearNormal.h"

#include <stdexcept>

namespace geocomp::dem {

LinearNormal::LinearNormal(const Parameters& p) : p_(p)
{
  if (p_.stiffness_input == Stiffness::direct) {
    if (!(p_.k_n > 0.0)) throw std::invalid_argument("LinearNormal: k_n must be positive");
  } else {
    if (!(p_.youngs_modulus > 0.0) || !(p_.impact_velocity > 0.0) || !(p_.poisson_ratio < 0.5) ||
        !(p_.poisson_ratio > -1.0))
      throw std::invalid_argument("LinearNormal: S0 stiffness needs E > 0, -1 < nu < 0.5, V_c > 0");
    e_star_ = p_.youngs_modulus / (2.0 * (1.0 - p_.poisson_ratio * p_.poisson_ratio));
  }
  if (p_.damping_input == Damping::restitution && !(p_.restitution >= 0.0 && p_.restitution <= 1.0))
    throw std::invalid_argument("LinearNormal: restitution must lie in [0, 1]");
  if (p_.damping_input == Damping::direct && !(p_.c_n >= 0.0))
    throw std::invalid_argument("LinearNormal: c_n must be >= 0");
  if (p_.damping_input == Damping::per_unit_mass && !(p_.gamma_n >= 0.0))
    throw std::invalid_argument("LinearNormal: gamma_n must be >= 0");
  zeta_ = damping_ratio_from_restitution(p_.restitution);
}

LinearNormal LinearNormal::with_stiffness(double k_n, double restitution, bool clamp_tensile)
{
  Parameters p;
  p.stiffness_input = Stiffness::direct;
  p.k_n = k_n;
  p.damping_input = Damping::restitution;
  p.restitution = restitution;
  p.clamp_tensile = clamp_tensile;
  return LinearNormal(p);
}

}  // namespace geocomp::dem
