#include "continuum/models/Mandel.h"

#include <cmath>

namespace geocomp::continuum {

namespace {
const double sqrt2 = std::sqrt(2.0);
}

int mandel_index(int i, int j) {
  if (i == j)
    return i;
  const int s = i + j; // 1 -> (0,1), 2 -> (0,2), 3 -> (1,2)
  return s == 3 ? 3 : (s == 2 ? 4 : 5);
}

double mandel_weight(int I) { return I < 3 ? 1.0 : sqrt2; }

Vector6 to_mandel(const Matrix3 &a) {
  Vector6 m;
  m << a(0, 0), a(1, 1), a(2, 2), sqrt2 * 0.5 * (a(1, 2) + a(2, 1)),
      sqrt2 * 0.5 * (a(0, 2) + a(2, 0)), sqrt2 * 0.5 * (a(0, 1) + a(1, 0));
  return m;
}

Matrix3 from_mandel(const Vector6 &m) {
  Matrix3 a;
  const double r = 1.0 / sqrt2;
  a << m(0), r * m(5), r * m(4), //
      r * m(5), m(1), r * m(3),  //
      r * m(4), r * m(3), m(2);
  return a;
}

double tensor4_component(const Matrix6 &C, int i, int j, int k, int l) {
  const int I = mandel_index(i, j), J = mandel_index(k, l);
  return C(I, J) / (mandel_weight(I) * mandel_weight(J));
}

Vector6 mandel_identity() {
  Vector6 one = Vector6::Zero();
  one.head<3>().setOnes();
  return one;
}

Matrix6 mandel_deviatoric_projector() {
  const Vector6 one = mandel_identity();
  return Matrix6::Identity() - one * one.transpose() / 3.0;
}

} // namespace geocomp::continuum
