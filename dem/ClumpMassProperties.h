// @sect3{Mass properties of a clump by voxel integration (S3 eqs. (12)-(17), S4 eqs. (1)-(3))}
//
// Why it exists: a clump is the *union* of overlapping spheres, so adding the members'
// masses and inertias counts every overlap twice. S3 and S4 integrate over a grid of
// small cubes instead: a cube belongs to the clump when its centre lies in any member
// sphere. With cube side $h$ (S4: $h = D_{min}/20$, "> 97 % accuracy") and cell centres
// $x_c$ inside the union, per unit density
// $$ V = \sum_c h^3,\qquad x_G = \frac{1}{V}\sum_c h^3 x_c \qquad \text{(S4 eqs. (1)-(2), S3 eqs. (12)-(14))} $$
// $$ I = \sum_c h^3\big[(r_c\cdot r_c)\mathbf 1 - r_c\otimes r_c\big] + \frac{h^5}{6}\mathbf 1,\quad r_c = x_c - x_G
//    \qquad \text{(S4 eq. (3), S3 eq. (15))} $$
// (the last term is each cube's own inertia about its centre). The principal axes are the
// eigenvectors of $I$ (S3 eq. (16) diagonalises by Jacobi rotations; we use Eigen's
// SelfAdjointEigenSolver), ordered as a right-handed frame $P$ ($\det P = +1$), so the
// body-to-world rotation of the clump starts as $P$ and member centres in the body frame
// are $s_k = P^T(c_k - x_G)$ (S3 eq. (17)).
// The voxel error is of the order of the surface area times $h$ with strong
// cancellation: the volume of a sphere at $h = D/20$ is within about 1 %.
#pragma once

#include "dem/Types.h"

#include <Eigen/Core>

#include <vector>

namespace geocomp::dem {

/// One member sphere of a clump (centre in any fixed frame).
struct ClumpMember
{
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
};

/// Volume, centroid and inertia of a union of spheres, per unit density.
struct ClumpMassProperties
{
  double volume = 0.0;                              ///< [m^3]
  Vec3 centroid = Vec3::Zero();                     ///< x_G, in the members' frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero(); ///< about x_G, members' axes [m^5]
  Vec3 principal_moments = Vec3::Zero();            ///< eigenvalues of `inertia`, ascending [m^5]
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity(); ///< columns: principal axes, det +1
};

/// Cube side of S4: the smallest member diameter / 20.
double default_voxel_size(const std::vector<ClumpMember>& members);

/// Voxel integration over the union of `members` with cubes of side `cell` (0: S4's
/// D_min/20). Throws std::invalid_argument for no members, a non-positive radius or a
/// grid of more than 2^31 cells.
ClumpMassProperties voxel_mass_properties(const std::vector<ClumpMember>& members, double cell = 0.0);

/// Closed form: volume of the lens where spheres of radii R1, R2 at distance d overlap
/// (DEM-NOTES section 8); 0 when apart, the smaller sphere when it is inside.
double lens_volume(double R1, double R2, double d);

}  // namespace geocomp::dem
