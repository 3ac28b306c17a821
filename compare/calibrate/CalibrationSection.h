#pragma once
// Declaring and parsing the `calibration` section (library geocomp_calibration_case).
#include "common/case/SectionReader.h"
#include "compare/calibrate/CalibrationParameters.h"
#include "continuum/case/ContinuumParameters.h"

namespace geocomp::sections {

void declare_calibration(dealii::ParameterHandler &prm);
/// Needs the parsed continuum section: a free table knot must exist in its table.
CalibrationParameters parse_calibration(dealii::ParameterHandler &prm, const Reader &r,
                                        const continuum::ContinuumParameters &continuum);

} // namespace geocomp::sections
