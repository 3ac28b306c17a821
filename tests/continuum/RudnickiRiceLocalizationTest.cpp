// Rudnicki & Rice (1975): the closed form against the worked example of
// CONTINUUM-THEORY.md, and the acoustic-tensor scan of a Drucker-Prager continuum tangent
// against the closed form: the hardening modulus at which min_n det(n.L.n)/det(n.C.n)
// reaches zero, and the angle of the critical normal from the sigma_III axis, to 1e-6.
#include "ContinuumTestSupport.h"

#include "continuum/models/AcousticTensorScan.h"
#include "continuum/models/DruckerPragerModel.h"
#include "continuum/models/RudnickiRice.h"

#include <gtest/gtest.h>

using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

TEST(RudnickiRiceClosedForm, ReproducesTheWorkedExampleTable) {
  // CONTINUUM-THEORY.md Sec. 3: nu = 0.3, mu = 0.6, beta = 0.3 (published to 5 digits).
  const RudnickiRiceMaterial m{0.6, 0.3, 0.3};
  const double r3 = 1.0 / std::sqrt(3.0);
  const RudnickiRicePrediction comp = rudnicki_rice_prediction(m, r3);
  EXPECT_NEAR(comp.critical_hardening_over_G, -0.48176, 1e-5);
  EXPECT_NEAR(comp.alpha, 0.31700, 1e-5);
  EXPECT_NEAR(comp.band_normal_angle * 180.0 / M_PI, 54.241, 1e-3);
  const RudnickiRicePrediction zero = rudnicki_rice_prediction(m, 0.0);
  EXPECT_NEAR(zero.critical_hardening_over_G, -0.03993, 1e-5);
  EXPECT_NEAR(zero.band_normal_angle * 180.0 / M_PI, 56.477, 1e-3);
  const RudnickiRicePrediction ext = rudnicki_rice_prediction(m, -r3);
  EXPECT_NEAR(ext.critical_hardening_over_G, -0.03143, 1e-5);
  EXPECT_NEAR(ext.alpha, 0.58367, 1e-5);
}

