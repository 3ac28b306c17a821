// @sect3{Specimen preparation: the consolidated specimen a case starts from}
//
// Why it exists: S0's results depend on how a specimen was prepared, so preparation is a
// recorded, reproducible input. prepare_specimen() turns the `specimen`, `contact` and
// `dem` sections of a case into a DemSystem in its six-wall box, consolidated to the
// isotropic pressure sigma_0. For `source = generate` it follows S0 "Packing generation"
// (docs/specimens.md):
//  1. radii from the size distribution and the seed; box edge L0 given, or from N, eta
//     and R; if L0 is given the radii are scaled so that the target eta is met;
//  2. random non-overlapping placement at radii f0 R_i (nominal packing fraction
//     `initial_packing_fraction`);
//  3. radius growth to R_i with frictionless particles and walls, the walls fixed
//     (RadiusGrowth.h): Newtonian with local damping `preparation_damping`, or
//     first-order "Aristotelian" motion (SpecimenParameters::aristotelian, mobility
//     `aristotelian_beta` dt / m); then relaxation at fixed radii until at rest;
//  4. mu_s and mu_p on, Newtonian, relaxation until at rest (S0: "let the specimen rest
//     until the kinetic energy decays");
//  5. isotropic consolidation to sigma_0 with the servo walls (hold_isotropic) until all
//     three wall stresses are within `stress_tolerance` of sigma_0 and the specimen is at
//     rest (unbalanced-force ratio and kinetic / elastic energy below the thresholds).
// Steps 2-5 use the case's law without S3's parts (bonds, adhesion, anchor-spring friction):
// they act from the prepared state on, so S3's bonds form on the touching pairs of the
// consolidated packing (docs/s3-bonded.md).
// `source = text` starts at step 3's relaxation with the file's spheres; `source = store`
// reads a specimen from a core store (SpecimenStore.h), exactly as it was written. With
// `preparation = as given` a text source (xyzr or LAMMPS data, with its velocities) starts
// the program exactly as read: no rest, no consolidation, no isotropic pressure needed.
// A rest phase in which nothing touches ends at once and says so (relax()).
// The same case and seed give the same specimen bit for bit.
#pragma once

#include "dem/case/DemParameters.h"
#include "dem/DemSystem.h"
#include "dem/program/DemEngine.h"
#include "dem/program/RadiusGrowth.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace geocomp::dem {

/// Thresholds and rates of the preparation (docs/specimens.md states and justifies them).
struct PreparationCriteria
{
  double stress_tolerance = 0.005;        ///< relative wall-stress error at sigma_0 (issue 4: 0.5 %)
  double unbalanced_force_ratio = 1e-3;   ///< consolidated: mean |net force| / mean |contact force|
  double kinetic_ratio = 1e-6;            ///< consolidated: kinetic / elastic energy
  RestCriteria packing{1e-4, 1e-6, 1.0, 500}; ///< relaxations at fixed walls (after growth, after friction on)
  double initial_packing_fraction = 0.25; ///< of the random placement (RSA jams near 0.38)
  /// Growth rate f'/f = I_g / (d sqrt(rho / sigma_0)): the inertial number of the growth
  /// at sigma_0 (DEM-NOTES section 8: keep it < 1e-3 once the packing carries load).
  double growth_inertial_number = 1e-3;
  std::uint64_t growth_interval = 10;     ///< steps between radius updates
  double preparation_damping = 0.2;       ///< Cundall local damping of the Newtonian packing stages
  double aristotelian_beta = 1.0;         ///< first-order mobility beta dt / m (stable below ~2)
  double max_time = 20.0;                 ///< [s] of DEM time for the consolidation before giving up
  double check_interval_steps = 2000;     ///< consolidation criteria checked every so many steps
};

/// How the specimen was made: stored with every specimen and DEM result, shown in reports.
struct PreparationRecord
{
  std::string method;              ///< e.g. "radius growth (Newtonian) + servo consolidation"
  std::uint64_t seed = 0;
  std::size_t particles = 0;
  std::string size_distribution;
  bool aristotelian = false;
  double box_size = 0.0;           ///< [m] L0 of the growth box (cube edge)
  double mean_radius = 0.0;        ///< [m] of the final radii
  double initial_packing_fraction = 0.0;  ///< random placement
  double grown_packing_fraction = 0.0;    ///< nominal, at the end of growth (the target)
  double final_packing_fraction = 0.0;    ///< consolidated, in the final box
  double pressure = 0.0;           ///< sigma_0 [Pa], compression positive
  double grown_pressure = 0.0;     ///< [Pa] mean wall stress (compression positive) after growth and rest
  PhaseCost growth, frictionless, frictional, consolidation;
  RestState frictionless_rest, frictional_rest, consolidated_rest;
  bool frictionless_converged = false, frictional_converged = false;
  HoldResult consolidated;         ///< the servo hold's last check
  double coordination = 0.0;       ///< Z = 2C/N, consolidated
  double mean_overlap = 0.0;       ///< mean particle-particle overlap / mean diameter, consolidated
  std::uint64_t steps = 0;         ///< all DEM steps
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
using PreparationProgress = PhaseProgress;

/// Refuses, before anything runs, a case whose specimen prepare_specimen() would refuse,
/// with the CaseError (file, parameter, message) it would throw: an unknown source, no
/// isotropic pressure to consolidate to, radii and box that do not fit (growth_target), a
/// text file that cannot be read or holds no sphere, a store or stored name that is
/// missing or was prepared with another friction or pressure. prepare_specimen() calls it
/// first; the command line calls it for every case that names the DEM engine, `geocomp
/// check` included, so that what check accepts the DEM accepts.
void check_specimen(const DemCase &c);

/// The `specimen` entries the case's source and preparation do not use, each that differs
/// from its default, as one message ("<file>: specimen/particles = 5000 is not used: the
/// packing file gives the spheres and the box"): the command line warns about each once.
std::vector<std::string> ignored_specimen_entries(const DemCase &c);

/// The case's consolidated specimen. Throws CaseError (file, parameter, message) for
/// inputs that cannot make one (check_specimen), std::runtime_error when a phase does not
/// converge.
PreparedSpecimen prepare_specimen(const DemCase &c, const PreparationCriteria &criteria = {},
                                  const PreparationProgress &progress = {});

/// Radii by id and the cube edge L0 for `source = generate`: the size distribution's
/// sample for the seed, and L0 = (sum 4/3 pi R^3 / eta)^(1/3), or the given L0 with the
/// radii scaled to meet eta (CaseError if that moves the mean radius by more than 10 %).
struct GrowthTarget
{
  std::vector<double> radii;
  double box_size = 0.0;
};
GrowthTarget growth_target(const DemCase &c);

/// Steps 2-3 alone (placement, growth and frictionless rest), for the preparation and
/// for measuring the Newtonian and Aristotelian routes against each other.
struct GrownPacking
{
  DemSystem system;
  GrowthResult growth;
  RelaxResult rest;
  double initial_packing_fraction = 0.0;
};
GrownPacking grow_packing(const DemCase &c, const PreparationCriteria &criteria,
                          const PreparationProgress &progress = {});

/// Nominal packing fraction sum 4/3 pi R^3 / box volume (walls 0..5 of add_box()).
double packing_fraction(const DemSystem &system);

/// Mean wall stress, compression positive: sum over the six walls (0..5 of add_box()) of
/// |F . n| / current face area, divided by six.
double mean_wall_pressure(const DemSystem &system);

} // namespace geocomp::dem
