#pragma once
// Declaring and parsing the DEM's case-file sections (`specimen`, `contact` with its
// optional parts, `dem`) with deal.II's ParameterHandler. A library of its own
// (geocomp_dem_case), so that the DEM core and program build without deal.II.
#include "common/case/SectionReader.h"
#include "dem/case/DemParameters.h"

namespace geocomp::sections {

void declare_specimen(dealii::ParameterHandler &prm);
dem::SpecimenParameters parse_specimen(dealii::ParameterHandler &prm, const Reader &r);
void declare_contact(dealii::ParameterHandler &prm);
dem::ContactParameters parse_contact(dealii::ParameterHandler &prm, const Reader &r);
/// Rolling, bonds, S3 friction: further entries of `contact` (ContactPartsSection.cpp).
void declare_contact_parts(dealii::ParameterHandler &prm);
/// The parts' checks (S3 friction and bonds need the linear normal model); parse_contact calls it.
void check_contact_parts(const dem::ContactParameters &p, const Reader &r);
void declare_dem(dealii::ParameterHandler &prm);
dem::DemParameters parse_dem(dealii::ParameterHandler &prm, const Reader &r);

/// All three sections, in case-file order.
void declare_dem_sections(dealii::ParameterHandler &prm);
/// Parses them into `c`'s DEM part (the head is the caller's).
void parse_dem_sections(dealii::ParameterHandler &prm, const Reader &r, dem::DemCase &c);

} // namespace geocomp::sections
