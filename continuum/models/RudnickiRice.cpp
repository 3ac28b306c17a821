#include "continuum/models/RudnickiRice.h"

#include "continuum/models/SpectralDecomposition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::continuum {

RudnickiRicePrediction rudnicki_rice_prediction(const RudnickiRiceMaterial &m, double N) {
  const double nu = m.nu;
  RudnickiRicePrediction r;
  const double bm = m.beta + m.mu;
  // Rudnicki & Rice 1975, critical h (CONTINUUM-THEORY.md Sec. 3)
  r.critical_hardening_over_G = (1.0 + nu) / (9.0 * (1.0 - nu)) * (m.beta - m.mu) * (m.beta - m.mu) -
                                0.5 * (1.0 + nu) * (N + bm / 3.0) * (N + bm / 3.0);
  // Rudnicki & Rice 1975, band angle (CONTINUUM-THEORY.md Sec. 3)
  r.alpha = (2.0 / 3.0 * (1.0 + nu) * bm - N * (1.0 - 2.0 * nu)) / std::sqrt(4.0 - 3.0 * N * N);
  r.closed_form_valid = std::abs(r.alpha) <= 1.0;
  const double a = std::clamp(r.alpha, -1.0, 1.0);
  r.band_normal_angle = M_PI / 4.0 + 0.5 * std::asin(a);
  r.band_plane_angle = M_PI / 2.0 - r.band_normal_angle;
  return r;
}

RudnickiRiceMaterial rudnicki_rice_from_drucker_prager(double omega, double Lambda, double nu) {
  return {3.0 * omega, Lambda, nu};
}

double deviatoric_state(const Matrix3 &stress) {
  const Vector3 v = sorted_spectrum(stress).values; // descending: I, II, III
  const Vector3 s = v - Vector3::Constant(v.sum() / 3.0);
  const double tau = std::sqrt(0.5 * s.squaredNorm());
  return tau > 0.0 ? s(1) / tau : 0.0;
}

Vector3 rudnicki_rice_band_normal(const Matrix3 &stress, double theta0) {
  const SortedSpectrum sp = sorted_spectrum(stress);
  return std::cos(theta0) * sp.vectors.col(2) + std::sin(theta0) * sp.vectors.col(0);
}

Matrix6 rudnicki_rice_tangent(const RudnickiRiceMaterial &m, double G, double h,
                              const Matrix3 &stress) {
  const double nu = m.nu;
  const double K = 2.0 * G * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
  const Vector6 one = mandel_identity();
  const Vector6 sig = to_mandel(stress);
  const Vector6 s = sig - sig.head<3>().sum() / 3.0 * one;
  const double tau = std::sqrt(0.5 * s.squaredNorm());
  if (!(tau > 0.0))
    throw std::invalid_argument("Rudnicki-Rice tangent: needs a non-hydrostatic stress");
  const Matrix6 C = K * one * one.transpose() + 2.0 * G * mandel_deviatoric_projector();
  const Vector6 a = G * s / tau + m.beta * K * one; // Rudnicki & Rice 1975 constitutive tangent (CONTINUUM-THEORY.md Sec. 3)
  const Vector6 b = G * s / tau + m.mu * K * one;
  return C - a * b.transpose() / (h + G + m.mu * m.beta * K);
}

} // namespace geocomp::continuum
