// @sect3{Specimen preparation: the consolidated specimen a case starts from}
//
// Why it exists: S0's results depend on how a specimen was prepared, so preparation is a
// recorded, reproducible input. prepare_specimen() turns the `specimen`, `contact` and
// `dem` sections of a case into a DemSystem in its six-wall box, consolidated to the
// isotropic pressure sigma_0 (S0 "Packing generation"): a loose start (generated from the
// seed, or read from a text file), frictionless servo compaction to sigma_0 (S0: particles
// and walls frictionless while the packing forms), then mu_s and mu_p switched on and
// the servo holding sigma_0 until the specimen is at rest (all three wall stresses within
// `stress_tolerance` of sigma_0, unbalanced-force ratio below `unbalanced_force_ratio`).
// The same case and seed give the same specimen bit for bit at a fixed thread count.
#pragma once

#include "common/case/CaseParameters.h"
#include "dem/DemSystem.h"
#include "dem/program/DemEngine.h"

#include <cstdint>
#include <functional>
#include <string>

namespace geocomp::dem {

struct PreparationCriteria
{
  double stress_tolerance = 0.005;       ///< relative wall-stress error (issue 4: 0.5 %)
  double unbalanced_force_ratio = 1e-3;  ///< quasi-static: mean |net force| / mean |contact force|
  double preparation_unbalanced = 1e-2;  ///< looser criterion for the frictionless compaction
  double max_time = 20.0;                ///< [s] of DEM time per phase before giving up
  double check_interval_steps = 2000;    ///< criteria checked every so many DEM steps
};

/// How the specimen was made: stored with every DEM result and shown in reports.
struct PreparationRecord
{
  std::string method;              ///< e.g. "jittered lattice + servo compaction"
  std::uint64_t seed = 0;
  std::size_t particles = 0;
  double initial_packing_fraction = 0.0, final_packing_fraction = 0.0;
  double pressure = 0.0;           ///< sigma_0 [Pa], compression positive
  HoldResult frictionless, frictional;
  std::uint64_t steps = 0;
  double wall_seconds = 0.0;
  /// One paragraph for logs and reports.
  std::string describe() const;
};

struct PreparedSpecimen
{
  DemSystem system;   ///< walls at rest, program time origin = now
  PreparationRecord record;
};

/// Called now and then with a phase name and the DEM time spent in it.
using PreparationProgress = std::function<void(const std::string &phase, double dem_time)>;

/// The case's consolidated specimen. Throws CaseError (file, parameter, message) for
/// inputs that cannot make one (unreadable text file, empty packing), std::runtime_error
/// when consolidation does not converge within the criteria's max_time.
PreparedSpecimen prepare_specimen(const CaseDescription &c, const PreparationCriteria &criteria = {},
                                  const PreparationProgress &progress = {});

} // namespace geocomp::dem
