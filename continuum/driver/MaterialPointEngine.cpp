#include "continuum/driver/MaterialPointEngine.h"
#include "continuum/driver/LocalizationColumns.h"


#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace geocomp::continuum {

struct MaterialPointEngine::Saved : EngineState {
  double time;
  Tensor3 strain;
  MaterialPointUpdate state;
  double q_min, onset_time;
  Vector3 onset_normal;
  bool plastic_control;
  int control_axis;
  double kappa_rate;
  Tensor3 last_step;
  double last_dt;
};

namespace {
AcousticTensorScan::Options scan_options(unsigned points)
{
  AcousticTensorScan::Options o;
  o.coarse_points = static_cast<int>(points);
  return o;
}
} // namespace

MaterialPointEngine::MaterialPointEngine(std::shared_ptr<const ConstitutiveModel> model,
                                         const MaterialPointParameters &parameters)
  : model_(std::move(model)), scan_(scan_options(parameters.localization_directions)), prm_(parameters)
{
  if (!model_)
    throw std::invalid_argument("MaterialPointEngine: no model");
  if (prm_.substeps_per_advance == 0)
    throw std::invalid_argument("MaterialPointEngine: substeps_per_advance must be >= 1");
  if (prm_.localization_directions < 10)
    throw std::invalid_argument("MaterialPointEngine: localization_directions must be >= 10");
  // The initial stress is carried as an elastic pre-strain that the box strain does not see.
  prestrain_ = model_->elasticity().compliance() * to_mandel(prm_.initial_stress * Tensor3::Identity());
  PointEvaluation start;
  if (!evaluate(Tensor3::Zero(), start))
    throw std::invalid_argument("MaterialPointEngine: the initial stress is not admissible");
  state_ = start.state;
}

MaterialPointEngine::MaterialPointEngine(const MaterialParameters &material,
                                         const MaterialPointParameters &parameters)
  : MaterialPointEngine(make_material_factory(material)->make(MaterialVariant{}), parameters)
{}

// Finite strain on the box. F = diag(1 + eps) never rotates, so F, b^e, tau and the plastic
// flow stay diagonal and the exponential map of FiniteStrain.h reduces to the small-strain
// update on the total logarithmic strain e = ln(1 + eps) (log1p: full precision at small
// strain) with the plastic logarithmic strain as history:
//     tau = model(e + eps_0, history),  sigma = tau / J,  J = exp(tr e) = prod(1 + eps_i),
//     d sigma_a / d eps_b = (D_ab - tau_a) / (J (1 + eps_b)),
// D the model's consistent tangent. (A test checks it against finite_strain_update.)
bool MaterialPointEngine::evaluate(const Tensor3 &eps, PointEvaluation &out) const
{
  try {
    if (prm_.kinematics == Kinematics::small_strain) {
      out.state = model_->update(to_mandel(eps) + prestrain_, state_.history);
      out.axial_tangent = out.state.tangent.topLeftCorner<3, 3>();
      return true;
    }
    Vector3 stretch, log_strain;
    for (int a = 0; a < 3; ++a) {
      stretch[a] = 1.0 + eps(a, a);
      log_strain[a] = std::log1p(eps(a, a));
    }
    if (!(stretch.minCoeff() > 0.0))
      return false;
    const double J = stretch.prod();
    out.state = model_->update(to_mandel(Matrix3(log_strain.asDiagonal())) + prestrain_, state_.history);
    const Vector6 tau = out.state.stress;
    out.state.stress = tau / J;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        out.axial_tangent(a, b) = (out.state.tangent(a, b) - tau[a]) / (J * stretch[b]);
    return true;
  } catch (const ReturnMapFailure &) {
    return false;
  }
}

std::vector<ExtraColumn> MaterialPointEngine::extra_columns() const
{
  std::vector<ExtraColumn> columns{
    {"kappa", "1", "equivalent plastic strain of the point"},
    {"state_flag", "1", "return region: 0 elastic, 1 plane, 2 left edge, 3 right edge, 4 apex"},
    {"plastic_volumetric_strain", "1", "tr(eps_p)"}};
  const std::vector<ExtraColumn> localization =
    localization_columns({"min over n of det(n.C_ep.n)/det(n.C_e.n) (1 elastic, <= 0 localized)", false});
  columns.insert(columns.end(), localization.begin(), localization.end());
  columns.push_back({"newton_iterations", "1", "largest stress-axis Newton iteration count in the last interval"});
  columns.push_back({"control", "1", "0: the program's strains; 1: plastic-strain control past a snap-back of the driven axis"});
  return columns;
}

