#pragma once
// @sect3{Plane stress for the kinetic point}
//
// Why: S1's specimens are plane-stress (thin plate) models, but the Nikolaevsky model
// lives in 3D invariants. The out-of-plane strain increment d eps_zz is the unknown that
// makes sigma_zz = 0 after the whole step (predictor, Wilkins correction, relaxation,
// fracture). The step is a monotone function of d eps_zz; it is solved by a secant
// iteration started from the elastic plane-stress guess
//   d eps_zz = -lambda / (lambda + 2G) (d eps_xx + d eps_yy),
// falling back to bisection once a bracket is known.
#include "continuum/kinetic/KineticNikolaevsky.h"

#include <Eigen/Dense>

namespace geocomp::kinetic {

/// One plane-stress step. @param in_plane (d eps_xx, d eps_yy, d gamma_xy) with the
/// engineering shear gamma_xy = 2 eps_xy. The returned state has sigma_zz = 0 to
/// `tolerance` times the largest stress component (plus 1 Pa).
KineticState plane_stress_step(const KineticNikolaevsky &model, const KineticState &old,
                               const Eigen::Vector3d &in_plane, double dt, double tolerance = 1e-10);

/// Scalar root of a monotone increasing f near x0 with initial slope `slope` (secant,
/// then bisection once bracketed). Returns the best x found after max_iter evaluations.
template <class F>
double monotone_root(F &&f, double x0, double slope, double abs_tolerance, int max_iter = 40);

} // namespace geocomp::kinetic

#include "continuum/kinetic/PlaneStress.tpp"
