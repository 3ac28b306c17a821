// @sect3{The LinearTangential contact part (S0 eq. (2), incremental Cundall-Strack spring)}
//
// Why it exists: S0's "developing / developed friction" is a tangential spring-dashpot
// capped by Coulomb. The spring is incremental: the history $\xi$ (tangential
// displacement of j relative to i) is turned with the contact frame, then
// (DEM-NOTES section 2, S0 eq. (2))
// $$ \xi \leftarrow \xi + v_t\Delta t,\qquad F_t^* = -k_t\xi - c_t v_t,\qquad
//    F_t = \begin{cases} F_t^* & |F_t^*| \le \mu F_n \\ \mu F_n\,F_t^*/|F_t^*| & \text{else}\end{cases}$$
// and when sliding the spring is truncated so that spring + dashpot equal the limit,
// $\xi = -(F_t + c_t v_t)/k_t$. No friction without compression ($F_n \le 0$).
// $k_t$ is given in N/m or as a ratio of the normal stiffness at this contact (S0 uses
// ratio 1; the benchmark 2/7); $c_t$ in N s/m or as a ratio of $c_n$ (default 0).
// Energy: the spring stores $\tfrac12 k_t|\xi|^2$; sliding dissipates $|F_t|$ times the
// slip $|\xi^* - \xi|$ (DEM-NOTES 10.3); the dashpot dissipates $c_t|v_t|^2\Delta t$.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/NormalResponse.h"
#include "dem/TangentialFrame.h"

#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

struct TangentialResponse
{
  Vec3 force = Vec3::Zero();  ///< F_t on j
  double damping_loss = 0.0;  ///< energy dissipated by the tangential dashpot this step
  double friction_loss = 0.0; ///< energy dissipated by sliding this step
};

class LinearTangential
{
public:
  struct Parameters
  {
    bool stiffness_is_ratio = true;
    double k_t = 2.0 / 7.0;   ///< ratio of k_n, or N/m
    bool damping_is_ratio = true;
    double c_t = 0.0;         ///< ratio of c_n, or N s/m
  };

  LinearTangential() = default;
  explicit LinearTangential(const Parameters& p) : p_(p)
  {
    if (!(p_.k_t > 0.0)) throw std::invalid_argument("LinearTangential: k_t must be positive");
    if (!(p_.c_t >= 0.0)) throw std::invalid_argument("LinearTangential: c_t must be >= 0");
  }
  static LinearTangential with_ratio(double kt_over_kn, double ct_over_cn = 0.0)
  {
    return LinearTangential(Parameters{true, kt_over_kn, true, ct_over_cn});
  }

  const Parameters& parameters() const { return p_; }

  double stiffness(const NormalResponse& nr) const { return p_.stiffness_is_ratio ? p_.k_t * nr.stiffness : p_.k_t; }

  /// Advances the spring `xi` (lab frame, acting on j) and returns the tangential force.
  GEOCOMP_CONTACT_KERNEL TangentialResponse evaluate(const ContactKinematics& k, const NormalResponse& nr, Vec3& xi) const
  {
    TangentialResponse t;
    const double kt = stiffness(nr);
    const double ct = p_.damping_is_ratio ? p_.c_t * nr.damping : p_.c_t;
    rotate_into_tangent_plane(xi, k.normal, k.spin * k.dt);
    xi += k.v_t * k.dt;
    const Vec3 f_trial = -kt * xi - ct * k.v_t;                 // S0 eq. (2), developing friction
    const double f_max = k.mu * std::max(nr.force, 0.0);        // S0 eq. (2), cap mu_s |F_n|
    const double f2 = f_trial.squaredNorm();
    if (f2 > f_max * f_max) {                                   // developed friction: slide
      const Vec3 xi_trial = xi;
      t.force = f_trial * (f_max / std::sqrt(f2));
      xi = -(t.force + ct * k.v_t) * (1.0 / kt);
      t.friction_loss = f_max * (xi_trial - xi).norm();  // |F_t| times the slip
    } else {
      t.force = f_trial;
    }
    t.damping_loss = ct * k.v_t.squaredNorm() * k.dt;
    return t;
  }

  double elastic_energy(const NormalResponse& nr, const Vec3& xi) const
  {
    return 0.5 * stiffness(nr) * xi.squaredNorm();
  }

  /// Ratio k_t / k_n for the time-step estimate (1 when k_t is given in N/m and unknown).
  double stiffness_for(double k_n) const { return p_.stiffness_is_ratio ? p_.k_t * k_n : p_.k_t; }

private:
  Parameters p_{};
};

}  // namespace geocomp::dem
