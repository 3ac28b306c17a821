// `geocomp export liggghts <case> --output DIR`: the case's consolidated specimen, walls,
// contact law and loading program as a LIGGGHTS 3.8 run (issue 34; dem/liggghts/).
#pragma once

#include <string>
#include <vector>

namespace geocomp::cli {

/// Files of an exported folder that `geocomp import liggghts` reads: the case's path, and
/// its parameters as parsed (parameters_text), to refuse a case changed since the export.
inline constexpr const char *kExportCaseFile = "geocomp-case";
inline constexpr const char *kExportParametersFile = "geocomp-parameters";

/// The help paragraph of the form, for `geocomp export --help`.
std::string liggghts_export_usage();

/// Runs the form on the arguments after `liggghts`; throws UsageError or CaseError (exit 2).
int export_liggghts(const std::vector<std::string> &args);

} // namespace geocomp::cli
