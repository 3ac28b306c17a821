#pragma once
// The Gauss rule of the cube's hexahedra, axis by axis (`continuum/quadrature points`).
//
// Why it exists: a plane-strain slab one element thick (the biaxial specimen: y held on both
// faces) carries fields that do not vary across its thickness, and a FEM x DEM point costs a
// whole DEM cell. The full rule of FE_Q(p) takes p + 1 Gauss points on every axis; across the
// slab p points are enough. The residual's integrand there is a shape function or its
// derivative times a stress that does not vary along y: a polynomial of degree <= p in y,
// integrated exactly by p Gauss points (exact to degree 2p - 1). The tangent loses exactness
// in y (its products of two shape functions have degree 2p), yet keeps its rank: a
// zero-energy mode would need a displacement whose every strain component vanishes at all
// points, and for p = 2 and 3, with the full p + 1 points on the other two axes, the only
// such fields are the rigid motions (tests/continuum_engines/GaussPointsTest.cpp: 6 zero
// eigenvalues of one element's stiffness). Not for p = 1: one point across y leaves the
// trilinear element the twist u = (-y z, x z, -x y) (centred coordinates), whose every strain
// is zero on the plane y = 0 (the same test: 7). Reducing two axes admits hourglass modes at
// every degree (counted there too). The rule refuses both. Plain C++ (no deal.II): the case
// reader checks it too.
#include <array>
#include <string>

namespace geocomp::continuum {

/// Gauss points along x, y, z of FE_Q(`degree`): all zero = degree + 1 on every axis.
inline std::array<unsigned, 3> gauss_points(unsigned degree, const std::array<unsigned, 3> &counts)
{
  if (counts[0] == 0 && counts[1] == 0 && counts[2] == 0)
    return {{degree + 1, degree + 1, degree + 1}};
  return counts;
}

/// Empty when `counts` is a rule the cube accepts for FE_Q(`degree`); else what it expects.
inline std::string gauss_points_problem(unsigned degree, const std::array<unsigned, 3> &counts)
{
  const std::array<unsigned, 3> n = gauss_points(degree, counts);
  const std::string full = std::to_string(degree + 1), reduced = std::to_string(degree);
  int below_full = 0;
  for (unsigned c : n) {
    if (c < degree || c > degree + 3)
      return "expects " + reduced + " to " + std::to_string(degree + 3) + " points on each axis for degree " +
             std::to_string(degree) + " (full integration: " + full + ")";
    below_full += c < degree + 1 ? 1 : 0;
  }
  if (below_full > 0 && degree < 2)
    return "expects " + full + " points on every axis for degree 1 (one point across an axis leaves "
           "the trilinear element a twisting zero-energy mode)";
  if (below_full > 1)
    return "allows " + reduced + " points (reduced) on one axis only, the others at least " + full +
           " (two reduced axes admit zero-energy modes)";
  return {};
}

} // namespace geocomp::continuum
