#include "MidPlane.h"
#include "Mpi.h"

#include "common/AtomicFile.h"
#include "common/Hdf5.h"

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
const char *const continuum_plane_file = "continuum-midplane.h5";
const char *const plane_columns[5] = {"x", "z", "u_x", "u_z", "kappa"};
} // namespace

// Collective: every rank of the cube takes part in mid_plane(); rank 0 writes.
void write_mid_plane(const continuum::CubeEngine &cube, const fs::path &dir, MPI_Comm comm)
{
  const continuum::MidPlaneSample plane = cube.mid_plane();
  if (rank_in(comm) != 0)
    return;
  fs::create_directories(dir);
  write_atomically(dir / continuum_plane_file, [&plane](const fs::path &tmp) {
    const h5::Handle f = h5::create_file(tmp);
    const std::vector<double> *columns[5] = {&plane.x, &plane.z, &plane.ux, &plane.uz, &plane.kappa};
    for (int k = 0; k < 5; ++k)
      h5::write(f.id(), plane_columns[k], *columns[k], {hsize_t(columns[k]->size())}, k == 4 ? "1" : "m");
  });
}

/// FE maps beside the DEM ones: u_x and the equivalent plastic strain kappa on y = L0/2.
/// The cube's bottom faces are rollers, so its displacements are measured from the x = 0
/// face; the DEM's platens move symmetrically about the box centre. The FE u_x is shifted
/// to the box centre, which moves by half the edge change, eps_xx L0 / 2 at the end of the
/// main path, so both maps share one reference.
void add_continuum_plane(compare::ReportInput &in, const fs::path &dir, const Response &response, double side)
{
  const fs::path file = dir / continuum_plane_file;
  if (!fs::exists(file))
    return;
  const h5::Handle f = h5::open_file(file);
  std::vector<std::vector<double>> c;
  for (const char *name : plane_columns)
    c.push_back(h5::read_doubles(f.id(), name));
  const std::vector<const ResponseSample *> main = response.path(0);
  const double centre = main.empty() ? 0.0 : 0.5 * main.back()->strain(0, 0) * side;
  for (double &u : c[2])
    u -= centre;
  compare::DisplacementMap ux{"FE cube, y = L0/2, end of the main path, from the box centre", "u_x", c[0], c[1],
                              c[2]};
  compare::DisplacementMap kappa{"FE cube, y = L0/2, end of the main path", "kappa", c[0], c[1], c[4], 100.0, "%"};
  in.maps.push_back(ux);
  in.maps.push_back(kappa);
}

} // namespace geocomp::cli
