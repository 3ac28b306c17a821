#pragma once
// A string as a JSON string literal: quoted, escaped, and always valid UTF-8.
//
// Why a file of its own: both JSON writers, the report's metrics.json (Report.cpp) and the
// calibration's fit.json (calibrate/FitReport.cpp), quote names, labels and notes alike,
// and some of them come from outside (a case file's name on the command line, a title or
// a note read back from a results file written by another build). JSON must be UTF-8:
// nlohmann-json writes the literal and puts U+FFFD in place of any invalid byte, so no
// input can make metrics.json unreadable.
#include <string>

namespace geocomp::compare {

std::string json_string(const std::string &s);

} // namespace geocomp::compare
