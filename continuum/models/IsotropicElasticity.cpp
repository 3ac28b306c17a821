#include "continuum/models/IsotropicElasticity.h"

#include <stdexcept>

namespace geocomp::continuum {

IsotropicElasticity::IsotropicElasticity(double E, double nu) : E_(E), nu_(nu) {
  if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5))
    throw std::invalid_argument("IsotropicElasticity: need E > 0 and -1 < nu < 0.5");
  G_ = E / (2.0 * (1.0 + nu));
  K_ = E / (3.0 * (1.0 - 2.0 * nu));
  const Vector6 one = mandel_identity();
  const Matrix6 P = mandel_deviatoric_projector();
  D_ = K_ * one * one.transpose() + 2.0 * G_ * P;
  S_ = one * one.transpose() / (9.0 * K_) + P / (2.0 * G_);
}

Matrix3 IsotropicElasticity::principal_stiffness() const {
  const Matrix3 ones = Matrix3::Ones();
  return K_ * ones + 2.0 * G_ * (Matrix3::Identity() - ones / 3.0);
}

} // namespace geocomp::continuum
