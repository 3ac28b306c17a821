#pragma once
// The cube's volume quadrature built from `continuum/quadrature points` (GaussPoints.h holds
// the rule and why one axis may be reduced).
#include "continuum/fe/GaussPoints.h"

#include <deal.II/base/quadrature_lib.h>

namespace geocomp::continuum {

/// QGauss<3>(n) when the three counts agree (the full rule: the same points and weights as
/// before the option existed), else the tensor product of 1D Gauss rules (QAnisotropic, x
/// fastest). A refused rule gives the full one; the cube's parameter check refuses it.
inline dealii::Quadrature<3> gauss_rule(unsigned degree, const std::array<unsigned, 3> &counts)
{
  const std::array<unsigned, 3> n = gauss_points(degree, counts);
  if (!gauss_points_problem(degree, n).empty())
    return dealii::QGauss<3>(degree + 1);
  if (n[0] == n[1] && n[1] == n[2])
    return dealii::QGauss<3>(n[0]);
  return dealii::QAnisotropic<3>(dealii::QGauss<1>(n[0]), dealii::QGauss<1>(n[1]), dealii::QGauss<1>(n[2]));
}

} // namespace geocomp::continuum
