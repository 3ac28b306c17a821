#include "continuum/kinetic/FractureCriterion.h"

#include <cmath>

namespace geocomp::kinetic {

double drucker_prager_parameter(const Vector6 &stress, double a)
{
  const Invariants inv = invariants(stress);
  const double sigma_eq = std::sqrt(3.0) * inv.tau;
  const double sigma_mean = inv.J1 / 3.0;
  return sigma_eq * 0.5 * (a + 1.0) + sigma_mean * 1.5 * (a - 1.0); // S1 eq. (6)
}

FractureCriterion::FractureCriterion(const S1Material &m)
  : compression_(FractureTimeCalibration::compression(m)), tension_(FractureTimeCalibration::tension(m))
{
}

bool FractureCriterion::static_criterion_met(const Vector6 &stress) const
{
  const double a = compression_.static_strength() / tension_.static_strength();
  return drucker_prager_parameter(stress, a) >= compression_.static_strength();
}

bool FractureCriterion::dynamic_criterion_met(const Vector6 &stress, double T) const
{
  if (T <= 0.0)
    return false;
  const double sc = compression_.dynamic_strength(T); // S1 eq. (11): sigma_c^dyn(t - t0)
  const double st = tension_.dynamic_strength(T);     //              sigma_t^dyn(t - t0)
  return drucker_prager_parameter(stress, sc / st) >= sc;
}

} // namespace geocomp::kinetic
