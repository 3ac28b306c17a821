#pragma once
// @sect3{The rate-sweep case file (cases/s1_*.prm)}
//
// Why: a rate sweep needs different inputs from the DEM/cube cases (an S1 material, a
// plane-stress specimen, a list of strain rates), so it has its own small set of sections,
// read with deal.II's ParameterHandler like common/case: every entry declared once with a
// default, a pattern and a help text, every failure a CaseError naming the file, the
// parameter and what was expected.
//
//   set title = ...
//   subsection material   preset (concrete | sandstone) and optional overrides of S1's table
//   subsection specimen   width, height, cells in x, cells in y
//   subsection loading    mode (compression | tension), strain rates, kinetic (on | off | both)
//   subsection dynamics   time step safety, quasi-static transits, stop load fraction
//   subsection output     directory
#include "common/case/CaseParameters.h"
#include "continuum/dynamics/RateSweep.h"

#include <string>

namespace geocomp::dynamics {

struct RateSweepCase {
  std::string file;
  RateSweepSetup setup;
  std::string output_directory = "results/s1";
};

/// Reads and validates a rate-sweep case; throws geocomp::CaseError.
RateSweepCase read_rate_sweep_case(const std::string &path);
/// The same from text; `path` names the file in messages.
RateSweepCase parse_rate_sweep_case(const std::string &text, const std::string &path);
/// Every parameter with its default, pattern and help (a commented .prm).
std::string describe_rate_sweep_parameters();

} // namespace geocomp::dynamics
