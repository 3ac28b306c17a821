#include "common/ProgramRunner.h"
#include "common/ElasticLimitBracket.h"
#include "common/UnloadingMeasure.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace geocomp {

double evaluate(Quantity q, const ResponseSample &s, const ConditionContext &ctx)
{
  switch (q) {
  case Quantity::Time: return s.time;
  case Quantity::StageTime: return s.time - ctx.stage_start_time;
  case Quantity::EpsXX: return s.strain(0, 0);
  case Quantity::EpsYY: return s.strain(1, 1);
  case Quantity::EpsZZ: return s.strain(2, 2);
  case Quantity::SigXX: return s.stress(0, 0);
  case Quantity::SigYY: return s.stress(1, 1);
  case Quantity::SigZZ: return s.stress(2, 2);
  case Quantity::GammaMax: return gamma_max(s.strain);
  case Quantity::TauMax: return tau_max(s.stress);
  case Quantity::VolumetricStrain: return volumetric_strain(s.strain);
  case Quantity::MeanStress: return mean_stress(s.stress);
  case Quantity::StressRatio: {
    const Vector3 p = principal_values(s.stress);
    return p[2] != 0.0 ? p[0] / p[2] : (p[0] != 0.0 ? INFINITY : 1.0);
  }
  case Quantity::PeakDrop: {
    const double tau = tau_max(s.stress);
    return ctx.tau_peak > 0.0 ? std::max(0.0, (ctx.tau_peak - tau) / ctx.tau_peak) : 0.0;
  }
  case Quantity::ServoError: {
    double err = 0.0;
    if (ctx.stage && !ctx.stage->isochoric)
      for (int a = 0; a < 3; ++a)
        if (ctx.stage->axes[a].is_stress()) {
          const double target = ctx.stage->axes[a].value;
          const double scale = std::abs(target) > 0.0 ? std::abs(target) : 1.0;
          err = std::max(err, std::abs(s.stress(a, a) - target) / scale);
        }
    return err;
  }
  }
  return 0.0;
}

bool holds(const Condition &c, const ResponseSample &s, const ConditionContext &ctx)
{
  const double v = evaluate(c.quantity, s, ctx);
  return c.at_least ? v >= c.value : v <= c.value;
}

ProgramRunner::ProgramRunner(const LoadingProgram &program, LoadingEngine &engine)
  : program_(program), engine_(engine)
{
  program_.validate();
}

void ProgramRunner::record(ResponseSample s, int stage, int branch, double fraction)
{
  s.stage = stage;
  s.branch = branch;
  if (!response_.interval_means)
    s.stress_mean = s.stress;
  response_.samples.push_back(std::move(s));
  if (progress_) {
    RunProgress p;
    p.stage = stage;
    p.stage_count = static_cast<int>(program_.stages.size());
    p.branch = branch;
    p.time = response_.samples.back().time;
    p.stage_fraction = std::clamp(fraction, 0.0, 1.0);
    p.sample = &response_.samples.back();
    progress_(p);
  }
}

ProgramStopped::ProgramStopped(double time, std::size_t samples)
  : std::runtime_error("program stopped on request at t = " + std::to_string(time) + " s after " +
                       std::to_string(samples) + " samples; checkpoint written"),
    time(time), samples(samples)
{
}

