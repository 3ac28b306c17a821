#include "dem/periodic/MatrixExponential.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <stdexcept>

namespace geocomp::dem {

Mat3 matrix_exponential(const Mat3& m)
{
  if (!m.allFinite()) throw std::invalid_argument("matrix_exponential: the matrix is not finite");
  return m.exp();  // Eigen: scaling and squaring with a Pade approximant
}

}  // namespace geocomp::dem
