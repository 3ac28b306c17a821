#pragma once
// Calibration targets named by their case: `calibration/targets` may list case files
// (.prm, .json) beside results files (.h5). A case file stands for its DEM run, the
// results file <its output directory>/dem.h5, which `pair` (calibrated) and `calibrate`
// make first - reused when up to date, as every engine run is - so that one command runs
// the whole workflow: the DEM programs the continuum is calibrated on, the fit, the pair.
//
// Only the target case's `dem` engine runs, with its own program, specimen and output
// folder (locked while it runs); its own engines, calibration and targets are not looked
// at (so targets naming each other cannot recurse). A target case must write somewhere
// else than the case that names it: the two would share one folder's lock and results.
#include "EngineRun.h"

#include "compare/case/CaseDescription.h"

#include <string>

namespace geocomp::cli {

/// Whether a calibration/targets item names a case file (.prm or .json) rather than results.
bool names_target_case(const std::string &target);

/// The results file a calibration/targets item stands for: the item itself, or for a case
/// file its DEM run's <output directory>/dem.h5 (the case is read; CaseError if it is bad).
std::string target_results_file(const std::string &target);

/// Reads and checks every case file among c's targets for its DEM engine, before anything
/// runs: CaseError naming the target's own file and entry, or naming `c`'s
/// calibration/targets when a target case writes into `c`'s output folder.
void validate_target_cases(const CaseDescription &c);

/// Runs (or reuses) the DEM of every case file among c's targets, each in its own output
/// folder under its lock; logs one line each.
void run_target_cases(const CaseDescription &c, const RunSettings &settings);

} // namespace geocomp::cli
