// @sect3{Fragment replacement modes (S2): cube, 4-ball and 18-ball}
//
// Why it exists: S2 compares three ways of turning a crushed sphere (centre $c_0$,
// radius $R_0$, density $\rho$) into children; the choice fixes the gradation the
// specimen evolves towards. They are pure functions of the parent and a seeded
// std::mt19937_64, so a run is reproducible and the statistics are testable.
//
// Cube replacement (S2 eqs. (1)-(2)). A unit cube cut by three planes through the point
// $(a, b, c)$, $a, b, c \sim U(0,1)$ raised to the power $p$ (plain p = 1, squared p = 2,
// cubed p = 3), splits into eight blocks with volume fractions
// $$ k = \{a, 1-a\} \cdot \{b, 1-b\} \cdot \{c, 1-c\}, \qquad \textstyle\sum k_i = 1 \quad \text{(S2 eq. (1))} $$
// and block i becomes the sphere $r_i = R_0 k_i^{1/3}$ (S2 eq. (2)), so $\sum r_i^3 = R_0^3$:
// mass is conserved. The block of octant $s = (\pm1, \pm1, \pm1)$ (the side of $a$ is -x)
// sits on the half-diagonal $d_i = s/\sqrt3$, internally tangent to the parent:
// $x_i = c_0 + (R_0 - r_i)\,d_i$. Children with $2 r_i < d_M$ are dropped and their volume
// goes to the smallest valid child (its radius grows to keep the total), so fewer than
// eight may result; if none is valid the parent does not break.
//
// 4-ball (McDowell & de Bono 2013): four equal spheres $r = R_0 4^{-1/3}$ (mass
// conserved, they overlap), internally tangent on the vertex directions of a regular
// tetrahedron turned at random.
//
// 18-ball (after Ciantia et al. 2015; the exact sketch is not in S2, this is our
// construction): six spheres $r_1 = R_0/(1+\sqrt2)$ on the $\pm$ axes (internally tangent,
// each touching its four neighbours) and twelve equal spheres on the edge directions
// $(\pm1,\pm1,0)/\sqrt2$ and permutations, as large as fits without overlap. No overlap,
// mass lost: $1 - 6 r_1^3/R_0^3 - 12 r_2^3/R_0^3$ of the parent (reported). The whole
// arrangement is turned at random. Children below $d_M$ are dropped (more loss).
//
// Every mode refuses parents smaller than the breakage limit $d_L$ (empty result).
#pragma once

#include "dem/Fragment.h"

#include <random>
#include <string>
#include <vector>

namespace geocomp::dem {

enum class BreakageMode { cube, four_ball, eighteen_ball };

/// "cube" | "4-ball" | "18-ball"; throws std::invalid_argument for anything else.
BreakageMode parse_breakage_mode(const std::string& name);
std::string to_string(BreakageMode m);

struct ParentSphere
{
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
  double density = 0.0;
};

struct FragmentRules
{
  BreakageMode mode = BreakageMode::cube;
  int cut_power = 2;             ///< cube mode: 1 plain (a,b,c), 2 squared, 3 cubed (S2: 2 fits best)
  double minimum_size = 0.0;     ///< d_M [m]: smaller children are dropped (S2: 1 mm)
  double breakage_limit = 0.0;   ///< d_L [m]: smaller parents never break (S2: 5 mm)
};

struct Fragmentation
{
  std::vector<Fragment> children;  ///< empty: the parent does not break
  double lost_volume = 0.0;        ///< parent volume not in any child (18-ball, dropped children)
  int dropped = 0;                 ///< children smaller than d_M
};

/// The eight volume fractions of S2 eq. (1) for a cut point, octant order
/// s = (sx, sy, sz) with bit 0 of the index: x side (0: -x, block a), bit 1 y, bit 2 z.
std::vector<double> cube_fractions(double a, double b, double c);

/// Breaks `parent` by the rules (S2 section 1-2); draws from `rng`.
Fragmentation fragment(const ParentSphere& parent, const FragmentRules& rules, std::mt19937_64& rng);

Fragmentation cube_replacement(const ParentSphere& parent, int cut_power, double minimum_size, std::mt19937_64& rng);
Fragmentation four_ball(const ParentSphere& parent, double minimum_size, std::mt19937_64& rng);
Fragmentation eighteen_ball(const ParentSphere& parent, double minimum_size, std::mt19937_64& rng);

/// Radius ratios r/R0 of the 18-ball arrangement: {axial, edge}.
std::pair<double, double> eighteen_ball_ratios();

}  // namespace geocomp::dem
