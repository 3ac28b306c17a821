// SecantPairs (continuum/fe/SecantPairs.h): the limited-memory BFGS step of the cube's
// quasi-Newton, on small dense problems with deal.II vectors.
#include "continuum/fe/SecantPairs.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using dealii::FullMatrix;
using Vector = dealii::Vector<double>;
using geocomp::continuum::SecantPairs;

/// A symmetric positive definite n x n matrix (a^T a + I: eigenvalues >= 1).
FullMatrix<double> spd_matrix(unsigned n)
{
  FullMatrix<double> a(n, n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j)
      a(i, j) = std::sin(1.0 + i + 3.0 * j) + std::sin(1.0 + j + 3.0 * i); // symmetric
  FullMatrix<double> spd(n, n);
  spd.Tmmult(a, a); // a^T a
  for (unsigned i = 0; i < n; ++i)
    spd(i, i) += 1.0;
  return spd;
}

Vector times(const FullMatrix<double> &m, const Vector &v)
{
  Vector out(v.size());
  m.vmult(out, v);
  return out;
}

/// Iterations of u <- u + H (b - J u) to |b - J u| <= 1e-10 |b| from u = 0, H the tangent
/// K^{-1} updated by at most `pairs` BFGS pairs (0: the tangent alone).
unsigned iterations_to_converge(const FullMatrix<double> &jacobian, const FullMatrix<double> &tangent_inverse,
                                const Vector &b, unsigned pairs)
{
  SecantPairs<Vector> secant(pairs);
  Vector u(b.size()), r(b);
  for (unsigned k = 1; k <= 200; ++k) {
    Vector step(r);
    secant.apply(step, [&](Vector &w) { w = times(tangent_inverse, w); });
    u += step;
    Vector r_next(b);
    r_next -= times(jacobian, u);
    Vector y(r);
    y -= r_next; // y = R(u_next) - R(u) with R = J u - b
    secant.add(step, y);
    r = r_next;
    if (r.l2_norm() <= 1e-10 * b.l2_norm())
      return k;
  }
  return 1000;
}

} // namespace

// The BFGS secant condition: after a pair (s, y) is added, the step of the residual
// difference y is s itself, whatever the tangent.
TEST(SecantPairs, TheUpdatedStepMapsTheLatestResidualDifferenceBackToItsStep)
{
  const unsigned n = 6;
  const FullMatrix<double> j = spd_matrix(n);
  SecantPairs<Vector> secant(4);
  for (unsigned k = 0; k < 3; ++k) {
    Vector s(n);
    for (unsigned i = 0; i < n; ++i)
      s[i] = std::cos(2.0 * i + 5.0 * k);
    const Vector y = times(j, s);
    ASSERT_TRUE(secant.add(s, y));
    Vector step(y);
    secant.apply(step, [](Vector &w) { w *= 0.5; }); // any tangent: here K^-1 = I / 2
    for (unsigned i = 0; i < n; ++i)
      EXPECT_NEAR(step[i], s[i], 1e-12 * s.l2_norm()) << "pair " << k << ", entry " << i;
  }
  EXPECT_EQ(secant.size(), 3u);
}

// A linear problem J u = b iterated with a tangent K = J + D, D a positive diagonal of
// about J's own (stiffer, as the cells' contact-stiffness tangent is, and not a multiple of
// J, which one pair would fix): the fixed tangent contracts the residual slowly, the secant
// pairs take at most half of its iterations (unit steps, no line search).
TEST(SecantPairs, WithATooStiffTangentTheSecantStepsConvergeInHalfTheTangentsIterations)
{
  const unsigned n = 12;
  const FullMatrix<double> j = spd_matrix(n);
  FullMatrix<double> k(j);
  for (unsigned i = 0; i < n; ++i)
    k(i, i) += j(i, i) * (1.0 + 0.5 * std::sin(3.0 * i));
  FullMatrix<double> k_inverse(n, n);
  k_inverse.invert(k);
  Vector b(n);
  for (unsigned i = 0; i < n; ++i)
    b[i] = 1.0 + std::sin(7.0 * i);
  const unsigned fixed = iterations_to_converge(j, k_inverse, b, 0);
  const unsigned secant = iterations_to_converge(j, k_inverse, b, 8);
  std::printf("iterations to 1e-10: tangent alone %u, with 8 secant pairs %u\n", fixed, secant); // 44, 20
  EXPECT_GE(fixed, 30u);
  EXPECT_LE(secant, fixed / 2);
}

// A pair along which the residual did not grow (no positive curvature) would make H
// indefinite: it is not kept, and a capacity of m keeps the latest m pairs.
TEST(SecantPairs, APairWithoutPositiveCurvatureIsNotKeptAndTheOldestPairsGoBeyondTheCapacity)
{
  Vector s(3), y(3);
  s[0] = 1.0;
  y[1] = 1.0; // y . s = 0
  SecantPairs<Vector> secant(2);
  EXPECT_FALSE(secant.add(s, y));
  y[0] = -0.5; // y . s < 0
  EXPECT_FALSE(secant.add(s, y));
  EXPECT_EQ(secant.size(), 0u);
  y[0] = 2.0;
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(secant.add(s, y));
  EXPECT_EQ(secant.size(), 2u);
  EXPECT_FALSE(SecantPairs<Vector>(0).add(s, y)); // capacity 0: plain Newton
}
