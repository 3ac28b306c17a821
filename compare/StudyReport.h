#pragma once
// @sect3{The study report: several cases' curves overlaid, their summary against one entry}
//
// Why it exists: S0 reads its friction series (Fig. 4) as a family - strength and secant
// modulus grow with the inter-particle friction, the specimen compacts before the peak and
// dilates sharply after it - and a store variant study the same way against packing
// fraction, restitution or friction. `geocomp study` (compare/case/StudyFile.h) runs the cases;
// this writes, from their Responses alone, one self-contained folder:
//
//   index.html  the summary table (one row per case and engine) and the figures
//   study.json  the same numbers, SI units (Pa, strain as a fraction, degrees), NaN as null
//   report.gp   the gnuplot script (run `gnuplot report.gp` in the folder to redraw)
//   data/*.dat  what it plots (strain in %, stress in MPa)
//   curves.png  per engine: every case's stress-strain curve and its V_r
//   summary.png peak stress, secant modulus, elastic limit, dilatancy angle, V_r at its
//               minimum and at the end, against the study's `against` entry
//
// The summary of one curve is compute_metrics() (compare/Metrics.h, docs/metrics.md) on the
// case's own program's curve, and S0's relative volume change (S0 Fig. 4b; the text calls it
// V_r): V_r = V / V_start - 1 = exp(eps_v) - 1, eps_v = ln(V / V_start) from the start of the
// analysed stage, dilation positive; the axial curve is compression positive. The folder is
// built under a temporary name and renamed into place; without gnuplot the tables and the
// script are still written.
#include "compare/Metrics.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geocomp::compare {

/// One engine's run of a study case: its label ("DEM") and its Response (interval means).
struct StudyRun {
  std::string engine;
  Response response;
};

struct StudyReportCase {
  std::string name;  ///< folder name
  std::string label; ///< legend
  std::string file;  ///< the case file the study wrote
  double x = 0.0;    ///< value of the study's `against` entry
  CurveKind kind = CurveKind::Auto;
  std::optional<AxialAxis> axial;
  std::vector<StudyRun> runs;
  std::string failure; ///< empty when every engine completed its program
};

struct StudyReportInput {
  std::string title, study_file;
  std::string against; ///< the abscissa's entry, e.g. "contact/particle friction"
  std::vector<StudyReportCase> cases;
};

/// What the summary plots show for one case and engine.
struct StudySummary {
  MetricSet metrics;
  double v_r_min = nan;   ///< smallest V_r on the main path (largest compaction)
  double v_r_final = nan; ///< V_r at the last main-path sample
  std::string error;      ///< why the metrics are missing, if they are
};

/// S0 Fig. 4b: V_r = V / V_start - 1 from eps_v = ln(V / V_start).
double relative_volume_change(double eps_v);

/// The summary of one Response on the curve `kind`/`axial` (as the pair report reads it).
StudySummary study_summary(const Response &response, CurveKind kind, const std::optional<AxialAxis> &axial);

/// The summary's numbers under study.json's keys, in its order (SI; NaN where missing):
/// peak_strain, peak_stress_Pa, secant_modulus_Pa, elastic_limit_stress_Pa,
/// dilatancy_angle_deg, V_r_min, V_r_final.
std::vector<std::pair<std::string, double>> study_summary_entries(const StudySummary &s);

/// study.json's text.
std::string study_json(const StudyReportInput &in);

struct StudyReportOutcome {
  std::filesystem::path dir;
  bool plots_made = false;
  std::string message; ///< why plots are missing, if they are
};

/// Writes the report folder `dir` (replacing an existing one).
StudyReportOutcome write_study_report(const StudyReportInput &in, const std::filesystem::path &dir,
                                      const std::string &gnuplot = "gnuplot");

} // namespace geocomp::compare
