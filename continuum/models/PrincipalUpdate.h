#pragma once
// The update of a model that returns in principal stress space (Mohr-Coulomb,
// Drucker-Prager): trial strain, its sorted spectrum, the model's principal return, then
// the stress, consistent tangent and history assembled back in the trial eigenvectors.
//
// Why a function of its own: only the principal return differs between the models; the
// elastic predictor and the assembly around it (SpectralDecomposition.h) are the same.
#include "continuum/models/ConstitutiveModel.h"
#include "continuum/models/MohrCoulombReturnMap.h"
#include "continuum/models/SpectralDecomposition.h"

namespace geocomp::continuum {

/// ConstitutiveModel::update for isotropic elasticity `el` and a principal return
/// `return_principal(sorted principal trial stresses, kappa_n) -> PrincipalReturn`.
template <class ReturnPrincipal>
MaterialPointUpdate principal_space_update(const IsotropicElasticity &el, const Vector6 &total_strain,
                                           const PlasticHistory &old, const ReturnPrincipal &return_principal)
{
  const Vector6 trial_strain = total_strain - old.plastic_strain;
  const SortedSpectrum spec = sorted_spectrum(from_mandel(trial_strain));
  const Matrix3 D_hat = el.principal_stiffness();
  const Vector3 trial_stress = D_hat * spec.values;

  const PrincipalReturn ret = return_principal(trial_stress, old.kappa);

  MaterialPointUpdate u;
  u.region = ret.region;
  u.trial_yield_value = ret.trial_yield;
  u.local_iterations = ret.iterations;
  u.history = old;
  if (ret.region == ReturnRegion::elastic) {
    u.stress = el.stiffness() * trial_strain;
    u.tangent = el.stiffness();
    return u;
  }
  u.stress = assemble_from_principal(ret.stress, spec.vectors);
  u.tangent = isotropic_function_tangent(spec.vectors, spec.values, ret.stress, ret.dstress_dtrial * D_hat);
  u.history.plastic_strain = total_strain - el.compliance() * u.stress;
  u.history.kappa = old.kappa + ret.delta_kappa;
  return u;
}

} // namespace geocomp::continuum
