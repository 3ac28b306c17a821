#pragma once
// An FE engine's mid-plane y = L_y/2 at every main-path sample of the last stage, for both
// engines on the deal.II mesh (the cube or the box of `continuum/box edges`): `continuum`
// (Mohr-Coulomb) into continuum-midplane.h5 and `fem-dem` (an RVE at every point) into
// fem-dem-midplane.h5. Recorded during the run (cube.mid_plane(): points of the cells cut by
// the plane, their displacements and the cell-mean equivalent plastic strain kappa), written
// beside the engine's results, read back for the report's maps at the named states
// (compare/SectionMaps.h) beside the DEM's mid-section, and for the strain-field onset
// (compare/SectionLocalization.h). Every sample is kept because the named states (B, the
// peak, D) are known only after the run; the plane holds 9 points per cut cell (n_x n_z
// cells), a few kB a sample.
#include "compare/SectionMaps.h"
#include "common/ProgramRunner.h"
#include "continuum/fe/CubeEngine.h"

#include <mpi.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geocomp::cli {

/// The mid-plane file of an FE engine: "continuum-midplane.h5", "fem-dem-midplane.h5".
std::string midplane_file(const std::string &engine);

/// Called at every sample (collective on the cube's communicator: mid_plane() gathers to rank
/// 0, which keeps the states); write() puts them in <dir>/<midplane_file(engine)>.
class CubeSectionRecorder {
public:
  CubeSectionRecorder(const continuum::CubeEngine &cube, std::string engine, MPI_Comm comm)
    : cube_(cube), engine_(std::move(engine)), comm_(comm)
  {
  }
  void operator()(const RunProgress &p);
  /// Rank 0 writes, atomically; the other ranks do nothing.
  void write(const std::filesystem::path &dir) const;

private:
  const continuum::CubeEngine &cube_;
  std::string engine_;
  MPI_Comm comm_;
  std::vector<double> times_;
  std::vector<continuum::MidPlaneSample> planes_;
};

/// The mid-plane `engine` recorded in `dir` on `mesh` as a section series labelled
/// `label`: displacements since its first state; the box centre (L_x/2, L_z/2) from the
/// mesh's edges; the point spacings s_x = L_x / (3 n_x), s_z = L_z / (3 n_z), a tile half of
/// each, the local-strain radius 1.5 max(s_x, s_z) (the neighbours along both axes and the
/// diagonal ones of a square grid). Empty when the file is missing.
std::optional<compare::SectionSeries> read_cube_section(const std::filesystem::path &dir, const std::string &engine,
                                                        const std::string &label,
                                                        const continuum::CubeParameters &mesh);

} // namespace geocomp::cli
