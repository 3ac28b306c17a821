#include "continuum/kinetic/RateCalibration.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace geocomp::kinetic {

namespace {
const double infinity = std::numeric_limits<double>::infinity();
}

double compressive_strength_factor(double strain_rate) { return 1.0 + 0.238 * std::pow(strain_rate, 0.348); } // S1 eq. (14)
double tensile_strength_factor(double strain_rate) { return 1.0 + 0.093 * std::pow(strain_rate, 0.617); }     // S1 eq. (15)
double printed_relaxation_function(double y) { return 0.00787 - 0.00216 * y; }                                // S1 eq. (22)

FractureTimeCalibration::FractureTimeCalibration(double static_strength, double youngs_modulus, double coefficient,
                                                 double exponent)
  : sigma_st_(static_strength), E_(youngs_modulus), c_(coefficient), p_(exponent)
{
  if (!(sigma_st_ > 0.0 && E_ > 0.0 && c_ > 0.0 && p_ > 0.0 && p_ < 1.0))
    throw std::invalid_argument("FractureTimeCalibration: expected positive strength, modulus, coefficient and "
                                "an exponent in (0, 1)");
}

FractureTimeCalibration FractureTimeCalibration::compression(const S1Material &m)
{
  return FractureTimeCalibration(m.compressive_strength, m.youngs_modulus, 0.238, 0.348); // S1 eq. (14)
}

FractureTimeCalibration FractureTimeCalibration::tension(const S1Material &m)
{
  return FractureTimeCalibration(m.tensile_strength, m.youngs_modulus, 0.093, 0.617); // S1 eq. (15)
}

double FractureTimeCalibration::dynamic_factor(double strain_rate) const
{
  return 1.0 + c_ * std::pow(strain_rate, p_);
}

double FractureTimeCalibration::fracture_time(double strain_rate) const
{
  // S1 eq. (9): T_f = (sigma^dyn - sigma^st) / (E epsdot) = sigma^st c epsdot^(p-1) / E
  return sigma_st_ * c_ * std::pow(strain_rate, p_ - 1.0) / E_;
}

double FractureTimeCalibration::strain_rate_for(double fracture_time) const
{
  if (fracture_time <= 0.0)
    return infinity;
  return std::pow(c_ * sigma_st_ / (E_ * fracture_time), 1.0 / (1.0 - p_));
}

double FractureTimeCalibration::dynamic_strength(double fracture_time) const
{
  if (fracture_time <= 0.0)
    return infinity;
  return sigma_st_ * dynamic_factor(strain_rate_for(fracture_time));
}

RelaxationCalibration::RelaxationCalibration(const S1Material &m)
  : Y_st_(m.static_cohesion()), E_star_(m.youngs_modulus / std::sqrt(3.0)), B_(m.cohesion_rate_gain),
    rate_r_(m.reference_rate)
{
}

double RelaxationCalibration::cohesion_ratio(double strain_rate) const
{
  return 1.0 + B_ * (1.0 - std::exp(-strain_rate / rate_r_)); // S1 eq. (19), reconstructed
}

double RelaxationCalibration::equivalent_rate(double y) const
{
  if (y <= 1.0)
    return 0.0;
  if (y >= 1.0 + B_)
    return infinity;
  return -rate_r_ * std::log1p(-(y - 1.0) / B_);
}

double RelaxationCalibration::relaxation_function(double y) const
{
  // S1 eq. (21): f(y) = (y - 1) / epsdot(y), with the limit B/epsdot_r at y -> 1.
  if (y <= 1.0 + 1e-12)
    return B_ / rate_r_;
  const double rate = equivalent_rate(y);
  return std::isinf(rate) ? 0.0 : (y - 1.0) / rate;
}

double RelaxationCalibration::relaxation_time(double y) const
{
  return relaxation_function(y) * Y_st_ / E_star_; // S1 eq. (20)
}

double RelaxationCalibration::relaxation_time_at_rate(double strain_rate) const
{
  return relaxation_time(cohesion_ratio(strain_rate));
}

double RelaxationCalibration::friction_ratio(double strain_rate) const
{
  return 0.49 + 0.51 * std::exp(-strain_rate / rate_r_); // S1 eq. (23)
}

double RelaxationCalibration::dilatancy_ratio(double strain_rate) const
{
  return friction_ratio(strain_rate); // S1 eq. (28): same form as eq. (27)
}

double RelaxationCalibration::plastic_share(double strain_rate) const
{
  return std::exp(-strain_rate / rate_r_); // S1 eq. (29)
}

} // namespace geocomp::kinetic
