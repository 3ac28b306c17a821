// The finite-strain update (continuum/models/FiniteStrain.h): small strains reproduce the
// small-strain update, the spatial tangent equals central finite differences of the whole
// update in every Mohr-Coulomb region and on the Drucker-Prager cone and apex (coincident
// eigenvalues included), a rigid rotation of a yielding state keeps its principal Cauchy
// stresses, and the exponential map keeps the volume of psi = 0 plastic flow.
#include "MohrCoulombConstruction.h"

#include "continuum/models/DruckerPragerModel.h"
#include "continuum/models/FiniteStrain.h"
#include "continuum/models/MohrCoulombModel.h"
#include "continuum/models/SpectralDecomposition.h"

#include <gtest/gtest.h>

using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

namespace {

MohrCoulombParameters mohr_coulomb(double cohesion, bool hardening)
{
  return tangent_test_material(cohesion, hardening);
}

Matrix3 random_matrix(std::mt19937_64 &rng)
{
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Matrix3 m;
  for (int i = 0; i < 9; ++i)
    m.data()[i] = U(rng);
  return m;
}

/// max|A - B| / max(max|B|, floor).
double relative(const Matrix9 &A, const Matrix9 &B, double floor)
{
  return (A - B).cwiseAbs().maxCoeff() / std::max(B.cwiseAbs().maxCoeff(), floor);
}

/// d tau / d H by central differences of F -> (I + h E_kl) F, column 3k+l.
Matrix9 finite_difference(const ConstitutiveModel &model, const Matrix3 &F, const FiniteStrainHistory &old, double h)
{
  Matrix9 fd;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      Matrix3 E = Matrix3::Zero();
      E(k, l) = h;
      const Matrix3 tp = finite_strain_update(model, (Matrix3::Identity() + E) * F, old).kirchhoff_stress;
      const Matrix3 tm = finite_strain_update(model, (Matrix3::Identity() - E) * F, old).kirchhoff_stress;
      const Matrix3 d = (tp - tm) / (2.0 * h);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          fd(pair_index(i, j), pair_index(k, l)) = d(i, j);
    }
  return fd;
}

/// d tau / d H of an update: its spatial tangent plus tau_il delta_jk.
Matrix9 kirchhoff_derivative(const FiniteStrainUpdate &u)
{
  Matrix9 d = u.spatial_tangent;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l)
        d(pair_index(i, j), pair_index(j, l)) += u.kirchhoff_stress(i, l);
  return d;
}

/// A deformation gradient from F_n that gives exactly the trial elastic log strain
/// `eps_trial` from `old` (F_inc = b_trial^{1/2} R b_n^{-1/2} for a random rotation R).
Matrix3 reaching(const Vector6 &eps_trial, const FiniteStrainHistory &old, std::mt19937_64 &rng)
{
  const Matrix3 root_trial = symmetric_exp(from_mandel(eps_trial));
  const Matrix3 inverse_root_n = symmetric_exp(-0.5 * symmetric_log(old.elastic_left_cauchy_green));
  return root_trial * random_rotation(rng) * inverse_root_n * old.deformation_gradient;
}

/// A history with a stretched, rotated F_n and an elastic strain eps_n.
FiniteStrainHistory random_history(double kappa, std::mt19937_64 &rng)
{
  FiniteStrainHistory h;
  h.deformation_gradient = random_rotation(rng) * (Matrix3::Identity() + 0.2 * random_matrix(rng));
  h.elastic_left_cauchy_green = symmetric_exp(2e-4 * (random_matrix(rng) + random_matrix(rng).transpose()));
  h.kappa = kappa;
  return h;
}

