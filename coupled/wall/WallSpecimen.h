#pragma once
// @sect3{The wall-bounded specimen of the RVE's packing: the RVE's preparation in a six-wall box}
//
// Why it exists: issue 35 asks whether an RVE gives the stress-strain curve of a
// wall-bounded specimen "of the same packing". A packing's response depends on how it was
// made, so "the same packing" is here the same grains made by the same protocol: this is
// prepare_rve() (coupled/RvePreparation.h) step by step, with the six frictionless walls
// of the wall-box engine (dem/program/DemEngine.h) in place of the periodic images:
//  1. radii uniform in R(1 +- a) drawn from the seed (dem::SizeDistribution: for the same
//     seed and count they are the RVE's radii, the two samplers differing by half an ulp),
//     a cube of the RVE's edge $L = (\sum \tfrac43\pi R_i^3/\eta_0)^{1/3}$, random sequential
//     placement without overlap with each other or the walls - at radii $f_0 R_i$,
//     $f_0 = (\eta_w/\eta_0)^{1/3}$ with the wall box's placement fraction $\eta_w = 0.25$ when
//     $\eta_0$ is above it (walls shrink the room for centres to $(L - 2R)^3$, and at 0.3 the
//     placement of 1 000 spheres jams); the growth makes up $f_0$ in a gas, before anything touches;
//  2. frictionless growth at fixed walls: every `growth_interval` steps all radii are
//     multiplied by $1 + r\,\Delta n$ (RveProtocol::growth_rate r), until the mean wall
//     pressure reaches RvePreparationSettings::growth_pressure_fraction of p (the RVE: its mean stress); the growth
//     multiplies every radius R_i by the same g (f_0 made up included: 1.22 at 5 000 spheres
//     of the biaxial case's grains, 1.21 at 1 000), so
//  2b. the grown specimen is scaled back by 1/g about the box origin, as the RVE is
//     (at_placed_radii): the six walls' points and the positions divided by g, the radii the
//     drawn R_i (masses at the grains' density), at rest (at_case_radii);
//  3. friction on (walls stay frictionless), and servo isotropic compression by the walls
//     (hold_isotropic, the wall box's servo) until every wall stress is within
//     `stress_tolerance` of -p and the unbalanced-force ratio at most `unbalanced`, checked
//     every `compression_check_interval` steps.
// The time step is the RVE's (rve_time_step, from the RVE's smallest sphere), and Cundall local
// damping `local_damping` acts throughout, as in the RVE. The same settings and seed give the
// same specimen bit for bit (any thread count).
#include "coupled/RvePreparation.h"
#include "dem/DemSystem.h"

#include <cstdint>
#include <vector>

namespace geocomp::coupled {

/// How the preparation went (for the comparison's tables).
struct WallPreparation {
  std::uint64_t growth_steps = 0;
  double grown_packing_fraction = 0.0;   ///< nominal, box volume, at the end of growth
  double grown_pressure = 0.0;           ///< [Pa] mean wall stress, compression positive
  double growth_factor = 0.0;            ///< g: the grown radii over the drawn R_i (step 2b divides by it)
  std::uint64_t compression_steps = 0;
  double stress_error = 0.0;             ///< largest |sigma_aa + p| / p at the end
  double unbalanced = 0.0;               ///< unbalanced-force ratio at the end
};

struct WallSpecimen {
  dem::DemSystem system;  ///< walls 0..5 the box faces (add_box order), at rest, at p
  WallPreparation record;
};

/// Step 2b: `grown` (no clumps) scaled about the origin, the box's corner, by 1/g with
/// g = its radius over radii[0] (the same for every sphere after a radius growth): walls'
/// points and positions divided by g, the spheres at `radii[id]` at their density, particles
/// and walls at rest. Returns g.
double at_case_radii(dem::DemSystem &grown, const std::vector<double> &radii);

/// The grains in their box, made by the RVE's protocol; `threads` of the DEM step (the bits
/// do not depend on it). Throws std::runtime_error naming the stage that did not converge.
WallSpecimen prepare_wall_specimen(const RveGrains &grains, const RvePreparationSettings &settings,
                                   const RveProtocol &protocol = {}, int threads = 1);

} // namespace geocomp::coupled
