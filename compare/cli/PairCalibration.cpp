#include "PairCalibration.h"
#include "Engines.h"
#include "TargetCases.h"
#include "Log.h"
#include "Mpi.h"

#include "common/case/JsonCase.h"
#include "common/case/ParseParameters.h"
#include "compare/calibrate/FitReport.h"
#include "compare/calibrate/Ladder.h"
#include "compare/calibrate/StartingValues.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;
using namespace geocomp::calibration;

namespace {
fs::path fragment_path(const CaseDescription &c, const fs::path &dir)
{
  return dir / "calibration" / c.calibration.output_file;
}
} // namespace

bool pair_calibrates(const CaseDescription &c) { return c.calibration.pair_continuum == "calibrated"; }

namespace {
/// The target `f` of c's calibration/targets (a results file, or the DEM run of a case file), weight `w`.
FitTarget load_case_target(const CaseDescription &c, const std::string &f, double w)
{
  const std::string file = target_results_file(f);
  const std::string of = file == f ? "" : " (the DEM run of target case '" + f + "')";
  if (!fs::exists(file))
    throw CaseError(c.file, "calibration/targets",
                    "'" + file + "'" + of + " does not exist (run the target case first, e.g. `geocomp dem <case>`)");
  if (!fs::is_regular_file(file))
    throw CaseError(c.file, "calibration/targets",
                    "'" + file + "'" + of + " is not a regular file: expected a results file (.h5)");
  try {
    return load_target(file, w);
  } catch (const CalibrationError &e) {
    throw CaseError(c.file, "calibration/targets", e.what());
  }
}
} // namespace

std::vector<FitTarget> case_targets(const CaseDescription &c)
{
  std::vector<FitTarget> targets;
  for (std::size_t k = 0; k < c.calibration.targets.size(); ++k)
    targets.push_back(load_case_target(c, c.calibration.targets[k],
                                       c.calibration.weights.empty() ? 1.0 : c.calibration.weights[k]));
  return targets;
}

void validate_pair_calibration(const CaseDescription &c)
{
  for (const std::string &f : c.calibration.scatter)
    if (!fs::is_regular_file(f))
      throw CaseError(c.file, "calibration/scatter",
                      "'" + f + "' is not a results file (expected the .h5 of the pair's program run on another "
                      "specimen)");
  if (!pair_calibrates(c))
    return;
  if (std::find(c.engines.begin(), c.engines.end(), "dem") == c.engines.end() && c.calibration.targets.empty())
    throw CaseError(c.file, "calibration/pair continuum",
                    "calibrated: the continuum is fitted to the pair's DEM run and to calibration/targets, expected "
                    "'dem' among the engines or at least one target");
  if (c.calibration.pair_dem == "held out" &&
      (std::find(c.engines.begin(), c.engines.end(), "dem") == c.engines.end() || c.calibration.targets.empty()))
    throw CaseError(c.file, "calibration/pair dem",
                    "held out: the continuum is fitted to calibration/targets and predicts the pair's DEM run, "
                    "expected 'dem' among the engines and at least one target");
  if (c.continuum.model == "nikolaevsky")
    throw CaseError(c.file, "calibration/pair continuum",
                    "calibrated: the calibration fits the Mohr-Coulomb parameters (E, nu, cohesion, friction, "
                    "dilatancy, also behind drucker-prager), expected continuum/model mohr-coulomb or "
                    "drucker-prager, got nikolaevsky");
  validate_target_cases(c);
  for (const std::string &f : c.calibration.targets) // a target case's results are made by the run
    if (!names_target_case(f))
      load_case_target(c, f, 1.0);
}

std::string calibration_summary(const CalibrationResult &r)
{
  std::ostringstream out;
  out << "calibrate: " << r.iterations << " iterations, " << r.seconds << " s, cost " << r.initial_cost << " -> "
      << r.final_cost << "\n";
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    out << "  " << r.parameters[i].name << " = " << r.value[i] << " +- " << r.standard_error[i] << "  (start "
        << r.start[i] << ")\n";
  for (const FixedParameter &f : r.fixed)
    out << "  " << f.name << " = " << f.value << "  (fixed: the case's value)\n";
  return out.str();
}

CaseDescription with_calibrated_continuum(const CaseDescription &c, const std::string &fragment)
{
  const bool json = c.file.size() >= 5 && c.file.substr(c.file.size() - 5) == ".json";
  const std::string text = (json ? json_to_prm(c.text, c.file) : c.text) + "\n" + fragment;
  // Parsed as a .prm beside the case (its includes resolve as the case's do), then named as the case.
  CaseDescription calibrated = parse_case(text, json ? c.file.substr(0, c.file.size() - 5) + ".prm" : c.file);
  calibrated.file = c.file;
  return calibrated;
}

