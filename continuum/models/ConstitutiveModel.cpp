#include "continuum/models/ConstitutiveModel.h"

#include <Eigen/Eigenvalues>

namespace geocomp::continuum {

PlasticHistory ConstitutiveModel::initial_history(const Vector6 &) const { return {}; }

const char *to_string(ReturnRegion region) {
  switch (region) {
  case ReturnRegion::elastic:
    return "elastic";
  case ReturnRegion::plane:
    return "plane";
  case ReturnRegion::left_edge:
    return "left_edge";
  case ReturnRegion::right_edge:
    return "right_edge";
  case ReturnRegion::apex:
    return "apex";
  }
  return "unknown";
}

double volumetric_plastic_strain(const PlasticHistory &h) {
  return h.plastic_strain.head<3>().sum();
}

double max_plastic_shear_strain(const PlasticHistory &h) {
  const Eigen::SelfAdjointEigenSolver<Matrix3> es(from_mandel(h.plastic_strain),
                                                  Eigen::EigenvaluesOnly);
  return es.eigenvalues()(2) - es.eigenvalues()(0);
}

} // namespace geocomp::continuum
