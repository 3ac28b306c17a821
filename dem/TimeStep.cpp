#include "dem/TimeStep.h"

#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

double spring_time_scale(double mass, double stiffness)
{
  if (!(mass > 0.0) || !(stiffness > 0.0)) throw std::invalid_argument("spring_time_scale: need m, k > 0");
  return std::sqrt(mass / stiffness);
}

double rayleigh_time_step(double radius, double density, double shear_modulus, double nu)
{
  return M_PI * radius * std::sqrt(density / shear_modulus) / (0.1631 * nu + 0.8766);  // S4 Rayleigh step
}

double linear_contact_duration(double m_eff, double k, double c)
{
  const double w2 = k / m_eff - (c / (2.0 * m_eff)) * (c / (2.0 * m_eff));
  if (!(w2 > 0.0)) throw std::domain_error("linear_contact_duration: overdamped contact");
  return M_PI / std::sqrt(w2);
}

double linear_restitution(double m_eff, double k, double c)
{
  const double zeta = c / (2.0 * std::sqrt(m_eff * k));
  if (zeta >= 1.0) return 0.0;
  return std::exp(-M_PI * zeta / std::sqrt(1.0 - zeta * zeta));
}

double hertz_contact_duration(double m_eff, double r_eff, double e_eff, double v0)
{
  return 2.868 * std::pow(m_eff * m_eff / (r_eff * e_eff * e_eff * v0), 0.2);
}

double hertz_max_overlap(double m_eff, double r_eff, double e_eff, double v0)
{
  return std::pow(15.0 * m_eff * v0 * v0 / (16.0 * e_eff * std::sqrt(r_eff)), 0.4);
}

}  // namespace geocomp::dem
