#pragma once
// @sect3{The crush case file (cases/s2_*.prm)}
//
// Why: S2's single-particle and uniaxial crushing programs need their own inputs (the
// S2 contact, the breakage rules, the two set-ups), read like every other case with
// deal.II's ParameterHandler: each entry declared once with a default, a pattern and a
// help text, each failure a CaseError naming the file and the parameter. Lengths in the
// file are in mm, stresses in MPa or kPa as the entry says; the struct is SI.
//
//   set title = ...
//   subsection program        mode (single particle | uniaxial), time step safety, record interval
//   subsection material       density, density scaling
//   subsection contact        S2's kn, ks, mu, mu_r; restitution, wall friction, local damping
//   subsection breakage       mode (cube | 4-ball | 18-ball), cut point, d_M, d_L, sigma_c, Weibull
//   subsection single particle  particles, diameters, platen speed, seed
//   subsection uniaxial       diameter, packing (lattice | grown), seating, lid speed, final strain
//   subsection output         directory, gradation bin, polar bins, polar walls
#include "common/case/CaseParameters.h"
#include "dem/program/CrushPrograms.h"

#include <string>

namespace geocomp::dem {

struct CrushCase {
  std::string file;
  CrushSetup setup;
  std::string output_directory = "results/s2";
};

/// Reads and validates a crush case; throws geocomp::CaseError.
CrushCase read_crush_case(const std::string &path);
/// The same from text; `path` names the file in messages.
CrushCase parse_crush_case(const std::string &text, const std::string &path);
/// Every parameter with default, pattern and help (a commented .prm).
std::string describe_crush_parameters();

} // namespace geocomp::dem
