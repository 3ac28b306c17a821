#pragma once
// The `dem rve` section of a case file (the fem-dem engine), as plain data: how the RVE of
// every quadrature point is made and driven, and how the engine's Newton treats its answer. Its grains and its state are the DEM
// specimen's (specimen: radius, radius spread, density, isotropic pressure; contact: the law
// and the particle friction; dem: the time step safety), so they are not repeated here (one
// home per parameter).
// Declared and parsed in coupled/case/RveSection.cpp.
#include <string>

namespace geocomp::coupled {

struct RveCaseParameters {
  unsigned int particles = 60;            ///< spheres in the cell
  unsigned int seed = 1;                  ///< of the random placement
  double placement_packing_fraction = 0.3; ///< eta_0 of the random placement
  double local_damping = 0.2;             ///< Cundall damping of the cell
  double growth_pressure_fraction = 0.1;  ///< frictionless growth up to this fraction of p
  unsigned int steps_per_increment = 200; ///< DEM steps per FE strain increment
  double newton_tolerance = 2e-3;         ///< of the fem-dem engine's cube (relative |R|)
  unsigned int secant_pairs = 8;          ///< BFGS pairs per load step on the cells' tangent
  std::string tangent = "branch secant";  ///< branch secant | contact stiffness

  template <class Self, class V>
  static void visit(Self &p, V &&v)
  {
    v("particles", p.particles);
    v("seed", p.seed);
    v("placement packing fraction", p.placement_packing_fraction);
    v("local damping", p.local_damping);
    v("growth pressure fraction", p.growth_pressure_fraction);
    v("steps per increment", p.steps_per_increment);
    v("newton tolerance", p.newton_tolerance);
    v("secant pairs", p.secant_pairs);
    v("tangent", p.tangent);
  }
};

} // namespace geocomp::coupled
