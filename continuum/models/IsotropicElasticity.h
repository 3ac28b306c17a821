#pragma once
// Isotropic linear elasticity, the elastic predictor of every model here.
//
// sigma = lambda tr(eps) 1 + 2 G eps = K tr(eps) 1 + 2 G dev(eps), with
// G = E / (2(1+nu)), K = E / (3(1-2nu)), lambda = K - 2G/3. Because it is isotropic,
// the trial stress has the eigenvectors of the trial strain, which is what lets the
// plastic returns work on three principal values (`principal_stiffness()`).
#include "continuum/models/Mandel.h"

namespace geocomp::continuum {

class IsotropicElasticity {
public:
  /// @param[in] youngs_modulus E > 0 [Pa]; @param[in] poisson_ratio nu in (-1, 0.5).
  IsotropicElasticity(double youngs_modulus, double poisson_ratio);

  double youngs_modulus() const { return E_; }
  double poisson_ratio() const { return nu_; }
  double shear_modulus() const { return G_; }
  double bulk_modulus() const { return K_; }
  double lame_lambda() const { return K_ - 2.0 * G_ / 3.0; }

  /// Stiffness in Mandel form, sigma_m = D_m eps_m.
  const Matrix6 &stiffness() const { return D_; }
  /// Compliance in Mandel form, eps_m = S_m sigma_m.
  const Matrix6 &compliance() const { return S_; }
  /// The 3x3 map between principal strains and principal stresses:
  /// D_hat = K 1 (x) 1 + 2G (I - 1 (x) 1 / 3).
  Matrix3 principal_stiffness() const;

private:
  double E_, nu_, G_, K_;
  Matrix6 D_, S_;
};

} // namespace geocomp::continuum
