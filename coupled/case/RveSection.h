#pragma once
// Declaring and parsing the `dem rve` section (RveCaseParameters.h) with deal.II's
// ParameterHandler, and the RVE material of a case: library geocomp_coupled_case.
#include "common/case/SectionReader.h"
#include "coupled/RvePreparation.h"
#include "coupled/RveMaterial.h"
#include "coupled/case/RveCaseParameters.h"
#include "dem/case/DemParameters.h"

#include <memory>

namespace geocomp::sections {

void declare_dem_rve(dealii::ParameterHandler &prm);
coupled::RveCaseParameters parse_dem_rve(dealii::ParameterHandler &prm, const Reader &r);

} // namespace geocomp::sections

namespace geocomp::coupled {

/// The case's grains (specimen, contact, dem sections); throws std::invalid_argument for a
/// size distribution the periodic placement does not draw (lognormal-mass).
RveGrains rve_grains(const dem::DemCase &c);
/// The preparation settings of the section, to the specimen's isotropic pressure.
RvePreparationSettings rve_settings(const dem::DemCase &c, const RveCaseParameters &p);
/// Prepares the RVE (seconds for ~100 spheres) and returns the material of every point.
std::shared_ptr<const RveMaterial> make_rve_material(const dem::DemCase &c, const RveCaseParameters &p);

} // namespace geocomp::coupled
