#include "dem/periodic/MatrixExponential.h"

#include <cmath>
#include <stdexcept>

namespace geocomp::dem {

Mat3 matrix_exponential(const Mat3& m)
{
  if (!m.allFinite()) throw std::invalid_argument("matrix_exponential: the matrix is not finite");
  // Scaling: ||M / 2^s||_1 <= 1/2 (Moler & Van Loan, scaling and squaring).
  const double norm = m.cwiseAbs().colwise().sum().maxCoeff();
  int s = 0;
  if (norm > 0.5) s = int(std::ceil(std::log2(norm / 0.5)));
  const Mat3 x = m * std::ldexp(1.0, -s);
  // Taylor series of exp(X), stopped when a term no longer changes the sum.
  Mat3 sum = Mat3::Identity();
  Mat3 term = Mat3::Identity();
  for (int k = 1; k <= 16; ++k) {
    term = term * x * (1.0 / double(k));
    const Mat3 next = sum + term;
    if (next == sum) break;
    sum = next;
  }
  for (int k = 0; k < s; ++k) sum = sum * sum;  // squaring
  return sum;
}

}  // namespace geocomp::dem
