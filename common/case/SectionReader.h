#pragma once
// What every case-file section's parse function needs: the file being read, for messages.
//
// Each engine declares and parses its own sections (dem/case, continuum/case,
// compare/calibrate, and the shared ones here: program, output); they all report bad input
// the same way, as one CaseError naming the file, the entry and what was expected.
#include "common/case/CaseParameters.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace geocomp::sections {

/// Context for messages: the file being read.
struct Reader {
  std::string file;
  [[noreturn]] void fail(const std::string &parameter, const std::string &message) const
  {
    throw CaseError(file, parameter, message);
  }
};

/// "0:1e5, 0.02:1.2e5" -> (kappa, value) points, kappa from 0 strictly increasing; fails
/// naming `parameter` (the piecewise-linear tables of the continuum and the calibration).
std::vector<std::pair<double, double>> parse_points(const std::string &text, const std::string &parameter,
                                                    const Reader &r);

/// Reads every field a struct's visit list names from the ParameterHandler's current
/// subsection, each by its type - so a parse function is `visit(p, ReadEntries{...})` and
/// the checks between entries, and an entry is written once: declared, and named in the
/// visit list beside its field.
struct ReadEntries {
  dealii::ParameterHandler &prm;
  const Reader &reader;
  std::string section; ///< for messages: `section/entry`

  void operator()(const char *entry, std::string &v) const { v = prm.get(entry); }
  void operator()(const char *entry, double &v) const { v = prm.get_double(entry); }
  void operator()(const char *entry, bool &v) const { v = prm.get_bool(entry); }
  void operator()(const char *entry, unsigned int &v) const { v = static_cast<unsigned int>(prm.get_integer(entry)); }
  void operator()(const char *entry, unsigned long long &v) const
  {
    v = static_cast<unsigned long long>(prm.get_integer(entry));
  }
  void operator()(const char *entry, std::vector<std::string> &v) const;
  void operator()(const char *entry, std::vector<double> &v) const;
  void operator()(const char *entry, std::vector<std::pair<double, double>> &v) const
  {
    v = parse_points(prm.get(entry), section + "/" + entry, reader);
  }
};

/// Enters `section`, reads the fields `visit` names into `p`, leaves.
template <class P>
void read_section(dealii::ParameterHandler &prm, const Reader &r, const std::string &section, P &p)
{
  prm.enter_subsection(section);
  P::visit(p, ReadEntries{prm, r, section});
  prm.leave_subsection();
}

/// The sections every case shares (ProgramSection.cpp, OutputSection.cpp, CaseHead.cpp).
void declare_head(dealii::ParameterHandler &prm);
void declare_program(dealii::ParameterHandler &prm, unsigned int stages);
LoadingProgram parse_program(dealii::ParameterHandler &prm, unsigned int stages, const Reader &r);
/// The program as canonical text (CanonicalText.h): every stage's entries as parsed.
std::string program_text(const LoadingProgram &p);
void declare_output(dealii::ParameterHandler &prm);
OutputParameters parse_output(dealii::ParameterHandler &prm, const Reader &r);

} // namespace geocomp::sections
