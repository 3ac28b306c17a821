#include "common/Tensor.h"

#include <cmath>

namespace geocomp {

Vector3 principal_values(const Tensor3 &symmetric)
{
  Eigen::SelfAdjointEigenSolver<Tensor3> solver(symmetric, Eigen::EigenvaluesOnly);
  return solver.eigenvalues();
}

double tau_max(const Tensor3 &stress)
{
  const Vector3 s = principal_values(stress);
  return 0.5 * (s[2] - s[0]);
}

double gamma_max(const Tensor3 &strain)
{
  const Vector3 e = principal_values(strain);
  return e[2] - e[0];
}

double mean_stress(const Tensor3 &stress) { return stress.trace() / 3.0; }

double von_mises(const Tensor3 &stress)
{
  const Tensor3 s = stress - mean_stress(stress) * Tensor3::Identity();
  return std::sqrt(1.5 * (s.array() * s.array()).sum());
}

Tensor3 logarithmic_strain(const Tensor3 &engineering_strain)
{
  Eigen::SelfAdjointEigenSolver<Tensor3> solver(engineering_strain);
  Vector3 l = solver.eigenvalues();
  for (int i = 0; i < 3; ++i)
    l[i] = std::log1p(l[i]);
  return solver.eigenvectors() * l.asDiagonal() * solver.eigenvectors().transpose();
}

double volumetric_strain(const Tensor3 &engineering_strain)
{
  return (Tensor3::Identity() + engineering_strain).determinant() - 1.0;
}

} // namespace geocomp
