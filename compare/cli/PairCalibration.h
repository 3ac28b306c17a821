#pragma once
// The calibrated pair (calibration/pair continuum = calibrated): the continuum fitted to the
// pair's own DEM run before the material point and the FE cube run, so that the comparison
// says where Mohr-Coulomb with its best parameters departs from the specimen, not where a
// hand-set section does.
//
// The fit is `geocomp calibrate`'s (compare/calibrate, docs/calibration.md: closed-form
// start, Levenberg-Marquardt over the material point): its targets are this pair's DEM
// Response, replayed with the case's program and isotropic pressure, then the results
// files calibration/targets names (other programs, other pressures; a case without the dem
// engine is fitted to these alone). The fit report and
// the calibrated section go to <dir>/calibration/. The continuum engines run the case
// with that section appended to its text (later entries override earlier ones), which is
// the text their results store in /meta/case_text - so a results file says itself which
// continuum made it, and `geocomp calibrate` can replay it. With calibration/pair dem = held
// out the DEM run is left out of the fit: the continuum predicts the pair's program from the
// targets alone (a hold-out test), and the report says which curves were calibrated on and
// which was predicted.
#include "compare/ModelLadder.h"
#include "compare/Report.h"
#include "compare/calibrate/Calibration.h"
#include "compare/case/CaseDescription.h"

#include <mpi.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace geocomp::cli {

/// Whether `pair` calibrates the case's continuum first.
bool pair_calibrates(const CaseDescription &c);

/// The results files calibration/targets names, loaded with their weights (CaseError naming
/// calibration/targets for a missing, non-regular or unreadable file).
std::vector<calibration::FitTarget> case_targets(const CaseDescription &c);

/// The checks of a calibrated pair before anything runs (CaseError): the dem engine among the
/// engines or at least one target, a Mohr-Coulomb or Drucker-Prager continuum, readable targets.
void validate_pair_calibration(const CaseDescription &c);

/// `geocomp calibrate`'s summary lines: iterations, cost, each parameter with its standard
/// error and start, the fixed ones.
std::string calibration_summary(const calibration::CalibrationResult &r);

/// The case with `fragment` (a calibrated `subsection continuum`) appended to its text and
/// parsed again: its continuum section is the calibrated one, every other entry the case's.
CaseDescription with_calibrated_continuum(const CaseDescription &c, const std::string &fragment);

/// Fits the case's continuum to `dem` (this pair's DEM Response; none for a case without the
/// dem engine) and its targets, writes the
/// fit report and the calibrated section into <dir>/calibration (rank 0 of `comm`) and returns
/// the case the continuum engines run. CaseError for a parameter the curves cannot identify.
CaseDescription calibrate_for_pair(const CaseDescription &c, const Response *dem, const std::filesystem::path &dir,
                                   MPI_Comm comm);

/// The report's curves of a calibrated pair: those of <dir>/calibration/fit.json "calibrated on",
/// and with calibration/pair dem = held out the DEM run `dem` "predicted" by the material point
/// with the `calibrated` case's section (its program's main path).
std::vector<compare::CalibrationCurve> calibration_curves(const CaseDescription &c, const CaseDescription &calibrated,
                                                         const Response *dem, const std::filesystem::path &dir);

/// The model ladder of <dir>/calibration/fit.json (calibration/ladder; empty without one).
std::vector<compare::LadderRung> calibration_ladder(const std::filesystem::path &dir);

/// The calibrated case of an earlier calibrated pair in `dir` (its section read back from
/// <dir>/calibration), none when the case is not calibrated or the section is missing.
std::optional<CaseDescription> calibrated_case_in(const CaseDescription &c, const std::filesystem::path &dir);

} // namespace geocomp::cli
