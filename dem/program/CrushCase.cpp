#include "dem/program/CrushCase.h"

#include "common/case/ParseParameters.h"

#include <deal.II/base/parameter_handler.h>

#include <sstream>

namespace geocomp::dem {

using namespace dealii;

namespace {

void declare(ParameterHandler &prm)
{
  prm.declare_entry("title", "", Patterns::Anything(), "A title for the outputs.");
  prm.enter_subsection("program");
  prm.declare_entry("mode", "single particle", Patterns::Selection("single particle|uniaxial"),
                    "S2's single-particle crushing test or the uniaxial (oedometric) compression.");
  prm.declare_entry("time step safety", "0.2", Patterns::Double(0.0, 1.0),
                    "dt = safety * critical step of the current particles (recomputed after breakage).");
  prm.declare_entry("record interval", "200", Patterns::Integer(1), "Steps between rows of the curve table.");
  prm.leave_subsection();
  prm.enter_subsection("material");
  prm.declare_entry("density", "2650", Patterns::Double(0.0), "Particle density [kg/m^3].");
  prm.declare_entry("density scaling", "1", Patterns::Double(1.0),
                    "Uniform mass scaling factor (>= 1) for quasi-static runs: lengthens the time step by its "
                    "square root.");
  prm.leave_subsection();
  prm.enter_subsection("contact");
  prm.declare_entry("normal stiffness", "7.0e7", Patterns::Double(0.0), "kn [N/m] (S2: 7.0e7).");
  prm.declare_entry("shear stiffness", "6.0e7", Patterns::Double(0.0), "ks [N/m] (S2: 6.0e7).");
  prm.declare_entry("friction", "0.40", Patterns::Double(0.0), "Particle friction mu (S2: 0.40).");
  prm.declare_entry("rolling friction", "0.70", Patterns::Double(0.0), "Rolling resistance mu_r (S2: 0.70).");
  prm.declare_entry("restitution", "0.3", Patterns::Double(0.0, 1.0), "Normal dashpot as a restitution e.");
  prm.declare_entry("wall friction", "0.0", Patterns::Double(0.0), "Friction of platens and box walls.");
  prm.declare_entry("local damping", "0.7", Patterns::Double(0.0, 1.0), "Cundall local damping (PFC: 0.7).");
  prm.leave_subsection();
  prm.enter_subsection("breakage");
  prm.declare_entry("mode", "cube", Patterns::Selection("cube|4-ball|18-ball"),
                    "Fragment replacement: S2's cube mode, McDowell's 4-ball, Ciantia's 18-ball.");
  prm.declare_entry("cut point", "squared", Patterns::Selection("plain|squared|cubed"),
                    "Cube mode: random cut point (a,b,c), (a^2,b^2,c^2) (S2's choice) or cubed.");
  prm.declare_entry("minimum size", "1", Patterns::Double(0.0), "d_M [mm]: smaller children are dropped (S2: 1).");
  prm.declare_entry("breakage limit", "5", Patterns::Double(0.0), "d_L [mm]: smaller particles never break (S2: 5).");
  prm.declare_entry("characteristic strength", "10", Patterns::Double(0.0),
                    "sigma_c [MPa] of S2 eq. (3), F_max / d^2 >= sigma_c (S2 gives no value).");
  prm.declare_entry("weibull modulus", "0", Patterns::Double(0.0),
                    "m of sigma_c(d) = sigma_c (d/d0)^(-3/m); 0: no size effect (S2).");
  prm.declare_entry("reference size", "29", Patterns::Double(0.0), "d0 [mm] of the Weibull size effect.");
  prm.declare_entry("check interval", "20", Patterns::Integer(1), "Steps between checks of the criterion.");
  prm.declare_entry("seed", "1", Patterns::Integer(0), "Seed of the fragment generator.");
  prm.declare_entry("overlap release speed", "0.05", Patterns::Double(0.0),
                    "u [m/s]: the fragments' overlaps at placement fall to zero at this speed (0: at once); "
                    "the kinetic energy a released pair gains is at most 2 m* u^2.");
  prm.declare_entry("shelter siblings", "false", Patterns::Bool(),
                    "Former scheme: children of one parent ignore each other until they no longer overlap "
                    "(compressed, they pass through each other).");
  prm.leave_subsection();
  prm.enter_subsection("single particle");
  prm.declare_entry("particles", "100", Patterns::Integer(1, 100000), "Number of particles crushed (S2: 100).");
  prm.declare_entry("minimum diameter", "28", Patterns::Double(0.0), "[mm] (S2: 28).");
  prm.declare_entry("maximum diameter", "30", Patterns::Double(0.0), "[mm] (S2: 30).");
  prm.declare_entry("platen speed", "0.01", Patterns::Double(0.0), "Closing speed of the two platens [m/s].");
  prm.declare_entry("seed", "1", Patterns::Integer(0), "Seed of the particle sizes.");
  prm.declare_entry("seeds", "1", Patterns::Integer(1, 1000),
                    "Repetitions of the whole test, each with its own cut points (S2 Fig. 3: ten seeds); "
                    "particle i of repetition r uses the fragment seed breakage/seed + r particles + i.");
  prm.leave_subsection();
  prm.enter_subsection("uniaxial");
  prm.declare_entry("diameter", "40", Patterns::Double(0.0), "One-size particle diameter [mm] (S2: 40).");
  prm.declare_entry("particles per edge", "5", Patterns::Integer(2, 40), "Lattice sites per box edge (n^3 spheres).");
  prm.declare_entry("packing", "lattice", Patterns::Selection("lattice|grown"),
                    "lattice: jittered simple cubic lattice (loose, load columns); grown: random placement and "
                    "frictionless radius growth to the packing fraction (S2 Figs. 8-11 need a random packing).");
  prm.declare_entry("packing fraction", "0.45", Patterns::Double(0.05, 0.64),
                    "grown: nominal solid fraction after growth, below jamming (the wall layers of a small box "
                    "jam it early: 0.55 is jammed for 216 spheres).");
  prm.declare_entry("lattice gap", "0.1", Patterns::Double(0.0, 1.0), "Lattice spacing d (1 + gap); jitter up to gap d/2.");
  prm.declare_entry("seating stress", "50", Patterns::Double(0.0), "Lid stress [kPa] that ends seating.");
  prm.declare_entry("seating speed", "0.5", Patterns::Double(0.0), "Lid speed during seating [m/s].");
  prm.declare_entry("lid speed", "0.05", Patterns::Double(0.0), "Lid speed during compression [m/s].");
  prm.declare_entry("final strain", "0.1", Patterns::Double(0.0, 0.6), "Vertical strain at the end.");
  prm.declare_entry("seed", "1", Patterns::Integer(0), "Seed of the lattice jitter.");
  prm.leave_subsection();
  prm.enter_subsection("output");
  prm.declare_entry("directory", "results/s2", Patterns::Anything(), "Where the TSV tables go.");
  prm.declare_entry("gradation bin", "2", Patterns::Double(0.0), "Sieve spacing [mm] (S2 Fig. 7: 2).");
  prm.declare_entry("polar bins", "36", Patterns::Integer(4, 720),
                    "Angular bins of the contact polar distributions (S2 Figs. 8-11), even (36: 10 deg).");
  prm.declare_entry("polar walls", "false", Patterns::Bool(),
                    "Bin particle-wall contacts too (S2 counts particle contacts: false).");
  prm.leave_subsection();
}

} // namespace

CrushCase parse_crush_case(const std::string &text, const std::string &path)
{
  ParameterHandler prm;
  declare(prm);
  parse_parameter_text(prm, text, path);
  auto fail = [&](const std::string &parameter, const std::string &expectation) {
    throw CaseError(path, parameter, expectation);
  };
  auto positive = [&](double v, const std::string &parameter, const std::string &what) {
    if (!(v > 0.0))
      fail(parameter, "a positive " + what);
    return v;
  };
  CrushCase c;
  c.file = path;
  CrushSetup &s = c.setup;
  s.title = prm.get("title");

  prm.enter_subsection("program");
  s.mode = prm.get("mode");
  s.time_step_safety = positive(prm.get_double("time step safety"), "program/time step safety", "value in (0, 1]");
  s.record_interval = std::uint64_t(prm.get_integer("record interval"));
  prm.leave_subsection();

  prm.enter_subsection("material");
  s.density = positive(prm.get_double("density"), "material/density", "density [kg/m^3]");
  s.density_scaling = prm.get_double("density scaling");
  prm.leave_subsection();

  prm.enter_subsection("contact");
  s.contact.normal_stiffness = positive(prm.get_double("normal stiffness"), "contact/normal stiffness", "kn [N/m]");
  s.contact.shear_stiffness = positive(prm.get_double("shear stiffness"), "contact/shear stiffness", "ks [N/m]");
  s.contact.friction = prm.get_double("friction");
  s.contact.rolling_friction = prm.get_double("rolling friction");
  s.contact.restitution = prm.get_double("restitution");
  s.contact.wall_friction = prm.get_double("wall friction");
  s.contact.local_damping = prm.get_double("local damping");
  prm.leave_subsection();
  if (s.contact.restitution == 0.0)
    fail("contact/restitution", "a restitution in (0, 1]");

  prm.enter_subsection("breakage");
  BreakageMonitor::Settings &b = s.breakage;
  b.rules.mode = parse_breakage_mode(prm.get("mode"));
  const std::string cut = prm.get("cut point");
  b.rules.cut_power = cut == "plain" ? 1 : cut == "squared" ? 2 : 3;
  b.rules.minimum_size = 1e-3 * prm.get_double("minimum size");
  b.rules.breakage_limit = 1e-3 * prm.get_double("breakage limit");
  b.criterion.strength =
    1e6 * positive(prm.get_double("characteristic strength"), "breakage/characteristic strength", "sigma_c [MPa]");
  b.criterion.weibull_modulus = prm.get_double("weibull modulus");
  b.criterion.reference_size = 1e-3 * prm.get_double("reference size");
  b.interval = std::uint64_t(prm.get_integer("check interval"));
  b.seed = std::uint64_t(prm.get_integer("seed"));
  b.replacement.shelter_siblings = prm.get_bool("shelter siblings");
  b.replacement.release_speed = prm.get_double("overlap release speed");
  prm.leave_subsection();
  if (b.rules.minimum_size > b.rules.breakage_limit)
    fail("breakage/minimum size", "d_M <= d_L (breakage limit); S2 uses d_M/d_L = 0.25");
  if (b.criterion.weibull_modulus > 0.0 && !(b.criterion.reference_size > 0.0))
    fail("breakage/reference size", "a positive d0 [mm] when the Weibull modulus is set");

  prm.enter_subsection("single particle");
  s.single.particles = prm.get_integer("particles");
  s.single.d_min = 1e-3 * positive(prm.get_double("minimum diameter"), "single particle/minimum diameter", "diameter");
  s.single.d_max = 1e-3 * prm.get_double("maximum diameter");
  s.single.platen_speed = positive(prm.get_double("platen speed"), "single particle/platen speed", "speed [m/s]");
  s.single.seed = std::uint64_t(prm.get_integer("seed"));
  s.single.runs = prm.get_integer("seeds");
  prm.leave_subsection();
  if (s.single.d_max < s.single.d_min)
    fail("single particle/maximum diameter", "a diameter >= the minimum diameter");

  prm.enter_subsection("uniaxial");
  s.uniaxial.diameter = 1e-3 * positive(prm.get_double("diameter"), "uniaxial/diameter", "diameter [mm]");
  s.uniaxial.per_edge = prm.get_integer("particles per edge");
  s.uniaxial.packing = prm.get("packing");
  s.uniaxial.packing_fraction = prm.get_double("packing fraction");
  s.uniaxial.lattice_gap = prm.get_double("lattice gap");
  s.uniaxial.seating_stress = 1e3 * positive(prm.get_double("seating stress"), "uniaxial/seating stress", "stress [kPa]");
  s.uniaxial.seating_speed = positive(prm.get_double("seating speed"), "uniaxial/seating speed", "speed [m/s]");
  s.uniaxial.lid_speed = positive(prm.get_double("lid speed"), "uniaxial/lid speed", "speed [m/s]");
  s.uniaxial.final_strain = positive(prm.get_double("final strain"), "uniaxial/final strain", "strain");
  s.uniaxial.seed = std::uint64_t(prm.get_integer("seed"));
  prm.leave_subsection();

  prm.enter_subsection("output");
  c.output_directory = prm.get("directory");
  s.gradation_bin = 1e-3 * positive(prm.get_double("gradation bin"), "output/gradation bin", "sieve spacing [mm]");
  s.polar.bins = prm.get_integer("polar bins");
  s.polar.include_walls = prm.get_bool("polar walls");
  prm.leave_subsection();
  if (s.polar.bins % 2 != 0)
    fail("output/polar bins", "an even number of bins (each contact counts at theta and theta + 180 deg)");
  if (c.output_directory.empty())
    fail("output/directory", "a directory name");
  return c;
}

CrushCase read_crush_case(const std::string &path)
{
  return parse_crush_case(read_parameter_file(path, ".prm crush case file"), path);
}

std::string describe_crush_parameters()
{
  ParameterHandler prm;
  declare(prm);
  std::ostringstream out;
  prm.print_parameters(out, ParameterHandler::Text);
  return out.str();
}

} // namespace geocomp::dem
