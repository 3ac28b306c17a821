// The continuum section of a case file as the material the engines take: tables in the
// case's units (Pa, degrees) to MohrCoulombParameters (Pa, radians) and the Drucker-Prager
// matching; for model = nikolaevsky, subsection nikolaevsky to S1's material (a row of
// S1Material's table or the custom values). Shared by the command line and the
// calibration, which varies the section.
#pragma once

#include "continuum/case/ContinuumParameters.h"
#include "continuum/driver/Materials.h"

namespace geocomp::continuum {

/// Throws std::invalid_argument when a value is out of the model's range.
MaterialParameters material_from_case(const ContinuumParameters &p);

} // namespace geocomp::continuum
