#pragma once
// `pair`: every engine a case names run on its one loading program (EngineRun.h), then
// the comparison - metrics of every Response, the Rudnicki-Rice verdict against each
// engine's onsets (the FE engines' acoustic tensor and mid-plane strain field), the engines'
// mid-section maps side by side at the named states - and the report.
// The same code serves `geocomp pair`, each item of `geocomp sweep`, `report`/`compare`
// on existing results and Python's geocomp.pair.
#include "EngineRun.h"

#include "compare/Report.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace geocomp::cli {

/// Engine name and its Response, in the order `pair` runs them (engine_names()).
using EngineRuns = std::vector<std::pair<std::string, Response>>;

/// An engine's name in reports and tables: "DEM", "FE cube", "material point".
std::string engine_label(const std::string &engine);

/// The comparison of `runs` of case `c` whose files are in `dir` (snapshots, mid-plane,
/// calibration table): what the report and metrics.json show.
compare::ReportInput report_input(const CaseDescription &c, const EngineRuns &runs, const std::filesystem::path &dir);

/// Writes <dir>/report (rank 0 of `comm`; the others write nothing) and says where;
/// returns the path of its index.html (empty on the other ranks).
std::filesystem::path write_report_and_say(const compare::ReportInput &in, const std::filesystem::path &dir,
                                           MPI_Comm comm);

/// What `pair` made: the engines' Responses, the comparison and the report's index.
struct PairOutcome {
  EngineRuns runs;
  compare::ReportInput comparison;
  std::filesystem::path report; ///< <dir>/report/index.html on rank 0, empty elsewhere
  bool complete = true;         ///< every engine completed its program (else a warning was logged)
};

/// Runs every engine of `c` into `dir`, compares and writes the report.
PairOutcome pair_case(const CaseDescription &c, const std::filesystem::path &dir, const RunSettings &settings);

} // namespace geocomp::cli
