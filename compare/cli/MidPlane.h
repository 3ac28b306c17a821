#pragma once
// The FE cube's mid-plane y = L0/2 at the end of the main path: written beside the
// continuum's results by the run, read back into the report's maps (u_x from the box
// centre and the equivalent plastic strain kappa), beside the DEM's mid-section.
#include "compare/Report.h"
#include "common/Response.h"
#include "continuum/fe/CubeEngine.h"

#include <mpi.h>

#include <filesystem>

namespace geocomp::cli {

/// Writes the cube's mid-plane to <dir>/continuum-midplane.h5 (collective on `comm`; rank 0
/// writes, atomically).
void write_mid_plane(const continuum::CubeEngine &cube, const std::filesystem::path &dir, MPI_Comm comm);

/// Adds the FE maps of <dir>/continuum-midplane.h5 to the report (nothing when the file is
/// missing); `response` is the cube's, `side` its edge L0.
void add_continuum_plane(compare::ReportInput &in, const std::filesystem::path &dir, const Response &response,
                         double side);

} // namespace geocomp::cli
