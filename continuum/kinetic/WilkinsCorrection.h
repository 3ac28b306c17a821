#pragma once
// @sect3{Wilkins' stress correction for the Nikolaevsky model (S1 eqs. (4)-(5))}
//
// Why: explicit codes (S1's movable cellular automata, our central-difference FE) solve
// the elastic problem in increments and then bring the stress back towards the yield
// surface in one closed-form step. With dilatancy the mean stress moves too, which the
// classic deviator-only Wilkins scaling misses; S1 eq. (5) gives both invariants, but
// the text extraction garbled it, so it is derived here.
//
// Derivation (tension positive; J1 = tr sigma; tau = sqrt(J2); I2 = e:e/2 as in S1 eq. (2)):
//   yield      Phi = omega J1 + tau                                       (S1 eq. (1))
//   flow       d eps^p = d gamma ( s/(2 tau) + (Lambda/3) 1 ),
//              so tr d eps^p = Lambda d gamma and 2 sqrt(I2(d e^p)) = d gamma,
//              i.e. I1^p = 2 Lambda sqrt(I2^p)                            (S1 eq. (2))
//   elasticity ds = -2G de^p  =>  d tau = -G d gamma;  dJ1 = -3K tr d eps^p = -3 K Lambda d gamma
//   hence dPhi = -(G + 3 K Lambda omega) d gamma; a prescribed drop dPhi = -DeltaPhi gives
//     d gamma = DeltaPhi / (G + 3 K Lambda omega)
//     sqrt(J2') = sqrt(J2) - G DeltaPhi / (G + 3 K Lambda omega)          (S1 eq. (5))
//     J1'       = J1 - 3 K Lambda DeltaPhi / (G + 3 K Lambda omega)       (S1 eq. (5))
//   and the stress is rebuilt by scaling the deviator, M = sqrt(J2'/J2)   (S1 eqs. (3)-(4)):
//     sigma'_ab = M (sigma_ab - delta_ab J1/3) + delta_ab J1'/3.
// DeltaPhi = Phi - Y is the quasi-static correction (lands on the surface); the kinetic
// model passes the relaxed part of eq. (13) instead. If G d gamma exceeds tau the
// deviator cannot absorb it: the stress goes to the apex (s = 0) with J1' from
// omega J1' = Phi - DeltaPhi, possible only when Lambda omega > 0.
#include "continuum/models/Mandel.h"

namespace geocomp::kinetic {

using continuum::Vector6;

/// Stress invariants used throughout S1.
struct Invariants {
  double J1 = 0.0;   ///< tr sigma [Pa]
  double tau = 0.0;  ///< sqrt(J2) [Pa]
  Vector6 deviator = Vector6::Zero();
};
Invariants invariants(const Vector6 &stress);

/// Constants of one correction.
struct NikolaevskyConstants {
  double shear_modulus = 0.0;  ///< G
  double bulk_modulus = 0.0;   ///< K
  double omega = 0.0;          ///< omega = alpha / 3
  double dilatancy = 0.0;      ///< Lambda
  double yield_function(const Vector6 &stress) const; ///< omega J1 + sqrt(J2)
  double denominator() const { return shear_modulus + 3.0 * bulk_modulus * dilatancy * omega; }
};

struct WilkinsResult {
  Vector6 stress = Vector6::Zero();  ///< corrected stress
  double plastic_shear = 0.0;        ///< d gamma (engineering plastic shear strain increment)
  double plastic_volumetric = 0.0;   ///< tr d eps^p
  bool apex = false;                 ///< deviator exhausted: the stress sits at the cone tip
};

/// Lowers the yield function of `stress` by delta_phi >= 0 (S1 eqs. (4)-(5)).
WilkinsResult wilkins_correction(const Vector6 &stress, double delta_phi, const NikolaevskyConstants &c);

} // namespace geocomp::kinetic
