#pragma once
// @sect3{Drucker-Prager (Mises-Schleicher / Nikolaevsky) with non-associated flow}
//
// Why: the smooth cone is the model Rudnicki & Rice (1975) analysed and the one S1 uses
// (Nikolaevsky plasticity with the Wilkins correction), so it is both the second material
// of the continuum side and the reference for the localization theory.
//
// Math (tension positive, p = tr(sigma)/3, s = dev sigma, tau = sqrt(J2) = sqrt(s:s/2)):
//   yield     Phi = omega tr(sigma) + tau - Y(kappa)            (S1 eq. (1); RR: mu = 3 omega)
//   potential g   = tau + (Lambda/3) tr(sigma)                   (S1 eq. (2); RR: beta = Lambda)
//   flow      d eps^p = d gamma ( s/(2 tau) + (Lambda/3) 1 )
// so d gamma = sqrt(2 de^p:de^p) is the engineering plastic shear strain and
// d eps_v^p = Lambda d gamma. Hardening variable: kappa = accumulated gamma^p
// (Rudnicki & Rice's gamma^p); Y, omega, Lambda are piecewise-linear in kappa.
//
// Return (backward Euler = the dilatant Wilkins correction, CONTINUUM-THEORY.md Sec. 5):
//   cone:  tau = tau_tr - G dg,  p = p_tr - K Lambda dg,
//          R(dg) = tau + 3 omega p - Y = 0 at kappa_n + dg (local Newton), valid if tau >= 0;
//   apex:  s = 0, p = Y/(3 omega), d kappa = d eps_v^p / Lambda (Lambda floored).
// The return runs on principal values and reuses the spectral tangent assembly, so
// coincident eigenvalues are handled the same way as in Mohr-Coulomb.
#include "continuum/models/ConstitutiveModel.h"
#include "continuum/models/MohrCoulombReturnMap.h"
#include "continuum/models/PiecewiseLinear.h"

namespace geocomp::continuum {

/// How a Drucker-Prager cone is fitted to Mohr-Coulomb c, phi, psi.
enum class DruckerPragerMatching {
  outer_cone,  ///< through the compression corners (triaxial compression meridian)
  inner_cone,  ///< through the extension corners (triaxial extension meridian)
  plane_strain ///< same limit load in plane strain (zero plastic out-of-plane strain rate)
};

struct DruckerPragerParameters {
  double youngs_modulus = 0.0;      ///< E [Pa]
  double poisson_ratio = 0.0;       ///< nu
  PiecewiseLinear strength;         ///< Y(kappa) [Pa]
  PiecewiseLinear friction;         ///< omega(kappa) > 0 (Rudnicki-Rice mu = 3 omega)
  PiecewiseLinear dilatancy;        ///< Lambda(kappa) >= 0 (Rudnicki-Rice beta)
  double apex_min_dilatancy = 1e-4; ///< floor on Lambda in the apex return

  void validate() const;

  /// Pointwise match of a Mohr-Coulomb material: (omega, Y, Lambda) are computed exactly
  /// at every breakpoint of c, phi, psi and interpolated linearly in between (exact when
  /// phi and psi are constant).
  static DruckerPragerParameters from_mohr_coulomb(const MohrCoulombParameters &mc,
                                                   DruckerPragerMatching matching);
};

/// (omega, Y/c, Lambda) of a matching, for one (phi, psi): Y = y_over_c * c.
struct DruckerPragerMatch {
  double omega, y_over_c, lambda;
};
DruckerPragerMatch match_mohr_coulomb(double phi, double psi, DruckerPragerMatching matching);

class DruckerPragerModel : public ConstitutiveModel {
public:
  explicit DruckerPragerModel(DruckerPragerParameters parameters);

  MaterialPointUpdate update(const Vector6 &total_strain,
                             const PlasticHistory &old) const override;
  double yield_function(const Vector6 &stress, double kappa) const override;
  const IsotropicElasticity &elasticity() const override { return elastic_; }
  std::string name() const override { return "drucker_prager"; }
  const DruckerPragerParameters &parameters() const { return p_; }

  /// Return of sorted principal trial stresses (PrincipalReturn.multipliers(0) = d gamma).
  PrincipalReturn return_principal(const Vector3 &sorted_trial, double kappa_n) const;

  /// Continuum elastoplastic tangent at a stress on the cone (not at the apex):
  ///   L = D - (D:P) (x) (Q:D) / (H + Q:D:P),  Q = dPhi/dsigma, P = dg/dsigma,
  ///   H = -dPhi/dkappa = Y' - omega' tr(sigma)
  /// (the Rudnicki & Rice 1975 tangent with mu = 3 omega, beta = Lambda, h = H).
  Matrix6 continuum_tangent(const Vector6 &stress, double kappa) const;

private:
  DruckerPragerParameters p_;
  IsotropicElasticity elastic_;
};

} // namespace geocomp::continuum
