#pragma once
// @sect3{The PointStateModel class: a material whose point state is an object it owns}
//
// Why it exists: the plasticity models carry their point state in a few numbers
// (PlasticHistory: eps^p, kappa). A model whose point is a small simulation (issue 35: a
// periodic DEM cell at every quadrature point, coupled/RveMaterial.h) has a state that only
// it understands. This interface lets such a model sit behind ConstitutiveModel unchanged,
// so the engines' double buffering, cut-backs and save/restore hold for it as they are:
//
//     (eps_{n+1}, committed state S_n at eps_n)  ->  (sigma_{n+1}, C, trial state S_{n+1})
//
// The state is opaque (PointState) and IMMUTABLE once made; it rides in
// PlasticHistory::state as a shared pointer. Its life cycle, in the caller's words:
//  - clone: advance() never touches S_n; it copies it, drives the copy by the increment
//    eps_{n+1} - eps_n (which the state records), and returns the copy as the trial state;
//  - commit: the caller's old history <- trial history (a pointer copy), after its Newton
//    converged; a cut-back drops the trial states (the committed ones are intact);
//  - save/restore: a saved history shares the committed state, and restoring it makes that
//    state current again (exact, nothing is re-simulated).
// Small strain only: eps is the total (small) strain the engines already pass; a finite
// strain caller (FiniteStrain.h's exponential map) is refused by the FE cube.
// The stress is the model's; the tangent is whatever the model documents (it need not be
// consistent: the caller's Newton then converges linearly, a quasi-Newton). There is no
// yield surface: region `elastic`, kappa 0, yield_function -1.
#include "continuum/models/ConstitutiveModel.h"

#include <memory>

namespace geocomp::continuum {

/// Base of every model-owned point state; a model downcasts to its own type.
class PointState {
public:
  virtual ~PointState() = default;
};

/// What advance() produces.
struct PointStateUpdate {
  Vector6 stress = Vector6::Zero();  ///< sigma_{n+1}, Mandel [Pa], tension positive
  Matrix6 tangent = Matrix6::Zero(); ///< the model's tangent, Mandel [Pa]
  std::shared_ptr<const PointState> state; ///< the trial state at eps_{n+1}
};

class PointStateModel : public ConstitutiveModel {
public:
  /// The virgin state, anchored at the caller's initial total strain eps_0 (Mandel).
  virtual std::shared_ptr<const PointState> initial_state(const Vector6 &initial_strain) const = 0;
  /// From the committed state `old` to the total strain eps_{n+1} (Mandel); must leave
  /// `old` as it is (it may return `old` itself when nothing changes).
  virtual PointStateUpdate advance(const Vector6 &total_strain, const std::shared_ptr<const PointState> &old) const = 0;

  /// The history holding initial_state(initial_strain).
  PlasticHistory initial_history(const Vector6 &initial_strain) const final;
  /// advance() on old.state; throws std::logic_error when the history holds no state (a
  /// caller that did not start from initial_history()).
  MaterialPointUpdate update(const Vector6 &total_strain, const PlasticHistory &old) const final;
  /// No yield surface: always admissible.
  double yield_function(const Vector6 &, double) const override { return -1.0; }
};

} // namespace geocomp::continuum
