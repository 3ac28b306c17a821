// @sect3{The CellMatrix class: the periodic cell's shape and its homogeneous deformation}
//
// Why it exists: a representative volume element (RVE) is a parallelepiped repeated
// through space. Its shape is the cell matrix H whose columns are the three cell vectors
// $h_1, h_2, h_3$; a point x has reduced coordinates $s = H^{-1}x$, and its images are
// $x + Hn$ for integer vectors n. An imposed velocity gradient L deforms the cell
// homogeneously (Yade's periodic Cell is the behavioural reference):
// $$ \dot H = L H \quad\Rightarrow\quad H(t+\Delta t) = e^{L\Delta t} H(t) \qquad
//    \text{(exact for L constant over the step)}, $$
// so for a constant L, $H(t) = e^{Lt}H_0$ to round-off (MatrixExponential.h). The same
// step matrix $A = e^{L\Delta t}$ maps the particles' positions (PeriodicCell.h), so the
// affine field and the cell never drift apart. The class also gives the volume
// $V = \det H$, the perpendicular widths $w_a = V/|h_b\times h_c|$ (the distance between
// opposite faces; the neighbour search needs them), and the wrap of a point into the
// cell, $x \leftarrow x - H\lfloor H^{-1}x\rfloor$.
#pragma once

#include "dem/Types.h"

#include <Eigen/Core>

namespace geocomp::dem {

using Mat3 = Eigen::Matrix3d;

class CellMatrix
{
public:
  CellMatrix() = default;
  /// A cell with the given cell vectors as columns (det H > 0 required).
  explicit CellMatrix(const Mat3& h);
  /// An axis-aligned box of edges (a, b, c).
  static CellMatrix box(const Vec3& edges);

  const Mat3& h() const { return h_; }
  const Mat3& inverse() const { return h_inv_; }
  double volume() const { return volume_; }
  /// Distance between the two faces spanned by the other two cell vectors, for a = 0..2.
  double width(int a) const;
  double min_width() const;

  /// Reduced coordinates s = H^{-1} x.
  Vec3 reduced(const Vec3& x) const { return h_inv_ * x; }
  /// The image of x inside the cell (reduced coordinates in [0, 1)).
  Vec3 wrap(const Vec3& x) const;
  /// The lattice vector H n of an integer shift n.
  Vec3 shift_vector(const Eigen::Vector3i& n) const { return h_ * n.cast<double>(); }

  /// H <- A H with the step matrix A = exp(L dt).
  void deform(const Mat3& step_matrix);
  /// Replaces H (det H > 0 required).
  void set(const Mat3& h);

private:
  void update_derived();

  Mat3 h_ = Mat3::Identity();
  Mat3 h_inv_ = Mat3::Identity();
  double volume_ = 1.0;
};

}  // namespace geocomp::dem
