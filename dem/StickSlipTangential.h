// @sect3{The StickSlipTangential contact part (S3 eq. (9), friction with anchor re-placement)}
//
// Why it exists: S3's soil model writes friction as a spring between two anchor points
// fixed on the particles at contact. The spring force grows with the tangential
// displacement $\delta_\tau$ until it reaches the Coulomb limit at a given displacement
// $\delta^*_\tau$:
// $$ F_\tau = \tan\varphi\,F_n\,\frac{\delta_\tau}{\delta^*_\tau}\quad (|\delta_\tau| < \delta^*_\tau)
//    \qquad \text{(S3 eq. (9))} $$
// i.e. a spring of stiffness $k_t = \mu F_n/\delta^*_\tau$ ($\mu = \tan\varphi$). When
// $|\delta_\tau|$ reaches $\delta^*_\tau$ the contact slips and the anchors are re-placed so
// that the spring shrinks to $k_\varphi\,\delta^*_\tau$, $k_\varphi \in [0, 1]$ (S3 eq. (9)):
// $k_\varphi = 1$ is classical Coulomb sliding (the force stays at $\mu F_n$), $k_\varphi = 0$
// drops the force to zero at every slip (stick-slip).
// The history is the anchor spring $\xi = \delta_\tau$ (j's anchor relative to i's,
// tangential), turned with the contact frame like the Cundall-Strack spring. Stored
// energy $\tfrac12 k_t|\xi|^2$; a slip dissipates $\tfrac12 k_t(|\xi^*|^2 - |\xi|^2)$.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/LinearTangential.h"
#include "dem/NormalResponse.h"
#include "dem/TangentialFrame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

class StickSlipTangential
{
public:
  struct Parameters
  {
    double slip_displacement = 1e-4; ///< delta*_tau [m]: tangential displacement at the Coulomb limit
    double retention = 1.0;          ///< k_phi in [0, 1]: spring kept after a slip, as a fraction of delta*_tau
  };

  StickSlipTangential() = default;
  explicit StickSlipTangential(const Parameters& p) : p_(p)
  {
    if (!(p_.slip_displacement > 0.0)) throw std::invalid_argument("StickSlipTangential: delta*_tau must be > 0");
    if (!(p_.retention >= 0.0 && p_.retention <= 1.0))
      throw std::invalid_argument("StickSlipTangential: k_phi must be in [0, 1]");
  }

  const Parameters& parameters() const { return p_; }

  /// k_t = mu F_n / delta*_tau at this contact.
  double stiffness(double mu, const NormalResponse& nr) const
  {
    return mu * std::max(nr.force, 0.0) / p_.slip_displacement;
  }

  TangentialResponse evaluate(const ContactKinematics& k, const NormalResponse& nr, Vec3& xi) const
  {
    TangentialResponse t;
    rotate_into_tangent_plane(xi, k.normal, k.spin * k.dt);
    xi += k.v_t * k.dt;
    const double kt = stiffness(k.mu, nr);
    const double d2 = xi.squaredNorm();
    const double limit = p_.slip_displacement;
    if (d2 >= limit * limit) {  // slip: re-place the anchors (S3 eq. (9))
      const double e_trial = 0.5 * kt * d2;
      xi *= p_.retention * limit / std::sqrt(d2);
      t.friction_loss = e_trial - 0.5 * kt * xi.squaredNorm();
    }
    t.force = -kt * xi;  // S3 eq. (9)
    return t;
  }

  double elastic_energy(double mu, const NormalResponse& nr, const Vec3& xi) const
  {
    return 0.5 * stiffness(mu, nr) * xi.squaredNorm();
  }

private:
  Parameters p_{};
};

}  // namespace geocomp::dem
