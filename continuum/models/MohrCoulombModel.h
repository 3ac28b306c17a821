#pragma once
// @sect3{The Mohr-Coulomb material point}
//
// Why: the FE solver and the material-point driver want "strain in, stress and tangent
// out"; MohrCoulombReturnMap works on three sorted principal values. This class is the
// glue: elastic predictor, spectral decomposition of the trial strain, principal return,
// and reassembly of stress and the consistent tangent including the eigenvector-rotation
// terms (SpectralDecomposition.h):
//
//   eps_tr = eps_{n+1} - eps^p_n,   s_tr = D_hat eps_tr (principal),
//   sigma_{n+1} = sum_i s_i e_i (x) e_i,
//   Dp = (d s / d s_tr) D_hat,   C_alg = sum Dp_ij E_i (x) E_j + sum r_ij N_ij (x) N_ij,
//   eps^p_{n+1} = eps_{n+1} - D^{-1} sigma_{n+1},  kappa_{n+1} = kappa_n + d kappa.
//
// At the apex with perfect plasticity the tangent is exactly zero (singular); the caller
// (FE) may blend in a fraction of the elastic tangent, see docs/continuum-models.md.
#include "continuum/models/ConstitutiveModel.h"
#include "continuum/models/MohrCoulombReturnMap.h"

namespace geocomp::continuum {

class MohrCoulombModel : public ConstitutiveModel {
public:
  explicit MohrCoulombModel(MohrCoulombParameters parameters);

  MaterialPointUpdate update(const Vector6 &total_strain,
                             const PlasticHistory &old) const override;
  double yield_function(const Vector6 &stress, double kappa) const override;
  const IsotropicElasticity &elasticity() const override { return map_.elasticity(); }
  std::string name() const override { return "mohr_coulomb"; }

  const MohrCoulombReturnMap &return_map() const { return map_; }

private:
  MohrCoulombReturnMap map_;
};

} // namespace geocomp::continuum
