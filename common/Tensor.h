#pragma once
// Small-strain tensor vocabulary shared by both engines.
//
// Everything is SI and tension positive. A Response stores full 3x3 tensors; the
// scalar measures that geomechanics reports (principal values, tau_max, gamma_max,
// mean stress, deviator) are derived here once, so both engines agree on them.
#include <Eigen/Dense>
#include <array>

namespace geocomp {

using Tensor3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;

/// Principal values in ascending order (most compressive first under tension-positive).
Vector3 principal_values(const Tensor3 &symmetric);

/// Maximum shear stress (s_max - s_min)/2 of a symmetric stress tensor.
double tau_max(const Tensor3 &stress);

/// Maximum engineering shear strain eps_max - eps_min (S0: gamma_max = eps_1 - eps_3).
double gamma_max(const Tensor3 &strain);

/// Mean stress p = tr(sigma)/3 (tension positive: compression gives p < 0).
double mean_stress(const Tensor3 &stress);

/// von Mises equivalent q = sqrt(3/2 s:s).
double von_mises(const Tensor3 &stress);

/// Logarithmic (Hencky) strain of the stretch I + eps, for an engineering strain whose
/// tensor is symmetric: ln of the eigenvalues, same eigenvectors.
Tensor3 logarithmic_strain(const Tensor3 &engineering_strain);

/// Exact volumetric strain (V - V0)/V0 = det(I + eps) - 1.
double volumetric_strain(const Tensor3 &engineering_strain);

} // namespace geocomp
