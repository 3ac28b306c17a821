#pragma once
// MaterialPointEngine: a loading program played on one material point.
//
// The homogeneous cube of the continuum model reduces to a single point when the state
// stays homogeneous: the box strain IS the point strain (frictionless platens, so the
// off-diagonal strains are zero) and the wall stresses ARE the point stresses. This engine
// is therefore the fast path for calibration and the reference the FE cube must reproduce
// before it localizes.
//
// Mixed control. On every load increment to time t the kinematic axes a in K get their
// target strains eps_aa = eps_a(t) from the StageControl (including S0 eq. (3)); the
// stress axes s in S get the unknown strains e_s that solve
//     r_s(e) = sigma_ss(eps_n, state_n; eps(e) - eps_n) - sigma*_s(t) = 0,   s in S,
// by Newton with the consistent tangent restricted to the stress axes,
//     J_{ss'} = C_alg(s, s'),   e <- e - J^+ r   (J^+: minimum-norm inverse, see below),
// damped by halving while |r| grows. Converged when every |r_s| <= tol * max(|sigma*_s|,
// max_i |sigma_ii|, 1 Pa). Each advance_to(t) is split into `substeps_per_advance`
// increments; an increment whose stress iteration fails is halved (cut-back) up to
// `max_cutbacks` times. On a corner of the yield surface (triaxial compression sits on
// the sigma_1 = sigma_2 edge of Mohr-Coulomb) J is singular: splitting the lateral strain
// antisymmetrically changes no stress, and round-off would pick an arbitrary split. So
// stress axes with equal targets and equal strains are tied to one unknown (symmetric
// programs stay symmetric), and the step is the minimum-norm solution of what remains.
//
// Stress targets that change at a stage boundary are ramped linearly from the stress at
// begin_control to the target over the first advance of the stage (a jump cannot be
// subdivided, a ramp can); after that the target is held exactly.
//
// Snap-back (plastic-strain control). A softening point under mixed control can reach a
// maximum of its driven strain: past it the homogeneous path needs the driven axis to move
// back while kappa grows (steep softening, |h| of the order of G), and no increment of the
// program's strain has a solution - the stress iteration fails at every cut-back. The
// driver then follows the path in kappa instead: the driven axis (the kinematic axis with
// the fastest rate) becomes an unknown and each increment prescribes
//     kappa_{n+1} = kappa_n + kappa_rate dt,
// kappa_rate the rate of the last advance before the switch (IncrementEquations,
// MixedControl.h). Time, samples and stop conditions go on as before; the extra `control`
// says which control a sample was reached under. Every increment first tries the program's
// control again; once that has a solution (the path has turned, e.g. onto a residual
// plateau) the program resumes - where a strain-controlled rig would have snapped to. The
// path between is what such a rig cannot follow and a closed-loop test controlled by the
// plastic strain records.
//
// Kinematics (`kinematics`, default finite strain; continuum/models/FiniteStrain.h). The
// program's box edges L_i(t) = L_i0 (1 + eps_i(t)) give the deformation gradient exactly,
//     F = diag(1 + eps_x, 1 + eps_y, 1 + eps_z),
// so S0's isochoric program has det F = 1 to round-off and tr(ln V) = 0. The box never
// rotates, so the exponential map of FiniteStrain.h is the model's update on the
// logarithmic strain ln(1 + eps) (evaluate() in the .cpp); the point reports the Cauchy
// stress sigma = tau / J, the force over the current area, which is what the DEM's walls
// measure. With small strain the model is called on eps = diag(eps_i) and sigma is its stress.
//
// Response: strain = diag(eps) (engineering strain of the box, relative to the program
// start; the log strain ln(1 + eps) follows from it), stress = sigma (Cauchy), extras =
// kappa, state flag, localization indicator and first onset of localization (time and band
// normal). The indicator scans the tangent of the stress measure the return works in
// (Kirchhoff against logarithmic strain at finite strain): the geometric terms of the
// spatial tangent, of the order of the stress over the modulus, are left out.
#include "common/LoadingEngine.h"
#include "continuum/driver/Materials.h"
#include "continuum/driver/MixedControl.h"
#include "continuum/models/AcousticTensorScan.h"
#include "continuum/models/FiniteStrain.h"

