// @sect3{Outputs of the contact polar distributions (S2 Figs. 8-11)}
//
// Why it exists: the roses of ContactPolarDistribution.h are read back as tables and looked
// at as S2 draws them. Three writers:
//  - a TSV of every bin: state (e.g. seated, final), plane (horizontal | vertical), variant
//    (all | mechanical), angle_deg (bin centre), contacts (N_k), mean_force_N ($\bar f_k$);
//  - a TSV of one summary row per state, plane and variant: contacts, the Fourier
//    coefficients a_c, a_s, anisotropy a and a_f (mean force), the axial (0/180 +- 30 deg)
//    and lateral (90/270 +- 30 deg) sector contacts and pooled mean forces;
//  - an SVG of four polar panels (contact number and mean force, horizontal and vertical
//    plane), each with the "all" and the "mechanical" curve, written directly (no plotting
//    dependency, like the rate-sweep plot). Horizontal panels: 0 deg = +x to the right,
//    counter-clockwise; vertical panels: 0 deg = +z (the loading axis) up, 90 deg = lateral
//    to the right. Radius proportional to the value, common scale for the two curves.
#pragma once

#include "dem/ContactPolarDistribution.h"

#include <string>
#include <utility>
#include <vector>

namespace geocomp::dem {

/// A distribution with the name of the state it was taken in.
using PolarState = std::pair<std::string, ContactPolarDistribution>;

/// Half-width [deg] of the axial and lateral sectors of the summary.
inline constexpr double kPolarSectorHalfWidth = 30.0;

void write_polar_tsv(const std::string& path, const std::vector<PolarState>& states);
void write_polar_summary_tsv(const std::string& path, const std::vector<PolarState>& states);
void write_polar_svg(const std::string& path, const std::string& title, const ContactPolarDistribution& d);

}  // namespace geocomp::dem
