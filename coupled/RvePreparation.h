#pragma once
// @sect3{Preparing the RVE of a case: the DEM specimen's grains in a periodic cell}
//
// Why it exists: `continuum/model = dem rve` puts at every quadrature point a copy of one
// RVE, which must be made from the case's grains (the DEM specimen's radius, spread, density
// and contact law, so that the FEM x DEM column answers for the same material as the DEM
// column) and carry the case's confining pressure. The route is the periodic cell's
// (dem/periodic/PeriodicPreparation.h, PeriodicProgram.h):
//  1. random sequential placement at the packing fraction eta_0 (radii uniform in R(1 +- a));
//  2. frictionless radius growth at fixed cell (2e-5 per step) to `growth pressure fraction`
//     of the pressure (a tenth by default: the density of the packing),
//     with local damping; the growth multiplies every radius by the same g (measured on the
//     biaxial case's grains, R = 1 mm, k_n = 1e5 N/m, 100 kPa, eta_0 = 0.3: g = 1.24), so
//  2b. the grown packing is scaled back by 1/g - cell matrix and positions divided by g, the
//     radii the placement's R(1 +- a) again, at rest: the same geometry at the case's grain
//     size, its overlaps divided by g (the stress of linear springs, F l / V ~ k_n delta / l^2,
//     times g: about p/8);
//  3. friction on, servo isotropic compression to the pressure (gain 0.2, largest rate 3/s;
//     done at 1 % on every stress component and an unbalanced-force ratio of 0.02).
// Time step: the wall-box engine's, `time step safety` times the critical step of the
// contact law for the smallest sphere (DemSystem::critical_time_step) - of the placed radii,
// which the cell has again from step 2b on.
// Before step 2b (until 2026-12-01) the cells kept the grown radii: a mean diameter of
// 2.48 mm for the case's 2 mm (docs/coupled.md, the RVE against the wall-bounded specimen).
#include "dem/ContactLaw.h"
#include "dem/periodic/PeriodicCell.h"
#include "dem/periodic/PeriodicProgram.h"

#include <cstdint>
#include <vector>

namespace geocomp::coupled {

/// The grains (from the case's specimen, contact and dem sections).
struct RveGrains {
  dem::ContactModel law;
  double radius = 1e-3;        ///< R [m], mean
  double radius_spread = 0.0;  ///< a: radii uniform in R (1 - a, 1 + a)
  double density = 2650.0;     ///< [kg/m^3]
  double friction = 0.5;       ///< mu between spheres
  double time_step_safety = 0.2;
};

/// How the RVE is made (the `dem rve` section, coupled/case/RveCaseParameters.h).
struct RvePreparationSettings {
  std::size_t particles = 60;
  std::uint64_t seed = 1;
  double pressure = 1e5;            ///< [Pa], compression positive
  double placement_packing_fraction = 0.3;
  double local_damping = 0.2;       ///< Cundall damping of the cell (growth, compression, loading)
  /// The frictionless growth ends at this fraction of the pressure (step 2): the packing's
  /// density - 1 grows it frictionless to p (the densest), 0.1 leaves friction the last 90 %.
  double growth_pressure_fraction = 0.1;
};

/// The fixed steps of the preparation (steps 2 and 3 above), in one place: the wall-bounded
/// specimen made the same way (coupled/wall/WallSpecimen.h) reads them from here.
struct RveProtocol {
  double growth_rate = 2e-5;               ///< relative radius growth per step
  std::uint64_t growth_interval = 10;      ///< steps between radius updates
  std::uint64_t growth_max_steps = 200000;
  double stress_tolerance = 0.01;          ///< compressed: every stress component within this of p
  double unbalanced = 0.02;                ///< compressed: unbalanced-force ratio at most this
  std::uint64_t compression_check_interval = 100; ///< steps between the checks of those two
  std::uint64_t compression_max_steps = 200000;
  double servo_gain = 0.2;                 ///< the periodic servo (MixedControl): gain
  double servo_max_strain_rate = 3.0;      ///< [1/s] and largest rate
};

/// The critical time step of `law` for a sphere of `radius` and `density` (the wall-box engine's).
double rve_critical_time_step(const dem::ContactModel &law, double radius, double density);

/// The RVE's time step: `time_step_safety` times the critical step of the smallest placed sphere.
double rve_time_step(const RveGrains &grains);

/// Step 3's compression of a cell whose friction is on: the protocol's servo and criteria.
dem::CompressionResult compress_rve(dem::PeriodicCell &cell, double pressure, const RveProtocol &protocol = {});

/// Step 2b: `grown` scaled by placed / grown radius (the same for every sphere after a radius
/// growth), its spheres at the `placed` radii, at rest, with its law and parameters.
dem::PeriodicCell at_placed_radii(const dem::PeriodicCell &grown, const std::vector<double> &placed, double density);

/// Places, grows, scales back to the placed radii and compresses; throws std::runtime_error
/// naming the stage that failed.
dem::PeriodicCell prepare_rve(const RveGrains &grains, const RvePreparationSettings &s,
                              const RveProtocol &protocol = {});

} // namespace geocomp::coupled
