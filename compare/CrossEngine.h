#pragma once
// @sect3{Two DEM engines on one specimen: is a difference the engine's or the specimen's?}
//
// Why it exists: geocomp's DEM and LIGGGHTS play the same specimen under the same loading
// program (issue 34). Their curves differ by what the engines do differently (contact
// histories, time integration, the servo's stiffness estimate); another specimen of the same
// material differs from the first by its fabric. The report puts the two beside each other.
//
// Both engines' curves are extracted as the metrics read them (Metrics.h, extract_curve: the
// analysed stage's main path, strains relative to its start), from the instantaneous wall
// stresses of both (LIGGGHTS has no interval mean). On the reference's samples x_i (the
// curve's abscissa: axial strain, or gamma_max) that lie inside the other curve's range, the
// other's value is interpolated linearly in x, and for each curve f
//   rms_f = sqrt( (1/n) sum_i (f_other(x_i) - f_ref(x_i))^2 ) / s_f,
// with the scale s_f of the reference's curve:
//  - stress ratio eta = q / p', p' = -tr(sigma)/3 (compression positive), q von Mises:
//    s = max_i |eta_ref|;
//  - volumetric strain eps_v = ln(V/V_start) (dilation positive): s = max(max_i |eps_v,ref|, 1e-3),
//    so that an isochoric program's eps_v (round-off about zero) is not divided by round-off;
//  - the curve the report plots (y: -sigma_aa or tau_max): s = max_i |y_ref|.
// The verdict is "engines agree within X %", X the larger relative rms of eta and eps_v,
// rounded up to 0.1 %. With other specimens of the same program (calibration/scatter), the
// reference engine's rms against each of them is computed the same way: the seed-to-seed
// difference the engines' difference is to be read against.
#include "compare/Metrics.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geocomp::compare {

/// One curve's difference between the engines, and the reference's against each other specimen.
struct CrossEngineRow {
  std::string key;              ///< "stress_ratio", "volumetric_strain", "curve"
  std::string label;            ///< for the report
  double scale = nan;           ///< s_f
  double engines = nan;         ///< rms_f between the engines, relative (fraction)
  std::vector<double> specimens; ///< rms_f of the reference against each other specimen
};

struct CrossEngineTable {
  std::string reference, other;       ///< engine labels, e.g. "DEM" and "LIGGGHTS"
  std::size_t common_samples = 0;     ///< n: the reference's samples inside the other's range
  std::vector<std::string> specimens; ///< names of the other specimens (results files)
  std::vector<CrossEngineRow> rows;
  double agreement = nan;    ///< X / 100: the larger of the stress-ratio and volumetric rms
  std::string verdict;       ///< "engines agree within X %"
  std::string scatter_note;  ///< the engines' difference against the specimens' (empty: none given)
};

/// A curve to compare, named, as extracted from a Response.
struct NamedCurve {
  std::string name;
  Curve curve;
};

/// The section for `reference` and `other`, with `specimens` (other specimens of the
/// reference's program; may be empty). Throws std::invalid_argument when fewer than 3 of the
/// reference's samples lie inside the other's range.
CrossEngineTable cross_engine_table(const NamedCurve &reference, const NamedCurve &other,
                                    const std::vector<NamedCurve> &specimens);

/// rms_f of `other` against `reference` for the curve `key` (as above; relative), and n.
std::pair<double, std::size_t> relative_rms(const Curve &reference, const Curve &other, const std::string &key);

} // namespace geocomp::compare