namespace {
double steady_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

namespace {
/// "stage 2", with the stage's name when it has one of its own: "stage 2 'shear'".
std::string stage_label(const LoadingProgram &program, int k)
{
  const std::string number = "stage " + std::to_string(k + 1);
  const std::string &name = k < int(program.stages.size()) ? program.stages[k].name : number;
  return name.empty() || name == number ? number : number + " '" + name + "'";
}
} // namespace

ProgramFailed::ProgramFailed(std::string status, Response partial)
  : std::runtime_error(status), status(std::move(status)), partial(std::move(partial))
{
}

template <class Body> void ProgramRunner::failing_safely(Body &&body)
{
  try {
    body();
  } catch (const ProgramStopped &) {
    throw;
  } catch (const std::exception &e) {
    std::ostringstream where;
    where << "failed in " << stage_label(program_, stage_);
    if (branch_ > 0)
      where << ", unloading branch " << branch_;
    where << ", after t = " << (response_.samples.empty() ? 0.0 : response_.samples.back().time) << " s: " << e.what();
    if (int(response_.stage_end_reasons.size()) == stage_)
      response_.stage_end_reasons.push_back(where.str());
    throw ProgramFailed(where.str(), std::move(response_));
  }
}

Response ProgramRunner::run()
{
  response_ = Response{};
  stage_start_sample_.clear();
  last_checkpoint_ = steady_seconds();
  response_.engine = engine_.name();
  response_.interval_means = engine_.gives_interval_means();
  response_.extras = engine_.extra_columns();
  for (const auto &s : program_.stages)
    response_.stage_names.push_back(s.name);
  stage_ = branch_ = 0;
  failing_safely([&] {
    record(engine_.measure(), 0, 0, 0.0);
    for (std::size_t i = 0; i < program_.stages.size(); ++i)
      run_stage(static_cast<int>(i));
  });
  return std::move(response_);
}

Response ProgramRunner::resume(RunnerState state, std::unique_ptr<EngineState> peak,
                              std::vector<std::unique_ptr<EngineState>> kept)
{
  if (state.stage < 0 || state.stage >= static_cast<int>(program_.stages.size()) ||
      state.stage_start_sample.size() != std::size_t(state.stage) + 1 ||
      state.fired.size() != program_.stages[state.stage].unload_at.size() || state.response.samples.empty() ||
      state.has_peak_state != bool(peak) || kept.size() != state.kept_samples.size())
    throw std::invalid_argument("ProgramRunner::resume: the checkpoint does not belong to this program");
  limit_states_.clear();
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (state.kept_samples[k] >= state.response.samples.size() || !kept[k])
      throw std::invalid_argument("ProgramRunner::resume: the checkpoint does not belong to this program");
    limit_states_[state.kept_samples[k]] = std::move(kept[k]);
  }
  response_ = std::move(state.response);
  stage_start_sample_.assign(state.stage_start_sample.begin(), state.stage_start_sample.end());
  last_checkpoint_ = steady_seconds();
  state.response = Response{};
  stage_ = state.stage;
  branch_ = 0;
  failing_safely([&] {
    run_stage(state.stage, &state, std::move(peak));
    for (std::size_t i = std::size_t(state.stage) + 1; i < program_.stages.size(); ++i)
      run_stage(static_cast<int>(i));
  });
  return std::move(response_);
}

void ProgramRunner::maybe_checkpoint(const RunnerState &state, const EngineState *peak)
{
  if (!checkpoints_.write)
    return;
  const bool stop = checkpoints_.stop_requested && checkpoints_.stop_requested();
  const double now = steady_seconds();
  if (!stop && !(checkpoints_.every_seconds > 0.0 && now - last_checkpoint_ >= checkpoints_.every_seconds))
    return;
  std::vector<const EngineState *> kept;
  for (const auto &entry : limit_states_) // in sample order, as state.kept_samples
    kept.push_back(entry.second.get());
  checkpoints_.write(state, *engine_.save(), peak, kept);
  last_checkpoint_ = steady_seconds();
  if (stop)
    throw ProgramStopped(state.time, state.response.samples.size());
}

namespace {
/// Fraction of the way from the stage start to a stop condition's threshold.
double condition_fraction(const Condition &c, const ResponseSample &start, const ResponseSample &now,
                          const ConditionContext &ctx)
{
  const double v0 = evaluate(c.quantity, start, ctx);
  const double v = evaluate(c.quantity, now, ctx);
  const double span = c.value - v0;
  if (span == 0.0 || !std::isfinite(span))
    return 0.0;
  return (v - v0) / span;
}
} // namespace

