#pragma once
// ProgramRunner: plays a LoadingProgram on any LoadingEngine and records the Response.
//
// It samples the engine every `sampling interval`, evaluates stop conditions and branch
// triggers on the samples, and runs the unloading branches of S0 Fig. 2: save the engine,
// reverse every kinematic rate until tau_max is back at the stage's starting level,
// record the branch and its residual shear strain, restore, go on. "peak" branches
// leave from the state saved at the running maximum of tau_max, confirmed once tau_max
// has fallen by the stage's peak tolerance.
#include "common/LoadingEngine.h"

#include <functional>

namespace geocomp {

struct RunProgress {
  int stage = 0;
  int stage_count = 0;
  int branch = 0;          ///< 0 on the main path
  double time = 0.0;
  double stage_fraction = 0.0; ///< best estimate of how far the stage is, in [0, 1]
  const ResponseSample *sample = nullptr;
};

/// Values a condition is evaluated against beyond the sample itself.
struct ConditionContext {
  double stage_start_time = 0.0;
  double tau_peak = 0.0;
  const Stage *stage = nullptr;
};

/// Value of a quantity for a sample.
double evaluate(Quantity q, const ResponseSample &s, const ConditionContext &ctx);
bool holds(const Condition &c, const ResponseSample &s, const ConditionContext &ctx);

class ProgramRunner {
public:
  ProgramRunner(const LoadingProgram &program, LoadingEngine &engine);
  /// Called after every recorded sample (progress bars, checkpoints, logs).
  void on_progress(std::function<void(const RunProgress &)> callback) { progress_ = std::move(callback); }
  Response run();

private:
  void run_stage(int index);
  void run_branch(int stage_index, const StageControl &main, const std::string &trigger,
                  std::size_t from_sample, const EngineState *from_state);
  void record(ResponseSample s, int stage, int branch, double fraction);

  const LoadingProgram &program_;
  LoadingEngine &engine_;
  Response response_;
  std::vector<std::size_t> stage_start_sample_; ///< main-path sample each stage left from
  std::function<void(const RunProgress &)> progress_;
};

} // namespace geocomp
