#pragma once
// A string as a JSON string literal: quoted, with '"', '\' and control characters escaped.
//
// Why a file of its own: both JSON writers, the report's metrics.json (Report.cpp) and the
// calibration's fit.json (calibrate/FitReport.cpp), quote names, labels and notes alike.
#include <string>

namespace geocomp::compare {

std::string json_string(const std::string &s);

} // namespace geocomp::compare
