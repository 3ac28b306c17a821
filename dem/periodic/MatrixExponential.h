// @sect3{The exponential of a 3x3 matrix (the cell's step matrix)}
//
// Why it exists: the cell and the affine part of the particles' motion advance by
// $A = e^{L\Delta t}$ (CellMatrix.h), which makes a constant L deform the cell exactly as
// $H(t) = e^{Lt}H_0$. Eigen's MatrixFunctions module computes it (scaling and squaring
// with a Pade approximant, Higham 2005), in fixed arithmetic: the same bits on every run.
#pragma once

#include "dem/periodic/CellMatrix.h"

namespace geocomp::dem {

Mat3 matrix_exponential(const Mat3& m);

}  // namespace geocomp::dem
