// Single material point, strain-driven with stress-controlled lateral axes: the
// Mohr-Coulomb peak must be the closed form (S0; CONTINUUM-THEORY.md Sec. 6).
#include "ContinuumTestSupport.h"

#include "continuum/models/MohrCoulombModel.h"

#include <gtest/gtest.h>

using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

namespace {

// Hardening to a peak plateau kappa in [2e-3, 4e-3], then softening to a residual.
MohrCoulombParameters hardening_softening_material() {
  MohrCoulombParameters p;
  p.youngs_modulus = 2.0e9;
  p.poisson_ratio = 0.25;
  p.cohesion = PiecewiseLinear({0.0, 2e-3, 4e-3, 2e-2}, {0.5e6, 1.0e6, 1.0e6, 0.2e6});
  p.friction_angle = PiecewiseLinear({0.0, 2e-3, 4e-3, 2e-2}, {deg(25), deg(35), deg(35), deg(28)});
  p.dilatancy_angle = PiecewiseLinear({0.0, 2e-3, 4e-3, 2e-2}, {deg(5), deg(10), deg(10), deg(0)});
  return p;
}

double N_of(double phi) { return (1.0 + std::sin(phi)) / (1.0 - std::sin(phi)); }

} // namespace

TEST(MohrCoulombMaterialPoint, TriaxialCompressionPeakEqualsClosedFormAndDilatesWithNpsi) {
  const MohrCoulombParameters par = hardening_softening_material();
  const MohrCoulombModel model(par);
  const double p = 2.0e6; // confining pressure, compression
  const double K = model.elasticity().bulk_modulus();
  AxisymmetricPoint point{model};
  point.strain.head<3>().setConstant(-p / (3.0 * K));

  // Closed form at the peak plateau (compression positive): s1 = s3 N + 2c sqrt(N).
  const double phi = deg(35), c = 1.0e6, psi = deg(10);
  const double peak_compression = p * N_of(phi) + 2.0 * c * std::sqrt(N_of(phi));

  double max_compression = 0.0;
  int plateau_steps = 0;
  Vector6 previous_strain = point.strain;
  for (int step = 1; step <= 400; ++step) {
    ASSERT_GE(point.step(-p / (3.0 * K) - 1e-4 * step, -p, 1e-13 * p), 0)
        << "mixed control diverged at " << step;
    const Vector6 &s = point.last.stress;
    max_compression = std::max(max_compression, -s(2));
    const double kappa = point.history.kappa;
    if (kappa > 2.05e-3 && kappa < 3.95e-3 && point.last.region != ReturnRegion::elastic) {
      // On the plateau the return is to the compression corner (left edge) and the
      // flow is steady: d eps_v / d eps_axial = 1 - N_psi (tension positive).
      EXPECT_EQ(point.last.region, ReturnRegion::left_edge);
      const Vector6 de = point.strain - previous_strain;
      const double ratio = de.head<3>().sum() / de(2);
      if (plateau_steps > 0) // the first plateau step still carries elastic unloading/loading
        EXPECT_NEAR(ratio, 1.0 - N_of(psi), 1e-8);
      ++plateau_steps;
    }
    previous_strain = point.strain;
  }
  EXPECT_GE(plateau_steps, 5);
  EXPECT_NEAR(max_compression / peak_compression, 1.0, 1e-10);
  // Softened to the residual: strength well below the peak at the end.
  EXPECT_LT(-point.last.stress(2), 0.9 * peak_compression);
  EXPECT_GT(point.history.kappa, 2e-2);
}

TEST(MohrCoulombMaterialPoint, PlaneStrainPeakEqualsClosedFormWithIntermediateStress) {
  MohrCoulombParameters par;
  par.youngs_modulus = 1.0e9;
  par.poisson_ratio = 0.3;
  par.cohesion = PiecewiseLinear(0.4e6);
  par.friction_angle = PiecewiseLinear(deg(30));
  par.dilatancy_angle = PiecewiseLinear(deg(8));
  const MohrCoulombModel model(par);
  const double nu = par.poisson_ratio, p = 1.5e6, c = 0.4e6, phi = deg(30);
  const double K = model.elasticity().bulk_modulus();
  MixedControlPoint point{model};
  point.strain.head<3>().setConstant(-p / (3.0 * K));

  // Plane strain in y (eps_yy frozen), sigma_xx = -p, eps_zz driven. With the main-plane
  // flow vector having no y component, eps^p_yy = 0 and sigma_yy stays elastic:
  // sigma_yy = -p + nu (sigma_zz + p). Peak: -sigma_zz = p N + 2c sqrt(N).
  const double szz_peak = -(p * N_of(phi) + 2.0 * c * std::sqrt(N_of(phi)));
  const double syy_peak = -p + nu * (szz_peak + p);
  double min_szz = 0.0;
  int plastic_steps = 0;
  for (int step = 1; step <= 150; ++step) {
    Vector6 target = Vector6::Zero();
    target(0) = -p;
    target(1) = -p / (3.0 * K);
    target(2) = -p / (3.0 * K) - 1e-4 * step;
    ASSERT_GE(point.step(target, {0}, 1e-13 * p), 0);
    min_szz = std::min(min_szz, point.last.stress(2));
    if (point.last.region != ReturnRegion::elastic) {
      ++plastic_steps;
      EXPECT_EQ(point.last.region, ReturnRegion::plane);
      EXPECT_NEAR(point.last.stress(1) / syy_peak, 1.0, 1e-10);
      EXPECT_NEAR(point.history.plastic_strain(1), 0.0, 1e-14);
    }
  }
  EXPECT_GT(plastic_steps, 50);
  EXPECT_NEAR(min_szz / szz_peak, 1.0, 1e-10);
  // The intermediate stress really is intermediate.
  EXPECT_LT(point.last.stress(1), -p);
  EXPECT_GT(point.last.stress(1), szz_peak);
}

TEST(MohrCoulombMaterialPoint, TriaxialExtensionReturnsToRightEdgeAtClosedForm) {
  MohrCoulombParameters par;
  par.youngs_modulus = 1.0e9;
  par.poisson_ratio = 0.2;
  par.cohesion = PiecewiseLinear(0.3e6);
  par.friction_angle = PiecewiseLinear(deg(32));
  par.dilatancy_angle = PiecewiseLinear(deg(5));
  const MohrCoulombModel model(par);
  const double p = 3.0e6, c = 0.3e6, N = N_of(deg(32));
  const double K = model.elasticity().bulk_modulus();
  AxisymmetricPoint point{model};
  point.strain.head<3>().setConstant(-p / (3.0 * K));
  // sigma_zz becomes the major stress: s3 = s1 N - 2 c sqrt(N) with s2 = s3 = -p.
  const double szz_limit = (-p + 2.0 * c * std::sqrt(N)) / N;
  double max_szz = -p;
  for (int step = 1; step <= 100; ++step) {
    ASSERT_GE(point.step(-p / (3.0 * K) + 5e-5 * step, -p, 1e-13 * p), 0);
    max_szz = std::max(max_szz, point.last.stress(2));
    if (point.last.region != ReturnRegion::elastic)
      EXPECT_EQ(point.last.region, ReturnRegion::right_edge);
  }
  EXPECT_EQ(point.last.region, ReturnRegion::right_edge);
  EXPECT_NEAR(max_szz / szz_limit, 1.0, 1e-10);
}
