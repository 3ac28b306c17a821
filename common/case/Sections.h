#pragma once
// Internal to the case reader: one declare/parse pair per case-file section.
#include "common/case/CaseParameters.h"

#include <deal.II/base/parameter_handler.h>

namespace geocomp::sections {

/// Context for messages: the file being read.
struct Reader {
  std::string file;
  [[noreturn]] void fail(const std::string &parameter, const std::string &message) const
  {
    throw CaseError(file, parameter, message);
  }
};

void declare_specimen(dealii::ParameterHandler &prm);
SpecimenParameters parse_specimen(dealii::ParameterHandler &prm, const Reader &r);
void declare_contact(dealii::ParameterHandler &prm);
ContactParameters parse_contact(dealii::ParameterHandler &prm, const Reader &r);
/// Rolling, bonds, S3 friction: further entries of `contact` (ContactPartsSection.cpp).
void declare_contact_parts(dealii::ParameterHandler &prm);
void parse_contact_parts(dealii::ParameterHandler &prm, const Reader &r, ContactParameters &p);
void declare_clumps(dealii::ParameterHandler &prm);
ClumpParameters parse_clumps(dealii::ParameterHandler &prm, const Reader &r);
void declare_dem(dealii::ParameterHandler &prm);
DemParameters parse_dem(dealii::ParameterHandler &prm, const Reader &r);
void declare_continuum(dealii::ParameterHandler &prm);
ContinuumParameters parse_continuum(dealii::ParameterHandler &prm, const Reader &r);
/// Subsection `nikolaevsky` of `continuum` (NikolaevskySection.cpp); called from inside it.
void declare_nikolaevsky(dealii::ParameterHandler &prm);
NikolaevskyParameters parse_nikolaevsky(dealii::ParameterHandler &prm, const Reader &r);
void declare_program(dealii::ParameterHandler &prm, unsigned int stages);
LoadingProgram parse_program(dealii::ParameterHandler &prm, unsigned int stages, const Reader &r);
void declare_output(dealii::ParameterHandler &prm);
OutputParameters parse_output(dealii::ParameterHandler &prm, const Reader &r);

void declare_calibration(dealii::ParameterHandler &prm);
/// Needs the parsed continuum section: a free table knot must exist in its table.
CalibrationParameters parse_calibration(dealii::ParameterHandler &prm, const Reader &r,
                                        const ContinuumParameters &continuum);

/// "0:1e5, 0.02:1.2e5" -> table; fails naming `parameter`.
HardeningTable parse_table(const std::string &text, const std::string &parameter, const Reader &r);

} // namespace geocomp::sections