#include <memory>

namespace geocomp::continuum {

/// Parameters of the material-point driver (declared in the case file by the lead).
struct MaterialPointParameters {
  unsigned substeps_per_advance = 20; ///< load increments per sample interval, >= 1
  unsigned localization_directions = 600; ///< coarse scan points of the localization indicator
  double stress_tolerance = 1e-12;    ///< relative tolerance on the stress targets
  unsigned max_iterations = 30;       ///< Newton iterations per increment on stress axes
  unsigned max_cutbacks = 12;         ///< halvings of an increment before giving up
  double initial_stress = 0.0;        ///< isotropic initial stress [Pa], tension positive
  Kinematics kinematics = Kinematics::finite_strain;
};

class MaterialPointEngine : public LoadingEngine {
public:
  MaterialPointEngine(std::shared_ptr<const ConstitutiveModel> model,
                      const MaterialPointParameters &parameters = {});
  /// The base material of a MaterialParameters (no variant: a point has no element size).
  MaterialPointEngine(const MaterialParameters &material, const MaterialPointParameters &parameters = {});

  std::string name() const override { return "material-point"; }
  std::vector<ExtraColumn> extra_columns() const override;
  void begin_control(const StageControl &control) override;
  void advance_to(double t_end) override;
  ResponseSample measure() override;
  std::unique_ptr<EngineState> save() const override;
  void restore(const EngineState &state) override;

  /// Converged state of the point (for tests and calibration).
  const MaterialPointUpdate &state() const { return state_; }
  Tensor3 stress() const { return from_mandel(state_.stress); }
  const Tensor3 &strain() const { return strain_; }
  /// Newton iterations of the last increment, and the largest in the last advance.
  unsigned last_iterations() const { return last_iterations_; }

private:
  /// Target stress of stress axis `a` at time t (with the stage-start ramp).
  double target_stress(int axis, double t) const;
  /// The point at box strain `eps` from the committed state; false when the return map fails.
  bool evaluate(const Tensor3 &eps, PointEvaluation &out) const;
  /// One increment to time t under the current control; false if it did not converge.
  bool increment(double t);
  /// Commits a converged increment and updates the localization record.
  void commit(const Tensor3 &eps, const PointEvaluation &up, double t, unsigned iterations);
  /// Switches to plastic-strain control after a failed increment, when it applies.
  bool start_plastic_control();

  std::shared_ptr<const ConstitutiveModel> model_;
  AcousticTensorScan scan_;
  MaterialPointParameters prm_;
  StageControl control_;
  bool has_control_ = false;

  double time_ = 0.0;
  Tensor3 strain_ = Tensor3::Zero(); ///< box strain (engineering, from the program start)
  Vector6 prestrain_ = Vector6::Zero(); ///< elastic strain of the initial stress
  MaterialPointUpdate state_;         ///< converged stress, tangent, history, region
  // Ramp of the stress targets at the start of a control.
  Vector3 ramp_from_ = Vector3::Zero();
  double ramp_t0_ = 0.0, ramp_t1_ = -1.0;
  // Localization bookkeeping.
  double q_min_ = 1.0;
  double onset_time_ = -1.0;
  Vector3 onset_normal_ = Vector3::Zero();
  unsigned last_iterations_ = 0, max_iterations_in_advance_ = 0;
  // Plastic-strain control (snap-back).
  bool plastic_control_ = false;
  int control_axis_ = -1;
  double kappa_rate_ = 0.0;  ///< kappa per unit time of the last advance that flowed
  Tensor3 last_step_ = Tensor3::Zero(); ///< strain change of the last increment (initial guess)
  double last_dt_ = 0.0;                ///< its time step

  struct Saved;
};

} // namespace geocomp::continuum
