// The small vocabulary: Mandel notation is an isometry and round-trips, the elastic
// stiffness is Hooke's law, piecewise-linear tables interpolate and hold their residual.
#include "ContinuumTestSupport.h"

#include "continuum/models/IsotropicElasticity.h"
#include "continuum/models/PiecewiseLinear.h"
#include "continuum/models/SpectralDecomposition.h"

#include <gtest/gtest.h>

using namespace geocomp::continuum;
using namespace geocomp::continuum::testing;

TEST(Mandel, RoundTripsAndPreservesDoubleContraction) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n(0.0, 1.0);
  Matrix3 a, b;
  for (int i = 0; i < 9; ++i) {
    a(i) = n(rng);
    b(i) = n(rng);
  }
  a = 0.5 * (a + a.transpose()).eval();
  b = 0.5 * (b + b.transpose()).eval();
  EXPECT_LT((from_mandel(to_mandel(a)) - a).norm(), 1e-15);
  EXPECT_NEAR(to_mandel(a).dot(to_mandel(b)), (a.array() * b.array()).sum(), 1e-14);
}

TEST(IsotropicElasticity, StiffnessIsHookesLawAndComponentsHaveMinorSymmetry) {
  const IsotropicElasticity el(3.0e9, 0.22);
  const double lambda = el.lame_lambda(), G = el.shear_modulus();
  std::mt19937_64 rng(2);
  std::normal_distribution<double> n(0.0, 1e-3);
  Matrix3 e;
  for (int i = 0; i < 9; ++i)
    e(i) = n(rng);
  e = 0.5 * (e + e.transpose()).eval();
  const Matrix3 hooke = lambda * e.trace() * Matrix3::Identity() + 2.0 * G * e;
  EXPECT_LT((from_mandel(el.stiffness() * to_mandel(e)) - hooke).norm(), 1e-6);
  EXPECT_LT((el.compliance() * el.stiffness() - Matrix6::Identity()).norm(), 1e-12);
  // C_ijkl = lambda d_ij d_kl + G (d_ik d_jl + d_il d_jk)
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          const double exact = lambda * (i == j) * (k == l) + G * ((i == k) * (j == l) + (i == l) * (j == k));
          EXPECT_NEAR(tensor4_component(el.stiffness(), i, j, k, l), exact, 1e-6);
        }
}

TEST(SpectralDecomposition, SortsDescendingAndReassembles) {
  std::mt19937_64 rng(3);
  const Matrix3 Q = random_rotation(rng);
  const Matrix3 a = Q * Vector3(-3.0, 5.0, 1.0).asDiagonal() * Q.transpose();
  const SortedSpectrum s = sorted_spectrum(a);
  EXPECT_NEAR(s.values(0), 5.0, 1e-14);
  EXPECT_NEAR(s.values(2), -3.0, 1e-14);
  EXPECT_LT((from_mandel(assemble_from_principal(s.values, s.vectors)) - a).norm(), 1e-13);
}

TEST(PiecewiseLinear, InterpolatesAndHoldsEndValues) {
  const PiecewiseLinear f({0.0, 1.0, 3.0}, {2.0, 4.0, 1.0});
  EXPECT_DOUBLE_EQ(f(0.5), 3.0);
  EXPECT_DOUBLE_EQ(f(2.0), 2.5);
  EXPECT_DOUBLE_EQ(f(10.0), 1.0); // residual
  EXPECT_DOUBLE_EQ(f(-1.0), 2.0);
  EXPECT_DOUBLE_EQ(f.slope(0.5), 2.0);
  EXPECT_DOUBLE_EQ(f.slope(1.0), -1.5); // right derivative at a breakpoint
  EXPECT_DOUBLE_EQ(f.slope(5.0), 0.0);
  EXPECT_THROW(PiecewiseLinear({1.0, 1.0}, {0.0, 1.0}), std::invalid_argument);
}