TEST(RudnickiRiceClosedForm, DeviatoricStateAndDruckerPragerMapping) {
  EXPECT_NEAR(deviatoric_state(Vector3(-1.0, -1.0, -5.0).asDiagonal()), 1.0 / std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(deviatoric_state(Vector3(-1.0, -5.0, -5.0).asDiagonal()), -1.0 / std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(deviatoric_state(Vector3(1.0, 0.0, -1.0).asDiagonal()), 0.0, 1e-14);
  const RudnickiRiceMaterial m = rudnicki_rice_from_drucker_prager(0.2, 0.15, 0.25);
  EXPECT_DOUBLE_EQ(m.mu, 0.6);
  EXPECT_DOUBLE_EQ(m.beta, 0.15);
}

namespace {

// Stress with deviatoric state N, on the cone of `model` at kappa, in a rotated frame.
Matrix3 stress_with_state(double N, double p, double tau, const Matrix3 &Q) {
  const double half = std::sqrt(1.0 - 0.75 * N * N);
  const Vector3 s(-0.5 * N + half, N, -0.5 * N - half); // s_I >= s_II >= s_III, J2 = 1
  return Q * (p * Vector3::Ones() + tau * s).asDiagonal() * Q.transpose();
}

// Drucker-Prager model whose hardening modulus at kappa = 5e-4 is h.
DruckerPragerModel dp_with_hardening(double E, double nu, double omega, double Lambda, double h) {
  DruckerPragerParameters p;
  p.youngs_modulus = E;
  p.poisson_ratio = nu;
  p.strength = PiecewiseLinear({0.0, 1e-3}, {1e7, 1e7 + 1e-3 * h});
  p.friction = PiecewiseLinear(omega);
  p.dilatancy = PiecewiseLinear(Lambda);
  return DruckerPragerModel(p);
}

struct Onset {
  double h_over_G;
  Vector3 normal;
};

// The hardening modulus where the scan's q_min crosses zero (bracketing + Illinois),
// found without using the closed form.
Onset scan_onset(double nu, double omega, double Lambda, double N, const Matrix3 &Q) {
  const double E = 2.6e9, G = E / (2.0 * (1.0 + nu)), kappa = 5e-4;
  const AcousticTensorScan scan;
  auto q_min = [&](double h_over_G, Vector3 *normal) {
    const DruckerPragerModel model = dp_with_hardening(E, nu, omega, Lambda, h_over_G * G);
    const double Y = model.parameters().strength(kappa), p = -2e7;
    const Matrix3 sigma = stress_with_state(N, p, Y - 3.0 * omega * p, Q);
    const Vector6 s6 = to_mandel(sigma);
    EXPECT_NEAR(model.yield_function(s6, kappa), 0.0, 1e-6 * Y);
    const LocalizationResult r =
        scan.scan(model.continuum_tangent(s6, kappa), model.elasticity().stiffness());
    if (normal)
      *normal = r.normal;
    return r.min_ratio;
  };
  // Bracket: from h = G (no localization) down until q_min < 0.
  double hi = 1.0, q_hi = q_min(hi, nullptr);
  EXPECT_GT(q_hi, 0.0);
  double lo = hi - 0.05, q_lo = q_min(lo, nullptr);
  while (q_lo > 0.0 && lo > -5.0) {
    hi = lo;
    q_hi = q_lo;
    lo -= 0.05;
    q_lo = q_min(lo, nullptr);
  }
  EXPECT_LT(q_lo, 0.0);
  int side = 0;
  double x = hi;
  for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
    x = (lo * q_hi - hi * q_lo) / (q_hi - q_lo);
    const double qx = q_min(x, nullptr);
    if (qx == 0.0)
      break;
    if (qx < 0.0) {
      lo = x;
      q_lo = qx;
      if (side == -1)
        q_hi *= 0.5;
      side = -1;
    } else {
      hi = x;
      q_hi = qx;
      if (side == 1)
        q_lo *= 0.5;
      side = 1;
    }
  }
  Onset o{x, Vector3::Zero()};
  q_min(x, &o.normal);
  return o;
}

} // namespace

TEST(RudnickiRiceLocalization, AcousticScanOfDruckerPragerTangentMatchesClosedForm) {
  std::mt19937_64 rng(53);
  struct Case {
    double nu, omega, Lambda, N;
  };
  const double r3 = 1.0 / std::sqrt(3.0);
  const Case cases[] = {
      {0.3, 0.2, 0.3, r3},      // worked example: mu = 0.6, beta = 0.3, axisymmetric compression
      {0.3, 0.2, 0.3, 0.0},     // N = 0 (plane-strain-like)
      {0.25, 0.15, 0.05, 0.3},  // low dilatancy, general state
      {0.2, 0.1, 0.1, -0.2},    // towards extension, mu = 0.3 > beta = 0.1
      {0.35, 0.25, 0.0, 0.45},  // no dilatancy
  };
  for (const Case &c : cases) {
    const Matrix3 Q = random_rotation(rng);
    const RudnickiRicePrediction rr =
        rudnicki_rice_prediction(rudnicki_rice_from_drucker_prager(c.omega, c.Lambda, c.nu), c.N);
    ASSERT_TRUE(rr.closed_form_valid);
    const Onset onset = scan_onset(c.nu, c.omega, c.Lambda, c.N, Q);
    EXPECT_NEAR(onset.h_over_G, rr.critical_hardening_over_G, 1e-6)
        << "nu " << c.nu << " mu " << 3 * c.omega << " beta " << c.Lambda << " N " << c.N;
    // Band normal: angle theta_0 from sigma_III, and (unless axisymmetric) no sigma_II part.
    const Vector3 e_III = Q.col(2), e_II = Q.col(1);
    const double theta = std::acos(std::min(1.0, std::abs(onset.normal.dot(e_III))));
    EXPECT_NEAR(theta, rr.band_normal_angle, 1e-6) << "N " << c.N;
    if (std::abs(std::abs(c.N) - r3) > 1e-3)
      EXPECT_LT(std::abs(onset.normal.dot(e_II)), 1e-6);
  }
}

TEST(RudnickiRiceLocalization, DruckerPragerContinuumTangentIsTheRudnickiRiceTangent) {
  const double nu = 0.28, E = 1.0e9, G = E / (2.0 * (1.0 + nu)), h = -0.1 * G;
  const DruckerPragerModel model = dp_with_hardening(E, nu, 0.18, 0.22, h);
  std::mt19937_64 rng(59);
  const Matrix3 Q = random_rotation(rng);
  const double Y = model.parameters().strength(5e-4), p = -1e7;
  const Matrix3 sigma = stress_with_state(0.2, p, Y - 3.0 * 0.18 * p, Q);
  const Matrix6 L = model.continuum_tangent(to_mandel(sigma), 5e-4);
  const Matrix6 RR = rudnicki_rice_tangent(rudnicki_rice_from_drucker_prager(0.18, 0.22, nu), G, h, sigma);
  EXPECT_LT(relative_difference(L, RR, 0.0), 1e-12);
}

TEST(AcousticTensorScan, ElasticTangentNeverLocalizesAndScanFindsPlantedMinimum) {
  const IsotropicElasticity el(1e9, 0.3);
  const AcousticTensorScan scan;
  const LocalizationResult r = scan.scan(el.stiffness(), el.stiffness());
  EXPECT_NEAR(r.min_ratio, 1.0, 1e-12);
  // Planted: C - k (m (x) m) with m = sym(n0 (x) t) removes stiffness along one band mode;
  // at k = 1/(m.S.m) the acoustic tensor is singular for normal n0 (det ratio 0).
  std::mt19937_64 rng(61);
  const Matrix3 Q = random_rotation(rng);
  const Vector3 n0 = Q.col(0), t = Q.col(1);
  const Vector6 m = to_mandel(0.5 * (n0 * t.transpose() + t * n0.transpose()));
  const Vector6 a = el.stiffness() * m;
  const Matrix6 C = el.stiffness() - a * a.transpose() / m.dot(a);
  const LocalizationResult planted = scan.scan(C, el.stiffness());
  EXPECT_NEAR(planted.min_ratio, 0.0, 1e-10);
  EXPECT_NEAR(AcousticTensorScan::determinant_ratio(C, el.stiffness(), n0), 0.0, 1e-12);
}
