#include "continuum/models/MohrCoulombModel.h"

#include "continuum/models/SpectralDecomposition.h"

namespace geocomp::continuum {

MohrCoulombModel::MohrCoulombModel(MohrCoulombParameters parameters)
    : map_(std::move(parameters)) {}

double MohrCoulombModel::yield_function(const Vector6 &stress, double kappa) const {
  return map_.yield_principal(sorted_spectrum(from_mandel(stress)).values, kappa);
}

MaterialPointUpdate MohrCoulombModel::update(const Vector6 &total_strain,
                                             const PlasticHistory &old) const {
  const IsotropicElasticity &el = map_.elasticity();
  const Vector6 trial_strain = total_strain - old.plastic_strain;
  const SortedSpectrum spec = sorted_spectrum(from_mandel(trial_strain));
  const Matrix3 D_hat = el.principal_stiffness();
  const Vector3 trial_stress = D_hat * spec.values;

  const PrincipalReturn ret = map_.return_principal(trial_stress, old.kappa);

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
  u.tangent = isotropic_function_tangent(spec.vectors, spec.values, ret.stress,
                                         ret.dstress_dtrial * D_hat);
  u.history.plastic_strain = total_strain - el.compliance() * u.stress;
  u.history.kappa = old.kappa + ret.delta_kappa;
  return u;
}

} // namespace geocomp::continuum