void ProgramRunner::run_stage(int index, const RunnerState *from, std::unique_ptr<EngineState> peak)
{
  const Stage &stage = program_.stages[index];
  stage_ = index;
  if (!from)
    stage_start_sample_.push_back(response_.samples.size() - 1);
  const ResponseSample start = response_.samples[stage_start_sample_[index]];
  StageControl control;
  control.stage = &stage;
  control.t0 = start.time;
  control.eps0 = start.strain.diagonal();
  control.direction = 1.0;
  if (!from) // a resumed engine is already following this control (it is part of its state)
    engine_.begin_control(control);

  ConditionContext ctx{start.time, 0.0, &stage};
  std::vector<bool> fired(stage.unload_at.size(), false);
  std::unique_ptr<EngineState> peak_state = std::move(peak);
  std::size_t peak_sample = response_.samples.size() - 1;
  const bool wants_peak_state =
    std::any_of(stage.unload_at.begin(), stage.unload_at.end(),
                [](const BranchTrigger &b) { return b.kind == BranchTrigger::Kind::AtPeak; });

  if (!from) // a resumed stage keeps the bracket's states its checkpoint carried (resume())
    limit_states_.clear();
  if (stage.locate_elastic_limit && !from)
    keep_limit_state(index, stage_start_sample_[index]);

  const double t_end = start.time + stage.max_duration;
  std::string reason;
  double t = start.time;
  if (from) {
    ctx.tau_peak = from->tau_peak;
    peak_sample = from->peak_sample;
    t = from->time;
    for (std::size_t k = 0; k < fired.size(); ++k)
      fired[k] = from->fired[k] != 0;
  }
  while (reason.empty()) {
    const double t_next = std::min(t + program_.sample_interval, t_end);
    engine_.advance_to(t_next);
    t = t_next;
    ResponseSample s = engine_.measure();
    const double tau = tau_max(s.stress);
    if (tau > ctx.tau_peak) {
      ctx.tau_peak = tau;
      peak_sample = response_.samples.size(); // index this sample will get
      if (wants_peak_state)
        peak_state = engine_.save();
    }
    double fraction = (t - start.time) / stage.max_duration;
    for (const auto &c : stage.stop_any)
      fraction = std::max(fraction, condition_fraction(c, start, s, ctx));
    for (const auto &c : stage.stop_any)
      if (reason.empty() && holds(c, s, ctx))
        reason = c.text;
    if (reason.empty() && t >= t_end)
      reason = "max duration";
    record(s, index, 0, reason.empty() ? fraction : 1.0);
    if (stage.locate_elastic_limit)
      keep_limit_state(index, response_.samples.size() - 1);

    const ResponseSample now = response_.samples.back(); // a copy: branches append samples
    const std::size_t now_index = response_.samples.size() - 1; // every trigger here leaves from it
    for (std::size_t k = 0; k < stage.unload_at.size(); ++k) {
      if (fired[k])
        continue;
      const BranchTrigger &trigger = stage.unload_at[k];
      if (trigger.kind == BranchTrigger::Kind::AtPeak) {
        if (peak_state && evaluate(Quantity::PeakDrop, now, ctx) >= stage.peak_tolerance) {
          fired[k] = true;
          run_branch(index, control, {trigger.text, peak_sample, peak_state.get()});
        }
      } else if (holds(trigger.condition, now, ctx)) {
        fired[k] = true;
        run_branch(index, control, {trigger.text, now_index, nullptr});
      }
    }
    if (reason.empty() && checkpoints_.write) {
      RunnerState state;
      state.stage = index;
      state.time = t;
      state.tau_peak = ctx.tau_peak;
      state.peak_sample = peak_sample;
      for (bool f : fired)
        state.fired.push_back(f ? 1 : 0);
      state.has_peak_state = bool(peak_state);
      state.stage_start_sample.assign(stage_start_sample_.begin(), stage_start_sample_.end());
      // The response is copied only when a checkpoint is due.
      const bool due = (checkpoints_.stop_requested && checkpoints_.stop_requested()) ||
                       (checkpoints_.every_seconds > 0.0 && steady_seconds() - last_checkpoint_ >= checkpoints_.every_seconds);
      if (due) {
        state.response = response_;
        for (const auto &kept : limit_states_) // their states: maybe_checkpoint, in this order
          state.kept_samples.push_back(kept.first);
        maybe_checkpoint(state, peak_state.get());
      }
    }
  }
  if (stage.locate_elastic_limit)
    locate_elastic_limit(index, control);
  limit_states_.clear();
  response_.stage_end_reasons.push_back(reason);
}

