// The cell's homogeneous deformation: H(t) = exp(L t) H0 for constant L, spheres carried
// affinely with zero fluctuations, the matrix exponential against closed forms.
#include "dem/periodic/MatrixExponential.h"
#include "dem/periodic/PeriodicCell.h"
#include "TestCells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace geocomp::dem;

TEST(MatrixExponential, EqualsTheClosedFormsOfARotationAndOfATriangularMatrix)
{
  // Skew matrix of theta about z: a rotation by theta.
  const double th = 0.7;
  Mat3 w = Mat3::Zero();
  w(0, 1) = -th;
  w(1, 0) = th;
  Mat3 rot = Mat3::Identity();
  rot(0, 0) = rot(1, 1) = std::cos(th);
  rot(0, 1) = -std::sin(th);
  rot(1, 0) = std::sin(th);
  EXPECT_LT((matrix_exponential(w) - rot).norm(), 1e-15);
  // Upper triangular [[a, g, 0], [0, b, 0], [0, 0, c]] (with scaling: norm > 1/2).
  const double a = 1.3, b = -0.4, g = 2.1, c = 0.25;
  Mat3 m = Mat3::Zero();
  m(0, 0) = a;
  m(1, 1) = b;
  m(2, 2) = c;
  m(0, 1) = g;
  Mat3 e = Mat3::Zero();
  e(0, 0) = std::exp(a);
  e(1, 1) = std::exp(b);
  e(2, 2) = std::exp(c);
  e(0, 1) = g * (std::exp(a) - std::exp(b)) / (a - b);
  EXPECT_LT((matrix_exponential(m) - e).norm(), 1e-14 * e.norm());
}

TEST(PeriodicCell, APureAffineGradientWithoutContactsKeepsTheFluctuationsAtZeroAndDeformsHAsExpLt)
{
  // Stretch, contraction and simple shear at once: L upper triangular, so exp(L t) has a
  // closed form. Five small spheres far apart never touch.
  Mat3 h0;
  h0 << 0.1, 0.02, 0.0, 0.0, 0.12, 0.01, 0.0, 0.0, 0.09;
  PeriodicCell::Parameters cp;
  cp.time_step = 1e-4;
  PeriodicCell cell(CellMatrix(h0), test::periodic_linear_law(1e4, 0.5), cp);
  const Vec3 x0[5] = {{0.01, 0.01, 0.01}, {0.06, 0.02, 0.03}, {0.03, 0.08, 0.05}, {0.09, 0.07, 0.08}, {0.05, 0.05, 0.02}};
  for (const Vec3& x : x0) cell.add_sphere(x, 1e-3, 2650.0);
  const double a = 0.5, b = -0.3, c = 0.2, g = 0.8;
  Mat3 l = Mat3::Zero();
  l(0, 0) = a;
  l(1, 1) = b;
  l(2, 2) = c;
  l(0, 1) = g;
  cell.set_velocity_gradient(l);
  const std::uint64_t n = 2000;
  cell.run(n);
  const double t = double(n) * cp.time_step;
  EXPECT_NEAR(cell.time(), t, 1e-12 * t);
  // exp(L dt)^n H0 against exp(L t) H0: n products, each rounding by a few epsilon.
  const double tol = 4.0 * double(n) * std::numeric_limits<double>::epsilon();
  Mat3 e = Mat3::Zero();
  e(0, 0) = std::exp(a * t);
  e(1, 1) = std::exp(b * t);
  e(2, 2) = std::exp(c * t);
  e(0, 1) = g * (std::exp(a * t) - std::exp(b * t)) / (a - b);
  const Mat3 h_exact = e * h0;
  EXPECT_LT((cell.cell().h() - h_exact).norm(), tol * h0.norm());
  EXPECT_NEAR(cell.cell().volume(), std::exp((a + b + c) * t) * h0.determinant(), tol * h0.determinant());
  EXPECT_EQ(cell.stress().contacts, 0u);
  for (Index p = 0; p < 5; ++p) {
    EXPECT_EQ(cell.fluctuation(p), Vec3::Zero()) << "sphere " << p;
    // Carried affinely: the same reduced coordinates (up to a wrap by whole cell vectors).
    Vec3 ds = cell.cell().reduced(cell.position(p)) - CellMatrix(h0).reduced(x0[p]);
    for (int k = 0; k < 3; ++k) ds[k] -= std::round(ds[k]);
    EXPECT_LT(ds.norm(), tol) << "sphere " << p;
    EXPECT_LT((cell.velocity(p) - l * cell.position(p)).norm(), 1e-15);
  }
}

TEST(MixedControl, AServoedComponentCompressesWhenTheStressIsAboveItsCompressiveTarget)
{
  MixedControl control(MixedControl::Parameters{0.5, 2.0});
  control.set_stress(0, 0, -1e5);
  control.set_strain_rate(2, 2, -0.1);
  CellStress s;
  s.elastic(0, 0) = -5e4;  // less compressive than the target (the servo reads the elastic share)
  s.contact(0, 0) = -2e5;  // the dashpots' share is not the servo's business
  s.stiffness(0, 0) = 1e8;
  const double dt = 1e-6;
  const Mat3 l = control.velocity_gradient(s, dt);
  EXPECT_DOUBLE_EQ(l(0, 0), -2.0);                    // 0.5 * (-5e4) / (1e8 * 1e-6) = -250, capped
  EXPECT_DOUBLE_EQ(l(2, 2), -0.1);
  s.elastic(0, 0) = -1.001e5;                         // slightly beyond: extend a little
  EXPECT_NEAR(control.velocity_gradient(s, dt)(0, 0), 0.5 * 100.0 / (1e8 * dt), 1e-12);
  s.stiffness.setZero();                              // no contact: the largest rate toward it
  EXPECT_DOUBLE_EQ(control.velocity_gradient(s, dt)(0, 0), 2.0);
}
