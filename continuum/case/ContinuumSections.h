#pragma once
// Declaring and parsing the continuum's case-file section (`continuum` and its subsection
// `nikolaevsky`) with deal.II's ParameterHandler: library geocomp_continuum_case.
#include "common/case/SectionReader.h"
#include "continuum/case/ContinuumParameters.h"

namespace geocomp::sections {

void declare_continuum(dealii::ParameterHandler &prm);
continuum::ContinuumParameters parse_continuum(dealii::ParameterHandler &prm, const Reader &r);
/// Subsection `nikolaevsky` of `continuum` (NikolaevskySection.cpp); called from inside it.
void declare_nikolaevsky(dealii::ParameterHandler &prm);
continuum::NikolaevskyParameters parse_nikolaevsky(dealii::ParameterHandler &prm, const Reader &r);

/// "0:1e5, 0.02:1.2e5" -> table; fails naming `parameter`.
continuum::HardeningTable parse_table(const std::string &text, const std::string &parameter, const Reader &r);

} // namespace geocomp::sections
