// @sect3{Lattice packings: a quick loose start for servo compaction, and ordered arrays}
//
// Why it exists: tests and small demos need a specimen in seconds, before the
// radius-growth core store (S0 "digital core store") is at hand. Spheres of radius
// R (1 + spread u), u uniform in [-1, 1], sit at the sites of a simple cubic lattice of
// spacing h = 2 R_max (1 + gap), each displaced at random by up to the slack
// h/2 - R_k per axis, so no two overlap and none crosses the box (of edge n h). The
// packing fraction is about (pi/6)/(1+gap)^3 (0.52 for gap 0): loose, so a servo
// compaction (hold_isotropic) produces the dense, load-carrying specimen. Deterministic
// for a seed.
#pragma once

#include "dem/specimen/Packing.h"

#include <cstdint>

namespace geocomp::dem {

Packing jittered_lattice(int n_per_edge, double radius, double spread, double gap, double density,
                         std::uint64_t seed);

/// An ordered face-centred cubic array of equal touching spheres: the sites
/// $(i, j, k)\,a/2$ with $i + j + k$ even, $0 \le i, j, k \le 2n$, of the cubic cell
/// $a = 2\sqrt2\,R$ (nearest neighbours at $2R$, packing fraction $\pi/(3\sqrt2) = 0.7405$ in
/// the bulk), $((2n+1)^3 + 1)/2$ spheres, in the box whose faces, (100) planes, touch the
/// outer spheres: edge $n a + 2R$. No overlap and no force: an ordered array as imported.
Packing fcc_lattice(int cells_per_edge, double radius, double density);

} // namespace geocomp::dem