void MaterialPointEngine::begin_control(const StageControl &control)
{
  control_ = control;
  has_control_ = true;
  plastic_control_ = false;
  // Ramp only the targets that change: a control resumed after a branch (or a stage that
  // keeps its stress) must follow exactly the path it would have followed without it.
  bool changes = false;
  for (int a = 0; a < 3; ++a) {
    ramp_from_[a] = control.kinematic(a) ? 0.0 : state_.stress[a];
    if (!control.kinematic(a)) {
      const double target = control.target_stress(a);
      const double scale = std::max({std::abs(target), std::abs(ramp_from_[a]), 1.0});
      if (std::abs(ramp_from_[a] - target) > 1e-6 * scale)
        changes = true;
      else
        ramp_from_[a] = target;
    }
  }
  ramp_t0_ = time_;
  ramp_t1_ = changes ? -1.0 : ramp_t0_; // -1: set by the first advance of this control
}

double MaterialPointEngine::target_stress(int axis, double t) const
{
  const double target = control_.target_stress(axis);
  if (ramp_t1_ <= ramp_t0_ || t >= ramp_t1_)
    return target;
  const double f = std::clamp((t - ramp_t0_) / (ramp_t1_ - ramp_t0_), 0.0, 1.0);
  return ramp_from_[axis] + f * (target - ramp_from_[axis]);
}

// The equations of one increment (MixedControl.h): the program's strains on the kinematic
// axes and its stress targets; under plastic-strain control the driven axis joins the
// unknowns and kappa its target.
bool MaterialPointEngine::increment(double t)
{
  if (plastic_control_) {
    // The program's control first: once it has a solution again, the path is back on the
    // program (a strain-controlled rig would have snapped there).
    plastic_control_ = false;
    if (increment(t))
      return true;
    plastic_control_ = true;
  }
  IncrementEquations eq;
  Tensor3 eps = strain_;
  for (int a = 0; a < 3; ++a) {
    if (plastic_control_ && a == control_axis_) {
      eq.unknown[eq.n_unknown++] = a;
      eps(a, a) += last_step_(a, a) * (t - time_) / std::max(last_dt_, 1e-300); // extrapolated guess
    } else if (control_.kinematic(a)) {
      eps(a, a) = control_.strain(a, t);
    } else {
      eq.unknown[eq.n_unknown++] = a;
      eq.stress_axis[eq.n_stress] = a;
      eq.target[eq.n_stress++] = target_stress(a, t);
    }
  }
  if (plastic_control_) {
    eq.control_kappa = true;
    eq.kappa_scale = kappa_rate_ * (t - time_);
    eq.kappa_target = state_.history.kappa + eq.kappa_scale;
  }
  IncrementSettings settings;
  settings.stress_tolerance = prm_.stress_tolerance;
  settings.max_iterations = prm_.max_iterations;
  const PointEvaluator evaluator = [this](const Tensor3 &e, PointEvaluation &out) { return evaluate(e, out); };
  PointEvaluation up;
  unsigned iterations = 0;
  if (!solve_increment(eq, evaluator, settings, eps, up, iterations))
    return false;
  commit(eps, up, t, iterations);
  return true;
}

void MaterialPointEngine::commit(const Tensor3 &eps, const PointEvaluation &up, double t, unsigned iterations)
{
  last_iterations_ = iterations;
  max_iterations_in_advance_ = std::max(max_iterations_in_advance_, iterations);
  last_step_ = eps - strain_;
  last_dt_ = t - time_;
  strain_ = eps;
  state_ = up.state;
  time_ = t;
  if (state_.region != ReturnRegion::elastic) {
    const LocalizationResult loc = scan_.scan(state_.tangent, model_->elasticity().stiffness());
    q_min_ = loc.min_ratio;
    if (onset_time_ < 0.0 && loc.localized()) {
      onset_time_ = time_;
      onset_normal_ = loc.normal;
      // Sign convention: the largest component positive.
      int big = 0;
      onset_normal_.cwiseAbs().maxCoeff(&big);
      if (onset_normal_[big] < 0)
        onset_normal_ = -onset_normal_;
    }
  } else {
    q_min_ = 1.0;
  }
}