void ProgramRunner::keep_limit_state(int stage_index, std::size_t sample)
{
  const ResponseSample &stage_start = response_.samples[stage_start_sample_[stage_index]];
  const LimitSearch search = search_limit(branch_points(response_, stage_index, stage_start), s0_residual_threshold);
  // Past the first branch at or above the threshold no state is needed: the crossing lies
  // before it. Before the last branch below it (and before the first one above) neither.
  if (!search.upper)
    limit_states_[sample] = engine_.save();
  if (search.lower)
    limit_states_.erase(limit_states_.begin(), limit_states_.lower_bound(search.lower->origin));
  if (search.upper)
    limit_states_.erase(limit_states_.upper_bound(search.upper->origin), limit_states_.end());
}

void ProgramRunner::locate_elastic_limit(int stage_index, const StageControl &main)
{
  const Stage &stage = *main.stage;
  const ResponseSample stage_start = response_.samples[stage_start_sample_[stage_index]];
  // Each branch lands strictly inside the bracket and becomes one of its ends, so the bracket
  // shrinks at every step; the cap only guards a stage whose strain stops growing.
  for (int step = 0; step < 64; ++step) {
    const LimitSearch search =
      search_limit(branch_points(response_, stage_index, stage_start), s0_residual_threshold);
    if (!search.bracketed() || search.width() <= stage.elastic_limit_tolerance)
      return;
    const double t_lo = search.lower->time, t_hi = search.upper->time;
    const double t_mid = 0.5 * (t_lo + t_hi);
    if (!(t_hi - t_lo > 1e-6 * program_.sample_interval))
      return; // the strain no longer moves with time
    BranchStart start{BranchRecord::bisection_trigger, 0, nullptr};
    double nearest = INFINITY;
    const EngineState *before = nullptr;
    std::size_t before_sample = 0;
    for (const auto &[sample, state] : limit_states_) { // in sample (= main-path time) order
      const double t = response_.samples[sample].time;
      if (t > t_lo && t < t_hi && std::abs(t - t_mid) < nearest) {
        nearest = std::abs(t - t_mid);
        start.from_sample = sample;
        start.from_state = state.get();
      }
      if (t <= t_mid) {
        before = state.get();
        before_sample = sample;
      }
    }
    if (!start.from_state) { // neighbouring samples: run the main path on to the midpoint
      if (!before)
        return; // not kept (a run resumed inside the bracket): the bracket stays as it is
      start.from_sample = before_sample;
      start.from_state = before;
      start.leave_at = t_mid;
    }
    run_branch(stage_index, main, start);
  }
}

