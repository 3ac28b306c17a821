// @sect3{Clump generation from S4's four templates with lognormal mass}
//
// Why it exists: S4's rubble is made of 926 clumps drawn from four templates, each grain
// with a mass from a lognormal distribution, $\ln m \sim N(\mu, \sigma)$ with m in grams,
// $\mu = -0.117$, $\sigma = 0.432$, grains of 0.4 to 2.0 g (the draw is truncated to that
// range by rejection), specific gravity 2.55. S4 describes the templates as "three of
// equal spheres, one with a sphere twice the other's diameter", overlaps random in
// $[0, 0.5 D_{min}]$; it does not draw them, and 2300 spheres in 926 clumps (2.48 per clump)
// fits this reading:
//  - template 0: two equal spheres, centre distance $D - o$;
//  - template 1: three equal spheres in a row, distances $D - o_1$, $D - o_2$;
//  - template 2: three equal spheres in an equilateral triangle of side $D - o$;
//  - template 3: a sphere of diameter $2D$ and one of $D$, distance $1.5D - o$;
// each overlap $o \sim U[0, 0.5D]$ ($D_{min} = D$). A grain is built at $D = 1$, its volume
// $V_1$ integrated on voxels of side $D_{min}/20$ (ClumpMassProperties.h), and scaled to
// $D = (m/(\rho V_1))^{1/3}$; the voxel grid scales with $D$, so the clump's voxel mass is m.
// Random numbers come from a seeded std::mt19937_64 through explicit transforms (no
// standard distribution classes), so a seed gives the same clumps on every machine.
#pragma once

#include "dem/ClumpMassProperties.h"
#include "dem/Types.h"

#include <cstdint>
#include <vector>

namespace geocomp::dem {

struct ClumpGenerationParameters
{
  double log_mass_mean = -0.117;  ///< mu of ln(m / 1 g) (S4)
  double log_mass_sigma = 0.432;  ///< sigma of ln(m / 1 g) (S4)
  double mass_min = 0.4e-3;       ///< [kg] lightest grain (S4: 0.4 g)
  double mass_max = 2.0e-3;       ///< [kg] heaviest grain (S4: 2.0 g)
  double density = 2550.0;        ///< [kg/m^3] (S4: specific gravity 2.55)
  double max_overlap = 0.5;       ///< overlaps in [0, max_overlap * D_min] (S4: 0.5)
};

/// One generated grain: members in its own frame (centroid at the origin).
struct ClumpShape
{
  int template_index = 0;
  double mass = 0.0;              ///< [kg], the voxel mass at the given density
  std::vector<ClumpMember> members;
};

/// Members of S4 template t (0..3) with small-sphere diameter d and overlaps o1, o2.
std::vector<ClumpMember> s4_template(int t, double d, double o1, double o2);

/// n grains, template chosen uniformly; deterministic in (n, parameters, seed).
std::vector<ClumpShape> generate_s4_clumps(std::size_t n, const ClumpGenerationParameters& p, std::uint64_t seed);

/// Places the grains (scaled by `scale`, e.g. 0.5 for S4's "random placement at half
/// size") at random positions and orientations in the box [lo, hi] so that their
/// bounding spheres do not overlap. Returns the members of each grain in world
/// coordinates; throws std::runtime_error when a grain finds no place in `attempts` tries.
std::vector<std::vector<ClumpMember>> place_clumps(const std::vector<ClumpShape>& shapes, const Vec3& lo,
                                                   const Vec3& hi, double scale, std::uint64_t seed,
                                                   int attempts = 10000);

}  // namespace geocomp::dem
