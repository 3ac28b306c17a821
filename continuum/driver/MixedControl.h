#pragma once
// @sect3{One increment of the material point under mixed control}
//
// Why a file of its own: the material point's increment is a small nonlinear system whose
// unknowns and equations change with the control - the strains of the stress axes under
// the program's own control, plus the strain of the driven axis under plastic-strain
// control past a snap-back (MaterialPointEngine.h) - while the Newton iteration that solves
// it (ties, minimum-norm step, damping) is the same.
//
// Unknowns: the strains e_u of the axes u in `unknown`; the other strains are given.
// Equations, scaled to be dimensionless:
//     r_k = (sigma_kk(e) - sigma*_k) / S,          k in the stress axes  (S = max(|sigma_ii|, 1 Pa))
//     r_kappa = (kappa(e) - kappa*) / Delta kappa,  under plastic-strain control,
// solved by Newton with J = dr/de: the stress rows from the point's d sigma_aa / d eps_bb,
// the kappa row by central differences of the update (the interface gives no d kappa / d eps;
// a point evaluates in microseconds). Stress axes with the same target and the same strain
// are tied to one unknown, so the corner of the yield surface a triaxial test sits on
// (sigma_1 = sigma_2, where the split of the lateral strain is indeterminate) cannot break
// a symmetric program's symmetry through round-off; the step is the minimum-norm solution of
// the rest (complete orthogonal decomposition), damped by halving while |r| grows.
// Converged when every |r_k| <= stress tolerance and |r_kappa| <= kappa tolerance.
#include "common/Tensor.h"
#include "continuum/models/ConstitutiveModel.h"

#include <functional>

namespace geocomp::continuum {

/// The point at a box strain: the state to commit (Cauchy stress; history, region and the
/// tangent of the model's update) and d sigma_aa / d eps_bb of the box strains.
struct PointEvaluation {
  MaterialPointUpdate state;
  Matrix3 axial_tangent = Matrix3::Zero();
};

/// Evaluates the point at a box strain from the committed state; false when the return fails.
using PointEvaluator = std::function<bool(const Tensor3 &eps, PointEvaluation &out)>;

/// What one increment solves for (see the file comment).
struct IncrementEquations {
  int unknown[3] = {0, 0, 0};   ///< axes whose strain is unknown
  int n_unknown = 0;
  int stress_axis[3] = {0, 0, 0}; ///< axes with a stress target
  double target[3] = {0.0, 0.0, 0.0};
  int n_stress = 0;
  bool control_kappa = false;   ///< plastic-strain control: kappa(e) = kappa_target
  double kappa_target = 0.0;
  double kappa_scale = 1.0;     ///< Delta kappa of the increment (> 0)
};

struct IncrementSettings {
  double stress_tolerance = 1e-12;
  double kappa_tolerance = 1e-9;
  unsigned max_iterations = 30;
};

/// Solves the increment from the initial guess `eps` (the given strains set, the unknown
/// ones guessed). On success `eps` and `out` hold the solution and `iterations` the Newton
/// iterations; false when it does not converge.
bool solve_increment(const IncrementEquations &equations, const PointEvaluator &evaluate,
                     const IncrementSettings &settings, Tensor3 &eps, PointEvaluation &out, unsigned &iterations);

} // namespace geocomp::continuum
