#pragma once
// @sect3{S1 calibration curves: strain-rate data turned into fracture and relaxation times}
//
// Why: S1's kinetic model is driven by two material times, the fracture (incubation)
// time T_f and the relaxation time T_r, not by the strain rate. Measured data are
// strain-rate curves normalized by the static values, the same for a wide class of brittle
// materials; S1 converts them into time dependencies for one material (Sec. 3). This file
// does that conversion in closed form, so the point model can evaluate it at every step.
//
// Fracture (compression; tension is the same with eq. (15) and sigma_t):
//   k_c(epsdot) = sigma_c^dyn / sigma_c^st = 1 + 0.238 epsdot^0.348       (S1 eq. (14))
//   k_t(epsdot) = sigma_t^dyn / sigma_t^st = 1 + 0.093 epsdot^0.617       (S1 eq. (15))
//   T_f(epsdot) = (sigma^dyn - sigma^st) / (E epsdot) = sigma^st c epsdot^(p-1) / E   (S1 eq. (9))
// which inverts exactly: epsdot(T_f) = (c sigma^st / (E T_f))^(1/(1-p)) and
// sigma^dyn(T_f) = sigma^st k(epsdot(T_f)) - a decreasing function of T_f, infinite at 0
// and sigma^st as T_f -> infinity (S1's piecewise fits (17)-(18) approximate this curve).
//
// Relaxation (cohesion Y, with E* = E / sqrt3, S1 eqs. (20)-(21)):
//   y(epsdot) = Y^dyn/Y^st = 1 + B (1 - exp(-epsdot/epsdot_r))     (S1 eq. (19), reconstructed)
//   T_r = (y - 1) Y^st / (E* epsdot) = f(y) Y^st / E*,  f(y) = (y - 1) / epsdot(y)
//   epsdot(y) = -epsdot_r ln(1 - (y - 1)/B),  y in [1, 1 + B)
// S1's printed eq. (19) lost its constants in the text extraction; B = 1.85 makes f(y)
// reproduce S1's own linear fit f = 0.00787 - 0.00216 y (eq. (22)) within a few per cent
// over 1e-3..1e3 1/s (docs/s1-kinetic-model.md). The other parameters follow the same
// equivalent rate epsdot(y), which is how S1 builds eqs. (27), (28), (30):
//   omega^dyn/omega^st = 0.49 + 0.51 exp(-epsdot/epsdot_r)            (S1 eqs. (23), (27))
//   Lambda^dyn/Lambda^st = the same function                          (S1 eq. (28))
//   eps_pl^dyn/eps_pl^st = exp(-epsdot/epsdot_r)                      (S1 eqs. (29), (30))
#include "continuum/kinetic/S1Material.h"

namespace geocomp::kinetic {

/// S1 eq. (14): normalized dynamic compressive strength.
double compressive_strength_factor(double strain_rate);
/// S1 eq. (15): normalized dynamic tensile strength.
double tensile_strength_factor(double strain_rate);
/// S1 eq. (22) as printed: f(y) [s] of the cohesion ratio y = Y^dyn/Y^st.
double printed_relaxation_function(double cohesion_ratio);

/// T_f <-> sigma^dyn for one loading kind (S1 eq. (9) applied to eq. (14) or (15)).
class FractureTimeCalibration {
public:
  /// dynamic factor k = 1 + coefficient * epsdot^exponent; exponent in (0, 1).
  FractureTimeCalibration(double static_strength, double youngs_modulus, double coefficient, double exponent);
  static FractureTimeCalibration compression(const S1Material &m);
  static FractureTimeCalibration tension(const S1Material &m);

  double static_strength() const { return sigma_st_; }
  double dynamic_factor(double strain_rate) const;
  /// T_f(epsdot) = sigma_st (k - 1) / (E epsdot) [s]  (S1 eq. (9)).
  double fracture_time(double strain_rate) const;
  /// The rate whose fracture time is T (inverse of fracture_time); +inf for T <= 0.
  double strain_rate_for(double fracture_time) const;
  /// sigma^dyn(T_f) [Pa]; +inf for T_f <= 0.
  double dynamic_strength(double fracture_time) const;

private:
  double sigma_st_, E_, c_, p_;
};

/// T_r and the rate-dependent plasticity parameters of one material.
class RelaxationCalibration {
public:
  explicit RelaxationCalibration(const S1Material &m);

  double cohesion_ratio(double strain_rate) const;   ///< y(epsdot), S1 eq. (19)
  /// epsdot(y), inverse of cohesion_ratio; +inf for y >= 1 + B, 0 for y <= 1.
  double equivalent_rate(double cohesion_ratio) const;
  /// f(y) = (y - 1)/epsdot(y) [s], S1 eq. (21); B/epsdot_r at y = 1.
  double relaxation_function(double cohesion_ratio) const;
  /// T_r(y) = f(y) Y^st / E* [s], S1 eq. (20).
  double relaxation_time(double cohesion_ratio) const;
  /// T_r at a strain rate (the same map, parametrized by the rate).
  double relaxation_time_at_rate(double strain_rate) const;
  double friction_ratio(double strain_rate) const;   ///< S1 eq. (23)
  double dilatancy_ratio(double strain_rate) const;  ///< S1 eq. (28): the eq. (23) form
  double plastic_share(double strain_rate) const;    ///< S1 eq. (29)
  double maximum_cohesion_ratio() const { return 1.0 + B_; }

private:
  double Y_st_, E_star_, B_, rate_r_;
};

} // namespace geocomp::kinetic
