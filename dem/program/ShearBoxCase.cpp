#include "dem/program/ShearBoxCase.h"

#include "common/case/ParseParameters.h"

namespace geocomp::dem {

using namespace dealii;

void declare_shear_box_parameters(ParameterHandler& prm)
{
  prm.declare_entry("title", "", Patterns::Anything(), "A title for the outputs.");
  prm.enter_subsection("box");
  prm.declare_entry("length", "0.10", Patterns::Double(0.0), "L, along the shear [m] (S4: 0.10).");
  prm.declare_entry("width", "0.10", Patterns::Double(0.0), "B [m] (S4: 0.10).");
  prm.declare_entry("half height", "0.0371", Patterns::Double(0.0), "H of each half [m] (S4: 0.0371).");
  prm.declare_entry("gap fraction", "0.5", Patterns::Double(0.0, 2.0),
                    "Gap between the halves / mean sphere diameter (S4: 0.5).");
  prm.declare_entry("void ratio", "0.46", Patterns::Double(0.0, 5.0),
                    "Sets the number of clumps, V_box = (1 + e) V_solid (S4: 0.46).");
  prm.declare_entry("clumps", "0", Patterns::Integer(0, 100000), "Number of clumps; 0: from the void ratio.");
  prm.leave_subsection();
  prm.enter_subsection("grains");
  prm.declare_entry("log mass mean", "-0.117", Patterns::Double(), "mu of ln(m / 1 g) (S4: -0.117).");
  prm.declare_entry("log mass sigma", "0.432", Patterns::Double(0.0), "sigma of ln(m / 1 g) (S4: 0.432).");
  prm.declare_entry("mass min", "0.4", Patterns::Double(0.0), "Lightest grain [g] (S4: 0.4).");
  prm.declare_entry("mass max", "2.0", Patterns::Double(0.0), "Heaviest grain [g] (S4: 2.0).");
  prm.declare_entry("density", "2550", Patterns::Double(0.0), "[kg/m^3] (S4: specific gravity 2.55).");
  prm.declare_entry("max overlap", "0.5", Patterns::Double(0.0, 0.99), "Member overlaps in [0, this * D_min] (S4: 0.5).");
  prm.declare_entry("seed", "1", Patterns::Integer(0), "Seed of the grain shapes and placement.");
  prm.leave_subsection();
  prm.enter_subsection("material");
  prm.declare_entry("youngs modulus", "58.54e9", Patterns::Double(0.0), "E [Pa] (S4: 58.54 GPa).");
  prm.declare_entry("modulus scale", "1", Patterns::Double(0.0, 1.0),
                    "E used = E * scale (< 1 lengthens the Rayleigh step; overlaps grow as scale^(-2/3)).");
  prm.declare_entry("poisson ratio", "0.221", Patterns::Double(0.0, 0.49), "nu (S4: 0.221).");
  prm.declare_entry("restitution", "0.5", Patterns::Double(0.0, 1.0),
                    "Sets the nonlinear normal damping constant A of S4 eq. (15).");
  prm.declare_entry("contact friction", "0.7", Patterns::Double(0.0), "Particle-particle mu (S4: 0.7).");
  prm.declare_entry("side friction", "0.2", Patterns::Double(0.0), "Particle-side wall mu (S4: 0.2).");
  prm.declare_entry("lid friction", "1.0", Patterns::Double(0.0), "Particle-lid and particle-floor mu (S4: 1.0).");
  prm.declare_entry("time step fraction", "0.2", Patterns::Double(0.0, 1.0),
                    "dt = fraction * Rayleigh step of the smallest sphere (S4: 0.2 dense).");
  prm.declare_entry("gravity", "9.81", Patterns::Double(0.0), "[m/s^2]");
  prm.leave_subsection();
  prm.enter_subsection("loading");
  prm.declare_entry("normal stress", "100e3", Patterns::Double(0.0),
                    "sigma_n on L x B [Pa], compression positive (S4: 100, 200, 300 kPa).");
  prm.declare_entry("shear speed", "0.05", Patterns::Double(0.0),
                    "Lower box speed [m/s] (S4: 3 mm/min, unaffordable; keep I = 0.1 v sqrt(rho/sigma_n) < 1e-3).");
  prm.declare_entry("max shear", "0.015", Patterns::Double(0.0), "[m] (S4: 15 mm), below L/2.");
  prm.declare_entry("output points", "100", Patterns::Integer(1, 100000), "Rows of the curve.");
  prm.declare_entry("lid weight", "0", Patterns::Double(0.0),
                    "The lid's own weight [N], a dead load added to sigma_n L B (S4 eq. (22)'s W_P is the "
                    "weight of the grains above the gap, computed).");
  prm.declare_entry("upper box", "free", Patterns::Selection("free|fixed"),
                    "free: the upper box (sides, rim, skirts) moves on z under its weight and the grains' "
                    "force, from the rest under the normal stress on (S4); fixed: held at the set gap.");
  prm.declare_entry("box weight", "9.81", Patterns::Double(0.0),
                    "W_B of S4 eq. (22) [N]: the free upper box's weight, carried by the specimen.");
  prm.declare_entry("box mass", "1.0", Patterns::Double(0.0), "m_B, inertia of the free upper box [kg].");
  prm.declare_entry("box max rise", "0.01", Patterns::Double(0.0),
                    "Top stop of the free upper box above its seat at the set gap [m]; the gap skirts "
                    "reach this far, so no grain leaves through the opened gap.");
  prm.declare_entry("lid mass", "1.0", Patterns::Double(0.0),
                    "Inertia of the loaded lid during rest and shear [kg] (a dead load; its weight is 'lid weight').");
  prm.leave_subsection();
  prm.enter_subsection("preparation");
  prm.declare_entry("growth start", "0.5", Patterns::Double(0.05, 1.0), "Placement size / full size (S4: 0.5).");
  prm.declare_entry("growth stages", "16", Patterns::Integer(1, 1000), "Uniform growth stages to full size.");
  prm.declare_entry("settle steps", "1500", Patterns::Integer(0), "Steps after each growth stage.");
  prm.declare_entry("local damping", "0.5", Patterns::Double(0.0, 1.0), "Local damping during preparation only.");
  prm.declare_entry("load tolerance", "0.02", Patterns::Double(0.0, 1.0),
                    "Loading ends when |P/P_target - 1| stays below this for 5 x 200 steps.");
  prm.declare_entry("load max time", "0.3", Patterns::Double(0.0), "DEM time limit of loading [s].");
  prm.declare_entry("preparation friction", "0", Patterns::Double(0.0),
                    "Contact and wall mu during growth and seating, standing for S4's vibration compaction "
                    "(restored to the material frictions before the normal load).");
  prm.declare_entry("seat stress", "10e3", Patterns::Double(0.0),
                    "Lid stress of the seating compaction with the preparation friction [Pa] (the same for every normal stress).");
  prm.declare_entry("rest ratio", "1e-4", Patterns::Double(0.0),
                    "Shear starts when kinetic energy < this x elastic energy under the normal stress (and the load holds).");
  prm.declare_entry("rest max time", "0.05", Patterns::Double(0.0), "DEM time limit of the rest phase [s].");
  prm.declare_entry("servo factor", "0.01", Patterns::Double(0.0, 1.0),
                    "Lid speed = factor (P_target - P) / (K dt), K the lid contact stiffness.");
  prm.leave_subsection();
  prm.enter_subsection("output");
  prm.declare_entry("directory", "results/s4", Patterns::Anything(), "Where the curve and the summary go.");
  prm.leave_subsection();
}

ShearBoxCase read_shear_box_case(const std::string& path)
{
  ParameterHandler prm;
  declare_shear_box_parameters(prm);
  parse_parameter_text(prm, read_parameter_file(path, ".prm shear-box case file"), path);
  ShearBoxCase c;
  c.file = path;
  c.title = prm.get("title");
  DirectShearParameters& p = c.p;
  prm.enter_subsection("box");
  p.length = prm.get_double("length");
  p.width = prm.get_double("width");
  p.half_height = prm.get_double("half height");
  p.gap_fraction = prm.get_double("gap fraction");
  p.void_ratio = prm.get_double("void ratio");
  p.n_clumps = std::size_t(prm.get_integer("clumps"));
  prm.leave_subsection();
  prm.enter_subsection("grains");
  p.clumps.log_mass_mean = prm.get_double("log mass mean");
  p.clumps.log_mass_sigma = prm.get_double("log mass sigma");
  p.clumps.mass_min = 1e-3 * prm.get_double("mass min");
  p.clumps.mass_max = 1e-3 * prm.get_double("mass max");
  p.clumps.density = prm.get_double("density");
  p.clumps.max_overlap = prm.get_double("max overlap");
  p.seed = std::uint64_t(prm.get_integer("seed"));
  prm.leave_subsection();
  prm.enter_subsection("material");
  p.youngs_modulus = prm.get_double("youngs modulus");
  p.modulus_scale = prm.get_double("modulus scale");
  p.poisson_ratio = prm.get_double("poisson ratio");
  p.restitution = prm.get_double("restitution");
  p.mu_contact = prm.get_double("contact friction");
  p.mu_side = prm.get_double("side friction");
  p.mu_lid = prm.get_double("lid friction");
  p.time_step_fraction = prm.get_double("time step fraction");
  p.gravity = prm.get_double("gravity");
  prm.leave_subsection();
  prm.enter_subsection("loading");
  p.normal_stress = prm.get_double("normal stress");
  p.shear_speed = prm.get_double("shear speed");
  p.max_shear = prm.get_double("max shear");
  p.output_points = std::size_t(prm.get_integer("output points"));
  p.lid_weight = prm.get_double("lid weight");
  p.upper_box_free = prm.get("upper box") == "free";
  p.box_weight = prm.get_double("box weight");
  p.box_mass = prm.get_double("box mass");
  p.box_max_rise = prm.get_double("box max rise");
  p.lid_mass = prm.get_double("lid mass");
  prm.leave_subsection();
  prm.enter_subsection("preparation");
  p.growth_start = prm.get_double("growth start");
  p.growth_stages = prm.get_integer("growth stages");
  p.settle_steps = std::size_t(prm.get_integer("settle steps"));
  p.local_damping = prm.get_double("local damping");
  p.load_tolerance = prm.get_double("load tolerance");
  p.load_max_time = prm.get_double("load max time");
  p.servo_factor = prm.get_double("servo factor");
  p.prep_friction = prm.get_double("preparation friction");
  p.seat_stress = prm.get_double("seat stress");
  p.rest_ratio = prm.get_double("rest ratio");
  p.rest_max_time = prm.get_double("rest max time");
  prm.leave_subsection();
  prm.enter_subsection("output");
  c.output_directory = prm.get("directory");
  prm.leave_subsection();
  auto fail = [&](const std::string& parameter, const std::string& expectation) {
    throw CaseError(path, parameter, expectation);
  };
  if (!(p.length > 0.0) || !(p.width > 0.0) || !(p.half_height > 0.0))
    fail("box", "length, width and half height must be > 0 [m]");
  if (!(p.max_shear > 0.0 && p.max_shear < 0.5 * p.length))
    fail("max shear", "expected 0 < max shear < length / 2 [m]");
  if (!(p.clumps.mass_min > 0.0 && p.clumps.mass_min < p.clumps.mass_max))
    fail("mass min", "expected 0 < mass min < mass max [g]");
  if (!(p.normal_stress > 0.0)) fail("normal stress", "expected > 0 [Pa] (compression positive)");
  if (!(p.shear_speed > 0.0)) fail("shear speed", "expected > 0 [m/s]");
  if (!(p.lid_mass > 0.0)) fail("lid mass", "expected > 0 [kg]");
  if (!(p.box_mass > 0.0)) fail("box mass", "expected > 0 [kg]");
  if (!(p.box_max_rise > 0.0 && p.box_max_rise < p.half_height))
    fail("box max rise", "expected 0 < box max rise < half height [m]");
  if (!(p.youngs_modulus > 0.0) || !(p.modulus_scale > 0.0))
    fail("youngs modulus", "youngs modulus and modulus scale must be > 0");
  if (!(p.clumps.density > 0.0)) fail("density", "expected > 0 [kg/m^3]");
  if (c.output_directory.find_first_not_of(" \t") == std::string::npos)
    fail("directory", "expected a non-empty output directory");
  return c;
}

}  // namespace geocomp::dem
