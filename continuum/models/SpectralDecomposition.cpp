#include "continuum/models/SpectralDecomposition.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace geocomp::continuum {

SortedSpectrum sorted_spectrum(const Matrix3 &a) {
  const Eigen::SelfAdjointEigenSolver<Matrix3> es(0.5 * (a + a.transpose()));
  // Eigen sorts ascending; reverse to descending.
  SortedSpectrum s;
  for (int i = 0; i < 3; ++i) {
    s.values(i) = es.eigenvalues()(2 - i);
    s.vectors.col(i) = es.eigenvectors().col(2 - i);
  }
  return s;
}

namespace {
Vector6 dyad_mandel(const Vector3 &a, const Vector3 &b) {
  const Matrix3 t = 0.5 * (a * b.transpose() + b * a.transpose());
  return to_mandel(t);
}
} // namespace

Vector6 assemble_from_principal(const Vector3 &values, const Matrix3 &vectors) {
  Vector6 m = Vector6::Zero();
  for (int i = 0; i < 3; ++i)
    m += values(i) * dyad_mandel(vectors.col(i), vectors.col(i));
  return m;
}

Matrix6 isotropic_function_tangent(const Matrix3 &vectors, const Vector3 &trial_strain,
                                   const Vector3 &stress, const Matrix3 &Dp,
                                   double coincidence_tolerance) {
  const double scale = trial_strain.cwiseAbs().maxCoeff();
  Matrix3 spin = Matrix3::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const double de = trial_strain(i) - trial_strain(j);
      if (std::abs(de) <= coincidence_tolerance * scale)
        spin(i, j) = 0.5 * ((Dp(i, i) - Dp(i, j)) + (Dp(j, j) - Dp(j, i))); // limiting formula
      else
        spin(i, j) = (stress(i) - stress(j)) / de;
    }
  return isotropic_function_tangent(vectors, Dp, spin);
}

Matrix6 isotropic_function_tangent(const Matrix3 &vectors, const Matrix3 &Dp, const Matrix3 &spin) {
  Vector6 E[3];
  for (int i = 0; i < 3; ++i)
    E[i] = dyad_mandel(vectors.col(i), vectors.col(i));

  Matrix6 C = Matrix6::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      C += Dp(i, j) * E[i] * E[j].transpose();
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      // N_ij = (e_i e_j + e_j e_i)/sqrt2 has unit Mandel norm; dyad_mandel gives half the sum.
      const Vector6 N = std::sqrt(2.0) * dyad_mandel(vectors.col(i), vectors.col(j));
      C += spin(i, j) * N * N.transpose();
    }
  return C;
}

} // namespace geocomp::continuum
