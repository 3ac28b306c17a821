#include "Engines.h"
#include "Log.h"
#include "Progress.h"
#include "CaseValidation.h"

#include "continuum/driver/CaseMaterial.h"
#include "continuum/driver/MaterialPointEngine.h"
#include "continuum/fe/CubeEngine.h"
#include "coupled/RveMaterialFactory.h"
#include "coupled/case/RveSection.h"
#include "common/AtomicFile.h"
#include "common/Version.h"
#include "dem/case/SpecimenRecord.h"
#include "dem/program/DemEngine.h"
#include "dem/program/SpecimenPreparation.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace geocomp::cli {

namespace fs = std::filesystem;

continuum::MaterialParameters continuum_material(const CaseDescription &c)
{
  try {
    return continuum::material_from_case(c.continuum);
  } catch (const std::invalid_argument &e) {
    throw CaseError(c.file, "continuum", e.what());
  }
}

namespace {
/// Cube edge of the specimen: given, or from N, eta and R (S0: L0^3 eta = N 4/3 pi R^3).
double box_size(const SpecimenParameters &s)
{
  if (s.box_size > 0.0)
    return s.box_size;
  return std::cbrt(s.particles * 4.0 / 3.0 * M_PI * std::pow(s.radius, 3) / s.packing_fraction);
}
} // namespace

