#pragma once
// The part of a case file every engine shares, as plain data: the file, its title, seed and
// engines (the top level), the loading program and the output section.
//
// A case file (.prm or .json, read by deal.II's ParameterHandler) has the sections
// `specimen`, `contact`, `clumps` and `dem` (the DEM's: dem/case/DemParameters.h),
// `continuum` (continuum/case/ContinuumParameters.h), `calibration`
// (compare/calibrate/CalibrationParameters.h), and the shared `program` and `output`
// declared here. Each engine declares, parses and writes its own sections in its own
// folder, one home per parameter; compare/case/CaseDescription.h puts them together.
// Engines take these structs, never the ParameterHandler, so the DEM core builds without
// deal.II.
//
// Conventions: SI units; stresses and strain rates in the program are tension
// positive; quantities named "pressure" are magnitudes, positive in compression.
#include "common/LoadingProgram.h"
#include "common/case/CaseError.h"

#include <string>
#include <vector>

namespace geocomp {

/// The top level of a case file, which every engine sees.
struct CaseHead {
  std::string file;                     ///< as given on the command line
  std::string text;                     ///< whole file, stored in every results file
  std::string title;
  std::vector<std::string> engines;     ///< dem, continuum, material-point, fem-dem, liggghts
  unsigned long long seed = 1;

  template <class Self, class Visitor>
  static void visit(Self &p, Visitor &&v)
  {
    v("title", p.title);
    v("engines", p.engines);
    v("seed", p.seed);
  }
};

struct OutputParameters {
  std::string directory = "results";
  bool report = true;
  bool fields = true;                   ///< VTU / XDMF field output

  template <class Self, class Visitor>
  static void visit(Self &p, Visitor &&v)
  {
    v("directory", p.directory);
    v("report", p.report);
    v("fields", p.fields);
  }
};

} // namespace geocomp
