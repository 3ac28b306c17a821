#pragma once
// The whole case file, as plain data: the shared head, the DEM's sections (a base: the
// DEM's functions take the case as dem::DemCase), the continuum's, the calibration, the
// loading program and the output.
//
// Why here: only this layer knows every engine. Each engine declares, parses and writes its
// own sections in its own folder (dem/case, continuum/case, compare/calibrate; the shared
// ones in common/case), and read_case() puts them into one ParameterHandler, so that one
// file, one `print-parameters` and one set of messages serve them all.
#include "common/case/CaseParameters.h"
#include "compare/calibrate/CalibrationParameters.h"
#include "continuum/case/ContinuumParameters.h"
#include "coupled/case/RveCaseParameters.h"
#include "dem/case/DemParameters.h"

#include <string>

namespace geocomp {

struct CaseDescription : dem::DemCase {
  continuum::ContinuumParameters continuum;
  coupled::RveCaseParameters rve; ///< section `dem rve` (continuum/model = dem rve)
  LoadingProgram program;
  OutputParameters output;
  CalibrationParameters calibration;
};

/// Reads and validates a case file; throws CaseError (never leaves anything behind).
CaseDescription read_case(const std::string &path);
/// The same for a case file's text; `path` names it in messages and picks .prm/.json.
CaseDescription parse_case(const std::string &text, const std::string &path);
/// The value of one entry of a case's text ('contact/particle friction', 'program/stage 1/z'),
/// as written or its default: what a study reads as its abscissa. Throws CaseError naming
/// `path` and `entry` when the text is refused or the entry is not declared.
std::string case_entry_value(const std::string &text, const std::string &path, const std::string &entry);
/// Every parameter with default, pattern and help text, as a .prm with comments.
std::string describe_parameters();
/// Every entry of every section (the program's as parsed), as canonical text
/// (CanonicalText.h): what `/meta/parameters` of each result holds, beside the case text;
/// results are up to date only when it matches (an included file may have changed).
std::string parameters_text(const CaseDescription &c);

} // namespace geocomp
