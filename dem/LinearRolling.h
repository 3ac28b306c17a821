// @sect3{The LinearRolling contact part (S2: PFC's rolling resistance linear model)}
//
// Why it exists: S2 gives its crushable grains rolling resistance (coefficient
// mu_r = 0.70) so that spheres roll as reluctantly as angular grains do. The model is
// PFC's "rrlinear": an incremental rolling spring whose moment is capped, the rotational
// counterpart of the Coulomb spring. With $\bar R = R^*$ ($1/\bar R = 1/R_i + 1/R_j$; $R$
// for a wall), the relative bending rotation rate
// $\omega_b = \omega_{rel} - (\omega_{rel}\cdot n)n$, $\omega_{rel} = \omega_j - \omega_i$:
// $$ M_r \leftarrow M_r - k_r\,\omega_b\,\Delta t,\qquad k_r = k_t\bar R^2 \qquad \text{(S2, PFC rrlinear)} $$
// $$ |M_r| \le M^* = \mu_r \bar R F_n ,$$
// and when the trial moment exceeds $M^*$ it is scaled back onto the limit (the spring
// slips, dissipating $M^*|\Delta\theta_{slip}|$). $M_r$ acts on body j, $-M_r$ on body i.
// Like the tangential spring, the stored moment is turned with the contact frame every
// step (TangentialFrame.h) so that a rigidly rotating pair keeps its moment.
// Stored energy $\tfrac12|M_r|^2/k_r$. Without compression ($F_n \le 0$) the cap is zero.
//
// Closed form used by the tests: a sphere rolling without slip on a plane with the
// moment at its cap $\mu_r R m g$ decelerates at $a = \mu_r R m g\,R/(I + mR^2) = \tfrac57\mu_r g$.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/TangentialFrame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

struct RollingResponse
{
  Vec3 moment = Vec3::Zero(); ///< M_r on j
  double loss = 0.0;          ///< energy dissipated by rolling slip this increment
};

class LinearRolling
{
public:
  static constexpr bool enabled = true;

  struct Parameters
  {
    double mu_r = 0.0;            ///< rolling resistance coefficient (S2: 0.70)
    double stiffness_ratio = 1.0; ///< k_r = stiffness_ratio * k_t * R*^2 (PFC: 1)
  };

  LinearRolling() = default;
  explicit LinearRolling(const Parameters& p) : p_(p)
  {
    if (!(p_.mu_r >= 0.0)) throw std::invalid_argument("LinearRolling: mu_r must be >= 0");
    if (!(p_.stiffness_ratio > 0.0)) throw std::invalid_argument("LinearRolling: stiffness ratio must be > 0");
  }

  const Parameters& parameters() const { return p_; }

  double stiffness(double k_t, double r_eff) const { return p_.stiffness_ratio * k_t * r_eff * r_eff; }

  /// Advances the rolling spring `m` (lab frame, on j) with relative spin `w_rel`,
  /// tangential stiffness `k_t` and normal force `f_n`.
  RollingResponse evaluate(const ContactKinematics& k, double k_t, double f_n, Vec3& m) const
  {
    RollingResponse r;
    const double kr = stiffness(k_t, k.r_eff);
    rotate_into_tangent_plane(m, k.normal, k.spin * k.dt);
    const Vec3 w_bend = k.w_rel - k.w_rel.dot(k.normal) * k.normal;
    m -= (kr * k.dt) * w_bend;                                   // S2 rolling spring, incremental
    const double m_max = p_.mu_r * k.r_eff * std::max(f_n, 0.0); // S2: M* = mu_r R* F_n
    const double m2 = m.squaredNorm();
    if (m2 > m_max * m_max) {
      const double scale = m_max / std::sqrt(m2);
      if (kr > 0.0) r.loss = m_max * (1.0 - scale) * std::sqrt(m2) / kr;
      m *= scale;
    }
    r.moment = m;
    return r;
  }

  double elastic_energy(double k_t, double r_eff, const Vec3& m) const
  {
    const double kr = stiffness(k_t, r_eff);
    return kr > 0.0 ? 0.5 * m.squaredNorm() / kr : 0.0;
  }

private:
  Parameters p_{};
};

}  // namespace geocomp::dem
