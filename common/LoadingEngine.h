#pragma once
// The contract between the loading program and an engine.
//
// ProgramRunner owns the program logic (stages, stop conditions, unloading branches,
// sampling); an engine only knows how to follow a StageControl in time, how to measure
// itself, and how to save and restore its whole state (for branches and checkpoints).
// DEM (walls + servo), the deal.II cube and the material-point driver implement it.
#include "common/LoadingProgram.h"
#include "common/Response.h"

#include <iosfwd>
#include <memory>

namespace geocomp {

/// Opaque saved state of an engine (particles + contacts, or FE history...).
struct EngineState {
  virtual ~EngineState() = default;
};

class LoadingEngine {
public:
  virtual ~LoadingEngine() = default;
  virtual std::string name() const = 0;
  /// Columns this engine appends to every sample.
  virtual std::vector<ExtraColumn> extra_columns() const = 0;
  /// Start following a control from the current state and time.
  virtual void begin_control(const StageControl &control) = 0;
  /// Advance the engine's time to t_end following the current control.
  virtual void advance_to(double t_end) = 0;
  /// Current time, strain, stress and extras (stage/branch are filled by the runner).
  virtual ResponseSample measure() = 0;
  /// True when measure() fills ResponseSample::stress_mean with the mean stress since the
  /// previous measure(); otherwise the runner copies the instantaneous stress there.
  virtual bool gives_interval_means() const { return false; }
  virtual std::unique_ptr<EngineState> save() const = 0;
  virtual void restore(const EngineState &state) = 0;
  /// The runner is about to play unloading branch `id` (> 0), or is back on the main path
  /// (0); it says so before it restores the state the branch starts from or returns to.
  /// Engines that write field output keep each branch in a series of its own, so the main
  /// series runs forward in time.
  virtual void set_branch(int id) { (void)id; }

  /// Program checkpoints (ProgramCheckpoint.h): engines whose saved states can go through a
  /// byte stream say so and implement the two functions below; the others are not
  /// checkpointed (their runs are short).
  virtual bool can_write_states() const { return false; }
  virtual void write_state(std::ostream &out, const EngineState &state) const;
  virtual std::unique_ptr<EngineState> read_state(std::istream &in) const;
};

/// True when a step of dt from `time` is an advance's last: it would reach t_end to within
/// 1e-9 of the nominal step. The steps' sum misses t_end by round-off (a few ulps of t_end,
/// more than 1e-12 dt at late times); a tighter test leaves a vanishing extra step, which
/// an elastic-predictor engine reports as elastic while the material flows.
inline bool is_last_step(double time, double dt, double t_end, double dt_nominal)
{
  return time + dt >= t_end - 1e-9 * (dt_nominal < 0.0 ? -dt_nominal : dt_nominal);
}

} // namespace geocomp