// Plastic-strain control applies to a flowing point whose program drives one axis and holds
// stresses on others: the driven axis is the kinematic axis with the fastest rate.
bool MaterialPointEngine::start_plastic_control()
{
  if (plastic_control_ || state_.region == ReturnRegion::elastic || !(kappa_rate_ > 0.0))
    return false;
  int axis = -1, stress_axes = 0;
  double fastest = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (!control_.kinematic(a)) {
      ++stress_axes;
      continue;
    }
    const double rate = std::abs(control_.strain_rate(a, time_));
    if (rate > fastest) {
      fastest = rate;
      axis = a;
    }
  }
  if (axis < 0 || stress_axes == 0)
    return false;
  plastic_control_ = true;
  control_axis_ = axis;
  last_step_ = Tensor3::Zero();
  return true;
}

void MaterialPointEngine::advance_to(double t_end)
{
  if (!has_control_)
    throw std::logic_error("MaterialPointEngine::advance_to before begin_control");
  if (ramp_t1_ < 0.0)
    ramp_t1_ = t_end;
  max_iterations_in_advance_ = 0;
  const double t_start = time_, kappa_start = state_.history.kappa;
  const double dt_nominal = (t_end - t_start) / prm_.substeps_per_advance;
  double dt = dt_nominal;
  unsigned cuts = 0;
  while (time_ < t_end) {
    const bool last = is_last_step(time_, dt, t_end, dt_nominal);
    const double t = last ? t_end : time_ + dt;
    if (increment(t)) {
      if (cuts > 0)
        dt = std::min(dt_nominal, 2.0 * dt); // grow back after a cut
      continue;
    }
    if (++cuts > prm_.max_cutbacks) {
      if (time_ > t_start && state_.history.kappa > kappa_start && !plastic_control_)
        kappa_rate_ = (state_.history.kappa - kappa_start) / (time_ - t_start);
      if (start_plastic_control()) { // a snap-back: follow it in kappa
        cuts = 0;
        dt = dt_nominal;
        continue;
      }
      std::ostringstream msg;
      msg << "material point: the stress-axis iteration did not converge at t = " << t
          << " after " << prm_.max_cutbacks << " cut-backs (is a stress-driven axis beyond the "
          << "strength of the material?)";
      throw std::runtime_error(msg.str());
    }
    dt *= 0.5;
  }
  if (!plastic_control_ && state_.history.kappa > kappa_start)
    kappa_rate_ = (state_.history.kappa - kappa_start) / (time_ - t_start);
}

ResponseSample MaterialPointEngine::measure()
{
  ResponseSample s;
  s.time = time_;
  s.strain = strain_;
  s.stress = from_mandel(state_.stress);
  s.extras = {state_.history.kappa,
              static_cast<double>(state_.region),
              volumetric_plastic_strain(state_.history),
              q_min_,
              onset_time_,
              onset_normal_[0],
              onset_normal_[1],
              onset_normal_[2],
              static_cast<double>(max_iterations_in_advance_),
              plastic_control_ ? 1.0 : 0.0};
  return s;
}

std::unique_ptr<EngineState> MaterialPointEngine::save() const
{
  auto s = std::make_unique<Saved>();
  s->time = time_;
  s->strain = strain_;
  s->state = state_;
  s->q_min = q_min_;
  s->onset_time = onset_time_;
  s->onset_normal = onset_normal_;
  s->plastic_control = plastic_control_;
  s->control_axis = control_axis_;
  s->kappa_rate = kappa_rate_;
  s->last_step = last_step_;
  s->last_dt = last_dt_;
  return s;
}

void MaterialPointEngine::restore(const EngineState &state)
{
  const auto &s = dynamic_cast<const Saved &>(state);
  time_ = s.time;
  strain_ = s.strain;
  state_ = s.state;
  q_min_ = s.q_min;
  onset_time_ = s.onset_time;
  onset_normal_ = s.onset_normal;
  plastic_control_ = s.plastic_control;
  control_axis_ = s.control_axis;
  kappa_rate_ = s.kappa_rate;
  last_step_ = s.last_step;
  last_dt_ = s.last_dt;
}

} // namespace geocomp::continuum
