#pragma once
// The constitutive interface both the material-point driver and the deal.II FE solver
// call at every point, in the spirit of deal.II step-42's ConstitutiveLaw: a pure,
// const function
//
//     (total strain eps_{n+1}, history at t_n)  ->  (sigma_{n+1}, C_alg, history_{n+1}, region)
//
// The model never stores point state; the caller keeps the old history and commits the
// new one only after its global Newton converged (double buffering), so a step can be cut
// back and repeated. Elastic predictor: sigma_trial = D : (eps_{n+1} - eps^p_n); plastic
// corrector: a backward-Euler return (model-specific); C_alg = d sigma_{n+1}/d eps_{n+1}
// is the algorithmic (consistent) tangent, which is non-symmetric for non-associated flow.
//
// Conventions: SI units, tension positive, Mandel vectors (see Mandel.h).
#include "continuum/models/IsotropicElasticity.h"
#include "continuum/models/Mandel.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace geocomp::continuum {

class PointState; // an opaque, model-owned point state (PointStateModel.h)

/// Which part of the yield surface the stress returned to. For Mohr-Coulomb (principal
/// stresses s1 >= s2 >= s3, tension positive): `plane` = the face s1-s3, `left_edge` = the
/// s1 = s2 corner (triaxial compression), `right_edge` = the s2 = s3 corner (triaxial
/// extension), `apex` = the hydrostatic tip. Drucker-Prager uses `plane` for the smooth cone.
enum class ReturnRegion { elastic = 0, plane = 1, left_edge = 2, right_edge = 3, apex = 4 };

const char *to_string(ReturnRegion region);

/// History at one material point.
struct PlasticHistory {
  /// Plastic strain tensor eps^p, Mandel.
  Vector6 plastic_strain = Vector6::Zero();
  /// Hardening variable kappa: accumulated plastic shear strain (dimensionless). Each
  /// model defines it exactly (see MohrCoulombReturnMap.h, DruckerPragerModel.h and
  /// docs/continuum-models.md); for both, on a smooth part of the surface it is the
  /// engineering plastic shear-strain measure the DEM comparison uses.
  double kappa = 0.0;
  /// The state of a model whose point is more than eps^p and kappa (PointStateModel.h: a
  /// DEM cell, ...): immutable once made, so copying the history (double buffering, the
  /// engines' save/restore) shares it; null for the plasticity models.
  std::shared_ptr<const PointState> state;
};

/// Volumetric plastic strain tr(eps^p).
double volumetric_plastic_strain(const PlasticHistory &h);
/// Maximum engineering plastic shear strain eps^p_1 - eps^p_3.
double max_plastic_shear_strain(const PlasticHistory &h);

/// Everything one update produces.
struct MaterialPointUpdate {
  Vector6 stress = Vector6::Zero();             ///< sigma_{n+1}, Mandel [Pa]
  Matrix6 tangent = Matrix6::Zero();            ///< d sigma_{n+1} / d eps_{n+1}, Mandel [Pa]
  PlasticHistory history;                       ///< history at t_{n+1}
  ReturnRegion region = ReturnRegion::elastic;  ///< state flag
  double trial_yield_value = 0.0;               ///< yield function at the trial state [Pa]
  int local_iterations = 0;                     ///< Newton iterations of the return
};

/// Thrown when a return map fails (no admissible region, local Newton diverged). The FE
/// solver catches it and cuts the load step back.
class ReturnMapFailure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class ConstitutiveModel {
public:
  virtual ~ConstitutiveModel() = default;

  /// @param[in] total_strain eps_{n+1} (Mandel). @param[in] old history at t_n.
  virtual MaterialPointUpdate update(const Vector6 &total_strain,
                                     const PlasticHistory &old) const = 0;

  /// The history of the virgin material at the caller's initial total strain eps_0 (its
  /// prestrain): empty for the plasticity models; a point-state model anchors its state
  /// there (PointStateModel.h).
  virtual PlasticHistory initial_history(const Vector6 &initial_strain) const;

  /// Yield function value at a stress and kappa (<= 0 admissible) [Pa].
  virtual double yield_function(const Vector6 &stress, double kappa) const = 0;

  /// Whether update()'s tangent is an elastoplastic one that Rice's acoustic tensor can scan
  /// for a loss of ellipticity (the plasticity models); a model without a yield surface
  /// (PointStateModel.h) has no such tangent, and an engine then reports no indicator.
  virtual bool has_plastic_tangent() const { return true; }

  virtual const IsotropicElasticity &elasticity() const = 0;
  virtual std::string name() const = 0;
};

} // namespace geocomp::continuum
