#pragma once
// `pair` on many independent cases spread over the MPI ranks: what `geocomp sweep` and
// `geocomp study` run. Case k runs on rank k mod N, each case's engines on that one rank
// (MPI_COMM_SELF; the DEM threads with OpenMP within it), into its own output/directory,
// locked while it runs (OutputFolderLock); up-to-date results are reused unless `reuse` is
// false (--force).
#include "compare/case/CaseDescription.h"

#include <string>
#include <vector>

namespace geocomp::cli {

/// Runs `pair` on each case (MPI started); returns on every rank each case's exit code
/// (0 ok, 1 run failure, 2 refused), logging one line per case prefixed with `command`.
std::vector<int> pair_over_ranks(const std::vector<CaseDescription> &cases, bool reuse, const std::string &command);

} // namespace geocomp::cli
