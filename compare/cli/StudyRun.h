#pragma once
// A study run as one job: what `geocomp study` does after reading its arguments, and what
// Python's geocomp.study calls - one code path. The study's cases (compare/case/StudyFile.h)
// are checked for their engines, written as case files, run through `pair` over the MPI
// ranks as `sweep` runs them (PairOverRanks.h), and rank 0 reads every case's results and
// writes <output>/report (compare/StudyReport.h).
#include "EngineRun.h"
#include "PairOverRanks.h"

#include "compare/StudyReport.h"
#include "compare/case/StudyFile.h"

#include <string>
#include <vector>

namespace geocomp::cli {

/// read_study(), then every case checked for its engines (CaseError naming the study file
/// and its parameter, with the case and the engine's message).
Study read_valid_study(const std::string &path);

/// What a study run made.
struct StudyOutcome {
  std::vector<int> codes;           ///< each case's exit code (Commands.h), on every rank
  compare::StudyReportInput report; ///< every case's results as the report read them (rank 0)
  compare::StudyReportOutcome written; ///< the report folder (rank 0)
  bool complete() const;            ///< every case ran its program to the end
};

/// Runs study `s` (MPI started here if it is not): takes the output folder's lock, writes the
/// case files (rank 0), runs `pair` on every case with `settings` (PairOverRanks.h; `progress`
/// told the case's index), writes the report (rank 0). Throws CaseError when the folder is
/// locked by another run; a case that fails is in `codes` and the report.
StudyOutcome run_study(const Study &s, const RunSettings &settings, const CaseProgress &progress = {});

} // namespace geocomp::cli
