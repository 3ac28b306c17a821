#pragma once
// Builds each engine of a case from its CaseDescription: the one place where the case
// file's plain structs meet the engines' own parameter structs.
#include "common/LoadingEngine.h"
#include "common/case/CaseParameters.h"
#include "continuum/driver/Materials.h"

#include <mpi.h>

#include <memory>
#include <string>

namespace geocomp::cli {

/// Engines a case may name, in the order `pair` runs them.
const std::vector<std::string> &engine_names();

/// A ready engine for `name` ("material-point", "continuum", "dem"), in the state at the
/// start of the program (consolidated to the case's isotropic pressure). Throws CaseError
/// for inconsistent parameters. `output_dir` receives the engine's field output.
std::unique_ptr<LoadingEngine> make_engine(const std::string &name, const CaseDescription &c,
                                           const std::string &output_dir, MPI_Comm communicator = MPI_COMM_WORLD);

/// The continuum material of a case (Mohr-Coulomb tables in radians; throws CaseError).
continuum::MaterialParameters continuum_material(const CaseDescription &c);

/// File name of an engine's results inside the output folder.
std::string results_file(const std::string &engine);

} // namespace geocomp::cli
