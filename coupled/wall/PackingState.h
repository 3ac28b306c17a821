#pragma once
// @sect3{The state of a packing before shear: packing fraction and coordination, inside and all}
//
// Why it exists: "the same packing" is checked by its state before shear, and a wall
// distorts that state near itself. A flat wall orders the first layers and leaves a layer of
// low solid fraction along it (centres at least R_i from the plane): over the whole box the
// nominal packing fraction $\phi = \sum_i \tfrac43\pi R_i^3 / V_{box}$ and the coordination
// $Z = 2C/N$ (particle-particle contacts; wall contacts apart) are both below the bulk's.
// DEM-NOTES section 8 asks for the bulk figures of an inner box at least 3 d from the walls
// as well; they are measured here as
//  - the solid fraction of the inner box, sampled on a lattice of spacing h: the fraction
//    of lattice points inside some sphere (each sphere cut by the inner box counts only
//    its part inside, so no estimate of the boundary is needed; error of order (h/d)^2 per
//    sphere, averaging out over many);
//  - the mean number of particle-particle contacts of the spheres whose centres lie in the
//    inner box (rattlers included, as in Z).
// A periodic cell has no wall: its inner figures are its whole figures.
#include "dem/DemSystem.h"
#include "dem/periodic/PeriodicCell.h"

#include <cstddef>
#include <vector>

namespace geocomp::coupled {

struct PackingState {
  std::size_t particles = 0;
  double mean_diameter = 0.0;           ///< [m]
  double edge = 0.0;                    ///< cube root of the box (cell) volume, in mean diameters
  double packing_fraction = 0.0;        ///< nominal, whole box or cell (overlaps counted twice)
  double coordination = 0.0;            ///< Z = 2C/N, particle-particle contacts, all particles
  std::size_t inner_particles = 0;      ///< centres in the inner box
  double inner_packing_fraction = 0.0;  ///< solid fraction of the inner box (sampled)
  double inner_coordination = 0.0;      ///< contacts per particle of the inner particles
};

/// A wall specimen (walls 0..5 the box faces): the inner box lies `margin` mean diameters
/// inside every wall; its solid fraction is sampled at a lattice spacing of d / 20.
PackingState packing_state(const dem::DemSystem &specimen, double margin);

/// A periodic cell: the inner figures equal the whole ones.
PackingState packing_state(const dem::PeriodicCell &cell);

/// The fraction of the points of the lattice $lo + h(i + \tfrac12, j + \tfrac12, k + \tfrac12)$ inside
/// the box [lo, hi] that lie inside at least one of the spheres (centres x, radii r).
double sampled_solid_fraction(const std::vector<dem::Vec3> &x, const std::vector<double> &r, const dem::Vec3 &lo,
                              const dem::Vec3 &hi, double h);

} // namespace geocomp::coupled
