// @sect3{Program checkpoints: a loading program stopped on its main path and resumed}
//
// Why it exists: S0's reference run (100 000 spheres, five unloading branches) takes many
// minutes; a killed or interrupted run must go on from where it was, with the same
// result bit for bit as if it had never stopped (issue 5). An engine checkpoint alone is
// not enough: the program's own state matters too (which stage, the samples and branches
// recorded so far, which branch triggers have fired, the running peak of tau_max and the
// engine state saved at that peak for the "peak" branch, and the main-path states the
// open elastic-limit bracket keeps for its bisection branches). ProgramRunner hands a
// `RunnerState` to its checkpoint sink at main-path samples; read back, it resumes the
// stage loop exactly there.
//
// The byte layout (common/BinaryState.h: raw doubles, sizes checked) is for restarting
// the same build on the same machine, not an exchange format.
#pragma once

#include "common/Response.h"

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace geocomp {

/// Where a program run stands at a main-path sample (after it was recorded and its
/// branch triggers were handled).
struct RunnerState
{
  Response response;                         ///< everything recorded so far
  std::vector<std::uint64_t> stage_start_sample; ///< main-path sample each stage left from
  int stage = 0;                             ///< the stage under way
  double time = 0.0;                         ///< program time of the last sample
  double tau_peak = 0.0;                     ///< running maximum of tau_max in this stage
  std::uint64_t peak_sample = 0;             ///< its sample index
  std::vector<std::uint8_t> fired;           ///< per branch trigger of the stage
  bool has_peak_state = false;               ///< an engine state at the peak is stored with it
  /// Main-path samples whose engine states the open elastic-limit bracket keeps (stored with
  /// it, in this order): a run resumed inside the bracket bisects it as the uninterrupted run.
  std::vector<std::uint64_t> kept_samples;
};

void write_runner_state(std::ostream &out, const RunnerState &s);
/// Throws binary::StateError for a truncated or foreign stream.
RunnerState read_runner_state(std::istream &in);

class LoadingEngine;
struct EngineState;

/// One checkpoint file of a program run: the run's key (what it belongs to: the case text
/// and the build), the runner state, the engine's current state, the engine state at the
/// peak (if any), the bracket's kept states (RunnerState::kept_samples) and a caller's
/// counter (e.g. particle snapshots written so far).
struct ProgramCheckpoint
{
  RunnerState runner;
  std::unique_ptr<EngineState> current, peak;
  std::vector<std::unique_ptr<EngineState>> kept;
  std::uint64_t counter = 0;
};

/// Writes under a temporary name, renamed when complete (a kill leaves the old file whole).
void write_program_checkpoint(const std::filesystem::path &file, const std::string &key, const RunnerState &runner,
                              const LoadingEngine &engine, const EngineState &current, const EngineState *peak,
                              const std::vector<const EngineState *> &kept, std::uint64_t counter);
/// The checkpoint in `file` if it exists and was written with `key`; nothing otherwise
/// (absent, another case or build, unreadable: the run then starts from the beginning).
std::optional<ProgramCheckpoint> read_program_checkpoint(const std::filesystem::path &file, const std::string &key,
                                                         const LoadingEngine &engine);

} // namespace geocomp
