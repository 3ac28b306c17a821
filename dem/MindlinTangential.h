// @sect3{The MindlinTangential contact part (S4 eq. (16), (17), (19))}
//
// Why it exists: S4 pairs Hertz with Mindlin's no-slip tangential stiffness, which grows
// with the contact radius $a = \sqrt{R^*\delta}$ (S4 eq. (16), (19)):
// $$ k_t = 8G^*\sqrt{R^*\delta},\qquad G^* = \frac{G}{2(2-\nu)},\ G = \frac{E}{2(1+\nu)} $$
// (for like materials; S4 prints $G/(2(1-\nu))$, a probable typo, DEM-NOTES section 0).
// Because $k_t$ changes with $\delta$, the *force* is stored, not a displacement
// (multiplying a stored $\xi$ by the current $k_t$ creates energy on re-loading):
// the stored spring force is turned with the frame, scaled by $k_t(\delta)/k_t(\delta_{old})$
// on unloading (LAMMPS mindlin_rescale; Thornton et al. 2013), incremented by
// $-k_t v_t\Delta t$, and capped, $|F_t| \le \mu F_n$ (S4 eq. (17)). Optional tangential
// damping $\eta_t = -2\sqrt{5/6}\beta\sqrt{k_t m^*}$ (off by default: S4 neglects it).
// Energy: $|F_s|^2/(2k_t)$ stored.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/LinearTangential.h"
#include "dem/NormalResponse.h"
#include "dem/TangentialFrame.h"

#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

class MindlinTangential
{
public:
  struct Parameters
  {
    double youngs_modulus = 0.0;   ///< E [Pa]
    double poisson_ratio = 0.0;    ///< nu
    double restitution = 1.0;      ///< e for the optional tangential dashpot (1: none)
  };

  MindlinTangential() = default;
  explicit MindlinTangential(const Parameters& p) : p_(p)
  {
    if (!(p_.youngs_modulus > 0.0) || !(p_.poisson_ratio > -1.0) || !(p_.poisson_ratio < 0.5))
      throw std::invalid_argument("MindlinTangential: need E > 0 and -1 < nu < 0.5");
    const double G = p_.youngs_modulus / (2.0 * (1.0 + p_.poisson_ratio));
    g_star_ = G / (2.0 * (2.0 - p_.poisson_ratio));  // Mindlin, like materials
    if (p_.restitution <= 0.0) beta_ = -1.0;
    else if (p_.restitution >= 1.0) beta_ = 0.0;
    else {
      const double l = std::log(p_.restitution);
      beta_ = l / std::sqrt(l * l + M_PI * M_PI);
    }
  }

  const Parameters& parameters() const { return p_; }
  double effective_shear_modulus() const { return g_star_; }

  double stiffness(double overlap, double r_eff) const
  {
    return 8.0 * g_star_ * std::sqrt(r_eff * overlap);  // S4 eq. (16), (19): K_s sqrt(delta)
  }

  TangentialResponse evaluate(const ContactKinematics& k, const NormalResponse& nr, Vec3& fs) const
  {
    TangentialResponse t;
    const double kt = stiffness(k.overlap, k.r_eff);
    rotate_into_tangent_plane(fs, k.normal, k.spin * k.dt);
    if (k.overlap < k.overlap_old)  // unloading: k_t(delta)/k_t(delta_old)
      fs *= std::sqrt(k.overlap / k.overlap_old);
    fs -= kt * k.v_t * k.dt;                                      // S4 eq. (16), incremental
    const double ct = -2.0 * std::sqrt(5.0 / 6.0) * beta_ * std::sqrt(kt * k.m_eff);
    const Vec3 f_trial = fs - ct * k.v_t;
    const double f_max = k.mu * std::max(nr.force, 0.0);          // S4 eq. (17)
    const double f2 = f_trial.squaredNorm();
    if (f2 > f_max * f_max) {
      const Vec3 fs_trial = fs;
      t.force = f_trial * (f_max / std::sqrt(f2));
      fs = t.force + ct * k.v_t;
      t.friction_loss = f_max * (fs_trial - fs).norm() / kt;  // |F_t| times the slip
    } else {
      t.force = f_trial;
    }
    t.damping_loss = ct * k.v_t.squaredNorm() * k.dt;
    return t;
  }

  double elastic_energy(double overlap, double r_eff, const Vec3& fs) const
  {
    const double kt = stiffness(overlap, r_eff);
    return kt > 0.0 ? 0.5 * fs.squaredNorm() / kt : 0.0;
  }

private:
  Parameters p_{};
  double g_star_ = 0.0;
  double beta_ = 0.0;
};

}  // namespace geocomp::dem
