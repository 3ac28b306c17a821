#pragma once
// @sect3{Drucker-Prager fracture with an incubation period (S1 eqs. (6), (8)-(11))}
//
// Why: S1 separates inelastic flow (Nikolaevsky) from local fracture, a second,
// two-parameter Drucker-Prager surface through the uniaxial compressive and tensile
// strengths. The kinetic extension delays fracture: the criterion is first met at t0, and
// the point fractures only once the force parameter exceeds the dynamic strength that
// belongs to the elapsed time T_f = t - t0.
//
// Math (tension positive; sigma_eq = sqrt(3 J2), sigma_mean = J1/3, a = sigma_c/sigma_t):
//   sigma_DP = sigma_eq (a + 1)/2 + sigma_mean 3 (a - 1)/2 >= sigma_c      (S1 eq. (6))
// Check: uniaxial compression sigma = -s gives sigma_DP = s, so s = sigma_c; uniaxial
// tension sigma = s gives sigma_DP = a s, so s = sigma_t.
// Kinetic form (S1 eqs. (8), (10), (11)): with T = t - t0,
//   sigma_DP(t; a_dyn) >= sigma_c^dyn(T),  a_dyn = sigma_c^dyn(T) / sigma_t^dyn(T),
// both dynamic strengths from FractureTimeCalibration (S1 eq. (9)). If the static
// criterion stops holding before that, incubation is cancelled (the Heaviside factor
// of eq. (8): the load must stay above the static strength for the whole period).
#include "continuum/kinetic/RateCalibration.h"
#include "continuum/kinetic/WilkinsCorrection.h"

namespace geocomp::kinetic {

/// S1 eq. (6): the Drucker-Prager force parameter of a stress for a = sigma_c/sigma_t.
double drucker_prager_parameter(const Vector6 &stress, double strength_ratio);

class FractureCriterion {
public:
  explicit FractureCriterion(const S1Material &m);

  /// Static criterion, S1 eq. (6).
  bool static_criterion_met(const Vector6 &stress) const;
  /// Kinetic criterion at T = t - t0 > 0, S1 eq. (11).
  bool dynamic_criterion_met(const Vector6 &stress, double time_since_onset) const;

  const FractureTimeCalibration &compression() const { return compression_; }
  const FractureTimeCalibration &tension() const { return tension_; }

private:
  FractureTimeCalibration compression_, tension_;
};

} // namespace geocomp::kinetic