void ProgramRunner::run_branch(int stage_index, const StageControl &main, const BranchStart &start)
{
  const Stage &stage = *main.stage;
  const std::unique_ptr<EngineState> resume = engine_.save();
  BranchRecord b;
  b.id = static_cast<int>(response_.branches.size()) + 1;
  branch_ = b.id;
  engine_.set_branch(b.id);
  if (start.from_state)
    engine_.restore(*start.from_state);
  // The sample the branch leaves from: the main-path sample at the saved state, or the main
  // path run on from it (as after any branch) to leave_at, recorded as the branch's first.
  std::size_t from_sample = start.from_sample;
  if (start.leave_at > response_.samples[from_sample].time) {
    engine_.begin_control(main);
    engine_.advance_to(start.leave_at);
    record(engine_.measure(), stage_index, b.id, 0.0);
    from_sample = response_.samples.size() - 1;
  }
  const ResponseSample origin = response_.samples[from_sample];

  b.stage = stage_index;
  b.trigger = start.trigger;
  b.first_sample = from_sample;
  b.tau_start = tau_max(origin.stress);
  b.gamma_start = gamma_max(origin.strain);
  // Level to return to: tau_max where the stage started, or the given one.
  const ResponseSample stage_start = response_.samples[stage_start_sample_[stage_index]];
  // Unloading is measured along the deviator the branch leaves with (UnloadingMeasure.h).
  const UnloadingMeasure along(origin.stress);
  b.tau_target = along.target(stage, stage_start.stress);

  StageControl reverse = main;
  reverse.t0 = origin.time;
  reverse.eps0 = origin.strain.diagonal();
  reverse.direction = -1.0;
  engine_.begin_control(reverse);

  double t = origin.time;
  double tau_prev = b.tau_start;
  const double tol = 1e-9 * std::max(1.0, std::abs(b.tau_start)); // "on the target
  const double t_end = origin.time + stage.max_duration;
  while (true) {
    const double t_next = std::min(t + program_.sample_interval, t_end);
    const std::unique_ptr<EngineState> before = engine_.save();
    engine_.advance_to(t_next);
    ResponseSample s = engine_.measure();
    double tau = along(s.stress);
    if (tau <= b.tau_target && tau < tau_prev) {
      // The target lies inside this interval: land the branch's last sample on it. False
      // position with the Illinois modification from the saved state, keeping the bracket
      // [ta, tb] with f(ta) > 0 >= f(tb) (f = tau - target): exact in one step for elastic
      // unloading (linear), and it still closes in on a noisy response (a large DEM
      // specimen's), where the plain secant crept along the flat side. The sample lands on
      // the bracket's far end, at or past the target, never short of it.
      double ta = t, fa = tau_prev - b.tau_target, tb = t_next, fb = tau - b.tau_target;
      bool at_b = true; // the engine and s hold the landing state (tb, or a point on the target)
      int side = 0;
      for (int k = 0; k < 8 && fb < -tol && fa > 0.0; ++k) {
        const double tc = std::clamp((ta * fb - tb * fa) / (fb - fa), ta, tb);
        if (tc <= ta || tc >= tb)
          break;
        engine_.restore(*before);
        engine_.advance_to(tc);
        ResponseSample c = engine_.measure();
        const double fc = along(c.stress) - b.tau_target;
        if (fc <= tol && fc > 0.0) { // on the target, to the tolerance
          s = std::move(c);
          at_b = true;
          break;
        }
        if (fc > 0.0) {
          ta = tc;
          fa = fc;
          if (side > 0)
            fb *= 0.5;
          side = 1;
          at_b = false;
        } else {
          tb = tc;
          fb = fc;
          s = std::move(c);
          if (side < 0)
            fa *= 0.5;
          side = -1;
          at_b = true;
        }
      }
      if (!at_b) {
        engine_.restore(*before);
        engine_.advance_to(tb);
        s = engine_.measure();
      }
      tau = along(s.stress);
    }
    t = s.time;
    tau_prev = tau;
    const double fraction =
      b.tau_start > b.tau_target ? (b.tau_start - tau) / (b.tau_start - b.tau_target) : 1.0;
    record(s, stage_index, b.id, fraction);
    if (tau <= b.tau_target + tol) {
      b.reached_target = true;
      break;
    }
    if (t >= t_end)
      break;
  }
  b.last_sample = response_.samples.size() - 1;
  // Residual shear strain of the stage: what unloading did not recover.
  b.residual_gamma = gamma_max(response_.samples.back().strain - stage_start.strain);
  response_.branches.push_back(b);

  engine_.set_branch(0);
  engine_.restore(*resume);
  engine_.begin_control(main);
  branch_ = 0;
}

std::string completion_status(const Response &r, const LoadingProgram &program)
{
  std::ostringstream out;
  for (std::size_t k = 0; k < r.stage_end_reasons.size() && k < program.stages.size(); ++k) {
    if (r.stage_end_reasons[k] != "max duration")
      continue;
    const Stage &s = program.stages[k];
    out << (out.tellp() > 0 ? "; " : "") << stage_label(program, int(k)) << " ended on its max duration ("
        << s.max_duration << " s) before its stop condition";
    for (std::size_t c = 0; c < s.stop_any.size(); ++c)
      out << (c == 0 ? " '" : " or '") << s.stop_any[c].text << "'";
  }
  for (const BranchRecord &b : r.branches)
    if (!b.reached_target)
      out << (out.tellp() > 0 ? "; " : "") << "unloading branch " << b.id << " (" << b.trigger
          << ") ended before reaching tau_max = " << b.tau_target << " Pa";
  return out.tellp() > 0 ? out.str() : "complete";
}

} // namespace geocomp
