// A case file for the contact-entry tests: the DEM engine, k_n = 1e5 N/m given directly,
// the `contact` entries given, and a one-stage program.
#pragma once

#include "compare/case/CaseDescription.h"

#include <string>

namespace geocomp::dem::test {

inline CaseDescription contact_case(const std::string &contact, const std::string &file)
{
  return parse_case("set engines = dem\nsubsection contact\n  set normal stiffness = 1e5\n" + contact +
                      "end\nsubsection program\n  subsection stage 1\n    set z = rate -1\n"
                      "    set stop when = eps_zz <= -0.01\n    set max duration = 1\n  end\nend\n",
                    file);
}

} // namespace geocomp::dem::test
