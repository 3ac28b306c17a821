#pragma once
// @sect3{Preparing the RVE of a case: the DEM specimen's grains in a periodic cell}
//
// Why it exists: `continuum/model = dem rve` puts at every quadrature point a copy of one
// RVE, which must be made from the case's grains (the DEM specimen's radius, spread, density
// and contact law, so that the FEM x DEM column answers for the same material as the DEM
// column) and carry the case's confining pressure. The route is the periodic cell's
// (dem/periodic/PeriodicPreparation.h, PeriodicProgram.h):
//  1. random sequential placement at the packing fraction eta_0 (radii uniform in R(1 +- a));
//  2. frictionless radius growth at fixed cell (2e-5 per step) to a tenth of the pressure,
//     with local damping;
//  3. friction on, servo isotropic compression to the pressure (gain 0.2, largest rate 3/s;
//     done at 1 % on every stress component and an unbalanced-force ratio of 0.02).
// Time step: the wall-box engine's, `time step safety` times the critical step of the
// contact law for the smallest sphere (DemSystem::critical_time_step).
#include "dem/ContactLaw.h"
#include "dem/periodic/PeriodicCell.h"

#include <cstdint>

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
};

/// The critical time step of `law` for a sphere of `radius` and `density` (the wall-box engine's).
double rve_critical_time_step(const dem::ContactModel &law, double radius, double density);

/// Places, grows and compresses; throws std::runtime_error naming the stage that failed.
dem::PeriodicCell prepare_rve(const RveGrains &grains, const RvePreparationSettings &s);

} // namespace geocomp::coupled
