#pragma once
// The `calibration` section of a case file, as plain data: what `geocomp calibrate` fits
// (docs/calibration.md). Declared and parsed in CalibrationSection.cpp (library
// geocomp_calibration_case); `visit` lists every entry for the canonical text
// (`/meta/parameters`), in declaration order.
#include "common/case/CanonicalText.h"

#include <string>
#include <vector>

namespace geocomp {

/// Bounds of one calibrated parameter family ("E", "nu", "cohesion", "friction",
/// "dilatancy"), in case-file units (Pa, degrees).
struct ParameterBounds {
  std::string name;
  double lower = 0.0, upper = 0.0;
};

/// One response quantity fitted by `geocomp calibrate` and its weight: "q" (deviator
/// sqrt(3 J2)), "p" (mean stress) or "eps_v" (volumetric strain).
struct FittedQuantity {
  std::string name;
  double weight = 1.0;
};

/// The rungs of the model ladder (calibration/ladder, compare/calibrate/Ladder.h), in the
/// order of their number of parameters on a case with tables.
inline const std::vector<std::string> &ladder_rung_names()
{
  static const std::vector<std::string> names{"mohr-coulomb constant", "mohr-coulomb tables", "drucker-prager",
                                              "nikolaevsky"};
  return names;
}

/// What `geocomp calibrate` fits (docs/calibration.md).
struct CalibrationParameters {
  std::vector<std::string> targets;     ///< results files (.h5) of the curves to fit, e.g. DEM runs
  std::vector<double> weights;          ///< one per target; empty: all 1
  /// E, nu, cohesion, friction, dilatancy; a table name frees all its knots, name[k] one knot.
  std::vector<std::string> free_parameters{"E", "nu", "cohesion", "friction", "dilatancy"};
  std::vector<ParameterBounds> bounds;  ///< overrides of the default bounds
  std::string starting_values = "closed-form"; ///< closed-form | case
  std::vector<FittedQuantity> quantities{{"q", 1.0}, {"eps_v", 1.0}}; ///< residuals at each sample
  unsigned int max_iterations = 100;
  std::string output_file = "calibrated.prm"; ///< inside the output directory's calibration/ folder
  /// The continuum `pair` runs: "as given" (the continuum section) or "calibrated" (fitted to
  /// the pair's own DEM run and the targets first).
  std::string pair_continuum = "as given";
  /// In a calibrated pair, the pair's DEM run "fitted" or "held out" (predicted, not fitted).
  std::string pair_dem = "fitted";
  /// Results files of the pair's program on other specimens: the DEM's scatter band in the report.
  std::vector<std::string> scatter;
  /// The model ladder: each rung (ladder_rung_names()) fitted to the same curves, with its
  /// residual and information criteria; empty: none.
  std::vector<std::string> ladder;

  /// Every entry, written as the case file gives it (bounds as `name:lower:upper`,
  /// quantities as `name:weight`); read-only (the lists are rebuilt for writing).
  template <class V>
  static void visit(const CalibrationParameters &p, V &&v)
  {
    v("targets", p.targets);
    v("weights", p.weights);
    v("free parameters", p.free_parameters);
    std::vector<std::string> bounds, quantities;
    for (const ParameterBounds &b : p.bounds)
      bounds.push_back(b.name + ":" + canonical_number(b.lower) + ":" + canonical_number(b.upper));
    for (const FittedQuantity &q : p.quantities)
      quantities.push_back(q.name + ":" + canonical_number(q.weight));
    v("bounds", bounds);
    v("starting values", p.starting_values);
    v("quantities", quantities);
    v("max iterations", p.max_iterations);
    v("pair continuum", p.pair_continuum);
    v("pair dem", p.pair_dem);
    v("scatter", p.scatter);
    v("ladder", p.ladder);
    v("output file", p.output_file);
  }
};

} // namespace geocomp
