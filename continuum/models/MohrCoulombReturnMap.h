#pragma once
// @sect3{Mohr-Coulomb return mapping in principal stress space}
//
// Why: Mohr-Coulomb is the strength criterion S0 reads its DEM results against
// (sigma_1 = sigma_3 N_phi + 2c sqrt(N_phi)), and its corners are where triaxial tests
// live, so the continuum needs an exact, corner-aware backward-Euler return with a
// consistent tangent. This class does the three-principal-value part; MohrCoulombModel
// wraps it with the spectral decomposition.
//
// Math (tension positive, principal stresses ordered s1 >= s2 >= s3 as in the trial).
// One yield plane per ordered pair (i,j), i the major, j the minor stress:
//
//   Phi_ij = (s_i - s_j) + (s_i + s_j) sin(phi) - 2 c cos(phi)    (de Souza Neto et al.
//            2008, Sec. 8.2; equivalent to S0's sigma_1 = sigma_3 N_phi + 2c sqrt(N_phi))
//   f_ij = dPhi_ij/ds = (1 + sin phi) e_i - (1 - sin phi) e_j,
//   g_ij = dPsi_ij/ds = (1 + sin psi) e_i - (1 - sin psi) e_j   (non-associated flow).
//
// Backward Euler with active planes A: s = s_tr - D_hat sum_{b in A} dgamma_b g_b(kappa),
// Phi_a(s, kappa) = 0 for a in A, with c, phi, psi evaluated at the new kappa.
// Regions tried in order (Box 8.5 of de Souza Neto et al.; CONTINUUM-THEORY.md Sec. 1):
//   plane      A = {13}          valid if dgamma >= 0 and s1 >= s2 >= s3
//   left edge  A = {13, 23}      (s1 = s2, triaxial compression)  valid if dgammas >= 0, s2 >= s3
//   right edge A = {13, 12}      (s2 = s3, triaxial extension)    valid if dgammas >= 0, s1 >= s2
//   apex       s = p 1, p = c cot(phi)
// The edge tried first is the right one if (1-sin psi)s1tr - 2 s2tr + (1+sin psi)s3tr > 0.
//
// Hardening variable (our definition): kappa is the accumulated plastic shear strain
//   d kappa = 2 sum_b dgamma_b,
// which on the main plane equals d(eps^p_1 - eps^p_3), the engineering plastic shear
// strain gamma^p that S0 and the DEM comparison report. Each generator g_ij has trace
// 2 sin psi, so everywhere d eps_v^p = sin(psi) d kappa; at the apex we use that to get
// d kappa = d eps_v^p / sin(psi) (psi floored at apex_min_dilatancy). (de Souza Neto et al.
// use d eps_bar^p = 2 cos(phi) sum dgamma instead; ours avoids a phi-dependent measure.)
//
// Local Newton on the multipliers with the full Jacobian, including d/dkappa of c, phi
// and psi:  J = -F M + 2 dPhi/dkappa 1^T,  M = D_hat [G + 2 w 1^T],  w = sum_c dgamma_c dg_c/dkappa,
// with F the rows f_a, G the columns g_b. At convergence the principal consistent tangent
// is  d s / d s_tr = I + M J^{-1} F  (implicit function theorem on R(dgamma, s_tr) = 0).
// Apex: one unknown d kappa, residual p_tr - K sin(psi) d kappa - c cot(phi) = 0.
// Where Newton stalls (a kink of a piecewise-linear table) a bracketed scalar solve in
// kappa takes over (ScalarRoot.h): at fixed kappa the plane conditions are linear in the
// multipliers, leaving kappa - kappa_n - 2 sum dgamma(kappa) = 0.
#include "continuum/models/ConstitutiveModel.h"
#include "continuum/models/IsotropicElasticity.h"
#include "continuum/models/PiecewiseLinear.h"

namespace geocomp::continuum {

struct MohrCoulombParameters {
  double youngs_modulus = 0.0;      ///< E [Pa]
  double poisson_ratio = 0.0;       ///< nu
  PiecewiseLinear cohesion;         ///< c(kappa) [Pa], >= 0
  PiecewiseLinear friction_angle;   ///< phi(kappa) [rad], in (0, pi/2)
  PiecewiseLinear dilatancy_angle;  ///< psi(kappa) [rad], in [0, pi/2)
  double apex_min_dilatancy = 1e-3; ///< floor on psi in the apex return [rad]

  /// Throws std::invalid_argument when a value is out of range, or psi > phi at some kappa.
  void validate() const;
};

/// Values and kappa-derivatives of the strength parameters at one kappa.
struct MohrCoulombStrength {
  double c, dc;          ///< cohesion and dc/dkappa
  double phi, dphi;      ///< friction angle and dphi/dkappa
  double psi, dpsi;      ///< dilatancy angle and dpsi/dkappa
};

/// Result of a return in principal space. Index order is the (descending) trial order.
struct PrincipalReturn {
  Vector3 stress = Vector3::Zero();                 ///< returned principal stresses
  Matrix3 dstress_dtrial = Matrix3::Identity();     ///< d s_i / d s_tr_j
  double delta_kappa = 0.0;                         ///< kappa_{n+1} - kappa_n
  Eigen::Vector2d multipliers = Eigen::Vector2d::Zero(); ///< dgamma of planes (a, b)
  ReturnRegion region = ReturnRegion::elastic;
  double trial_yield = 0.0;                         ///< Phi_13 at the trial state, kappa_n
  int iterations = 0;
};

class MohrCoulombReturnMap {
public:
  explicit MohrCoulombReturnMap(MohrCoulombParameters parameters);

  const MohrCoulombParameters &parameters() const { return p_; }
  const IsotropicElasticity &elasticity() const { return elastic_; }
  MohrCoulombStrength strength(double kappa) const;

  /// Phi_13 of principal stresses sorted descending.
  double yield_principal(const Vector3 &sorted_stress, double kappa) const;

  /// Backward-Euler return of sorted trial principal stresses (s_tr(0) >= s_tr(1) >=
  /// s_tr(2)) from kappa_n. Throws ReturnMapFailure if no region is admissible.
  PrincipalReturn return_principal(const Vector3 &sorted_trial, double kappa_n) const;

  /// Unit-free flow generator g_ij (major i, minor j) for a dilatancy angle psi.
  static Vector3 flow_generator(int i, int j, double psi);

private:
  bool return_to_planes(int m, const int (*planes)[2], const Vector3 &trial, double kappa_n,
                        PrincipalReturn &out) const;
  bool return_to_apex(const Vector3 &trial, double kappa_n, PrincipalReturn &out) const;

  MohrCoulombParameters p_;
  IsotropicElasticity elastic_;
  Matrix3 D_hat_;
};

} // namespace geocomp::continuum
