#include "continuum/dynamics/RateSweepCase.h"

#include "common/case/ParseParameters.h"

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>

namespace geocomp::dynamics {

using namespace dealii;

namespace {

// Entries of the material section: name in the file, help, and the S1Material field.
struct MaterialEntry {
  const char *name;
  const char *help;
  double S1Material::*field;
  double unit; ///< file value * unit = SI value
};
const MaterialEntry material_entries[] = {
  {"youngs modulus", "E [GPa]", &S1Material::youngs_modulus, 1e9},
  {"poisson ratio", "nu", &S1Material::poisson_ratio, 1.0},
  {"density", "rho [kg/m^3]", &S1Material::density, 1.0},
  {"yield stress", "sigma_y, static uniaxial compressive yield stress [MPa]", &S1Material::yield_stress, 1e6},
  {"compressive strength", "sigma_c, static [MPa]", &S1Material::compressive_strength, 1e6},
  {"tensile strength", "sigma_t, static [MPa]", &S1Material::tensile_strength, 1e6},
  {"internal friction", "alpha = 3 omega (S1 eq. (1))", &S1Material::internal_friction, 1.0},
  {"dilatancy", "Lambda (S1 eq. (2))", &S1Material::dilatancy, 1.0},
  {"plastic strain at strength",
   "axial plastic strain at the static compressive strength; sets the linear hardening (not in S1's table)",
   &S1Material::plastic_strain_at_strength, 1.0},
  {"cohesion rate gain", "B of the reconstructed S1 eq. (19), Y_dyn/Y_st = 1 + B (1 - exp(-epsdot/epsdot_r))",
   &S1Material::cohesion_rate_gain, 1.0},
  {"reference rate", "epsdot_r of S1 eqs. (19), (23), (29) [1/s]", &S1Material::reference_rate, 1.0},
};

void declare(ParameterHandler &prm)
{
  prm.declare_entry("title", "", Patterns::Anything(), "A title for the plot and the table.");
  prm.enter_subsection("material");
  prm.declare_entry("preset", "sandstone", Patterns::Selection("concrete|sandstone"),
                    "Row of S1's material table the entries below start from.");
  for (const auto &e : material_entries)
    prm.declare_entry(e.name, "", Patterns::Anything(),
                      std::string(e.help) + ". Empty: the preset's value.");
  prm.leave_subsection();
  prm.enter_subsection("specimen");
  prm.declare_entry("width", "6", Patterns::Double(0.0), "Width [mm] (S1: 6 mm).");
  prm.declare_entry("height", "9", Patterns::Double(0.0), "Height along the load [mm] (S1: 9 mm).");
  prm.declare_entry("cells in x", "8", Patterns::Integer(2, 200), "Q1 cells across the width (even).");
  prm.declare_entry("cells in y", "12", Patterns::Integer(2, 300), "Q1 cells along the height.");
  prm.leave_subsection();
  prm.enter_subsection("loading");
  prm.declare_entry("mode", "compression", Patterns::Selection("compression|tension"), "Uniaxial compression or tension.");
  prm.declare_entry("strain rates", "1e-3, 1e-2, 1e-1, 1, 1e1, 1e2, 1e3", Patterns::List(Patterns::Double(0.0)),
                    "Nominal axial strain rates [1/s], each > 0 and <= 1e4.");
  prm.declare_entry("kinetic", "both", Patterns::Selection("on|off|both"),
                    "The kinetic extension (relaxation and incubation times): on, off (S1 Fig. 6: inertia only) "
                    "or both.");
  prm.leave_subsection();
  prm.enter_subsection("dynamics");
  prm.declare_entry("time step safety", "0.5", Patterns::Double(0.0, 1.0), "dt = safety * h_min / c, in (0, 1].");
  prm.declare_entry("quasi-static transits", "100", Patterns::Double(1.0),
                    "Density scaling of slow rates: the time to the static strength is at least this many wave "
                    "transits of the specimen height (>= 1).");
  prm.declare_entry("stop load fraction", "0.5", Patterns::Double(0.0, 1.0),
                    "A test stops once a point fractured and the end load fell below this fraction of its peak.");
  prm.declare_entry("fixed bottom", "false", Patterns::Bool(),
                    "false: both platens move at epsdot H / 2 and the strength is their mean force; true: the "
                    "bottom platen stays, the top one moves at epsdot H and the strength is its force.");
  prm.declare_entry("platens", "smooth", Patterns::Selection("smooth|bonded"),
                    "smooth: the ends slide freely along the platens (u_x held at the middle node only); "
                    "bonded: no end node slides (rough platens, the ends cannot expand laterally). S1 does not "
                    "say which.");
  prm.declare_entry("platen rise fraction", "0.5", Patterns::Double(0.0, 1.0),
                    "The platen speed rises smoothly (half cosine) from rest to its constant value over this "
                    "fraction of t_st = sigma_st / (E epsdot); 0: impulsive start.");
  prm.leave_subsection();
  prm.enter_subsection("output");
  prm.declare_entry("directory", "results/s1", Patterns::Anything(), "Where the TSV table, SVG plot and gnuplot "
                                                                      "script go.");
  prm.leave_subsection();
}

} // namespace

RateSweepCase parse_rate_sweep_case(const std::string &text, const std::string &path)
{
  ParameterHandler prm;
  declare(prm);
  parse_parameter_text(prm, text, path);
  auto fail = [&](const std::string &parameter, const std::string &expectation) {
    throw CaseError(path, parameter, expectation);
  };
  RateSweepCase c;
  c.file = path;
  RateSweepSetup &s = c.setup;
  s.title = prm.get("title");

  prm.enter_subsection("material");
  s.material = S1Material::preset(prm.get("preset"));
  for (const auto &e : material_entries) {
    const std::string v = prm.get(e.name);
    if (v.find_first_not_of(" \t") == std::string::npos)
      continue;
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(v, &used);
    } catch (const std::exception &) {
      used = 0;
    }
    if (used == 0 || v.find_first_not_of(" \t", used) != std::string::npos || !std::isfinite(x))
      fail(std::string("material/") + e.name, "'" + v + "' is not a number: expected " + e.help);
    s.material.*(e.field) = x * e.unit;
  }
  s.material.name = prm.get("preset");
  prm.leave_subsection();
  try {
    s.material.validate();
  } catch (const std::invalid_argument &e) {
    const std::string what = e.what();
    const auto colon = what.find(':');
    fail("material/" + what.substr(0, colon), what.substr(colon + 2));
  }

