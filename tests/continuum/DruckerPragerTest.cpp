// Drucker-Prager: constructed returns (cone, apex, elastic) are recovered exactly;
// random trials land on the cone with flow s/(2 tau) + Lambda/3 1; the consistent
// tangent equals finite differences (coincident eigenvalues included); the algorithmic
// tangent tends to the continuum tangent as the step vanishes; and the Mohr-Coulomb
// matchings reproduce the Mohr-Coulomb limit states they are built for.
#include "ContinuumTestSupport.h"

#include "continuum/models/DruckerPragerModel.h"
#include "continuum/models/MohrCoulombModel.h"

#include <gtest/gtest.h>

using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

namespace {

DruckerPragerParameters material(bool hardening) {
  DruckerPragerParameters p;
  p.youngs_modulus = 1.0e9;
  p.poisson_ratio = 0.25;
  if (hardening) {
    p.strength = PiecewiseLinear({0.0, 1e-2, 5e-2}, {0.8e6, 1.3e6, 0.7e6});
    p.friction = PiecewiseLinear({0.0, 1e-2, 5e-2}, {0.15, 0.25, 0.2});
    p.dilatancy = PiecewiseLinear({0.0, 1e-2, 5e-2}, {0.05, 0.2, 0.1});
  } else {
    p.strength = PiecewiseLinear(1.0e6);
    p.friction = PiecewiseLinear(0.2);
    p.dilatancy = PiecewiseLinear(0.12);
  }
  return p;
}

// Unit deviator direction (tau = 1) for a Lode-type angle theta; theta = 0 gives
// s2 = s3 (axisymmetric, coincident eigenvalues).
Vector3 deviator_direction(double theta) {
  const double k = 2.0 / std::sqrt(3.0);
  return k * Vector3(std::cos(theta), std::cos(theta - 2.0 * M_PI / 3.0),
                     std::cos(theta + 2.0 * M_PI / 3.0));
}

struct Constructed {
  Vector3 trial, stress;
  double kappa_new;
};

Constructed construct(const DruckerPragerModel &model, ReturnRegion region, double kappa_n,
                      double dk, std::mt19937_64 &rng, bool coincident) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const DruckerPragerParameters &p = model.parameters();
  const double G = model.elasticity().shear_modulus(), K = model.elasticity().bulk_modulus();
  const Vector3 dir = deviator_direction(coincident ? 0.0 : 2.0 * M_PI * U(rng));
  const Vector3 one = Vector3::Ones();
  Constructed c;
  if (region == ReturnRegion::elastic) {
    const double om = p.friction(kappa_n), Y = p.strength(kappa_n);
    const double pm = Y / (3.0 * om) - Y * (0.1 + 20.0 * U(rng));
    const double tau = coincident ? 0.0 : (Y - 3.0 * om * pm) * (0.05 + 0.9 * U(rng));
    c.trial = c.stress = pm * one + tau * dir;
    c.kappa_new = kappa_n;
    return c;
  }
  const double k1 = kappa_n + dk;
  const double om = p.friction(k1), Y = p.strength(k1), lam = p.dilatancy(k1);
  c.kappa_new = k1;
  if (region == ReturnRegion::plane) {
    const double pm = Y / (3.0 * om) - Y * (0.05 + 20.0 * U(rng));
    const double tau = Y - 3.0 * om * pm;
    c.stress = pm * one + tau * dir;
    c.trial = (pm + K * lam * dk) * one + (tau + G * dk) * dir;
  } else { // apex
    const double pm = Y / (3.0 * om);
    c.stress = pm * one;
    c.trial = (pm + K * lam * dk) * one + (coincident ? 0.0 : 0.95 * U(rng) * G * dk) * dir;
  }
  return c;
}

} // namespace

TEST(DruckerPragerReturn, RecoversConstructedReturnsOnConeApexAndInside) {
  for (bool hardening : {false, true}) {
    const DruckerPragerModel model(material(hardening));
    const Matrix6 &S = model.elasticity().compliance();
    std::mt19937_64 rng(hardening ? 17 : 19);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (ReturnRegion region : {ReturnRegion::elastic, ReturnRegion::plane, ReturnRegion::apex}) {
      int failures = 0;
      for (int n = 0; n < 10000; ++n) {
        const double kappa_n = hardening ? 0.06 * U(rng) : 0.0;
        const double dk = 1e-4 + 5e-3 * U(rng);
        const Constructed c = construct(model, region, kappa_n, dk, rng, n % 10 == 0);
        const Matrix3 Q = random_rotation(rng);
        PlasticHistory old;
        old.kappa = kappa_n;
        const MaterialPointUpdate u = model.update(S * rotated(c.trial, Q), old);
        const double scale = std::max(c.trial.cwiseAbs().maxCoeff(), 1e6);
        const double err = (u.stress - rotated(c.stress, Q)).cwiseAbs().maxCoeff() / scale;
        if ((u.region != region || err > 1e-10 ||
             std::abs(u.history.kappa - c.kappa_new) > 1e-10 * std::max(dk, 1e-3)) &&
            ++failures <= 3)
          ADD_FAILURE() << to_string(region) << " got " << to_string(u.region) << " err " << err
                        << " kappa " << u.history.kappa << " vs " << c.kappa_new;
      }
      EXPECT_EQ(failures, 0) << to_string(region);
    }
  }
}

