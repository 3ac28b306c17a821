// @sect3{What a calibration writes}
//
// Why it exists: the fitted values must flow back into case files and into the
// comparison report, with enough evidence beside them to judge the fit. write_fit_report()
// writes a folder, built under a temporary name beside it and renamed when complete (so
// a failed run never leaves a half report under the final name):
//   <output file>     the calibrated `subsection continuum` (a .prm fragment that case
//                     files pull in with deal.II's `include <path>`)
//   parameters.tsv    name, start, value, standard error (read by the comparison report)
//   fit.json          values, standard errors, correlations, costs, per-target residuals
//                     (rms and max of q, p, eps_v), the FE-cube verification if run, the
//                     model ladder if asked for (compare/ModelLadder.h)
//   index.html        the same as tables, with fit_k.png (target and fitted curves) and
//                     residuals_k.png (residual of each quantity along each curve), gnuplot
#pragma once

#include "compare/ModelLadder.h"
#include "compare/calibrate/Calibration.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace geocomp::calibration {

/// The calibrated section rerun on the deal.II cube for one target's program
/// (`geocomp calibrate --verify`): the largest differences of q along the path, relative
/// to the target's largest q.
struct Verification {
  std::string target;
  double cube_vs_point = 0.0;  ///< max |q_cube - q_material point| / max q_target
  double cube_vs_target = 0.0; ///< max |q_cube - q_target| / max q_target
  double point_vs_target = 0.0; ///< max |q_material point - q_target| / max q_target
  double seconds = 0.0;        ///< of the cube run
};

/// The continuum section of `p` as a .prm fragment.
std::string continuum_fragment(const ContinuumParameters &p, const std::string &comment);
/// The calibrated section as written back: only the entries that hold a free parameter
/// (E, nu, a table with a free knot - whole, its other knots as the case has them), so
/// that a case including it changes nothing the calibration did not fit.
std::string calibrated_fragment(const CalibrationResult &result, const std::string &comment);
/// The fragment's comment in the fit report: the case and the number of target curves.
std::string fragment_comment(const std::string &case_file, std::size_t targets);

void write_fit_report(const std::filesystem::path &dir, const std::string &fragment_name,
                      const CalibrationResult &result, const std::vector<FitTarget> &targets,
                      const std::string &case_file, const std::vector<Verification> &verification = {},
                      const std::vector<compare::LadderRung> &ladder = {});

/// (name, "value +- standard error") rows of <dir>/parameters.tsv; empty if absent.
std::vector<std::pair<std::string, std::string>> read_parameter_table(const std::filesystem::path &dir);

} // namespace geocomp::calibration
