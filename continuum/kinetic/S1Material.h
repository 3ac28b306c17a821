#pragma once
// @sect3{S1 material: the parameters of Grigoriev et al. (2017), Table}
//
// Why: the kinetic model of S1 needs, besides elasticity, the static yield, compressive
// and tensile strengths, the internal friction alpha = 3 omega and the dilatancy Lambda.
// This struct holds them in SI units and derives the Nikolaevsky constants the point
// model uses, so every other file reads one source.
//
// Math (tension positive, J1 = tr sigma, sqrt(J2) = sqrt(s:s/2)):
//   omega = alpha / 3                                             (S1 eq. (1))
//   uniaxial compression at |sigma| = s: Phi = s (1/sqrt3 - omega) =: m_c s
//   uniaxial tension     at  sigma  = s: Phi = s (1/sqrt3 + omega) =: m_t s
//   static cohesion Y0 = m_c sigma_y  (S1 quotes Y = 15.4 MPa for its sandstone:
//   40 MPa * (0.5774 - 0.19) = 15.5 MPa, which fixes the sign convention).
// Hardening between yield and strength is linear, Y(kappa) = Y0 + H kappa, with kappa
// the accumulated plastic shear strain gamma^p; S1 does not print H, so it is set by the
// axial plastic strain eps_p* reached at the static compressive strength:
//   |d eps^p_axial| = d gamma (1/sqrt3 - Lambda/3) in uniaxial compression, hence
//   H = m_c (sigma_c - sigma_y) (1/sqrt3 - Lambda/3) / eps_p*.
#include <string>

namespace geocomp::kinetic {

struct S1Material {
  std::string name = "custom";
  double youngs_modulus = 0.0;        ///< E [Pa]
  double poisson_ratio = 0.0;         ///< nu
  double density = 0.0;               ///< rho [kg/m^3]
  double yield_stress = 0.0;          ///< sigma_y, uniaxial compression [Pa] (magnitude)
  double compressive_strength = 0.0;  ///< sigma_c [Pa] (magnitude)
  double tensile_strength = 0.0;      ///< sigma_t [Pa]
  double internal_friction = 0.0;     ///< alpha = 3 omega
  double dilatancy = 0.0;             ///< Lambda (S1 eq. (2))
  /// Axial plastic strain at the static compressive strength (not in S1's table; an
  /// assumption, see docs/s1-kinetic-model.md).
  double plastic_strain_at_strength = 0.0;
  /// B of the reconstructed S1 eq. (19): Y_dyn/Y_st = 1 + B (1 - exp(-epsdot/epsdot_r)).
  double cohesion_rate_gain = 1.85;
  double reference_rate = 317.0;      ///< epsdot_r of S1 eqs. (19), (23), (29) [1/s]

  /// Throws std::invalid_argument naming the first bad field.
  void validate() const;
  /// Only the fields of the quasi-static model (E, nu, sigma_y, sigma_c, alpha, Lambda,
  /// eps_p*): what NikolaevskyModel needs; validate() checks these and the rest.
  void validate_plasticity() const;

  double omega() const { return internal_friction / 3.0; }
  double shear_modulus() const;
  double bulk_modulus() const;
  double compression_factor() const;  ///< m_c = 1/sqrt3 - omega
  double tension_factor() const;      ///< m_t = 1/sqrt3 + omega
  double static_cohesion() const;     ///< Y0 = m_c sigma_y
  double hardening_modulus() const;   ///< H = dY/dkappa [Pa]
  /// Static tensile yield stress Y0 / m_t [Pa].
  double tensile_yield_stress() const { return static_cohesion() / tension_factor(); }

  /// S1's table, row "concrete" (density 4660 kg/m^3 and sigma_t = 21 MPa as printed).
  static S1Material concrete();
  /// S1's table, row "sandstone".
  static S1Material sandstone();
  /// "concrete" or "sandstone"; throws std::invalid_argument otherwise.
  static S1Material preset(const std::string &name);
};

} // namespace geocomp::kinetic
