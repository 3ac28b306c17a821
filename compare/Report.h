#pragma once
// The comparison report: a self-contained folder that reads like S0's figure set with the
// continuum beside it.
//
//   index.html      overlay plots, metrics table with differences, Rudnicki-Rice verdict,
//                   calibrated parameters, the definitions used
//   metrics.json    the same numbers, machine-readable
//   *.png           plots made by gnuplot from a generated report.gp (kept, with data/)
//
// Every number in the HTML tables is printed by format_number() from the same double as
// in metrics.json, and each numeric cell names its JSON location (data-path, an RFC 6901
// pointer without the leading slash), so a test can check that they are equal. The folder
// is built under a temporary name beside `dir` and renamed into place when complete.
// Units in the report: MPa, %, degrees; the lateral-pressure curve is compression positive.
#include "compare/CrossEngine.h"
#include "compare/Localization.h"
#include "compare/Metrics.h"
#include "compare/ModelLadder.h"
#include "compare/Scatter.h"
#include "compare/SectionMaps.h"
#include "compare/Verdict.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geocomp::compare {

struct NamedResponse {
  std::string label; ///< "DEM", "continuum", ...
  Response response;
};

struct NamedMetrics {
  std::string label;
  MetricSet metrics;
};

/// A curve of a calibrated pair (docs/calibration.md): one the continuum was calibrated on, or
/// the held-out one it predicts; rms differences of the material point's curve from it, each
/// relative to the curve's scale (q and p: its largest q; eps_v: its range, at least 1e-3).
struct CalibrationCurve {
  std::string curve;
  std::string role; ///< "calibrated on" or "predicted"
  double rms_q = 0.0, rms_p = 0.0, rms_eps_v = 0.0;
};

struct ReportInput {
  std::string title = "geocomp: DEM and continuum compared";
  std::string case_name;
  CurveKind kind = CurveKind::Auto; ///< of the overlays; Auto: the first metric set's kind
  std::optional<AxialAxis> axial;   ///< axis of an axial curve (axial_axis_for); empty: guessed
  int stage = -1;                   ///< analysed stage (-1: last)
  std::vector<NamedResponse> responses;
  std::vector<NamedMetrics> metrics; ///< the first is the reference of the differences
  std::optional<RrVerdict> verdict;
  /// Maps at the named states (B, peak, D, DEM onset), one panel per engine's section
  /// (DEM | FE cube | FEM x DEM) per row (SectionMaps.h);
  /// `state_maps_note` says where the states and the sections come from.
  std::vector<StateMaps> state_maps;
  std::string state_maps_note;
  std::vector<std::pair<std::string, std::string>> calibrated_parameters;
  std::vector<CalibrationCurve> calibration_curves;
  /// The DEM's specimen-to-specimen scatter and each continuum engine's verdict (Scatter.h).
  std::optional<ScatterTable> scatter;
  /// The model ladder of a calibrated pair (ModelLadder.h); empty: none asked for.
  std::vector<LadderRung> ladder;
  /// Two DEM engines on the same specimen (geocomp's and LIGGGHTS), CrossEngine.h.
  std::optional<CrossEngineTable> cross_engine;
  std::vector<std::string> notes;
};

struct ReportOptions {
  std::string gnuplot = "gnuplot"; ///< program name or path; empty: no plots
};

struct ReportOutcome {
  std::filesystem::path dir;
  std::vector<std::string> plots; ///< PNG file names written
  bool plots_made = false;
  std::string message;            ///< why plots are missing, if they are
};

/// Writes the report folder `dir` atomically (replacing an existing one).
ReportOutcome write_report(const ReportInput &input, const std::filesystem::path &dir,
                           const ReportOptions &options = {});

/// The one number format of the report: "%.6g", "null" for NaN or infinity.
std::string format_number(double value);
/// a - b to the digits format_number shows a and b with (six significant digits of the larger):
/// a difference below the last shown digit is round-off and comes out as 0 (not -8.5e-14).
double shown_difference(double a, double b);

/// metrics.json text (also used by write_report).
std::string metrics_json(const ReportInput &input);

} // namespace geocomp::compare
