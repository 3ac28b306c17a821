// @sect3{What a calibration writes}
//
// Why it exists: the fitted values must flow back into case files and into the
// comparison report. write_fit_report() writes a folder (built under a temporary name and
// renamed when complete):
//   <output file>     the calibrated `subsection continuum` (a .prm fragment that case
//                     files pull in with deal.II's `include <path>`)
//   parameters.tsv    name, start, value, standard error (read by the comparison report)
//   fit.json          values, standard errors, correlations, costs, per-target rms
//   index.html + fit_k.png  target and fitted curves (gnuplot), residual levels, tables
#pragma once

#include "compare/calibrate/Calibration.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace geocomp::calibration {

/// The continuum section of `p` as a .prm fragment.
std::string continuum_fragment(const ContinuumParameters &p, const std::string &comment);

void write_fit_report(const std::filesystem::path &dir, const std::string &fragment_name,
                      const CalibrationResult &result, const std::vector<FitTarget> &targets,
                      const std::string &case_file);

/// (name, "value +- standard error") rows of <dir>/parameters.tsv; empty if absent.
std::vector<std::pair<std::string, std::string>> read_parameter_table(const std::filesystem::path &dir);

} // namespace geocomp::calibration
