#pragma once
// The DEM's mid-section at every main-path sample of the last stage, for the report's maps at
// the named states (compare/SectionMaps.h): B, the peak and D are known only after the run, so
// every sample is kept, but only for the particles in the slab |Y - L0/2| <= 2 mean radii of
// the first sample (chosen once; S0 Fig. 4's section) and only their in-plane centres (x, z).
//
// Size: a slab holds the fraction 4 R / L0 of the particles; at S0's eta = 0.69,
// L0 / R = (4 pi N / (3 eta))^(1/3), so 100 000 spheres give L0 / R = 85 and about 4 700 slab
// particles, 16 bytes each a sample: 75 kB a sample, 75 MB for 1 000 samples, on disk only
// (the report reads it back once). The full snapshots (DemSnapshots.h) stay at dem/snapshots.
// Each record copies the engine's fields once (DemEngine::snapshot, O(particles + contacts)),
// while the sampling interval before it took many time steps, each O(particles + contacts) too.
//
// File <dir>/dem-midplane.bin, little-endian, appended one fixed-size record a sample so that a
// sample costs O(slab) (an HDF5 file here is rewritten whole on every append):
//   header  "GCSECT01", uint64 n, double centre_x, centre_z, mean_radius,
//           int64 ids[n], double x0[n], z0[n]          (the slab at the first sample)
//   record  double time, then (x, z) of each slab particle, in the header's order
// A resumed run (program checkpoint) truncates the records later than the checkpoint's time.
#include "common/ProgramRunner.h"
#include "compare/SectionMaps.h"
#include "compare/case/CaseDescription.h"
#include "dem/program/DemEngine.h"

#include <filesystem>
#include <optional>
#include <unordered_map>

namespace geocomp::cli {

class DemSectionRecorder {
public:
  DemSectionRecorder(const dem::DemEngine &engine, const CaseDescription &c, const std::filesystem::path &dir);
  /// A run from the start: no records yet.
  void start();
  /// Going on from a checkpoint at program time `time`: the records up to then are kept.
  void resume(double time);
  /// Called at every sample: one record per main-path sample of the last stage.
  void operator()(const RunProgress &p);

private:
  void write_header(const dem::ParticleFields &f);

  const dem::DemEngine &engine_;
  std::filesystem::path file_;
  double tolerance_;                          ///< half a sample interval
  std::optional<double> last_time_;
  std::vector<std::int64_t> ids_;
  std::unordered_map<std::int64_t, std::size_t> slot_;
};

/// <dir>/dem-midplane.bin as a section series (displacements since its first record; local
/// strain radius 3 mean radii, as the DEM onset's; discs of the mean radius); empty when missing.
std::optional<compare::SectionSeries> read_dem_section(const std::filesystem::path &dir);

} // namespace geocomp::cli
