// @sect3{The LinearNormal contact part (S0 linear spring-dashpot)}
//
// Why it exists: S0's specimen uses the linear ("Hooke") version of Hertz-Mindlin, and
// comparisons with LIGGGHTS/PFC need the constants to be given exactly as those engines
// take them. The force on j along n is
// $$ F_n = k_n\delta - c_n v_n \qquad \text{(S0 eq. (1), with } \dot\delta = -v_n) $$
// with the stiffness either given in N/m or S0's secant Hertz stiffness at impact speed V_c,
// $$ k_n = \tfrac{16}{15}\sqrt{R^*}E^*\Big(\frac{15 m^* V_c^2}{16\sqrt{R^*}E^*}\Big)^{1/5}, $$
// and the dashpot given in N s/m, per unit effective mass ($c_n = \gamma_n m^*$, LIGGGHTS
// gamma_n), or from the restitution coefficient e (S0's formula, identical to
// $2\zeta\sqrt{m^*k_n}$):
// $$ c_n = \sqrt{\frac{4 m^* k_n}{1 + (\pi/\ln e)^2}} = 2\zeta\sqrt{m^*k_n},\quad
//    \zeta = \frac{-\ln e}{\sqrt{\pi^2 + \ln^2 e}}. $$
// With `clamp_tensile` (default) $F_n \ge 0$: a cohesionless contact never pulls. The
// closed-form e above holds without the clamp; with it the effective e is higher
// (DEM-NOTES section 3 table), which is the documented convention of the clamped law.
// For like materials $E^* = E/(2(1-\nu^2))$.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/NormalResponse.h"

#include <algorithm>
#include <cmath>

namespace geocomp::dem {

class LinearNormal
{
public:
  enum class Stiffness { direct, from_impact_velocity };
  enum class Damping { direct, per_unit_mass, restitution };

  struct Parameters
  {
    Stiffness stiffness_input = Stiffness::direct;
    double k_n = 0.0;              ///< [N/m] when direct
    double youngs_modulus = 0.0;   ///< E [Pa] when from_impact_velocity
    double poisson_ratio = 0.0;    ///< nu when from_impact_velocity
    double impact_velocity = 0.0;  ///< V_c [m/s] when from_impact_velocity
    Damping damping_input = Damping::restitution;
    double c_n = 0.0;              ///< [N s/m] when direct
    double gamma_n = 0.0;          ///< [1/s] when per_unit_mass: c_n = gamma_n m*
    double restitution = 1.0;      ///< e in [0, 1] when restitution
    bool clamp_tensile = true;     ///< F_n >= 0
  };

  LinearNormal() = default;
  explicit LinearNormal(const Parameters& p);

  /// k_n in N/m, c_n from restitution e (the LIGGGHTS hooke/stiffness idiom).
  static LinearNormal with_stiffness(double k_n, double restitution, bool clamp_tensile = true);

  const Parameters& parameters() const { return p_; }
  /// Damping ratio zeta of the restitution input (DEM-NOTES section 3).
  double damping_ratio() const { return zeta_; }

  double stiffness(double m_eff, double r_eff) const
  {
    if (p_.stiffness_input == Stiffness::direct) return p_.k_n;
    // S0: secant Hertz stiffness at the characteristic impact velocity V_c.
    const double sr = std::sqrt(r_eff);
    return 16.0 / 15.0 * sr * e_star_ *
           std::pow(15.0 * m_eff * p_.impact_velocity * p_.impact_velocity / (16.0 * sr * e_star_), 0.2);  // S0 k_n
  }

  double damping(double m_eff, double k_n) const
  {
    switch (p_.damping_input) {
      case Damping::direct: return p_.c_n;
      case Damping::per_unit_mass: return p_.gamma_n * m_eff;
      case Damping::restitution: default: return 2.0 * zeta_ * std::sqrt(m_eff * k_n);  // S0 c_n
    }
  }

  GEOCOMP_CONTACT_KERNEL NormalResponse evaluate(const ContactKinematics& k) const
  {
    NormalResponse r;
    r.stiffness = stiffness(k.m_eff, k.r_eff);
    r.damping = damping(k.m_eff, r.stiffness);
    r.elastic = r.stiffness * k.overlap;
    const double f = r.elastic - r.damping * k.v_n;  // S0 eq. (1)
    r.force = p_.clamp_tensile ? std::max(f, 0.0) : f;
    return r;
  }

  /// Elastic energy stored at overlap delta: k_n delta^2 / 2.
  double elastic_energy(double overlap, double m_eff, double r_eff) const
  {
    return 0.5 * stiffness(m_eff, r_eff) * overlap * overlap;
  }

  /// Largest normal stiffness for the time-step estimate, at the given pair.
  double max_stiffness(double m_eff, double r_eff) const { return stiffness(m_eff, r_eff); }

private:
  Parameters p_{};
  double zeta_ = 0.0;   ///< damping ratio from e
  double e_star_ = 0.0; ///< effective modulus E* of two like bodies
};

/// Damping ratio for restitution e of the unclamped linear oscillator (DEM-NOTES section 3).
inline double damping_ratio_from_restitution(double e)
{
  if (e <= 0.0) return 1.0;
  if (e >= 1.0) return 0.0;
  const double l = std::log(e);
  return -l / std::sqrt(M_PI * M_PI + l * l);
}

}  // namespace geocomp::dem
