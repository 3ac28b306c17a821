#pragma once
// The FE cube's mid-plane y = L0/2 at every main-path sample of the last stage: recorded
// during the run (cube.mid_plane(): points of the cells cut by the plane, their displacements
// and the cell-mean equivalent plastic strain kappa), written beside the continuum's results,
// read back into the report's maps at the named states (compare/SectionMaps.h) beside the DEM's
// mid-section. Every sample is kept because the named states (B, the peak, D) are known only
// after the run; the plane holds 9 points per cut cell (cells^2 of them), a few kB a sample.
#include "compare/SectionMaps.h"
#include "common/ProgramRunner.h"
#include "continuum/fe/CubeEngine.h"

#include <mpi.h>

#include <filesystem>
#include <optional>
#include <vector>

namespace geocomp::cli {

/// Called at every sample (collective on the cube's communicator: mid_plane() gathers to rank
/// 0, which keeps the states); write() puts them in <dir>/continuum-midplane.h5.
class CubeSectionRecorder {
public:
  CubeSectionRecorder(const continuum::CubeEngine &cube, MPI_Comm comm) : cube_(cube), comm_(comm) {}
  void operator()(const RunProgress &p);
  /// Rank 0 writes, atomically; the other ranks do nothing.
  void write(const std::filesystem::path &dir) const;

private:
  const continuum::CubeEngine &cube_;
  MPI_Comm comm_;
  std::vector<double> times_;
  std::vector<continuum::MidPlaneSample> planes_;
};

/// The recorded mid-plane of <dir>/continuum-midplane.h5 as a section series (displacements
/// since its first state; box centre (L0/2, L0/2); local-strain radius 1.5 point spacings, a
/// tile half a spacing, spacing L0 / (3 cells)); empty when the file is missing.
std::optional<compare::SectionSeries> read_cube_section(const std::filesystem::path &dir, double side,
                                                        unsigned cells_per_side);

} // namespace geocomp::cli
