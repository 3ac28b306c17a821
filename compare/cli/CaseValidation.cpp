// See CaseValidation.h: each engine's refusals, before any engine runs.
#include "CaseValidation.h"
#include "PairCalibration.h"
#include "Log.h"

#include "Engines.h"
#include "LiggghtsEngine.h"

#include "coupled/case/RveSection.h"
#include "dem/program/SpecimenPreparation.h"

#include <algorithm>
#include <stdexcept>

namespace geocomp::cli {

void validate_engine(const std::string &name, const CaseDescription &c)
{
  if (name == "fem-dem") { // the cube of the continuum section, the RVE of section 'dem rve'
    try {
      coupled::rve_grains(c);
      continuum::check_cube_parameters(fem_dem_cube_parameters(c, ""));
    } catch (const std::invalid_argument &e) {
      throw CaseError(c.file, "dem rve", e.what());
    }
    return;
  }
  if (name == "material-point" || name == "continuum") {
    continuum_material(c);
    try {
      material_point_parameters(c);
      if (name == "continuum")
        continuum::check_cube_parameters(cube_parameters(c, ""));
    } catch (const std::invalid_argument &e) {
      throw CaseError(c.file, "continuum", e.what());
    }
    return;
  }
  if (name == "dem") {
    dem::check_specimen(c);
    return;
  }
  if (name == "liggghts") {
    dem::check_specimen(c);
    check_liggghts_case(c);
    return;
  }
  throw CaseError(c.file, "engines", "the '" + name + "' engine is not available in this build");
}

void validate_engines(const CaseDescription &c, const std::vector<std::string> &also)
{
  std::vector<std::string> names = c.engines;
  for (const auto &e : also)
    if (std::find(names.begin(), names.end(), e) == names.end())
      names.push_back(e);
  for (const auto &e : names)
    validate_engine(e, c);
  validate_pair_calibration(c);
}

CaseDescription read_valid_case(const std::string &path, const std::vector<std::string> &also)
{
  CaseDescription c = read_case(path);
  validate_engines(c, also);
  std::string engines;
  for (const std::string &e : c.engines)
    engines += " " + e;
  log::debug("case " + c.file + " read and validated: engines" + engines + ", " +
             std::to_string(c.program.stages.size()) + " stage(s), output folder " + c.output.directory);
  return c;
}

} // namespace geocomp::cli
