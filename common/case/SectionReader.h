#pragma once
// What every case-file section's parse function needs: the file being read, for messages.
//
// Each engine declares and parses its own sections (dem/case, continuum/case,
// compare/calibrate, and the shared ones here: program, output); they all report bad input
// the same way, as one CaseError naming the file, the entry and what was expected.
#include "common/case/CaseParameters.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace geocomp::sections {

/// Context for messages: the file being read.
struct Reader {
  std::string file;
  [[noreturn]] void fail(const std::string &parameter, const std::string &message) const
  {
    throw CaseError(file, parameter, message);
  }
};

/// The sections every case shares (ProgramSection.cpp, OutputSection.cpp, CaseHead.cpp).
void declare_head(dealii::ParameterHandler &prm);
void declare_program(dealii::ParameterHandler &prm, unsigned int stages);
LoadingProgram parse_program(dealii::ParameterHandler &prm, unsigned int stages, const Reader &r);
/// The program as canonical text (CanonicalText.h): every stage's entries as parsed.
std::string program_text(const LoadingProgram &p);
void declare_output(dealii::ParameterHandler &prm);
OutputParameters parse_output(dealii::ParameterHandler &prm, const Reader &r);

} // namespace geocomp::sections