  prm.enter_subsection("specimen");
  s.geometry.width = prm.get_double("width") * 1e-3;
  s.geometry.height = prm.get_double("height") * 1e-3;
  s.geometry.cells_x = prm.get_integer("cells in x");
  s.geometry.cells_y = prm.get_integer("cells in y");
  prm.leave_subsection();
  if (!(s.geometry.width > 0.0))
    fail("specimen/width", "a positive width [mm]");
  if (!(s.geometry.height > 0.0))
    fail("specimen/height", "a positive height [mm]");
  if (s.geometry.cells_x % 2 != 0)
    fail("specimen/cells in x", "an even number, so that a node sits at mid-width (got " +
                                    std::to_string(s.geometry.cells_x) + ")");

  prm.enter_subsection("loading");
  s.mode = prm.get("mode") == "tension" ? LoadingMode::tension : LoadingMode::compression;
  const std::string rates = prm.get("strain rates");
  std::istringstream rs(rates);
  for (std::string item; std::getline(rs, item, ',');) {
    const double r = std::stod(item);
    if (!(r > 0.0 && r <= 1e4))
      fail("loading/strain rates", "every rate in (0, 1e4] 1/s (got " + item + ")");
    s.strain_rates.push_back(r);
  }
  if (s.strain_rates.empty())
    fail("loading/strain rates", "at least one strain rate");
  const std::string kinetic = prm.get("kinetic");
  s.kinetic_modes = kinetic == "on" ? std::vector<bool>{true} : kinetic == "off" ? std::vector<bool>{false}
                                                                                 : std::vector<bool>{true, false};
  prm.leave_subsection();

  prm.enter_subsection("dynamics");
  s.controls.time_step_safety = prm.get_double("time step safety");
  s.controls.quasi_static_transits = prm.get_double("quasi-static transits");
  s.controls.stop_load_fraction = prm.get_double("stop load fraction");
  s.controls.platen_rise_fraction = prm.get_double("platen rise fraction");
  s.controls.fixed_bottom = prm.get_bool("fixed bottom");
  s.controls.bonded_platens = prm.get("platens") == "bonded";
  prm.leave_subsection();
  if (!(s.controls.time_step_safety > 0.0))
    fail("dynamics/time step safety", "a value in (0, 1]");

  prm.enter_subsection("output");
  c.output_directory = prm.get("directory");
  prm.leave_subsection();
  if (c.output_directory.empty())
    fail("output/directory", "a directory name");
  return c;
}

RateSweepCase read_rate_sweep_case(const std::string &path)
{
  return parse_rate_sweep_case(read_parameter_file(path, ".prm rate-sweep case file"), path);
}

std::string describe_rate_sweep_parameters()
{
  ParameterHandler prm;
  declare(prm);
  std::ostringstream out;
  prm.print_parameters(out, ParameterHandler::Text);
  return out.str();
}

} // namespace geocomp::dynamics
