#pragma once
// Text as HTML character data or an attribute value: &, <, > and " escaped. One home for
// the three HTML writers (the comparison report, the shear-box report, the fit report),
// whose names, titles and notes can come from outside (case files, results files).
#include <string>

namespace geocomp::compare {

std::string html_text(const std::string &s);

} // namespace geocomp::compare
