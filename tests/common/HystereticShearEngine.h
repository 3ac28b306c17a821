#pragma once
// A closed-form engine for testing the program logic: shear stress follows the backbone
// tau_b(g) = A (g/g0) exp(1 - g/g0) (peak A at g = g0) on first loading and unloads
// elastically with slope K from the largest shear strain reached. Mean stress -p0.
// Every number a test checks can be computed by hand from these formulas. shear_program()
// is the isochoric shear the tests play on it.
#include "common/LoadingEngine.h"

#include <cmath>
#include <string>
#include <vector>

namespace geocomp::testing {

class HystereticShearEngine : public LoadingEngine {
public:
  double A = 1.0e6, g0 = 0.05, K = 1.0e8, p0 = 2.0e6;

  double backbone(double g) const { return g <= 0 ? 0.0 : A * (g / g0) * std::exp(1.0 - g / g0); }
  double tau_of(double g, double g_hist) const
  {
    if (g >= g_hist)
      return backbone(g);
    return backbone(g_hist) - K * (g_hist - g);
  }

  std::string name() const override { return "hysteretic-test"; }
  std::vector<ExtraColumn> extra_columns() const override { return {{"g_hist", "1", "largest gamma reached"}}; }
  void begin_control(const StageControl &c) override { control_ = c; }
  void advance_to(double t_end) override
  {
    // Sub-steps so the history variable sees the path, as a real engine would.
    const int n = 10;
    const double t0 = time_;
    for (int k = 1; k <= n; ++k) {
      time_ = t0 + (t_end - t0) * k / n;
      for (int a = 0; a < 3; ++a)
        eps_[a] = control_.strain(a, time_);
      g_hist_ = std::max(g_hist_, gamma());
    }
  }
  double gamma() const { return eps_.maxCoeff() - eps_.minCoeff(); }
  ResponseSample measure() override
  {
    ResponseSample s;
    s.time = time_;
    s.strain = eps_.asDiagonal();
    const double tau = tau_of(gamma(), g_hist_);
    s.stress = Tensor3::Identity() * -p0;
    s.stress(0, 0) -= tau;
    s.stress(2, 2) += tau;
    s.extras = {g_hist_};
    return s;
  }
  struct State : EngineState {
    double time, g_hist;
    Vector3 eps;
  };
  std::unique_ptr<EngineState> save() const override
  {
    auto s = std::make_unique<State>();
    s->time = time_;
    s->g_hist = g_hist_;
    s->eps = eps_;
    return s;
  }
  void restore(const EngineState &state) override
  {
    const auto &s = dynamic_cast<const State &>(state);
    time_ = s.time;
    g_hist_ = s.g_hist;
    eps_ = s.eps;
  }

private:
  StageControl control_;
  double time_ = 0.0, g_hist_ = 0.0;
  Vector3 eps_ = Vector3::Zero();
};

/// lambda = 0 isochoric shear at 0.05/s, sampled every 0.01 s, to gamma_max = `stop_gamma`
/// (gamma_max = eps_z - eps_x grows at about 2 * rate), with unloading branches at `triggers`.
inline LoadingProgram shear_program(std::vector<std::string> triggers, double stop_gamma = 0.2,
                                    double max_duration = 100.0)
{
  LoadingProgram p;
  p.sample_interval = 0.01;
  Stage s;
  s.name = "shear";
  s.isochoric = true;
  s.lambda = 0.0;
  s.isochoric_rate = 0.05;
  s.stop_any = {parse_condition("gamma_max >= " + std::to_string(stop_gamma), "test")};
  s.max_duration = max_duration;
  for (const auto &t : triggers)
    s.unload_at.push_back(parse_trigger(t, "test"));
  p.stages.push_back(s);
  return p;
}

} // namespace geocomp::testing
