#pragma once
// Mandel notation: the vector/matrix form of symmetric second- and fourth-order tensors
// that every constitutive model in geocomp::continuum speaks.
//
// Why Mandel and not Voigt: with the weights below the map is an isometry
// (a:b = a_m . b_m for symmetric a, b), stress and strain use the *same* weights, and a
// fourth-order tensor with minor symmetries becomes a 6x6 matrix whose products and
// inverses are the tensor products and inverses. No factor-2 bookkeeping on shears.
//
//   a_m = ( a11, a22, a33, sqrt2 a23, sqrt2 a13, sqrt2 a12 )
//   C_m(I,J) = w_I w_J C_ijkl,  (ij) <-> I, (kl) <-> J,  w = (1,1,1,sqrt2,sqrt2,sqrt2)
//
// so sigma_m = C_m eps_m. To fill a deal.II SymmetricTensor<4,3> C from a Matrix6 Cm,
// use C[i][j][k][l] = tensor4_component(Cm, i, j, k, l); to go back use
// mandel_index() and the weights. SI units, tension positive throughout.
#include <Eigen/Dense>

namespace geocomp::continuum {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;

/// Mandel index of the tensor index pair (i,j), i,j in {0,1,2}: 00->0, 11->1, 22->2,
/// 12/21->3, 02/20->4, 01/10->5.
int mandel_index(int i, int j);

/// Weight of Mandel slot I: 1 for the normal slots 0..2, sqrt(2) for the shear slots.
double mandel_weight(int I);

/// Symmetric 3x3 tensor -> Mandel 6-vector (the tensor is symmetrized first).
Vector6 to_mandel(const Matrix3 &symmetric);

/// Mandel 6-vector -> symmetric 3x3 tensor.
Matrix3 from_mandel(const Vector6 &m);

/// Component C_ijkl of the fourth-order tensor represented by the Mandel matrix C.
double tensor4_component(const Matrix6 &C, int i, int j, int k, int l);

/// Mandel vector of the second-order identity, (1,1,1,0,0,0).
Vector6 mandel_identity();

/// Mandel matrix of the deviatoric projector I_dev = I_sym - (1/3) 1 (x) 1.
Matrix6 mandel_deviatoric_projector();

} // namespace geocomp::continuum
