#pragma once
// One engine of a case played through the case's loading program into
// <dir>/<engine>.h5, the way `geocomp <engine>`, `pair`, `sweep` and Python's
// geocomp.pair run it: results made from the same case text and parameters by the same
// build are reused; the DEM writes program checkpoints (periodic, and on SIGINT/SIGTERM
// under the command line) and resumes from one; it takes particle snapshots along the
// main path; the FE cube writes its mid-plane; a run that fails mid-way still writes what
// it recorded, with /meta/status saying where and why, then throws.
#include "LiggghtsEngine.h"

#include "common/ProgramRunner.h"
#include "common/Response.h"
#include "compare/case/CaseDescription.h"

#include <mpi.h>

#include <filesystem>
#include <functional>
#include <string>

namespace geocomp::cli {

/// How a run goes beside its case (the parts the command line and Python set differently).
struct RunSettings {
  /// The engines' communicator: the world for `continuum`/`pair`, one rank each in a sweep.
  MPI_Comm comm = MPI_COMM_WORLD;
  /// Reuse up-to-date results and resume from a program checkpoint (false: --force).
  bool reuse = true;
  /// Recorded in /meta/command of the results.
  std::string command_line;
  /// SIGINT/SIGTERM write a checkpoint and stop the DEM (the command line); Python keeps
  /// its own Ctrl-C handling, and its runs stop through the progress callback.
  bool signal_checkpoints = true;
  /// Called on rank 0 at every sample instead of the terminal progress display, when set.
  std::function<void(const std::string &engine, const RunProgress &)> progress;
  /// How the `liggghts` engine starts LIGGGHTS (`--mpi N`: its ranks).
  LiggghtsLaunch liggghts;
};

/// True when <dir>/<engine>.h5 holds a complete run of `c` (the same case text and parameters
/// as parsed) made by this build: run_engine() reuses it.
bool results_up_to_date(const std::string &engine, const CaseDescription &c, const std::filesystem::path &dir);

/// Runs `engine` ("material-point", "continuum", "dem", "liggghts": LiggghtsEngine.h) of `c` and writes
/// <dir>/<engine>.h5 (rank 0); returns its Response. Throws CaseError for a refused case,
/// std::runtime_error for a run that failed mid-way or was stopped by a signal (the
/// message says where its samples or its checkpoint are).
Response run_engine(const std::string &engine, const CaseDescription &c, const std::filesystem::path &dir,
                    const RunSettings &settings);

} // namespace geocomp::cli