CaseDescription calibrate_for_pair(const CaseDescription &c, const Response *dem, const fs::path &dir, MPI_Comm comm)
{
  std::vector<FitTarget> targets;
  if (dem && c.calibration.pair_dem == "fitted")
    targets.push_back(make_target((dir / results_file("dem")).string(), *dem, c.program,
                                  -c.specimen.isotropic_pressure, c.continuum.point_substeps, 1.0));
  for (FitTarget &t : case_targets(c))
    targets.push_back(std::move(t));
  try {
    const StartingValues start = starting_values(c.continuum, targets, c.calibration);
    CalibrationResult r = calibrate(start.parameters, targets, c.calibration);
    r.notes.insert(r.notes.begin(), start.notes.begin(), start.notes.end());
    const std::string fragment = calibrated_fragment(r, fragment_comment(c.file, targets.size())); // as written
    std::vector<compare::LadderRung> ladder;
    if (!c.calibration.ladder.empty() && rank_in(comm) == 0) {
      // With the DEM run held out, each rung predicts it as the calibration does.
      std::optional<FitTarget> held_out;
      if (dem && c.calibration.pair_dem == "held out")
        held_out = make_target((dir / results_file("dem")).string(), *dem, c.program, -c.specimen.isotropic_pressure,
                               c.continuum.point_substeps, 1.0);
      ladder = run_ladder({&c.continuum, &targets, &c.calibration, held_out ? &*held_out : nullptr});
    }
    if (rank_in(comm) == 0) {
      log::info(calibration_summary(r) + "calibrated section: " + fragment_path(c, dir).string() +
                (ladder.empty() ? "" : "\n" + ladder_summary(ladder)));
      for (const auto &w : r.warnings)
        log::warning(c.file + ": calibration/free parameters: " + w);
      write_fit_report(dir / "calibration", c.calibration.output_file, r, targets, c.file, {}, ladder);
    }
    return with_calibrated_continuum(c, fragment);
  } catch (const CalibrationError &e) {
    throw CaseError(c.file, e.parameter, e.what());
  }
}

std::vector<compare::CalibrationCurve> calibration_curves(const CaseDescription &c, const CaseDescription &calibrated,
                                                         const Response *dem, const fs::path &dir)
{
  std::vector<compare::CalibrationCurve> out;
  auto row = [](std::string curve, std::string role, const std::vector<ResidualSummary> &rows) {
    compare::CalibrationCurve r{std::move(curve), std::move(role)};
    for (const ResidualSummary &q : rows)
      (q.quantity == "q" ? r.rms_q : q.quantity == "p" ? r.rms_p : r.rms_eps_v) = q.rms;
    return r;
  };
  const fs::path fit = dir / "calibration" / "fit.json";
  if (fs::is_regular_file(fit)) {
    const nlohmann::json j = nlohmann::json::parse(read_parameter_file(fit.string(), "fit report (fit.json)"));
    for (const auto &t : j.at("targets")) {
      std::vector<ResidualSummary> rows;
      for (const auto &[quantity, r] : t.at("residuals").items()) {
        ResidualSummary summary;
        summary.quantity = quantity;
        summary.rms = r.at("rms").get<double>();
        rows.push_back(summary);
      }
      out.push_back(row(t.at("file").get<std::string>(), "calibrated on", rows));
    }
  }
  if (dem && c.calibration.pair_dem == "held out") {
    const FitTarget target = make_target((dir / results_file("dem")).string(), *dem, c.program,
                                         -c.specimen.isotropic_pressure, c.continuum.point_substeps, 1.0);
    const Response predicted = simulate(target, continuum_material(calibrated));
    out.push_back(row(target.name, "predicted", summarize_residuals(target, predicted, fitted_quantities(c.calibration))));
  }
  return out;
}

std::vector<compare::LadderRung> calibration_ladder(const fs::path &dir)
{
  const fs::path fit = dir / "calibration" / "fit.json";
  if (!fs::is_regular_file(fit))
    return {};
  return compare::ladder_from_fit_json(read_parameter_file(fit.string(), "fit report (fit.json)"));
}

std::optional<CaseDescription> calibrated_case_in(const CaseDescription &c, const fs::path &dir)
{
  const fs::path file = fragment_path(c, dir);
  if (!pair_calibrates(c) || !fs::is_regular_file(file))
    return std::nullopt;
  return with_calibrated_continuum(c, read_parameter_file(file.string(), "calibrated continuum section (.prm)"));
}

} // namespace geocomp::cli