void check_mohr_coulomb_tangent(bool hardening, double kappa_n)
{
  const MohrCoulombModel model(mohr_coulomb(1.0e6, hardening));
  const Matrix6 &S = model.elasticity().compliance();
  const double floor = 1e-3 * model.elasticity().stiffness().cwiseAbs().maxCoeff();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int checked = 0;
  for (ReturnRegion region : {ReturnRegion::elastic, ReturnRegion::plane, ReturnRegion::left_edge,
                              ReturnRegion::right_edge, ReturnRegion::apex}) {
    for (bool coincident : {false, true}) {
      if (coincident && region == ReturnRegion::plane)
        continue;
      for (int sample = 0; sample < 4; ++sample) {
        const Constructed c = construct(model.return_map(), region, kappa_n, 1e-3 + 4e-3 * U(rng), rng, coincident);
        const FiniteStrainHistory old = random_history(kappa_n, rng);
        const Matrix3 F = reaching(S * rotated(c.trial, random_rotation(rng)), old, rng);
        const FiniteStrainUpdate u = finite_strain_update(model, F, old);
        ASSERT_EQ(u.region, region) << to_string(region);
        const Matrix9 fd = finite_difference(model, F, old, 1e-8);
        const double err = relative(kirchhoff_derivative(u), fd, floor);
        EXPECT_LT(err, 1e-6) << to_string(region) << (coincident ? " coincident" : "") << " sample " << sample;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 9 * 4);
}

} // namespace

TEST(FiniteStrain, SmallStrainsReproduceTheSmallStrainUpdate)
{
  // Cohesion of 10 Pa against E = 1 GPa: strains of 1e-6 yield, so plastic and elastic
  // steps both occur on this path; a compressive drift keeps it off the apex.
  const MohrCoulombModel model(mohr_coulomb(10.0, false));
  const double E = model.elasticity().youngs_modulus();
  std::mt19937_64 rng(3);
  FiniteStrainHistory finite;
  PlasticHistory small;
  Matrix3 H_total = Matrix3::Zero();
  int plastic = 0;
  for (int step = 0; step < 20; ++step) {
    H_total += 1e-7 * (random_matrix(rng) - 0.15 * Matrix3::Identity());
    const Matrix3 F = Matrix3::Identity() + H_total; // |H| up to ~1e-6
    const FiniteStrainUpdate f = finite_strain_update(model, F, finite);
    const MaterialPointUpdate s = model.update(to_mandel(0.5 * (H_total + H_total.transpose())), small);
    const Matrix3 sigma_small = from_mandel(s.stress);
    EXPECT_EQ(f.region, s.region) << "step " << step;
    EXPECT_LT((f.cauchy_stress() - sigma_small).cwiseAbs().maxCoeff(), 1e-10 * E) << "step " << step;
    // The difference is of the order of the strain, relative to the stress.
    EXPECT_LT((f.cauchy_stress() - sigma_small).norm(), 1e-5 * sigma_small.norm()) << "step " << step;
    // The symmetric part of the spatial tangent is the small-strain tangent.
    Matrix6 C;
    for (int J = 0; J < 6; ++J) {
      const Matrix3 dH = from_mandel(Vector6::Unit(J)); // symmetric perturbation, unit Mandel
      Vector6 column = Vector6::Zero();
      Matrix3 d = Matrix3::Zero();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
              d(i, j) += f.spatial_tangent(pair_index(i, j), pair_index(k, l)) * dH(k, l);
      column = to_mandel(d);
      C.col(J) = column;
    }
    EXPECT_LT((C - s.tangent).cwiseAbs().maxCoeff(), 1e-5 * E) << "step " << step;
    plastic += f.region != ReturnRegion::elastic;
    finite = f.history;
    small = s.history;
  }
  EXPECT_GE(plastic, 5);
  EXPECT_LE(plastic, 15);
}

TEST(FiniteStrain, TangentMatchesFiniteDifferencesInEveryMohrCoulombRegionPerfectPlasticity)
{
  check_mohr_coulomb_tangent(false, 0.0);
}

TEST(FiniteStrain, TangentMatchesFiniteDifferencesInEveryMohrCoulombRegionOnHardeningAndSofteningBranches)
{
  check_mohr_coulomb_tangent(true, 0.004);
  check_mohr_coulomb_tangent(true, 0.03);
}

TEST(FiniteStrain, TangentMatchesFiniteDifferencesOnTheDruckerPragerConeAndApex)
{
  DruckerPragerParameters p;
  p.youngs_modulus = 1.0e9;
  p.poisson_ratio = 0.25;
  p.strength = PiecewiseLinear({0.0, 1e-2, 5e-2}, {0.8e6, 1.3e6, 0.7e6});
  p.friction = PiecewiseLinear({0.0, 1e-2, 5e-2}, {0.15, 0.25, 0.2});
  p.dilatancy = PiecewiseLinear({0.0, 1e-2, 5e-2}, {0.05, 0.2, 0.1});
  const DruckerPragerModel model(p);
  const double floor = 1e-3 * model.elasticity().stiffness().cwiseAbs().maxCoeff();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int cone = 0, apex = 0;
  for (int sample = 0; sample < 12; ++sample) {
    const bool to_apex = sample % 3 == 2;
    const bool axisymmetric = sample % 4 == 1; // two equal trial eigenvalues
    const double mean = to_apex ? 4e6 + 1e6 * U(rng) : -2e6 * U(rng);
    const double shear = (to_apex ? 0.1e6 : 3e6) * (1.0 + U(rng));
    const Vector3 trial = Vector3::Constant(mean) +
                          shear * (axisymmetric ? Vector3(2, -1, -1) / 3.0 : Vector3(1.0, -0.3, -0.7));
    const FiniteStrainHistory old = random_history(0.003, rng);
    const Matrix3 F = reaching(model.elasticity().compliance() * rotated(trial, random_rotation(rng)), old, rng);
    const FiniteStrainUpdate u = finite_strain_update(model, F, old);
    ASSERT_NE(u.region, ReturnRegion::elastic);
    (u.region == ReturnRegion::apex ? apex : cone) += 1;
    const double err = relative(kirchhoff_derivative(u), finite_difference(model, F, old, 1e-8), floor);
    EXPECT_LT(err, 1e-6) << to_string(u.region) << " sample " << sample;
  }
  EXPECT_GT(cone, 4);
  EXPECT_GT(apex, 1);
}

TEST(FiniteStrain, RigidRotationOfAYieldingPointKeepsItsPrincipalCauchyStresses)
{
  const MohrCoulombModel model(mohr_coulomb(1.0e5, false));
  // Load into yield: compression, then a 5 % shear with stretches.
  FiniteStrainHistory h = initial_finite_strain_history(model, -1e6 * Matrix3::Identity());
  Matrix3 F = Matrix3::Identity();
  FiniteStrainUpdate u;
  for (int k = 1; k <= 20; ++k) {
    F << 1.0 - 0.002 * k, 0.0025 * k, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 + 0.001 * k;
    u = finite_strain_update(model, F, h);
    h = u.history;
  }
  ASSERT_NE(u.region, ReturnRegion::elastic);
  const Matrix3 sigma0 = u.cauchy_stress();
  const Vector3 principal0 = sorted_spectrum(sigma0).values;
  // 90 degrees about an oblique axis in 100 steps.
  const Vector3 axis = Vector3(1.0, 2.0, -0.5).normalized();
  const Matrix3 F0 = F;
  for (int k = 1; k <= 100; ++k) {
    const Matrix3 Q = Eigen::AngleAxisd(0.5 * M_PI * k / 100.0, axis).toRotationMatrix();
    u = finite_strain_update(model, Q * F0, h);
    h = u.history;
    const Vector3 principal = sorted_spectrum(u.cauchy_stress()).values;
    ASSERT_LT((principal - principal0).cwiseAbs().maxCoeff(), 1e-10 * principal0.cwiseAbs().maxCoeff())
      << "step " << k;
  }
  const Matrix3 Q = Eigen::AngleAxisd(0.5 * M_PI, axis).toRotationMatrix();
  EXPECT_LT((u.cauchy_stress() - Q * sigma0 * Q.transpose()).cwiseAbs().maxCoeff(), 1e-9 * sigma0.norm());
}

TEST(FiniteStrain, NonDilatantFlowUnderIsochoricShearKeepsTheElasticVolume)
{
  // psi = 0: every flow direction is traceless, so ln det F^p = 0 and, with det F = 1,
  // tr eps^e (hence the mean Kirchhoff stress) stays at its initial value at 40 % shear.
  MohrCoulombParameters p = mohr_coulomb(1.0e4, false);
  p.dilatancy_angle = PiecewiseLinear(0.0);
  const MohrCoulombModel model(p);
  const double p0 = -1e5;
  FiniteStrainHistory h = initial_finite_strain_history(model, p0 * Matrix3::Identity());
  for (int k = 1; k <= 400; ++k) {
    const double ex = 1.0 - 0.4 * k / 400.0;
    const Matrix3 F = Vector3(ex, 1.0, 1.0 / ex).asDiagonal();
    const FiniteStrainUpdate u = finite_strain_update(model, F, h);
    h = u.history;
    ASSERT_NEAR(u.kirchhoff_stress.trace() / 3.0, p0, 1e-9 * std::abs(p0)) << "step " << k;
  }
  EXPECT_GT(h.kappa, 0.5);
}

TEST(FiniteStrain, InvertedDeformationGradientIsAReturnMapFailure)
{
  const MohrCoulombModel model(mohr_coulomb(1.0e5, false));
  EXPECT_THROW(finite_strain_update(model, Vector3(1.0, 1.0, -0.1).asDiagonal(), {}), ReturnMapFailure);
}
