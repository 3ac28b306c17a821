// @sect3{Preparing an RVE: random spheres in the periodic cell, radius growth, packings}
//
// Why it exists: an RVE must start as a packing that carries load, made reproducibly.
// Two routes:
//  1. place_spheres(): N spheres with radii uniform in $R(1 \pm a)$, placed one after the
//     other at uniform random points of a cubic cell (edge from the placement's packing
//     fraction $\eta_0$: $L^3 = \sum \tfrac43\pi R_i^3/\eta_0$), each redrawn while it
//     overlaps an earlier one through the minimum image (random sequential addition;
//     keep $\eta_0 \lesssim 0.35$). Then grow_radii(): every `interval` steps all radii are
//     multiplied by $1 + r\,\Delta n$ at fixed cell (the S0 packing route, DEM-NOTES section 8,
//     here without walls) until the mean pressure reaches the target; the caller then
//     usually compresses by servo (PeriodicProgram.h) to the exact pressure.
//  2. cell_from_packing(): the spheres of an existing Packing (dem/specimen/Packing.h,
//     e.g. a consolidated specimen exported by the wall-box engine, or a LIGGGHTS data
//     file), the packing's box becoming the cell.
// Random numbers: std::mt19937_64 (its output is fixed by the standard) turned into
// doubles by the top 53 bits, so the same seed gives the same cell on every platform.
#pragma once

#include "dem/periodic/PeriodicCell.h"
#include "dem/specimen/Packing.h"

#include <cstdint>

namespace geocomp::dem {

struct RandomPlacement
{
  std::size_t particles = 300;
  double mean_radius = 1e-3;       ///< R [m]
  double radius_spread = 0.2;      ///< a: radii uniform in R (1 - a, 1 + a)
  double density = 2650.0;         ///< [kg/m^3]
  double packing_fraction = 0.3;   ///< eta_0 of the placement
  std::uint64_t seed = 1;
  std::size_t max_attempts = 100000;  ///< redraws of one sphere before giving up
};

/// A cubic cell with the placement's spheres at rest.
PeriodicCell place_spheres(const RandomPlacement& p, const ContactModel& law, const PeriodicCell::Parameters& cell);

struct RadiusGrowth
{
  double pressure = 0.0;             ///< [Pa] mean pressure (compression positive) that ends the growth
  double rate = 1e-5;                ///< r: relative radius growth per step
  std::uint64_t interval = 10;       ///< steps between radius updates
  std::uint64_t max_steps = 200000;
};

struct GrowthResult
{
  bool reached = false;
  std::uint64_t steps = 0;
  double packing_fraction = 0.0;
  double pressure = 0.0;            ///< [Pa] at the end
};

/// Grows the radii at fixed cell (L = 0 prescribed) until the pressure is reached.
GrowthResult grow_radii(PeriodicCell& cell, const RadiusGrowth& g);

/// The packing's spheres in a cell equal to its box (positions relative to box_min).
PeriodicCell cell_from_packing(const Packing& packing, const ContactModel& law, const PeriodicCell::Parameters& cell);

}  // namespace geocomp::dem
