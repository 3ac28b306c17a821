#pragma once
// @sect3{Shear-box runs read back from their results folder}
//
// Why it exists: S4's figures compare runs, not one run. Fig. 5 overlays the shear stress
// and the vertical displacement of several normal stresses; Fig. 7 plots the effective
// friction mu_b (S4 eq. 24) against the normal stress and against the contact friction. Each
// `geocomp shear-box` run writes <case>.tsv (one row per output step) and
// <case>-summary.txt (key<TAB>value lines); this reads every such pair in a folder into one
// record per run, so the report (ShearBoxReport.h) draws the figures from what was run and
// nothing else. Units as in the files, SI: m, Pa, N; compression positive, lid rise > 0 is
// dilation. The residual mu_b is the mean of the rows in the last tenth of the shear (S4's
// "critical state" end of the curve), the peak is the largest row.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace geocomp::compare {

struct ShearBoxCurvePoint
{
  double shear = 0.0;     ///< U [m]
  double lid_rise = 0.0;  ///< [m], > 0 dilation
  double tau_x = 0.0;     ///< [Pa] S4 eq. (23)
  double mu_b = 0.0;      ///< S4 eq. (24)
};

struct ShearBoxRun
{
  std::string name;             ///< the case's stem (file name without .tsv)
  double normal_stress = 0.0;   ///< sigma_n [Pa]
  double contact_friction = 0.0;
  std::uint64_t seed = 0;
  double box_length = 0.0;      ///< L [m]; 0 when the summary predates the entry
  std::size_t clumps = 0;
  double void_ratio = 0.0;      ///< at the start of shear
  double inertial_number = 0.0; ///< I = gamma_dot d sqrt(rho / sigma_n)
  double shear_speed = 0.0;     ///< [m/s]; 0 when the summary predates the entry
  double peak_mu_b = 0.0, shear_at_peak = 0.0;
  double residual_mu_b = 0.0;   ///< mean mu_b over the last tenth of the shear
  double max_contraction = 0.0; ///< [m] >= 0
  double final_dilation = 0.0;  ///< [m] lid rise at the end
  double seconds = 0.0;         ///< wall time, preparation and shear
  std::vector<ShearBoxCurvePoint> curve;
};

/// One run from `tsv` and the summary beside it (<stem>-summary.txt). Throws
/// std::runtime_error naming the file and what is missing.
ShearBoxRun read_shear_box_run(const std::filesystem::path& tsv);

/// Every <case>.tsv in `dir` that has its <case>-summary.txt, sorted by name.
std::vector<ShearBoxRun> read_shear_box_runs(const std::filesystem::path& dir);

/// Mean mu_b over the rows with U >= (1 - fraction) U_max.
double residual_mu_b(const std::vector<ShearBoxCurvePoint>& curve, double fraction = 0.1);

}  // namespace geocomp::compare