namespace {
std::string read_text(const fs::path &file)
{
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

/// The case's consolidated specimen in its engine: from `<dir>/dem-specimen.bin` when its
/// record (`dem-specimen.key`: the build, the seed and every DEM entry the specimen depends
/// on, dem/case/SpecimenRecord.h) is the case's, otherwise prepared now
/// (dem::prepare_specimen) and cached there with its record. The contact law is part of the
/// record, so the cached engine's law is always the case's.
std::unique_ptr<dem::DemEngine> make_dem_engine(const CaseDescription &c, const fs::path &dir)
{
  dem::DemEngineParameters p = dem::DemEngineParameters::from_case(c.dem);
  p.check_interrupts = false; // SIGINT/SIGTERM stop the program at its next sample (program checkpoint)
  const fs::path cache = dir / "dem-specimen.bin", key_file = dir / "dem-specimen.key";
  const std::string key = dem::specimen_record(c, GEOCOMP_GIT_HASH);
  if (fs::exists(cache) && fs::exists(key_file) && read_text(key_file) == key) {
    try {
      auto e = dem::DemEngine::from_checkpoint(cache, p);
      e->set_num_threads(int(c.dem.threads)); // not in the record (same bits for any count)
      log::info("dem: prepared specimen reused: " + cache.string());
      return e;
    } catch (const std::exception &) {
      // Unreadable cache: prepare again.
    }
  }
  std::ostringstream what;
  what << "dem: preparing the specimen (" << c.specimen.particles << " spheres, sigma_0 = "
       << c.specimen.isotropic_pressure << " Pa)";
  log::info(what.str());
  PhasePrinter phases("dem");
  dem::PreparedSpecimen s = dem::prepare_specimen(c, {}, std::ref(phases));
  phases.finish();
  log::info("dem: specimen: " + s.record.describe());
  auto e = std::make_unique<dem::DemEngine>(std::move(s.system), p);
  fs::create_directories(dir);
  e->write_checkpoint(cache);
  write_atomically(key_file, [&key](const fs::path &tmp) { std::ofstream(tmp) << key; });
  return e;
}

const std::vector<std::string> &engine_names()
{
  static const std::vector<std::string> names = {"material-point", "continuum", "fem-dem", "dem", "liggghts"};
  return names;
}

std::string results_file(const std::string &engine) { return engine + ".h5"; }

continuum::MaterialPointParameters material_point_parameters(const CaseDescription &c)
{
  continuum::MaterialPointParameters p;
  p.initial_stress = -c.specimen.isotropic_pressure; // tension positive
  p.substeps_per_advance = c.continuum.point_substeps;
  p.kinematics = continuum::parse_kinematics(c.continuum.kinematics);
  return p;
}

continuum::CubeParameters cube_parameters(const CaseDescription &c, const std::string &output_dir,
                                          const std::string &fields_folder)
{
  continuum::CubeParameters p;
  p.side = box_size(c.specimen);
  p.cells_per_side = c.continuum.cells_per_edge;
  p.threads = c.continuum.threads;
  p.verbose = log::verbosity() == log::Verbosity::verbose; // -v: the Newton log of the FE engines too
  for (std::size_t a = 0; a < c.continuum.box_edges.size() && a < 3; ++a)
    p.box_edges[a] = c.continuum.box_edges[a];
  for (std::size_t a = 0; a < c.continuum.box_cells.size() && a < 3; ++a)
    p.box_cells[a] = static_cast<unsigned>(c.continuum.box_cells[a]);
  p.degree = c.continuum.degree;
  for (std::size_t a = 0; a < c.continuum.quadrature_points.size() && a < 3; ++a)
    p.quadrature_points[a] = static_cast<unsigned>(c.continuum.quadrature_points[a]);
  p.initial_stress = -c.specimen.isotropic_pressure; // tension positive
  p.imperfection_radius = c.continuum.imperfection_radius;
  p.imperfection_cohesion_factor = c.continuum.imperfection_factor;
  for (int a = 0; a < 3; ++a)
    p.imperfection_centre[a] = c.continuum.imperfection_centre[a] * p.edges()[a];
  p.regularization = c.continuum.regularization;
  p.volumetric_integration = c.continuum.volumetric_integration;
  p.kinematics = continuum::parse_kinematics(c.continuum.kinematics);
  p.linear_solver = c.continuum.linear_solver;
  p.preconditioner = c.continuum.preconditioner;
  p.near_null_space = c.continuum.near_null_space;
  p.newton_tolerance = c.continuum.newton_tolerance;
  p.steps_per_advance = c.continuum.load_steps_per_sample;
  p.band_reference_width = c.continuum.reference_element_size;
  if (c.output.fields)
    p.output_directory = output_dir + "/" + fields_folder;
  return p;
}

// The fem-dem engine's Newton (docs/coupled.md, "Newton with the cells"): the cells' answer
// has a floor of about 2e-3 of the load past the peak (500-sphere cells: their grains'
// fluctuation), so the tolerance is `dem rve`'s and a step that stalls below twice it is
// accepted (counted in relaxed_steps); BFGS pairs on the contact-stiffness tangent, which
// plateau for a few iterations before they drop (a step is cut back after 5 iterations
// without halving |R|, not 3); two halvings of the line search (a quarter step is as far as
// the cells' answer resolves a direction), after which no descent ends the step.
continuum::CubeParameters fem_dem_cube_parameters(const CaseDescription &c, const std::string &output_dir)
{
  continuum::CubeParameters p = cube_parameters(c, output_dir, "fem-dem-fields");
  p.newton_tolerance = c.rve.newton_tolerance;
  p.newton_stagnation_factor = 2.0;
  p.secant_pairs = c.rve.secant_pairs;
  p.stall_iterations = 5;
  p.line_search_steps = 2;
  return p;
}

std::unique_ptr<LoadingEngine> make_engine(const std::string &name, const CaseDescription &c,
                                           const std::string &output_dir, MPI_Comm communicator)
{
  validate_engine(name, c);
  log::debug(name + ": setting up the engine of " + c.file);
  if (name == "material-point")
    return std::make_unique<continuum::MaterialPointEngine>(continuum_material(c), material_point_parameters(c));
  if (name == "fem-dem") { // FEM x DEM: the continuum section's cube, an RVE per point (docs/coupled.md)
    log::info("fem-dem: preparing the RVE of every quadrature point (" + std::to_string(c.rve.particles) +
              " spheres)");
    auto rves = std::make_shared<coupled::RveMaterialFactory>(coupled::make_rve_material(c, c.rve));
    return std::make_unique<continuum::CubeEngine>(fem_dem_cube_parameters(c, output_dir), std::move(rves),
                                                   communicator);
  }
  if (name == "continuum")
    return std::make_unique<continuum::CubeEngine>(cube_parameters(c, output_dir, "continuum-fields"),
                                                   continuum_material(c), communicator);
  if (name == "dem")
    return make_dem_engine(c, output_dir);
  if (name == "liggghts")
    throw std::logic_error("the liggghts engine runs outside this process: run_engine() plays it (LiggghtsEngine.h)");
  throw CaseError(c.file, "engines", "the '" + name + "' engine is not available in this build");
}

} // namespace geocomp::cli
