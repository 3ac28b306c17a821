#pragma once
// One validation path: a case is checked for every engine it names before any of them
// runs, by the same functions the engines call when they are built.
//
// Why it exists: reading a case (read_case) checks each entry against its declaration,
// but some refusals belong to an engine - the DEM refuses a text specimen with no
// pressure to consolidate to, a store prepared with another friction; the cube refuses a
// polynomial degree it has no element for. When those ran only as the engine was built,
// `pair` ran the material point, wrote material-point.h5, then met the DEM's refusal
// (exit 2 with a file behind), and `check` passed cases that `dem` refused. Here each
// engine's checks are one function, validate_engine(); make_engine() calls it first, and
// `check`, `pair`, `dem`, `continuum`, `material-point`, `calibrate`, `pack` and `sweep`
// call it for every engine of a case before anything is written.
#include "compare/case/CaseDescription.h"

#include <string>
#include <vector>

namespace geocomp::cli {

/// Every refusal make_engine(name, c) can raise, raised without building anything (and
/// without MPI): the engine's material and parameters as it builds them, checked by its
/// own checks; for the DEM dem::check_specimen(). Throws CaseError naming the parameter.
void validate_engine(const std::string &name, const CaseDescription &c);

/// validate_engine() for each engine the case names and for each of `also` (the engines
/// a command runs whether the case names them or not).
void validate_engines(const CaseDescription &c, const std::vector<std::string> &also = {});

/// read_case(path), then validate_engines(): the case as every command that takes one
/// reads it. Throws CaseError.
CaseDescription read_valid_case(const std::string &path, const std::vector<std::string> &also = {});

} // namespace geocomp::cli
