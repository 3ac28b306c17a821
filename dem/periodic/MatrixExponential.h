// @sect3{The exponential of a 3x3 matrix (the cell's step matrix)}
//
// Why it exists: the cell and the affine part of the particles' motion advance by
// $A = e^{L\Delta t}$ (CellMatrix.h), which makes a constant L deform the cell exactly as
// $H(t) = e^{Lt}H_0$. The exponential is computed by scaling and squaring
// (Moler & Van Loan 1978, "Nineteen dubious ways", method 3):
// $$ e^{M} = \big(e^{M/2^s}\big)^{2^s},\quad \|M/2^s\|_1 \le 1/2,\qquad
//    e^{X} \approx \sum_{k=0}^{16} X^k/k! \ (\text{truncation} < 10^{-20}). $$
// DEM steps give $\|L\Delta t\| \ll 1$, so s = 0 and the series converges in a few terms
// (it stops once a term no longer changes the sum). Fixed arithmetic in a fixed order:
// the same bits on every run.
#pragma once

#include "dem/periodic/CellMatrix.h"

namespace geocomp::dem {

Mat3 matrix_exponential(const Mat3& m);

}  // namespace geocomp::dem