TEST(DruckerPragerReturn, RandomTrialsLandOnConeWithFlowConsistentWithDilatancy) {
  for (bool hardening : {false, true}) {
    const DruckerPragerModel model(material(hardening));
    const Matrix3 Dinv = model.elasticity().principal_stiffness().inverse();
    std::mt19937_64 rng(hardening ? 23 : 29);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    int failures = 0, cone = 0, apex = 0;
    for (int n = 0; n < 25000; ++n) {
      Vector3 e;
      for (int i = 0; i < 3; ++i)
        e(i) = 1e6 * (n % 2 ? -3.0 + 10.0 * U(rng) : -40.0 + 45.0 * U(rng));
      std::sort(e.data(), e.data() + 3, std::greater<double>());
      const double kappa_n = hardening ? 0.06 * U(rng) : 0.0;
      const PrincipalReturn r = model.return_principal(e, kappa_n);
      if (r.region == ReturnRegion::elastic)
        continue;
      const double k1 = kappa_n + r.delta_kappa;
      const DruckerPragerParameters &p = model.parameters();
      const Vector6 s6 = to_mandel(Matrix3(r.stress.asDiagonal()));
      const double scale = r.stress.cwiseAbs().maxCoeff() + p.strength(k1);
      std::string why;
      if (std::abs(model.yield_function(s6, k1)) > 1e-10 * scale)
        why = "off the cone";
      const Vector3 dep = Dinv * (e - r.stress);
      const Vector3 sdev = r.stress - Vector3::Constant(r.stress.mean());
      const double tau = std::sqrt(0.5 * sdev.squaredNorm());
      if (r.region == ReturnRegion::plane) {
        ++cone;
        const Vector3 flow = r.delta_kappa * (sdev / (2.0 * tau) + Vector3::Constant(p.dilatancy(k1) / 3.0));
        if ((dep - flow).norm() > 1e-9 * dep.norm())
          why = "cone flow not s/(2 tau) + Lambda/3 1";
      } else {
        ++apex;
        const Vector3 dev = dep - Vector3::Constant(dep.mean());
        if (std::abs(dep.sum() - p.dilatancy(k1) * r.delta_kappa) > 1e-9 * dep.norm() ||
            std::sqrt(2.0 * dev.squaredNorm()) > r.delta_kappa * (1.0 + 1e-9))
          why = "apex flow outside the cone of potential gradients";
      }
      if (!why.empty() && ++failures <= 5)
        ADD_FAILURE() << why << " trial " << e.transpose();
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(cone, 1000);
    EXPECT_GT(apex, 100);
  }
}

TEST(DruckerPragerTangent, MatchesFiniteDifferencesOnConeAndApexWithAndWithoutHardening) {
  for (double kappa_n : {0.0, 0.003, 0.03}) {
    const bool hardening = kappa_n > 0.0;
    const DruckerPragerModel model(material(hardening));
    const Matrix6 &S = model.elasticity().compliance();
    const Matrix6 &D = model.elasticity().stiffness();
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (ReturnRegion region : {ReturnRegion::elastic, ReturnRegion::plane, ReturnRegion::apex})
      for (bool coincident : {false, true})
        for (int sample = 0; sample < 5; ++sample) {
          const Constructed c = construct(model, region, kappa_n, 1e-3 + 4e-3 * U(rng), rng, coincident);
          const Matrix3 Q = random_rotation(rng);
          PlasticHistory old;
          old.kappa = kappa_n;
          const Vector6 eps = S * rotated(c.trial, Q);
          const MaterialPointUpdate u = model.update(eps, old);
          ASSERT_EQ(u.region, region);
          const Matrix6 fd = finite_difference_tangent(model, eps, old, 1e-9);
          EXPECT_LT(relative_difference(u.tangent, fd, 1e-3 * D.cwiseAbs().maxCoeff()), 1e-6)
              << to_string(region) << (coincident ? " coincident" : "") << " kappa_n " << kappa_n
              << "\nC_alg=\n" << u.tangent << "\nFD=\n" << fd;
        }
  }
}

TEST(DruckerPragerTangent, AlgorithmicTangentTendsToContinuumTangentForVanishingStep) {
  const DruckerPragerModel model(material(true));
  const Matrix6 &S = model.elasticity().compliance();
  std::mt19937_64 rng(37);
  for (double kappa_n : {0.004, 0.03}) {
    const Constructed c = construct(model, ReturnRegion::plane, kappa_n, 1e-13, rng, false);
    const Matrix3 Q = random_rotation(rng);
    PlasticHistory old;
    old.kappa = kappa_n;
    const MaterialPointUpdate u = model.update(S * rotated(c.trial, Q), old);
    ASSERT_EQ(u.region, ReturnRegion::plane);
    const Matrix6 L = model.continuum_tangent(u.stress, u.history.kappa);
    EXPECT_LT(relative_difference(u.tangent, L, 0.0), 1e-6);
    // ... and differs from it by O(dgamma) for a finite step.
    const Constructed big = construct(model, ReturnRegion::plane, kappa_n, 5e-3, rng, false);
    const MaterialPointUpdate v = model.update(S * rotated(big.trial, Q), old);
    EXPECT_GT(relative_difference(v.tangent, model.continuum_tangent(v.stress, v.history.kappa), 0.0), 1e-3);
  }
}

namespace {
MohrCoulombParameters mc_material(double phi, double psi, double c) {
  MohrCoulombParameters p;
  p.youngs_modulus = 1.0e9;
  p.poisson_ratio = 0.3;
  p.cohesion = PiecewiseLinear(c);
  p.friction_angle = PiecewiseLinear(phi);
  p.dilatancy_angle = PiecewiseLinear(psi);
  return p;
}
double N_of(double phi) { return (1.0 + std::sin(phi)) / (1.0 - std::sin(phi)); }
} // namespace

TEST(DruckerPragerMatching, OuterConeHasMohrCoulombTriaxialCompressionStrength) {
  const double phi = deg(30), c = 0.5e6, p = 2.0e6;
  const DruckerPragerModel dp(DruckerPragerParameters::from_mohr_coulomb(
      mc_material(phi, deg(10), c), DruckerPragerMatching::outer_cone));
  AxisymmetricPoint point{dp};
  const double K = dp.elasticity().bulk_modulus();
  point.strain.head<3>().setConstant(-p / (3.0 * K));
  double peak = 0.0;
  for (int step = 1; step <= 200; ++step) {
    ASSERT_GE(point.step(-p / (3.0 * K) - 1e-4 * step, -p, 1e-13 * p), 0);
    peak = std::max(peak, -point.last.stress(2));
  }
  EXPECT_NEAR(peak / (p * N_of(phi) + 2.0 * c * std::sqrt(N_of(phi))), 1.0, 1e-10);
}

TEST(DruckerPragerMatching, InnerConeHasMohrCoulombTriaxialExtensionStrength) {
  const double phi = deg(30), c = 0.5e6, p = 4.0e6;
  const DruckerPragerModel dp(DruckerPragerParameters::from_mohr_coulomb(
      mc_material(phi, deg(10), c), DruckerPragerMatching::inner_cone));
  AxisymmetricPoint point{dp};
  const double K = dp.elasticity().bulk_modulus();
  point.strain.head<3>().setConstant(-p / (3.0 * K));
  double limit = -p;
  for (int step = 1; step <= 200; ++step) {
    ASSERT_GE(point.step(-p / (3.0 * K) + 5e-5 * step, -p, 1e-13 * p), 0);
    limit = std::max(limit, point.last.stress(2));
  }
  const double N = N_of(phi);
  EXPECT_NEAR(limit / ((-p + 2.0 * c * std::sqrt(N)) / N), 1.0, 1e-10);
}

TEST(DruckerPragerMatching, PlaneStrainMatchReachesMohrCoulombPlaneStrainLimit) {
  // Under plane strain, steady plastic flow needs d eps^p_yy = 0; the matched cone then
  // gives the Mohr-Coulomb limit s3 = s1 N - 2c sqrt(N) in the x-z plane, for any psi.
  for (double psi : {deg(0), deg(10), deg(30)}) {
    const double phi = deg(30), c = 0.4e6, p = 1.5e6;
    const DruckerPragerModel dp(DruckerPragerParameters::from_mohr_coulomb(
        mc_material(phi, psi, c), DruckerPragerMatching::plane_strain));
    MixedControlPoint point{dp};
    const double K = dp.elasticity().bulk_modulus();
    point.strain.head<3>().setConstant(-p / (3.0 * K));
    for (int step = 1; step <= 1000; ++step) {
      Vector6 target = Vector6::Zero();
      target(0) = -p;
      target(1) = -p / (3.0 * K);
      target(2) = -p / (3.0 * K) - 2e-4 * step;
      ASSERT_GE(point.step(target, {0}, 1e-13 * p), 0);
    }
    const double N = N_of(phi);
    EXPECT_NEAR(point.last.stress(2) / (-p * N - 2.0 * c * std::sqrt(N)), 1.0, 1e-8)
        << "psi " << psi;
  }
}
