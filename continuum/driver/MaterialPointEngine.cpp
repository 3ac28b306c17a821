#include "continuum/driver/MaterialPointEngine.h"


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
  Evaluation start;
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
bool MaterialPointEngine::evaluate(const Tensor3 &eps, Evaluation &out) const
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
  return {{"kappa", "1", "equivalent plastic strain of the point"},
          {"state_flag", "1", "return region: 0 elastic, 1 plane, 2 left edge, 3 right edge, 4 apex"},
          {"plastic_volumetric_strain", "1", "tr(eps_p)"},
          {"localization_q", "1", "min over n of det(n.C_ep.n)/det(n.C_e.n) (1 elastic, <= 0 localized)"},
          {"localization_onset_time", "s", "program time of the first q <= 0 (-1: not yet)"},
          {"localization_nx", "1", "band normal at onset, x"},
          {"localization_ny", "1", "band normal at onset, y"},
          {"localization_nz", "1", "band normal at onset, z"},
          {"newton_iterations", "1", "largest stress-axis Newton iteration count in the last interval"}};
}

void MaterialPointEngine::begin_control(const StageControl &control)
{
  control_ = control;
  has_control_ = true;
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

bool MaterialPointEngine::increment(double t)
{
  Tensor3 eps = strain_;
  int stress_axes[3], n_s = 0;
  for (int a = 0; a < 3; ++a) {
    if (control_.kinematic(a))
      eps(a, a) = control_.strain(a, t);
    else
      stress_axes[n_s++] = a;
  }
  Evaluation up;
  if (!evaluate(eps, up))
    return false;
  unsigned it = 0;
  if (n_s > 0) {
    Eigen::VectorXd target(n_s), r(n_s);
    // Mandel slots 0..2 are the normal components, unweighted.
    auto residual = [&](const Evaluation &e, Eigen::VectorXd &res) {
      const MaterialPointUpdate &u = e.state;
      double scale = 1.0;
      for (int i = 0; i < 3; ++i)
        scale = std::max(scale, std::abs(u.stress[i]));
      double worst = 0.0;
      for (int k = 0; k < n_s; ++k) {
        const int a = stress_axes[k];
        res[k] = u.stress[a] - target[k];
        worst = std::max(worst, std::abs(res[k]) / std::max(scale, std::abs(target[k])));
      }
      return worst;
    };
    for (int k = 0; k < n_s; ++k)
      target[k] = target_stress(stress_axes[k], t);
    double err = residual(up, r);
    while (err > prm_.stress_tolerance) {
      if (++it > prm_.max_iterations)
        return false;
      Eigen::MatrixXd J(n_s, n_s);
      for (int k = 0; k < n_s; ++k)
        for (int m = 0; m < n_s; ++m)
          J(k, m) = up.axial_tangent(stress_axes[k], stress_axes[m]);
      // Symmetric programs stay symmetric: stress axes with the same target and the same
      // strain are tied to one unknown (P maps tied unknowns to axes), so the corner of the
      // yield surface a triaxial test sits on (sigma_1 = sigma_2, where the split of the
      // lateral strain is indeterminate) cannot break the symmetry through round-off.
      Eigen::MatrixXd P = Eigen::MatrixXd::Zero(n_s, n_s);
      int n_u = 0;
      std::array<int, 3> group{-1, -1, -1};
      for (int k = 0; k < n_s; ++k) {
        for (int m = 0; m < k && group[k] < 0; ++m) {
          const int a = stress_axes[k], b = stress_axes[m];
          const double de = std::abs(eps(a, a) - eps(b, b));
          if (target[k] == target[m] && de <= 1e-13 * std::max(std::abs(eps(a, a)), 1e-6))
            group[k] = group[m];
        }
        if (group[k] < 0)
          group[k] = n_u++;
        P(k, group[k]) = 1.0;
      }
      P.conservativeResize(n_s, n_u);
      const Eigen::MatrixXd J_red = P.transpose() * J * P;
      // Minimum-norm step: on a corner the remaining block can still be singular.
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(J_red);
      cod.setThreshold(1e-10);
      if (cod.rank() == 0)
        return false;
      const Eigen::VectorXd de = -P * cod.solve(P.transpose() * r);
      // Damped update: halve while the residual norm grows.
      double alpha = 1.0;
      Eigen::VectorXd r_new(n_s);
      Evaluation trial;
      Tensor3 eps_trial;
      bool ok = false;
      for (int ls = 0; ls < 8; ++ls, alpha *= 0.5) {
        eps_trial = eps;
        for (int k = 0; k < n_s; ++k)
          eps_trial(stress_axes[k], stress_axes[k]) += alpha * de[k];
        if (!evaluate(eps_trial, trial))
          continue;
        ok = true;
        residual(trial, r_new);
        if (r_new.norm() < r.norm())
          break;
      }
      if (!ok)
        return false;
      eps = eps_trial;
      up = trial;
      err = residual(up, r);
    }
  }
  last_iterations_ = it;
  max_iterations_in_advance_ = std::max(max_iterations_in_advance_, it);
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
  return true;
}

void MaterialPointEngine::advance_to(double t_end)
{
  if (!has_control_)
    throw std::logic_error("MaterialPointEngine::advance_to before begin_control");
  if (ramp_t1_ < 0.0)
    ramp_t1_ = t_end;
  max_iterations_in_advance_ = 0;
  const double t_start = time_;
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
      std::ostringstream msg;
      msg << "material point: the stress-axis iteration did not converge at t = " << t
          << " after " << prm_.max_cutbacks << " cut-backs (is a stress-driven axis beyond the "
          << "strength of the material?)";
      throw std::runtime_error(msg.str());
    }
    dt *= 0.5;
  }
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
              static_cast<double>(max_iterations_in_advance_)};
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
}

} // namespace geocomp::continuum
