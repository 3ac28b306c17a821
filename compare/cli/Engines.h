#pragma once
// Builds each engine of a case from its CaseDescription: the one place where the case
// file's plain structs meet the engines' own parameter structs.
#include "common/LoadingEngine.h"
#include "compare/case/CaseDescription.h"
#include "continuum/driver/Materials.h"
#include "continuum/driver/MaterialPointEngine.h"
#include "continuum/fe/CubeEngine.h"
#include "dem/program/DemEngine.h"

#include <mpi.h>

#include <memory>
#include <string>

namespace geocomp::cli {

/// Engines a case may name, in the order `pair` runs them (LIGGGHTS after the DEM, whose
/// prepared specimen it starts from).
const std::vector<std::string> &engine_names();

/// A ready engine for `name` ("material-point", "continuum", "dem"), in the state at the
/// start of the program (consolidated to the case's isotropic pressure). Throws CaseError
/// for inconsistent parameters, all of them from validate_engine() (CaseValidation.h),
/// which it calls first. `output_dir` receives the engine's field output.
std::unique_ptr<LoadingEngine> make_engine(const std::string &name, const CaseDescription &c,
                                           const std::string &output_dir, MPI_Comm communicator = MPI_COMM_WORLD);

/// The DEM engine of a case in its state at the start of the program: the consolidated
/// specimen cached in `dir` (`dem-specimen.bin`, as `geocomp dem` caches it) when its record
/// is the case's, otherwise prepared now and cached there. `geocomp export liggghts` takes
/// its specimen from here, so the export is the specimen `geocomp dem` starts from.
std::unique_ptr<dem::DemEngine> make_dem_engine(const CaseDescription &c, const std::filesystem::path &dir);

/// The continuum material of a case (Mohr-Coulomb tables in radians; throws CaseError).
continuum::MaterialParameters continuum_material(const CaseDescription &c);

/// The engines' own parameters as make_engine() builds them from a case (the validation
/// builds the same ones and checks them, CaseValidation.h).
continuum::MaterialPointParameters material_point_parameters(const CaseDescription &c);
/// The cube's parameters from the continuum section; its VTU fields go to
/// `<output_dir>/<fields_folder>` (continuum-fields, fem-dem-fields) when output/fields is on.
continuum::CubeParameters cube_parameters(const CaseDescription &c, const std::string &output_dir,
                                          const std::string &fields_folder = "continuum-fields");
/// The fem-dem engine's cube: cube_parameters with the Newton of the cells' answer (the
/// tolerance and secant pairs of section `dem rve`, docs/coupled.md).
continuum::CubeParameters fem_dem_cube_parameters(const CaseDescription &c, const std::string &output_dir);

/// File name of an engine's results inside the output folder.
std::string results_file(const std::string &engine);

} // namespace geocomp::cli
