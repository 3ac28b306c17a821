#include "continuum/models/MohrCoulombModel.h"

#include "continuum/models/PrincipalUpdate.h"
#include "continuum/models/SpectralDecomposition.h"

namespace geocomp::continuum {

MohrCoulombModel::MohrCoulombModel(MohrCoulombParameters parameters)
    : map_(std::move(parameters)) {}

double MohrCoulombModel::yield_function(const Vector6 &stress, double kappa) const {
  return map_.yield_principal(sorted_spectrum(from_mandel(stress)).values, kappa);
}

MaterialPointUpdate MohrCoulombModel::update(const Vector6 &total_strain,
                                             const PlasticHistory &old) const {
  return principal_space_update(map_.elasticity(), total_strain, old,
                                [this](const Vector3 &trial, double kappa_n) {
                                  return map_.return_principal(trial, kappa_n);
                                });
}

} // namespace geocomp::continuum
