#pragma once
// @sect3{The crush report: S2's curves, gradations (Fig. 7), Fig. 3 and the contact roses}
//
// Why it exists: `geocomp crush` writes tables; S2 (Zhao & Chi 2022) shows figures. This
// draws, for the runs of one results folder (CrushRuns.h), with gnuplot as the shear-box
// report does:
//
//   stress_strain.png   uniaxial runs: lid stress against vertical strain, one curve per run
//   force_approach.png  single-particle runs: platen force against approach, every particle
//                       of the first seed (each ends at its crushing force F = sigma_c d^2)
//   gradation.png       percent passing by mass against sieve size (log axis), one curve per
//                       run: S2 Fig. 7 when the folder holds one uniaxial run per mode
//                       (cube continuous, 4- and 18-ball stepped)
//   fig3.png            single-particle runs: the fragment size distribution of every seed
//                       (percent of the seed's fragments by number per size bin), S2 Fig. 3
//   *_polar_*.svg       the contact-number and mean-force roses of uniaxial runs (S2
//                       Figs. 8-11), copied in and embedded
//   index.html          the runs' table, the per-seed table of Fig. 3 (fragments, mean d/D,
//                       with the closed form of CrushRuns.h) and the figures
//   report.gp, data/    the script and what it plots
//
// Several modes in one plot come from several cases run into one folder (each run rewrites
// the report from every run there). The folder is built under a temporary name and renamed;
// without gnuplot the tables and the script are still written.
#include "compare/CrushRuns.h"

#include <filesystem>
#include <string>
#include <vector>

namespace geocomp::compare {

struct CrushReportOutcome
{
  std::filesystem::path dir;
  bool plots_made = false;
  std::vector<std::string> plots;  ///< the PNG files made (or to be made by report.gp)
  std::string message;             ///< why plots are missing, if they are
};

/// Writes the report folder `dir` (replacing an existing one) for `runs` (at least one).
CrushReportOutcome write_crush_report(const std::vector<CrushRun>& runs, const std::filesystem::path& dir,
                                      const std::string& gnuplot = "gnuplot");

}  // namespace geocomp::compare
