#pragma once
// @sect3{The shear-box report: S4's Fig. 5 and Fig. 7 from the runs in a folder}
//
// Why it exists: S4 (Yan & Ji 2009) shows its direct shear results as two figures. Fig. 5:
// the vertical displacement of the lid and the shear stress tau_x = F_S / (B (L - U))
// (S4 eq. 23) against the shear displacement U, one curve per normal stress (and here a third
// panel: the first fifth of the shear, lid in um, where the contraction shows). Fig. 7: the
// effective friction mu_b = F_S / F_N (S4 eq. 24) (a) against the normal stress and (b)
// against the contact friction. This writes them for the runs of one results folder
// (ShearBoxRuns.h) as gnuplot plots in a self-contained report folder:
//
//   index.html   the runs' table (sigma_n, contact mu, seed, e, inertial number
//                I = gamma_dot d sqrt(rho / sigma_n), peak and residual mu_b, contraction,
//                dilation, wall time), the means over seeds, and the figures
//   report.gp    the gnuplot script (run `gnuplot report.gp` in the folder to redraw)
//   data/*.dat   what it plots (mm, kPa)
//   fig5.png, fig7.png
//
// Fig. 7 groups runs that differ only by the abscissa: (a) one series per box length and
// contact friction, (b) one per box length and normal stress; each series shows every
// run's peak mu_b (filled) and residual mu_b (open, the mean over the last tenth of the
// shear) and a line through the means over seeds. The folder is built under a temporary
// name and renamed into place; without gnuplot the tables and the script are still written.
#include "compare/ShearBoxRuns.h"

#include <filesystem>
#include <string>
#include <vector>

namespace geocomp::compare {

struct ShearBoxReportOutcome
{
  std::filesystem::path dir;
  bool plots_made = false;
  std::string message;  ///< why plots are missing, if they are
};

/// Writes the report folder `dir` (replacing an existing one) for `runs` (at least one).
ShearBoxReportOutcome write_shear_box_report(const std::vector<ShearBoxRun>& runs, const std::filesystem::path& dir,
                                             const std::string& gnuplot = "gnuplot");

/// One point of a Fig. 7 series: the abscissa, and the peak and residual mu_b of each run
/// there; the means are over the runs (seeds).
struct MuBPoint
{
  double x = 0.0;
  std::vector<double> peak, residual;
  double mean_peak() const;
  double mean_residual() const;
};

struct MuBSeries
{
  std::string label;            ///< e.g. "L = 6 cm, contact mu = 0.7"
  std::vector<MuBPoint> points; ///< by increasing x
};

/// Fig. 7(a): mu_b against sigma_n [kPa], a series per (box length, contact friction).
std::vector<MuBSeries> mu_b_against_normal_stress(const std::vector<ShearBoxRun>& runs);
/// Fig. 7(b): mu_b against the contact friction, a series per (box length, sigma_n).
std::vector<MuBSeries> mu_b_against_contact_friction(const std::vector<ShearBoxRun>& runs);

}  // namespace geocomp::compare
