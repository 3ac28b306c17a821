// @sect3{A jittered-lattice packing: a quick loose start for servo compaction}
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

} // namespace geocomp::dem
