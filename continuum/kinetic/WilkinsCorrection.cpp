#include "continuum/kinetic/WilkinsCorrection.h"

#include <algorithm>
#include <cmath>

namespace geocomp::kinetic {

using continuum::mandel_identity;

Invariants invariants(const Vector6 &stress)
{
  Invariants inv;
  inv.J1 = stress(0) + stress(1) + stress(2);
  inv.deviator = stress - (inv.J1 / 3.0) * mandel_identity();
  // Mandel is an isometry: s:s = |s_m|^2, J2 = s:s / 2.
  inv.tau = std::sqrt(0.5 * inv.deviator.squaredNorm());
  return inv;
}

double NikolaevskyConstants::yield_function(const Vector6 &stress) const
{
  const Invariants inv = invariants(stress);
  return omega * inv.J1 + inv.tau; // S1 eq. (1)
}

WilkinsResult wilkins_correction(const Vector6 &stress, double delta_phi, const NikolaevskyConstants &c)
{
  WilkinsResult r;
  const Invariants inv = invariants(stress);
  delta_phi = std::max(0.0, delta_phi);
  double d_gamma = delta_phi / c.denominator();
  double tau_new = inv.tau - c.shear_modulus * d_gamma;                           // S1 eq. (5)
  double J1_new = inv.J1 - 3.0 * c.bulk_modulus * c.dilatancy * d_gamma;           // S1 eq. (5)
  if (tau_new < 0.0) {
    // Apex: s = 0 and omega J1' = Phi - delta_phi, reached by volumetric flow alone.
    r.apex = true;
    tau_new = 0.0;
    const double phi = c.omega * inv.J1 + inv.tau;
    const double kl = c.bulk_modulus * c.dilatancy * c.omega;
    if (kl > 0.0) {
      J1_new = (phi - delta_phi) / c.omega;
      // tr d eps^p = Lambda d gamma = (J1 - J1') / (3K)
      d_gamma = (inv.J1 - J1_new) / (3.0 * c.bulk_modulus * c.dilatancy);
    } else {
      J1_new = inv.J1;
      d_gamma = inv.tau / c.shear_modulus;
    }
  }
  const double M = inv.tau > 0.0 ? tau_new / inv.tau : 0.0; // S1 eq. (4): M = sqrt(J2'/J2)
  r.stress = M * inv.deviator + (J1_new / 3.0) * mandel_identity(); // S1 eq. (4)
  r.plastic_shear = d_gamma;
  r.plastic_volumetric = c.dilatancy * d_gamma;
  return r;
}

} // namespace geocomp::kinetic
