// @sect3{The S3Bonding contact part: cohesion (breaks for good) and adhesion (restorable)}
//
// Why it exists: S3's soil has a Coulomb-Mohr strength $\tau = \sigma\tan\varphi + C$,
// $C = C_c + C_a$ (S3 eq. (1)), split into a cohesive bond that breaks once and a
// capillary adhesion that forms again whenever grains meet. Both are "virtual springs"
// much softer than the grains ($E_c, E_a \ll E$, S3 eq. (2)). With the pair radius
// $r_{ij} = 2R^*$ (S3: $2r_ir_j/(r_i+r_j)$; $2R$ for a wall), forces along the normal are
// positive when repulsive, as everywhere in the contact code:
//
// Cohesion (S3 eq. (8)). At the first contact ($\delta > 0$) anchor points are fixed on
// both bodies; the bond spring $e$ is j's anchor relative to i's. Its normal part is
// the change of the gap since the bond formed, $e_n = \delta_0 - \delta$, exactly; its
// tangential part $e_t$ is integrated from the tangential velocity and turned with the
// contact frame. The force on j is
// $$ F_c = -E_c r_{ij}\,(e_n n + e_t) \qquad\text{until}\qquad |e| \ge \varepsilon^* = r_{ij}C_c/E_c ,$$
// when the bond breaks and never forms again for this pair (its key is kept, see
// ContactMemory.h). The largest bond force is thus $C_c r_{ij}^2$.
//
// Adhesion (S3 eq. (7)). Formed at contact ($\delta > 0$), it pulls along the normal
// while $\delta > -\delta^*$, $\delta^* = r_{ij}C_a/E_a$:
// $$ F_a = E_a r_{ij}(\delta^* + \delta), $$
// and vanishes when the gap exceeds $\delta^*$; it forms again at the next contact. An
// approaching pair feels no adhesion before it touches (a capillary bridge needs a
// contact to form). Potential $U_a = -\tfrac12 E_a r_{ij}(\delta^*+\delta)^2$, zero at rupture; the
// jump at formation and the bond energy released at breakage are reported as losses.
//
// The interaction outlives the overlap, so the neighbour lists must reach further than
// the spheres: `reach(R*)` is the largest gap at which this part can still act.
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/ContactMemory.h"
#include "dem/TangentialFrame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

struct BondResponse
{
  double normal = 0.0;          ///< along n on j (> 0 repulsive; bonds and adhesion pull: < 0)
  Vec3 tangential = Vec3::Zero();///< on j
  double loss = 0.0;            ///< energy released by breakage or adhesion formation
};

class S3Bonding
{
public:
  static constexpr bool enabled = true;

  struct Parameters
  {
    double cohesion = 0.0;          ///< C_c [Pa] (0: no bonds)
    double cohesion_modulus = 1e6;  ///< E_c [Pa]
    double adhesion = 0.0;          ///< C_a [Pa] (0: no adhesion)
    double adhesion_modulus = 1e6;  ///< E_a [Pa]
  };

  S3Bonding() = default;
  explicit S3Bonding(const Parameters& p) : p_(p)
  {
    if (!(p_.cohesion >= 0.0) || !(p_.adhesion >= 0.0))
      throw std::invalid_argument("S3Bonding: strengths C_c and C_a must be >= 0");
    if (!(p_.cohesion_modulus > 0.0) || !(p_.adhesion_modulus > 0.0))
      throw std::invalid_argument("S3Bonding: moduli E_c and E_a must be > 0");
  }

  const Parameters& parameters() const { return p_; }

  /// Bond breaking length eps* = r_ij C_c / E_c (S3 eq. (8)).
  double bond_limit(double r_eff) const { return 2.0 * r_eff * p_.cohesion / p_.cohesion_modulus; }
  /// Adhesion range delta* = r_ij C_a / E_a (S3 eq. (7)).
  double adhesion_range(double r_eff) const { return 2.0 * r_eff * p_.adhesion / p_.adhesion_modulus; }
  /// Largest gap at which a contact of effective radius R* can still carry force.
  double reach(double r_eff) const { return std::max(bond_limit(r_eff), adhesion_range(r_eff)); }

  /// Advances bond and adhesion of one contact (also for delta <= 0). `k.bonding`
  /// false (e.g. walls) means nothing forms.
  BondResponse evaluate(const ContactKinematics& k, ContactMemory& m) const
  {
    BondResponse b;
    const double r_ij = 2.0 * k.r_eff;
    // Cohesion, S3 eq. (8).
    if (p_.cohesion > 0.0) {
      if (!m.has(ContactMemory::bonded) && !m.has(ContactMemory::bond_broken) && k.overlap > 0.0 && k.bonding) {
        m.state |= ContactMemory::bonded;  // anchors fixed at first contact
        m.bond_origin = k.overlap;
        m.bond.setZero();
      }
      if (m.has(ContactMemory::bonded)) {
        rotate_into_tangent_plane(m.bond, k.normal, k.spin * k.dt);
        m.bond += k.v_t * k.dt;
        const double e_n = m.bond_origin - k.overlap;
        const double e2 = e_n * e_n + m.bond.squaredNorm();
        const double eps = bond_limit(k.r_eff);
        const double kc = p_.cohesion_modulus * r_ij;
        if (e2 >= eps * eps) {  // breaks for good
          b.loss += 0.5 * kc * e2;
          m.state = (m.state & ~ContactMemory::bonded) | ContactMemory::bond_broken;
          m.bond.setZero();
          m.bond_origin = 0.0;
        } else {
          b.normal -= kc * e_n;             // S3 eq. (8): F_c = -E_c r_ij e
          b.tangential -= kc * m.bond;
        }
      }
    }
    // Adhesion, S3 eq. (7).
    if (p_.adhesion > 0.0) {
      const double range = adhesion_range(k.r_eff);
      const double ka = p_.adhesion_modulus * r_ij;
      if (!m.has(ContactMemory::adhesion_active) && k.overlap > 0.0 && k.bonding) {
        m.state |= ContactMemory::adhesion_active;  // (re)formed at contact
        b.loss += 0.5 * ka * (range + k.overlap) * (range + k.overlap);
      }
      if (m.has(ContactMemory::adhesion_active)) {
        if (k.overlap > -range) b.normal -= ka * (range + k.overlap);  // S3 eq. (7)
        else m.state &= ~ContactMemory::adhesion_active;               // bridge ruptured
      }
    }
    return b;
  }

  /// Energy stored in the bond spring and the adhesion potential of one contact.
  double elastic_energy(double overlap, double r_eff, const ContactMemory& m) const
  {
    double e = 0.0;
    const double r_ij = 2.0 * r_eff;
    if (m.has(ContactMemory::bonded)) {
      const double e_n = m.bond_origin - overlap;
      e += 0.5 * p_.cohesion_modulus * r_ij * (e_n * e_n + m.bond.squaredNorm());
    }
    if (m.has(ContactMemory::adhesion_active)) {
      const double s = adhesion_range(r_eff) + overlap;
      if (s > 0.0) e -= 0.5 * p_.adhesion_modulus * r_ij * s * s;
    }
    return e;
  }

private:
  Parameters p_{};
};

}  // namespace geocomp::dem
