#include "dem/periodic/CellMatrix.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

CellMatrix::CellMatrix(const Mat3& h) { set(h); }

CellMatrix CellMatrix::box(const Vec3& edges)
{
  return CellMatrix(Mat3(edges.asDiagonal()));
}

void CellMatrix::set(const Mat3& h)
{
  if (!h.allFinite() || !(h.determinant() > 0.0))
    throw std::invalid_argument("CellMatrix: the cell vectors must be finite and right-handed (det H > 0)");
  h_ = h;
  update_derived();
}

void CellMatrix::deform(const Mat3& step_matrix) { set(step_matrix * h_); }

void CellMatrix::update_derived()
{
  h_inv_ = h_.inverse();
  volume_ = h_.determinant();
}

double CellMatrix::width(int a) const
{
  // w_a = V / |h_b x h_c| = 1 / |row a of H^{-1}|.
  return 1.0 / h_inv_.row(a).norm();
}

double CellMatrix::min_width() const { return std::min({width(0), width(1), width(2)}); }

Vec3 CellMatrix::wrap(const Vec3& x) const
{
  const Vec3 s = h_inv_ * x;
  Vec3 n(std::floor(s.x()), std::floor(s.y()), std::floor(s.z()));
  if (n.isZero()) return x;
  return x - h_ * n;
}

}  // namespace geocomp::dem
