// @sect3{The crushing criterion (S2 eq. (3)) with an optional Weibull size effect}
//
// Why it exists: S2 breaks a particle when its largest contact force, scaled by the
// square of its size, reaches the characteristic strength (maximum-contact-force
// criterion of Marketos & Bolton 2009, S2 ref. [18]):
// $$ \sigma = F_{max} / d^2 \ge \sigma_c \qquad \text{(S2 eq. (3))} $$
// Optionally the strength follows the Weibull size effect of McDowell & Bolton,
// $\sigma_c(d) = \sigma_{c0}\,(d/d_0)^{-3/m}$ (m = 0: no size effect, S2's setting).
#pragma once

#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

struct CrushingCriterion
{
  double strength = 0.0;          ///< sigma_c0 [Pa]
  double reference_size = 0.0;    ///< d_0 [m] (Weibull only)
  double weibull_modulus = 0.0;   ///< m (0: no size effect)

  void validate() const
  {
    if (!(strength > 0.0)) throw std::invalid_argument("crushing strength must be > 0");
    if (!(weibull_modulus >= 0.0)) throw std::invalid_argument("Weibull modulus must be >= 0");
    if (weibull_modulus > 0.0 && !(reference_size > 0.0))
      throw std::invalid_argument("Weibull reference size must be > 0");
  }

  /// sigma_c(d): the strength of a particle of diameter d.
  double strength_at(double d) const
  {
    if (weibull_modulus > 0.0) return strength * std::pow(d / reference_size, -3.0 / weibull_modulus);
    return strength;
  }

  /// S2 eq. (3): F_max / d^2 >= sigma_c(d).
  bool breaks(double f_max, double d) const { return f_max / (d * d) >= strength_at(d); }

  /// The force at which a particle of diameter d breaks.
  double crushing_force(double d) const { return strength_at(d) * d * d; }
};

}  // namespace geocomp::dem
