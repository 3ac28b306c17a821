// The `calibration` section: which curves `geocomp calibrate` fits, which continuum
// parameters are free, their bounds and weights (docs/calibration.md).
#include "compare/calibrate/CalibrationSection.h"

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <regex>

namespace geocomp::sections {

using dealii::Patterns::Anything;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void declare_calibration(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("calibration");
  prm.declare_entry("targets", "", Anything(),
                    "Comma-separated results files (.h5, e.g. results/<case>/dem.h5) whose main-path curves "
                    "are fitted; each file carries the case it was run from, so its loading program is "
                    "replayed on the material point. A case file (.prm, .json) stands for its DEM run "
                    "(<its output directory>/dem.h5), which `pair` and `calibrate` run first (reused when "
                    "up to date).");
  prm.declare_entry("weights", "", Anything(), "One weight per target (default: all 1).");
  prm.declare_entry("free parameters", "E, nu, cohesion, friction, dilatancy", Anything(),
                    "Continuum parameters to fit: E, nu, and the tables cohesion, friction, dilatancy "
                    "(all knots; the knots' kappa stay fixed) or one knot as name[k], k from 0.");
  prm.declare_entry("bounds", "", Anything(),
                    "Overrides of the default bounds, 'name: lower upper; ...' in Pa and degrees "
                    "(defaults E: 1e5 1e12; nu: 0 0.49; cohesion: 0 1e9; friction: 0.5 85; dilatancy: 0 60).");
  prm.declare_entry("starting values", "closed-form", Selection("closed-form|case"),
                    "Start from closed-form estimates from the target curves (E, nu from the initial slopes, "
                    "phi and c from the peak Mohr envelope, psi from the volumetric slope) or from the "
                    "continuum section's values.");
  prm.declare_entry("quantities", "q, eps_v", Anything(),
                    "Response quantities compared at every main-path sample of every target, each "
                    "optionally with a weight as name:weight (default 1): q (deviator stress sqrt(3 J2), "
                    "scaled by the target's largest q), p (mean stress, scaled by the same largest q; the "
                    "quantity that shows dilatancy in isochoric shear), eps_v (volumetric strain, scaled by "
                    "its range, at least 1e-3).");
  prm.declare_entry("max iterations", "100", Integer(1, 100000), "Levenberg-Marquardt iterations at most.");
  prm.declare_entry("pair continuum", "as given", Selection("as given|calibrated"),
                    "The continuum `pair` runs: the continuum section as given, or first calibrated to the "
                    "pair's own DEM run (and to the targets above): the DEM runs first, the fit and its "
                    "report go to <output directory>/calibration/, and the material point and the FE cube "
                    "run the calibrated section (`pair --calibrate` sets calibrated).");
  prm.declare_entry("pair dem", "fitted", Selection("fitted|held out"),
                    "In a calibrated pair, whether the pair's own DEM run is among the curves fitted, or held "
                    "out: fitted to the targets alone, the continuum then predicts the pair's program, and the "
                    "report separates the curves calibrated on (fit residuals) from the one predicted.");
  prm.declare_entry("scatter", "", Anything(),
                    "Comma-separated results files of the pair's program run on other specimens (seeds, store "
                    "variants): with the pair's own DEM run they give each metric's specimen-to-specimen band, "
                    "and `pair`'s report says whether each continuum engine's value lies within it.");
  prm.declare_entry("ladder", "", Anything(),
                    "Comma-separated model ladder: each rung fitted to the same curves as the calibration, with "
                    "its number of parameters, residual, AIC and BIC (and the held-out curve's error in a pair "
                    "with pair dem = held out): mohr-coulomb constant (E, nu, c, phi, psi each one value), "
                    "mohr-coulomb tables (the free parameters above on the continuum's tables), drucker-prager "
                    "(the same, behind the Drucker-Prager matching), nikolaevsky (S1's quasi-static model: E, nu, "
                    "sigma_y, sigma_c, alpha, Lambda). Empty: no ladder.");
  prm.declare_entry("output file", "calibrated.prm", Anything(),
                    "The calibrated 'subsection continuum' fragment, written to <output directory>/calibration/; "
                    "case files pull it in with 'include <path>'.");
  prm.leave_subsection();
}

CalibrationParameters parse_calibration(dealii::ParameterHandler &prm, const Reader &r,
                                        const ContinuumParameters &continuum)
{
  CalibrationParameters p;
  p.quantities.clear();
  prm.enter_subsection("calibration");
  p.targets = dealii::Utilities::split_string_list(prm.get("targets"));
  const std::vector<std::string> weights = dealii::Utilities::split_string_list(prm.get("weights"));
  p.free_parameters = dealii::Utilities::split_string_list(prm.get("free parameters"));
  const std::string bounds = prm.get("bounds");
  p.starting_values = prm.get("starting values");
  const std::vector<std::string> quantities = dealii::Utilities::split_string_list(prm.get("quantities"));
  p.max_iterations = prm.get_integer("max iterations");
  p.output_file = prm.get("output file");
  p.pair_continuum = prm.get("pair continuum");
  p.pair_dem = prm.get("pair dem");
  p.scatter = dealii::Utilities::split_string_list(prm.get("scatter"));
  p.ladder = dealii::Utilities::split_string_list(prm.get("ladder"));
  prm.leave_subsection();

  const std::vector<std::string> &rungs = ladder_rung_names();
  for (std::size_t k = 0; k < p.ladder.size(); ++k) {
    if (std::find(rungs.begin(), rungs.end(), p.ladder[k]) == rungs.end())
      r.fail("calibration/ladder", "'" + p.ladder[k] + "' is not a rung of the model ladder (expected " +
                                     "mohr-coulomb constant, mohr-coulomb tables, drucker-prager or nikolaevsky)");
    if (std::find(p.ladder.begin(), p.ladder.begin() + long(k), p.ladder[k]) != p.ladder.begin() + long(k))
      r.fail("calibration/ladder", "'" + p.ladder[k] + "' is named twice: expected each rung once");
  }

  for (const auto &w : weights) {
    char *end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0' || !(v >= 0.0) || !std::isfinite(v))
      r.fail("calibration/weights", "'" + w + "' is not a weight (expected a number >= 0)");
    p.weights.push_back(v);
  }
  if (!p.weights.empty() && p.weights.size() != p.targets.size())
    r.fail("calibration/weights", "expected one weight per target (" + std::to_string(p.targets.size()) +
                                    "), got " + std::to_string(p.weights.size()));
  const std::regex name("(E|nu|cohesion|friction|dilatancy)(?:\\[([0-9]+)\\])?");
  for (const auto &f : p.free_parameters) {
    std::smatch m;
    if (!std::regex_match(f, m, name))
      r.fail("calibration/free parameters",
             "'" + f + "' is not a parameter (expected E, nu, cohesion, friction, dilatancy or name[k])");
    const std::string family = m[1];
    const HardeningTable *table = family == "cohesion"   ? &continuum.cohesion
                                  : family == "friction" ? &continuum.friction_angle
                                  : family == "dilatancy" ? &continuum.dilatancy_angle
                                                          : nullptr;
    if (m[2].matched && !table)
      r.fail("calibration/free parameters", "'" + f + "': " + family + " is a number, not a table with knots");
    if (m[2].matched && (m[2].length() > 6 || std::stoul(m[2].str()) >= table->points.size()))
      r.fail("calibration/free parameters", "'" + f + "': the continuum " + family + " table has " +
                                              std::to_string(table->points.size()) + " knots (0 ... " +
                                              std::to_string(table->points.size() - 1) + ")");
  }
  if (p.free_parameters.empty())
    r.fail("calibration/free parameters", "expected at least one free parameter");
  for (const auto &item : quantities) {
    const std::regex form("(q|p|eps_v)\\s*(?::\\s*(\\S+))?");
    std::smatch m;
    FittedQuantity q;
    if (std::regex_match(item, m, form)) {
      q.name = m[1];
      char *end = nullptr;
      const std::string w = m[2].matched ? m[2].str() : "1";
      q.weight = std::strtod(w.c_str(), &end);
      const bool repeated = std::any_of(p.quantities.begin(), p.quantities.end(),
                                        [&](const FittedQuantity &o) { return o.name == q.name; });
      if (*end == '\0' && std::isfinite(q.weight) && q.weight > 0.0 && !repeated) {
        p.quantities.push_back(q);
        continue;
      }
    }
    r.fail("calibration/quantities",
           "'" + item + "' is not a fitted quantity (expected q, p or eps_v, each once, optionally as name:weight with weight > 0)");
  }
  if (p.quantities.empty())
    r.fail("calibration/quantities", "expected at least one of q, p, eps_v");
  for (const auto &item : dealii::Utilities::split_string_list(bounds, ';')) {
    const std::regex form("\\s*(E|nu|cohesion|friction|dilatancy)\\s*:\\s*(\\S+)\\s+(\\S+)\\s*");
    std::smatch m;
    ParameterBounds b;
    char *e1 = nullptr, *e2 = nullptr;
    if (std::regex_match(item, m, form)) {
      const std::string lo = m[2], hi = m[3];
      b.name = m[1];
      b.lower = std::strtod(lo.c_str(), &e1);
      b.upper = std::strtod(hi.c_str(), &e2);
      if (*e1 == '\0' && *e2 == '\0' && std::isfinite(b.lower) && std::isfinite(b.upper) && b.lower < b.upper) {
        p.bounds.push_back(b);
        continue;
      }
    }
    r.fail("calibration/bounds", "'" + item + "' is not 'name: lower upper' with finite lower < upper");
  }
  // Written inside <output>/calibration/: a name, not a path that leads elsewhere.
  if (p.output_file.empty() || p.output_file == "." || p.output_file == ".." ||
      p.output_file.find('/') != std::string::npos)
    r.fail("calibration/output file", "'" + p.output_file + "' is not a file name: expected a name without a folder");
  return p;
}

} // namespace geocomp::sections
