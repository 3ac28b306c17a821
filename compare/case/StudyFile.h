#pragma once
// @sect3{A study file: several cases, or one case with one entry swept, run as one job}
//
// Why it exists: S0's figures compare runs, not one run - Fig. 4 overlays five specimens that
// differ only by their inter-particle friction, the store variants differ by packing
// fraction, restitution or friction. A study file names those cases once, with the entry
// the summary plots are drawn against (`geocomp study`, compare/StudyReport.h):
//
//   set title = S0 Fig. 4: friction series
//   subsection study
//     set cases            = ../small/s0_lateral_pressure_phi0_n3000.prm, ...   # a list of cases,
//     # or one case and an entry swept over values:
//     # set base case = ../small/s0_lateral_pressure_phi30_n3000.prm
//     # set swept entry = contact/particle friction
//     # set values = 0, 0.268, 0.577
//     set against          = contact/particle friction   # abscissa of the summary plots
//     set engines          = dem                         # optional: overrides the cases' engines
//     set overrides        = program.prm                 # optional: fragments included into every case
//     set output directory = results/studies/s0_fig4
//   end
//
// Each case of the study becomes a case file of its own, <output>/cases/<name>/<name>.prm:
// an `include` of the source case (absolute path) followed by the study's overrides - an
// `include` of each file of `overrides` (e.g. a loading program for specimens that have
// none), the swept entry's value, the engines, and output/directory = that folder - so that
// `geocomp pair` runs it alone into the same folder, and reuses or refreshes the same
// results. Case paths are relative to the study file's folder; the output directory, like a
// case's, is relative to the working directory. Reading a study parses every case it makes
// (with the case reader: includes, limits and encoding checks apply) and reads the
// `against` entry of each as a number, before anything is written; any refusal is a
// CaseError naming the study file and its parameter.
#include "compare/case/CaseDescription.h"

#include <string>
#include <vector>

namespace geocomp {

/// The entries of a study file, one home each (declared and parsed in StudyFile.cpp).
struct StudyParameters {
  std::string title;
  std::vector<std::string> cases; ///< case files, relative to the study file
  std::string base_case;          ///< or one case ...
  std::string swept_entry;        ///< ... with this entry ...
  std::vector<std::string> values; ///< ... set to each of these
  std::string against;            ///< the entry the summary plots use as abscissa
  std::vector<std::string> engines; ///< empty: each case's own
  std::vector<std::string> overrides; ///< parameter files included into every case after it
  std::string output_directory = "results/study";

  template <class Self, class Visitor>
  static void visit(Self &p, Visitor &&v)
  {
    v("cases", p.cases);
    v("base case", p.base_case);
    v("swept entry", p.swept_entry);
    v("against", p.against);
    v("engines", p.engines);
    v("overrides", p.overrides);
    v("output directory", p.output_directory);
  }
};

/// One case of a study, as the study writes and runs it.
struct StudyCase {
  std::string name;            ///< folder and file stem, unique in the study
  std::string label;           ///< legend: "<against or swept entry> = <value>" (with the name where two share it)
  std::string source;          ///< the case file it comes from (absolute)
  std::string folder;          ///< <output>/cases/<name> (absolute): its results
  std::string file;            ///< <folder>/<name>.prm, the case file the study writes
  double x = 0.0;              ///< the value of `against` in this case
  CaseDescription description; ///< parsed from the text below, as `file`
};

struct Study {
  std::string file;   ///< the study file as given
  StudyParameters parameters;
  std::string output; ///< output directory (absolute)
  std::vector<std::string> overrides; ///< the files of `overrides` (absolute)
  std::vector<StudyCase> cases;
};

/// Reads and checks a study file and every case it makes (nothing is written). Throws
/// CaseError naming the study file and its parameter ("study/values", ...), with the
/// case reader's message about the case concerned.
Study read_study(const std::string &path);

/// Every study parameter with default and help, as a .prm with comments.
std::string describe_study_parameters();

} // namespace geocomp
