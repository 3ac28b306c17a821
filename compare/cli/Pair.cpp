#include "Pair.h"
#include "DemSnapshots.h"
#include "Engines.h"
#include "Log.h"
#include "Mpi.h"
#include "PairCalibration.h"
#include "PairMaps.h"
#include "PairSections.h"
#include "TargetCases.h"

#include "compare/LocalizationOnsets.h"
#include "compare/Metrics.h"
#include "compare/calibrate/FitReport.h"
#include "common/ResponseFile.h"

#include <algorithm>
#include <optional>

namespace geocomp::cli {

namespace fs = std::filesystem;

std::string engine_label(const std::string &engine)
{
  if (engine == "dem")
    return "DEM";
  if (engine == "continuum")
    return "FE cube";
  if (engine == "liggghts")
    return "LIGGGHTS";
  if (engine == "fem-dem")
    return "FEM x DEM";
  return "material point";
}

namespace {

/// The DEM's band over this pair's DEM run and the results files of calibration/scatter (the
/// same program on other specimens), each continuum engine judged against it (compare/Scatter.h).
compare::ScatterTable specimen_scatter(const CaseDescription &c, const std::vector<compare::NamedMetrics> &metrics,
                                       const compare::MetricOptions &options)
{
  std::vector<std::string> names, engines;
  std::vector<compare::MetricSet> specimens, judged;
  for (const auto &m : metrics) {
    const bool dem = m.label == engine_label("dem");
    (dem ? specimens : judged).push_back(m.metrics);
    (dem ? names : engines).push_back(dem ? results_file("dem") : m.label);
  }
  for (const std::string &file : c.calibration.scatter) {
    specimens.push_back(compare::compute_metrics(with_interval_means(read_response(file)), options));
    names.push_back(file);
  }
  return compare::scatter_table(names, specimens, engines, judged);
}

/// The cross-engine section when the pair has both DEM engines (compare/CrossEngine.h): their
/// curves from the instantaneous wall stresses, beside the DEM against calibration/scatter's
/// specimens. A curve that cannot be compared becomes a note.
void add_cross_engine(compare::ReportInput &in, const CaseDescription &c, const EngineRuns &runs)
{
  const auto find = [&runs](const std::string &e) {
    return std::find_if(runs.begin(), runs.end(), [&e](const auto &r) { return r.first == e; });
  };
  const auto dem = find("dem"), liggghts = find("liggghts");
  if (dem == runs.end() || liggghts == runs.end())
    return;
  const auto curve = [&in](const std::string &name, const Response &r) {
    return compare::NamedCurve{name, compare::extract_curve(r, in.kind, in.stage, in.axial)};
  };
  try {
    std::vector<compare::NamedCurve> specimens;
    for (const std::string &file : c.calibration.scatter)
      specimens.push_back(curve(file, read_response(file)));
    in.cross_engine = compare::cross_engine_table(curve(engine_label("dem"), dem->second),
                                                  curve(engine_label("liggghts"), liggghts->second), specimens);
  } catch (const std::exception &e) {
    in.notes.push_back(std::string("Cross-engine section not computed: ") + e.what());
  }
}
} // namespace

compare::ReportInput report_input(const CaseDescription &c, const EngineRuns &runs, const fs::path &dir)
{
  compare::ReportInput in;
  in.title = c.title.empty() ? "geocomp: " + c.file : c.title;
  in.case_name = c.file;
  in.kind = compare::curve_kind_for(c.program);
  in.axial = compare::axial_axis_for(c.program);
  compare::MetricOptions options;
  options.kind = in.kind;
  options.axial = in.axial;
  for (const auto &[engine, instantaneous] : runs) {
    // Metrics, curves and tables read each engine's interval-mean stresses (the DEM's; the
    // continuum's samples are its states), and the report says so.
    const Response response = with_interval_means(instantaneous);
    if (instantaneous.interval_means)
      in.notes.push_back(engine_label(engine) + ": stresses in the curves, tables and metrics are means over each "
                         "sampling interval (the instantaneous samples are /response/stress of " +
                         results_file(engine) + ").");
    in.responses.push_back({engine_label(engine), response});
    try {
      in.metrics.push_back({engine_label(engine), compare::compute_metrics(response, options)});
    } catch (const std::exception &e) {
      in.notes.push_back(engine_label(engine) + ": metrics not computed: " + e.what());
    }
  }
  if (!c.calibration.scatter.empty())
    in.scatter = specimen_scatter(c, in.metrics, options);
  add_cross_engine(in, c, runs);
  // Rudnicki-Rice: the theory along the material-point path against each engine's onset: the
  // DEM's from its particles, each FE engine's acoustic tensor and its mid-plane's strain field.
  const std::vector<PairSection> sections = recorded_sections(c, dir);
  const Response *point = nullptr;
  std::vector<compare::OnsetEstimate> onsets;
  for (const auto &[engine, response] : runs) {
    if (engine == "material-point")
      point = &response;
    if (engine == "dem")
      add_dem_fields(in, dir, onsets);
    else if (engine != "liggghts") { // LIGGGHTS writes no fields; its stresses have no tangent to test
      // An engine whose material has no plastic tangent (fem-dem's cells: a contact-stiffness
      // tangent, positive semi-definite) records no indicator; only its strain field tells.
      if (response.extra_index("localization_q") >= 0)
        onsets.push_back(compare::acoustic_tensor_onset(response, engine_label(engine) + " (acoustic tensor)", in.kind,
                                                        -1, in.axial));
      add_strain_field_onset(in, sections, engine, onsets);
    }
  }
  // One panel per recorded section at the named states (B, peak, D, DEM onset).
  add_state_maps(in, sections, onsets);
  in.calibrated_parameters = calibration::read_parameter_table(dir / "calibration");
  // A calibrated pair's continuum engines ran the calibrated section (PairCalibration.h).
  const std::optional<CaseDescription> calibrated = calibrated_case_in(c, dir);
  if (pair_calibrates(c)) {
    const bool with_dem = std::find(c.engines.begin(), c.engines.end(), "dem") != c.engines.end();
    const std::size_t n = c.calibration.targets.size();
    const std::string to = std::string(with_dem ? "this pair's DEM run" : "") + (with_dem && n > 0 ? " and " : "") +
                           (n > 0 ? std::to_string(n) + " results file(s) of calibration/targets" : "");
    in.notes.push_back(calibrated ? "Material point and FE cube: the continuum section calibrated to " + to + ", " +
                                      (dir / "calibration" / c.calibration.output_file).string() +
                                      " (fit report: calibration/index.html)."
                                  : "The case asks for a continuum calibrated to " + to +
                                      ", but no calibrated section is in " + (dir / "calibration").string() +
                                      ": run `geocomp pair` again.");
  }
  const CaseDescription &continuum_case = calibrated ? *calibrated : c;
  if (calibrated) {
    const auto dem = std::find_if(runs.begin(), runs.end(), [](const auto &r) { return r.first == "dem"; });
    in.calibration_curves = calibration_curves(c, *calibrated, dem == runs.end() ? nullptr : &dem->second, dir);
    in.ladder = calibration_ladder(dir);
  }
  if (point && c.continuum.model == "nikolaevsky") {
    in.notes.push_back("No Rudnicki-Rice prediction: it is computed from the Mohr-Coulomb parameters, and the "
                       "case's model is nikolaevsky.");
  } else if (point) {
    const continuum::MaterialParameters m = continuum_material(continuum_case);
    const compare::KappaMeasure measure = c.continuum.model == "drucker-prager" ? compare::KappaMeasure::shear_strain
                                                                                : compare::KappaMeasure::mohr_coulomb;
    in.verdict = compare::rudnicki_rice_verdict(
      compare::rudnicki_rice_onset(*point, m.mohr_coulomb, m.drucker_prager_matching, measure, in.kind, -1, in.axial),
      onsets);
  } else {
    in.notes.push_back("No Rudnicki-Rice prediction: add 'material-point' to the case's engines.");
  }
  in.notes.push_back("Measures, the same for every engine: logarithmic strain ln(L/L0) of the box edges and "
                     "Cauchy stress (force over current area); continuum kinematics: " + c.continuum.kinematics + ". " +
                     (in.kind == compare::CurveKind::AxialLateral
                        ? "Axial curve on axis " + in.axial.value_or(compare::AxialAxis{}).describe() + "."
                        : std::string("tau_max and gamma_max are sign-free.")));
  return in;
}

fs::path write_report_and_say(const compare::ReportInput &in, const fs::path &dir, MPI_Comm comm)
{
  if (rank_in(comm) != 0)
    return {};
  const compare::ReportOutcome out = compare::write_report(in, dir / "report");
  log::info("report: " + (out.dir / "index.html").string());
  if (!out.plots_made)
    log::info("  (" + out.message + ")");
  return out.dir / "index.html";
}

PairOutcome pair_case(const CaseDescription &c, const fs::path &dir, const RunSettings &settings)
{
  PairOutcome outcome;
  std::vector<std::string> engines;
  for (const auto &engine : engine_names())
    if (std::find(c.engines.begin(), c.engines.end(), engine) != c.engines.end())
      engines.push_back(engine);
  // A missing LIGGGHTS is bad input found before any engine runs (unless its results stand).
  if (std::find(engines.begin(), engines.end(), "liggghts") != engines.end() &&
      !(settings.reuse && results_up_to_date("liggghts", c, dir)))
    require_liggghts(c, settings.liggghts);
  if (!pair_calibrates(c)) {
    for (const auto &engine : engines)
      outcome.runs.emplace_back(engine, run_engine(engine, c, dir, settings));
  } else {
    // The DEM first; the continuum engines run the section calibrated to it.
    std::optional<Response> dem;
    if (std::find(engines.begin(), engines.end(), "dem") != engines.end())
      dem = run_engine("dem", c, dir, settings);
    run_target_cases(c, settings);
    const CaseDescription calibrated = calibrate_for_pair(c, dem ? &*dem : nullptr, dir, settings.comm);
    for (const auto &engine : engines)
      outcome.runs.emplace_back(engine, engine == "dem"        ? *dem
                                        : engine == "liggghts" ? run_engine(engine, c, dir, settings) // a DEM
                                                               : run_engine(engine, calibrated, dir, settings));
  }
  outcome.comparison = report_input(c, outcome.runs, dir);
  outcome.report = write_report_and_say(outcome.comparison, dir, settings.comm);
  for (const auto &[engine, response] : outcome.runs)
    outcome.complete = outcome.complete && completion_status(response, c.program) == "complete";
  return outcome;
}

} // namespace geocomp::cli
