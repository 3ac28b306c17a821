#pragma once
// @sect3{The shear-box case file (cases/s4_*.prm)}
//
// Why: S4's direct shear box of clumped rubble has its own inputs (the box, the grains'
// lognormal masses, the Hertz-Mindlin material, the loading and the preparation), read like
// every other case with deal.II's ParameterHandler: each entry declared once with a default,
// a pattern and a help text, each failure a CaseError naming the file and the parameter.
// Masses in the file are in grams as S4 prints them; the struct is SI. It lives with the
// engine it configures (DirectShearBox.h), not in the command line.
//
//   set title = ...
//   subsection box          length, width, half height, gap fraction, void ratio, clumps
//   subsection grains       log mass mean/sigma, mass min/max [g], density, max overlap, seed
//   subsection material     E, modulus scale, nu, restitution, frictions, time step, gravity
//   subsection loading      normal stress, shear speed, max shear, lid and upper box
//   subsection preparation  growth, settling, seating, load servo, rest
//   subsection output       directory
#include "common/case/CaseParameters.h"
#include "dem/program/DirectShearBox.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace geocomp::dem {

struct ShearBoxCase
{
  std::string file;
  std::string title;
  DirectShearParameters p;
  std::string output_directory = "results/s4";
};

/// Every entry of a shear-box case with default, pattern and help.
void declare_shear_box_parameters(dealii::ParameterHandler& prm);
/// Reads and validates a shear-box case; throws geocomp::CaseError.
ShearBoxCase read_shear_box_case(const std::string& path);

}  // namespace geocomp::dem
