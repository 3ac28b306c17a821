#pragma once
// @sect3{Rudnicki & Rice (1975): localization in a pressure-sensitive dilatant solid}
//
// Why: S0 reads its DEM shear bands against this theory, and it gives the continuum side
// an exact closed form to verify the acoustic-tensor scan against.
//
// Model (Rudnicki & Rice 1975, JMPS 23:371, Sec. 2; tension positive, sigma = tr/3):
//   yield  tau + mu sigma = k(gamma^p),  h = dk/dgamma^p,  tau = sqrt(J2),
//   flow   d eps^p = d gamma^p ( s/(2 tau) + (beta/3) 1 ),
//   tangent L = C - (G s/tau + beta K 1) (x) (G s/tau + mu K 1) / (h + G + mu beta K).
// Deviatoric state N = s_II / tau (s_I >= s_II >= s_III): +1/sqrt3 in axisymmetric
// compression, -1/sqrt3 in axisymmetric extension.
//
// Closed form (Rudnicki & Rice 1975, restated in CONTINUUM-THEORY.md Sec. 3), small
// stress/modulus terms neglected:
//   h_cr/G = (1+nu)/(9(1-nu)) (beta - mu)^2 - (1+nu)/2 (N + (beta+mu)/3)^2,
//   theta_0 = pi/4 + (1/2) asin(alpha),
//   alpha = [ (2/3)(1+nu)(beta+mu) - N(1-2nu) ] / sqrt(4 - 3 N^2),
// with the band normal in the I-III plane at theta_0 from the sigma_III (most compressive)
// axis; valid for |alpha| <= 1.
//
// Drucker-Prager link: Phi = omega tr(sigma) + tau - Y gives mu = 3 omega; the flow
// d eps_v^p = Lambda d gamma^p gives beta = Lambda; h = dY/dkappa - tr(sigma) domega/dkappa.
#include "continuum/models/Mandel.h"

namespace geocomp::continuum {

struct RudnickiRiceMaterial {
  double mu = 0.0;   ///< internal friction coefficient (d tau / d(-sigma) on yield)
  double beta = 0.0; ///< dilatancy factor d eps_v^p / d gamma^p
  double nu = 0.0;   ///< Poisson ratio
};

struct RudnickiRicePrediction {
  double critical_hardening_over_G = 0.0; ///< h_cr / G
  double alpha = 0.0;                     ///< the argument of asin in theta_0
  double band_normal_angle = 0.0;         ///< theta_0 [rad] between normal and sigma_III axis
  double band_plane_angle = 0.0;          ///< pi/2 - theta_0: band plane to sigma_III axis
  bool closed_form_valid = true;          ///< |alpha| <= 1 (otherwise alpha was clamped)
};

/// Closed-form critical hardening modulus and band angle for deviatoric state N.
RudnickiRicePrediction rudnicki_rice_prediction(const RudnickiRiceMaterial &material, double N);

/// mu = 3 omega, beta = Lambda (Drucker-Prager parameters of DruckerPragerModel).
RudnickiRiceMaterial rudnicki_rice_from_drucker_prager(double omega, double Lambda, double nu);

/// N = s_II / tau of a stress tensor (0 for a hydrostatic state).
double deviatoric_state(const Matrix3 &stress);

/// The band normal in space: cos(theta_0) e_III + sin(theta_0) e_I for the principal
/// directions of `stress` (one of the two conjugate bands; the other flips e_I).
Vector3 rudnicki_rice_band_normal(const Matrix3 &stress, double theta0);

/// Rudnicki & Rice's elastoplastic tangent L (Mandel) for a stress on the yield surface.
Matrix6 rudnicki_rice_tangent(const RudnickiRiceMaterial &material, double shear_modulus,
                              double hardening, const Matrix3 &stress);

} // namespace geocomp::continuum
