#pragma once
// ProgramRunner: plays a LoadingProgram on any LoadingEngine and records the Response.
//
// It samples the engine every `sampling interval`, evaluates stop conditions and branch
// triggers on the samples, and runs the unloading branches of S0 Fig. 2: save the engine,
// reverse every kinematic rate until tau_max is back at the stage's starting level,
// record the branch and its residual shear strain, restore, go on. "peak" branches
// leave from the state saved at the running maximum of tau_max, confirmed once tau_max
// has fallen by the stage's peak tolerance.
//
// A stage with `locate elastic limit` keeps the engine state of every main-path sample
// from the last branch whose residual is below S0's 1 % (ElasticLimitBracket.h) up to the
// first one at or above it. Once the main path has ended, it bisects that bracket: an
// unloading branch ("bisection") from the main-path sample nearest the bracket's midpoint
// strictly inside it, or, once the ends are neighbouring samples, from the main path run
// on from the earlier sample's state to the midpoint time; the half whose ends still
// straddle 1 % is kept, until the ends' start strains are closer than the tolerance.
#include "common/LoadingEngine.h"
#include "common/ProgramCheckpoint.h"

#include <functional>
#include <map>
#include <stdexcept>

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

/// When and where a run checkpoints itself (ProgramCheckpoint.h). At a main-path sample,
/// once `every_seconds` of wall time have passed since the last checkpoint (0: never on
/// time) or when `stop_requested()` says so, the runner calls `write` with its state, the
/// engine's current state, the engine state at the running peak (null if none) and the
/// states the open elastic-limit bracket keeps (one per RunnerState::kept_samples entry).
struct CheckpointPolicy {
  double every_seconds = 0.0;
  std::function<void(const RunnerState &, const EngineState &current, const EngineState *peak,
                     const std::vector<const EngineState *> &kept)>
    write;
  std::function<bool()> stop_requested;
};

/// Thrown by run()/resume() after a requested stop, once the checkpoint is written.
struct ProgramStopped : std::runtime_error {
  ProgramStopped(double time, std::size_t samples);
  double time;
  std::size_t samples;
};

/// Thrown by run()/resume() when the engine fails mid-run (any exception from it: a DEM
/// guard, a continuum solver that does not converge...): the samples and branches
/// recorded so far, the stage under way marked as failed, and where and why (`status`, as
/// /meta/status of the results file: "failed in stage 2 'shear', branch 1, after
/// t = 0.0123 s: <the engine's message>"). Callers write `partial` with that status.
struct ProgramFailed : std::runtime_error {
  ProgramFailed(std::string status, Response partial);
  std::string status;
  Response partial;
};

/// "complete" when every stage of a finished run ended on one of its stop conditions and
/// every unloading branch reached its target; otherwise what did not ("stage 1 'load'
/// ended on its max duration (1 s) before its stop condition 'eps_zz <= -0.1'; ...").
std::string completion_status(const Response &response, const LoadingProgram &program);

class ProgramRunner {
public:
  ProgramRunner(const LoadingProgram &program, LoadingEngine &engine);
  /// Called after every recorded sample (progress bars, checkpoints, logs).
  void on_progress(std::function<void(const RunProgress &)> callback) { progress_ = std::move(callback); }
  void set_checkpoints(CheckpointPolicy policy) { checkpoints_ = std::move(policy); }
  Response run();
  /// Continues a run from a checkpoint: the engine must already hold the checkpoint's
  /// current state (engine.restore(*engine.read_state(...))); `peak` is the stored peak
  /// state, if the checkpoint has one, and `kept` the bracket's states (one per
  /// state.kept_samples entry). The result equals the uninterrupted run's.
  Response resume(RunnerState state, std::unique_ptr<EngineState> peak,
                  std::vector<std::unique_ptr<EngineState>> kept = {});

private:
  /// Runs stage `index` from its start, or from `from` (a checkpoint in it).
  void run_stage(int index, const RunnerState *from = nullptr, std::unique_ptr<EngineState> peak = nullptr);
  void maybe_checkpoint(const RunnerState &state, const EngineState *peak);
  /// Where an unloading branch leaves the main path: the main-path sample `from_sample`,
  /// in the engine state `from_state` (null: the engine's current state); or, when
  /// `leave_at` is later than that sample, the main path run on from it to `leave_at`.
  struct BranchStart {
    std::string trigger;
    std::size_t from_sample = 0;
    const EngineState *from_state = nullptr;
    double leave_at = -1.0;
  };
  void run_branch(int stage_index, const StageControl &main, const BranchStart &start);
  /// Keeps the state of main-path sample `sample` while the stage's bracket is open.
  void keep_limit_state(int stage_index, std::size_t sample);
  /// Bisects the stage's bracket with extra branches (after its main path).
  void locate_elastic_limit(int stage_index, const StageControl &main);
  void record(ResponseSample s, int stage, int branch, double fraction);
  /// Runs `body`; an engine's exception becomes ProgramFailed with the response so far.
  template <class Body> void failing_safely(Body &&body);

  const LoadingProgram &program_;
  LoadingEngine &engine_;
  Response response_;
  std::vector<std::size_t> stage_start_sample_; ///< main-path sample each stage left from
  std::function<void(const RunProgress &)> progress_;
  CheckpointPolicy checkpoints_;
  double last_checkpoint_ = 0.0; ///< steady-clock seconds
  int stage_ = 0, branch_ = 0;  ///< where the run is (for ProgramFailed)
  /// Main-path states of the stage under way, by sample, kept to locate its elastic limit.
  std::map<std::size_t, std::unique_ptr<EngineState>> limit_states_;
};

} // namespace geocomp
