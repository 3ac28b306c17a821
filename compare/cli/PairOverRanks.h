#pragma once
// `pair` on many independent cases spread over the MPI ranks: what `geocomp sweep`,
// `geocomp study` and Python's geocomp.study run. Case k runs on rank k mod N, each case's
// engines on that one rank (MPI_COMM_SELF; the DEM threads with OpenMP within it), into its
// own output/directory, locked while it runs (OutputFolderLock); up-to-date results are
// reused unless the settings say otherwise (--force).
#include "EngineRun.h"

#include "compare/case/CaseDescription.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace geocomp::cli {

/// Runs `body`, mapping failures onto exit codes (Commands.h): a CaseError is logged and
/// gives bad input (2), any other exception is logged and gives a run failure (1); a
/// UsageError passes through.
int guarded(const std::function<int()> &body);

/// The progress of case `k` (its index in the list) and one of its engines.
using CaseProgress = std::function<void(std::size_t k, const std::string &engine, const RunProgress &)>;

/// Runs `pair` on each case (MPI started) with `settings` (its communicator replaced by
/// MPI_COMM_SELF; its progress by `progress`, when set, told which case runs); returns on
/// every rank each case's exit code (0 ok, 1 run failure, 2 refused), logging one line per
/// case prefixed with `command`.
std::vector<int> pair_over_ranks(const std::vector<CaseDescription> &cases, const RunSettings &settings,
                                 const std::string &command, const CaseProgress &progress = {});

} // namespace geocomp::cli
