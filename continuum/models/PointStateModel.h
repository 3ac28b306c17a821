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
// Small strain: eps is the total (small) strain the engines pass, and the state records
// eps_n. Finite strain: finite_strain_update() (FiniteStrain.h) hands the deformation
// gradient F_{n+1} to advance_finite(), the state records F_n, and the model returns the
// Kirchhoff stress tau = J sigma and a spatial tangent J a with (J a) : H ~ d tau - tau H^T
// for F -> (I + H) F, the measure the total-Lagrangian cube assembles. For a model that
// answers in a rate form (its Cauchy stress rate co-rotating with the spin W = skw H, as a
// cell whose grains turn with the deformation: a Jaumann rate)
// $$ \dot\sigma = C : D + W\sigma - \sigma W,\qquad \dot J = J\,\mathrm{tr}\,D, $$
// the spatial tangent follows in closed form (jaumann_spatial_tangent below):
// $$ (Ja)_{ijkl} = J C_{ijkl} + \tfrac12(\delta_{ik}\tau_{jl} - \delta_{il}\tau_{jk}
//    - \tau_{ik}\delta_{jl} + \tau_{il}\delta_{jk}) + \tau_{ij}\delta_{kl} - \tau_{il}\delta_{jk}. $$
// A pure spin H = W then gives (J a) : W = W tau, the rotation of tau to first order.
// The stress is the model's; the tangent is whatever the model documents (it need not be
// consistent: the caller's Newton then converges linearly, a quasi-Newton). There is no
// yield surface: region `elastic`, kappa 0, yield_function -1.
#include "continuum/models/ConstitutiveModel.h"
#include "continuum/models/FiniteStrain.h"

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

  /// Finite strain: from the committed state `old` (at F_n, which it records; the virgin
  /// state is at F = I) to the deformation gradient F_{n+1} (det F > 0): Kirchhoff stress,
  /// jacobian, spatial tangent, `logarithmic_tangent` = the model's own tangent (Mandel),
  /// history {F_{n+1}, state}, region elastic. Must leave `old` as it is. Throws
  /// ReturnMapFailure when it cannot follow F (the cube then cuts the step back).
  virtual FiniteStrainUpdate advance_finite(const Matrix3 &deformation_gradient,
                                            const FiniteStrainHistory &old) const = 0;

  /// The history holding initial_state(initial_strain).
  PlasticHistory initial_history(const Vector6 &initial_strain) const final;
  /// advance() on old.state; throws std::logic_error when the history holds no state (a
  /// caller that did not start from initial_history()).
  MaterialPointUpdate update(const Vector6 &total_strain, const PlasticHistory &old) const final;
  /// No yield surface: always admissible.
  double yield_function(const Vector6 &, double) const override { return -1.0; }
  /// Its tangent is the model's own (a DEM cell's contact stiffness: positive semi-definite),
  /// not an elastoplastic one: nothing for the acoustic tensor to scan.
  bool has_plastic_tangent() const override { return false; }
};

/// J a of a rate-form point (the file comment): C the tangent of the Cauchy stress in D
/// (Mandel), tau the Kirchhoff stress, J = det F. Row 3i+j, column 3k+l (FiniteStrain.h).
Matrix9 jaumann_spatial_tangent(const Matrix6 &tangent, const Matrix3 &kirchhoff_stress, double jacobian);

} // namespace geocomp::continuum
