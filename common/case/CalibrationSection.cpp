// The `calibration` section: which curves `geocomp calibrate` fits, which continuum
// parameters are free, their bounds and weights (docs/calibration.md).
#include "common/case/Sections.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <regex>

namespace geocomp::sections {

using dealii::Patterns::Anything;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void declare_calibration(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("calibration");
  prm.declare_entry("targets", "", Anything(),
                    "Comma-separated results files (.h5, e.g. results/<case>/dem.h5) whose main-path curves "
                    "are fitted; each file carries the case it was run from, so its loading program is "
                    "replayed on the material point.");
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
  prm.declare_entry("volumetric weight", "1", Double(0, 1e6),
                    "Weight of the volumetric-strain residuals relative to the deviator-stress residuals.");
  prm.declare_entry("max iterations", "100", Integer(1, 100000), "Levenberg-Marquardt iterations at most.");
  prm.declare_entry("output file", "calibrated.prm", Anything(),
                    "The calibrated 'subsection continuum' fragment, written to <output directory>/calibration/; "
                    "case files pull it in with 'include <path>'.");
  prm.leave_subsection();
}

CalibrationParameters parse_calibration(dealii::ParameterHandler &prm, const Reader &r)
{
  CalibrationParameters p;
  prm.enter_subsection("calibration");
  p.targets = dealii::Utilities::split_string_list(prm.get("targets"));
  const std::vector<std::string> weights = dealii::Utilities::split_string_list(prm.get("weights"));
  p.free_parameters = dealii::Utilities::split_string_list(prm.get("free parameters"));
  const std::string bounds = prm.get("bounds");
  p.starting_values = prm.get("starting values");
  p.volumetric_weight = prm.get_double("volumetric weight");
  p.max_iterations = prm.get_integer("max iterations");
  p.output_file = prm.get("output file");
  prm.leave_subsection();

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
  const std::regex name("(E|nu|cohesion|friction|dilatancy)(\\[[0-9]+\\])?");
  for (const auto &f : p.free_parameters)
    if (!std::regex_match(f, name))
      r.fail("calibration/free parameters",
             "'" + f + "' is not a parameter (expected E, nu, cohesion, friction, dilatancy or name[k])");
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
      if (*e1 == '\0' && *e2 == '\0' && b.lower < b.upper) {
        p.bounds.push_back(b);
        continue;
      }
    }
    r.fail("calibration/bounds", "'" + item + "' is not 'name: lower upper' with lower < upper");
  }
  if (p.output_file.empty())
    r.fail("calibration/output file", "expected a file name");
  return p;
}

} // namespace geocomp::sections
