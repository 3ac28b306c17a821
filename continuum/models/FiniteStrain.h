#pragma once
// @sect3{Finite strain: the small-strain return maps on logarithmic strains}
//
// Why: S0 shears its box to gamma_max = 30 %. With small strains the isochoric box
// (det F = 1) has tr(eps) = e^2/(1-e) != 0 and the continuum's mean stress drifts where the
// DEM's cannot. Multiplicative elastoplasticity with a Hencky (logarithmic) elastic strain
// and the exponential map keeps every principal-space return map of this folder unchanged
// (Eterovic & Bathe 1990; Simo 1992; de Souza Neto, Peric & Owen 2008, ch. 14 - "DSPO" below;
// CONTINUUM-THEORY.md Sec. 7):
//
//   F = F^e F^p,  b^e = F^e F^e^T,  eps^e = 1/2 ln b^e,  tau = J sigma = D^e : eps^e.
//
// Update from t_n to t_{n+1} (DSPO ch. 14):
//   F_inc = F_{n+1} F_n^{-1},  b^e_trial = F_inc b^e_n F_inc^T,
//   eps^e_trial = 1/2 ln b^e_trial                       (spectral: 1/2 ln lambda_i^2),
//   (tau, D, Delta eps^p, kappa_{n+1}) = the small-strain update of `model` at the total
//       strain eps^e_trial from a history with no plastic strain and kappa_n,
//   eps^e_{n+1} = eps^e_trial - Delta eps^p,  b^e_{n+1} = exp(2 eps^e_{n+1}),  sigma = tau / J.
// The return map, run "as if small strain", is the backward-Euler exponential map of the
// plastic flow: for psi = 0 every flow direction is traceless, so ln det F^p stays 0 exactly.
//
// Consistent spatial tangent of this algorithm (DSPO ch. 14):
//   J a_ijkl = 1/2 [D : L : B]_ijkl - tau_il delta_jk,
//   L = d ln b / d b at b^e_trial,   B_ijkl = delta_ik b_jl + delta_jk b_il  (b = b^e_trial),
// with D = d tau / d eps^e_trial the small-strain algorithmic tangent. It is the derivative
// the weak form needs: for F -> (I + H) F (H = grad_x du),
//   d(tau F^{-T}) F^T = (J a) : H,   i.e.  (J a) : H = d tau - tau H^T.
// L is the tangent of the isotropic function ln, with spin coefficients
// r_ij = (ln x_i - ln x_j)/(x_i - x_j) evaluated as log1p((x_i - x_j)/x_j)/(x_i - x_j), which
// stays accurate as the eigenvalues x_i of b^e_trial meet (limit 1/x_j).
//
// Sign convention and units as everywhere in continuum/: SI, tension positive. The tangent
// is a 9x9 matrix of the full (non-symmetric) fourth-order tensor, row 3i+j, column 3k+l.
#include "continuum/models/ConstitutiveModel.h"

namespace geocomp::continuum {

using Matrix9 = Eigen::Matrix<double, 9, 9>;

/// Which kinematics an engine uses: finite strain (this file; the default of every case) or
/// small strain (the models' own update on eps = sym grad u; kept for comparison and tests).
enum class Kinematics { finite_strain, small_strain };
/// "finite strain" | "small strain".
const char *to_string(Kinematics kinematics);
/// Inverse of to_string; throws std::invalid_argument naming the accepted values.
Kinematics parse_kinematics(const std::string &text);

/// State of a finite-strain point at the end of a converged step.
struct FiniteStrainHistory {
  Matrix3 deformation_gradient = Matrix3::Identity();      ///< F_n
  Matrix3 elastic_left_cauchy_green = Matrix3::Identity(); ///< b^e_n = F^e_n F^e_n^T
  double kappa = 0.0;                                      ///< hardening variable (as the model)
  /// A point-state model's own state at F_n (PointStateModel.h: a DEM cell, ...); null for
  /// the plasticity models, whose state is b^e and kappa.
  std::shared_ptr<const PointState> state;
};

/// Everything one finite-strain update produces.
struct FiniteStrainUpdate {
  Matrix3 kirchhoff_stress = Matrix3::Zero(); ///< tau_{n+1} = J sigma [Pa]
  double jacobian = 1.0;                      ///< J = det F_{n+1}
  /// J a, the spatial tangent above [Pa]: (J a) : H = d tau - tau H^T for F -> (I + H) F.
  Matrix9 spatial_tangent = Matrix9::Zero();
  /// D = d tau / d eps^e_trial (Mandel) [Pa]: the small-strain algorithmic tangent in
  /// logarithmic strain, used by the localization scan.
  Matrix6 logarithmic_tangent = Matrix6::Zero();
  FiniteStrainHistory history;                ///< at t_{n+1}
  ReturnRegion region = ReturnRegion::elastic;
  double trial_yield_value = 0.0;
  int local_iterations = 0;

  Matrix3 cauchy_stress() const { return kirchhoff_stress / jacobian; }
  /// Elastic logarithmic strain eps^e_{n+1} = 1/2 ln b^e_{n+1}.
  Matrix3 elastic_log_strain() const;
};

/// The update of `model` from `old` to the deformation gradient F (det F > 0). Throws
/// ReturnMapFailure when the return fails or F is not orientation preserving. A
/// PointStateModel answers through its own advance_finite() (no b^e, no return map).
FiniteStrainUpdate finite_strain_update(const ConstitutiveModel &model, const Matrix3 &F,
                                        const FiniteStrainHistory &old);

/// A point at rest (F = I) under an initial stress: b^e = exp(2 D^-1 : sigma_0); a
/// PointStateModel's virgin state instead (its stress is its own).
FiniteStrainHistory initial_finite_strain_history(const ConstitutiveModel &model,
                                                  const Matrix3 &initial_stress);

/// ln of a symmetric positive definite tensor and exp of a symmetric one (spectral).
Matrix3 symmetric_log(const Matrix3 &spd);
Matrix3 symmetric_exp(const Matrix3 &symmetric);

/// Index 3i+j of the component (i, j) in the 9x9 tangent.
constexpr int pair_index(int i, int j) { return 3 * i + j; }

} // namespace geocomp::continuum
