// The `contact`, `dem` and `continuum` sections: the two engines' material descriptions.
#include "common/case/Sections.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geocomp::sections {

using dealii::Patterns::Anything;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::List;
using dealii::Patterns::Selection;


namespace {
/// Each linear-law constant given one way, and none of the new linear-only entries with
/// hertz-mindlin (whose damping and tangential stiffness follow from E, nu and e).
void check_linear_contact_entries(const ContactParameters &p, const Reader &r)
{
  const ContactParameters d{};
  if (p.normal_damping > 0.0 && p.normal_damping_per_mass > 0.0)
    r.fail("contact/normal damping per mass", "c_n is given twice: set 'normal damping' [N s/m] or 'normal damping "
                                              "per mass' [1/s], not both");
  if (p.tangential_stiffness > 0.0 && std::abs(p.tangential_stiffness_ratio - d.tangential_stiffness_ratio) > 1e-9)
    r.fail("contact/tangential stiffness", "k_t is given twice: set 'tangential stiffness' [N/m] or 'tangential "
                                           "stiffness ratio', not both");
  if (p.tangential_damping > 0.0 && p.tangential_damping_ratio != d.tangential_damping_ratio)
    r.fail("contact/tangential damping", "c_t is given twice: set 'tangential damping' [N s/m] or 'tangential "
                                         "damping ratio', not both");
  if (p.tangential_stiffness > 0.0 && p.normal_stiffness == 0.0 && p.tangential_damping == 0.0 &&
      p.tangential_damping_ratio < 0.0)
    r.fail("contact/tangential damping ratio",
           "the default c_t = (k_t/k_n) c_n needs k_n given too ('normal stiffness') when k_t is given in N/m; "
           "set 'tangential damping ratio' or 'tangential damping'");
  if (p.model == "hertz-mindlin") {
    const char *linear_only[] = {"normal damping per mass", "tangential stiffness", "tangential damping",
                                 "tangential damping ratio"};
    const bool set[] = {p.normal_damping_per_mass != d.normal_damping_per_mass,
                        p.tangential_stiffness != d.tangential_stiffness, p.tangential_damping != d.tangential_damping,
                        p.tangential_damping_ratio != d.tangential_damping_ratio};
    for (int k = 0; k < 4; ++k)
      if (set[k])
        r.fail(std::string("contact/") + linear_only[k],
               "is an entry of the linear model; hertz-mindlin takes its damping and tangential stiffness from "
               "E, nu and the restitution");
  }
}
} // namespace

void declare_contact(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("contact");
  prm.declare_entry("model", "linear", Selection("linear|hertz-mindlin"),
                    "'linear': S0 eq. (1)-(2) spring-dashpot with Coulomb cap; 'hertz-mindlin': S4 eq. (15)-(19).");
  prm.declare_entry("youngs modulus", "7e9", Double(1e3, 1e13), "Particle Young's modulus E [Pa].");
  prm.declare_entry("poisson ratio", "0.25", Double(0, 0.4999), "Particle Poisson ratio nu [1].");
  prm.declare_entry("impact velocity", "1.0", Double(1e-6, 1e4),
                    "Characteristic impact velocity V_c [m/s] in S0's k_n formula.");
  prm.declare_entry("restitution", "0.5", Double(1e-6, 1.0),
                    "Coefficient of restitution c_r in (0, 1] [1]; gives c_n unless 'normal damping' or "
                    "'normal damping per mass' is set.");
  prm.declare_entry("normal stiffness", "0", Double(0, 1e15),
                    "k_n [N/m] given directly (as LIGGGHTS hooke/stiffness); 0 = S0 formula from E*, R*, m*, V_c.");
  prm.declare_entry("normal damping", "0", Double(0, 1e12),
                    "c_n [N s/m] given directly; 0 = from 'normal damping per mass' or the restitution.");
  prm.declare_entry("normal damping per mass", "0", Double(0, 1e12),
                    "gamma_n [1/s], LIGGGHTS' hooke damping per unit effective mass: c_n = gamma_n m*; 0 = not "
                    "used (linear model).");
  prm.declare_entry("tangential stiffness ratio", "0.285714285714", Double(0, 10),
                    "k_t / k_n [1] (2/7: the tangential and normal periods agree; S0: 1).");
  prm.declare_entry("tangential stiffness", "0", Double(0, 1e15),
                    "k_t [N/m] given directly; 0 = 'tangential stiffness ratio' times k_n (linear model).");
  prm.declare_entry("tangential damping ratio", "-1", Double(-1, 10),
                    "c_t / c_n [1]; -1 (default) = k_t / k_n, S0 eq. (2)'s dashpot in the proportion of the "
                    "springs; 0 = no tangential dashpot; 1 = LIGGGHTS' gamma_t = gamma_n (linear model).");
  prm.declare_entry("tangential damping", "0", Double(0, 1e12),
                    "c_t [N s/m] given directly; 0 = 'tangential damping ratio' (linear model).");
  prm.declare_entry("particle friction", "0.4", Double(0, 100), "Inter-particle Coulomb friction mu_s [1].");
  prm.declare_entry("wall friction", "0", Double(0, 100), "Particle-wall friction mu_p [1] (S0: 0).");
  prm.leave_subsection();
}

ContactParameters parse_contact(dealii::ParameterHandler &prm, const Reader &r)
{
  ContactParameters p;
  prm.enter_subsection("contact");
  p.model = prm.get("model");
  p.youngs_modulus = prm.get_double("youngs modulus");
  p.poisson_ratio = prm.get_double("poisson ratio");
  p.impact_velocity = prm.get_double("impact velocity");
  p.restitution = prm.get_double("restitution");
  p.normal_stiffness = prm.get_double("normal stiffness");
  p.normal_damping = prm.get_double("normal damping");
  p.normal_damping_per_mass = prm.get_double("normal damping per mass");
  p.tangential_stiffness_ratio = prm.get_double("tangential stiffness ratio");
  p.tangential_stiffness = prm.get_double("tangential stiffness");
  p.tangential_damping_ratio = prm.get_double("tangential damping ratio");
  p.tangential_damping = prm.get_double("tangential damping");
  p.particle_friction = prm.get_double("particle friction");
  p.wall_friction = prm.get_double("wall friction");
  prm.leave_subsection();
  check_linear_contact_entries(p, r);
  return p;
}

void declare_dem(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("dem");
  prm.declare_entry("time step safety", "0.2", Double(1e-4, 1.0),
                    "Time step as a fraction of the critical step (sqrt(m/k) or S4's Rayleigh step).");
  prm.declare_entry("threads", "0", Integer(0, 1024), "OpenMP threads; 0 = the OpenMP default.");
  prm.declare_entry("local damping", "0", Double(0, 0.99),
                    "Cundall local non-viscous damping while loading (0 = off; S0 loads without it).");
  prm.declare_entry("skin", "0.1", Double(0.001, 2.0), "Verlet skin as a fraction of the mean diameter.");
  prm.declare_entry("servo max velocity", "0.05", Double(1e-9, 100),
                    "Speed cap of a servo-controlled wall [m/s], raised to 'servo speed ratio' times the speed of "
                    "the fastest kinematic wall of the stage.");
  prm.declare_entry("servo speed ratio", "4", Double(0, 1e3),
                    "The servo walls' speed cap is at least this times the fastest kinematic wall's speed [1] "
                    "(a specimen widens about as fast as it is shortened; docs/dem.md).");
  prm.declare_entry("servo gain", "0.5", Double(1e-6, 1.0),
                    "g_P: fraction of the stiffness-based stress correction applied per step (proportional part "
                    "of the wall servo, docs/dem.md).");
  prm.declare_entry("servo integral gain", "0.1", Double(0, 1),
                    "g_I: per-step gain of the servo's integral part, which learns the wall speed an axis needs "
                    "(integral time g_P/g_I steps; 0 = proportional only, docs/dem.md).");
  prm.declare_entry("guard min edge", "3", Double(0, 1e3),
                    "A box edge shorter than this many largest particle diameters stops the run as failed "
                    "(exit 1, results so far, /meta/status) [1].");
  prm.declare_entry("guard stress ratio", "1e3", Double(1, 1e12),
                    "A wall stress above this times the reference (the largest |sigma_aa| at the start and of "
                    "every stress goal) stops the run as failed [1].");
  prm.declare_entry("snapshots", "4", Integer(0, 10000), "Particle snapshots kept for localization analysis.");
  prm.declare_entry("checkpoint interval", "600", Double(0, 1e9),
                    "Wall-clock seconds between checkpoints of a DEM program run (<output>/dem-program.ckpt, "
                    "at main-path samples; 0 = only on SIGINT/SIGTERM). Running the same command again "
                    "resumes from it, bit for bit.");
  prm.leave_subsection();
}

DemParameters parse_dem(dealii::ParameterHandler &prm, const Reader &)
{
  DemParameters p;
  prm.enter_subsection("dem");
  p.time_step_safety = prm.get_double("time step safety");
  p.threads = prm.get_integer("threads");
  p.local_damping = prm.get_double("local damping");
  p.skin = prm.get_double("skin");
  p.servo_max_velocity = prm.get_double("servo max velocity");
  p.servo_speed_ratio = prm.get_double("servo speed ratio");
  p.servo_gain = prm.get_double("servo gain");
  p.servo_integral_gain = prm.get_double("servo integral gain");
  p.guard_min_edge = prm.get_double("guard min edge");
  p.guard_stress_ratio = prm.get_double("guard stress ratio");
  p.snapshots = prm.get_integer("snapshots");
  p.checkpoint_interval = prm.get_double("checkpoint interval");
  prm.leave_subsection();
  return p;
}

void declare_continuum(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("continuum");
  prm.declare_entry("model", "mohr-coulomb", Selection("mohr-coulomb|drucker-prager|nikolaevsky"),
                    "Constitutive model: Mohr-Coulomb with hardening/softening, Drucker-Prager matched to it, or "
                    "nikolaevsky: S1's quasi-static model (Mises-Schleicher yield, Nikolaevsky non-associated flow, "
                    "linear hardening; docs/s1-kinetic-model.md), whose material is subsection nikolaevsky: the "
                    "entries E, nu, cohesion, friction and dilatancy angle below are then not used.");
  prm.declare_entry("drucker prager matching", "outer", Selection("outer|inner|plane-strain"),
                    "How Drucker-Prager is matched to the Mohr-Coulomb c and phi.");
  prm.declare_entry("youngs modulus", "200e6", Double(1e3, 1e13),
                    "Young's modulus E [Pa] (mohr-coulomb, drucker-prager).");
  prm.declare_entry("poisson ratio", "0.25", Double(0, 0.4999), "Poisson ratio nu (mohr-coulomb, drucker-prager).");
  prm.declare_entry("cohesion", "0:1e5", Anything(),
                    "Cohesion c(kappa) [Pa], piecewise linear: 'kappa:value, kappa:value, ...', kappa from 0 "
                    "increasing; constant beyond the last point.");
  prm.declare_entry("friction angle", "0:30", Anything(), "Friction angle phi(kappa) [deg], same format.");
  prm.declare_entry("dilatancy angle", "0:5", Anything(),
                    "Dilatancy angle psi(kappa) [deg], same format; psi <= phi (non-associated flow).");
  prm.declare_entry("kinematics", "finite strain", Selection("finite strain|small strain"),
                    "finite strain: multiplicative plasticity with logarithmic elastic strain, F from the box edges "
                    "(material point) or total Lagrangian (FE cube), Cauchy stress as force over current area; "
                    "small strain: eps = sym grad u, force over initial area (for comparison). Both engines.");
  prm.declare_entry("cells per edge", "4", Integer(1, 512), "Hexahedra per cube edge.");
  prm.declare_entry("degree", "1", Integer(1, 4), "Polynomial degree of the FE_Q displacement.");
  prm.declare_entry("volumetric integration", "full", Selection("full|b-bar"),
                    "full: every quadrature point takes its own volumetric strain; b-bar: the cell average "
                    "(Hughes 1980), which removes the volumetric locking of Q1 under nearly isochoric plastic "
                    "flow (docs/continuum-fe.md). Meant for degree 1.");
  prm.declare_entry("imperfection radius", "0", Double(0, 1e3),
                    "Radius [m] of a weaker zone that triggers a band; 0 = none.");
  prm.declare_entry("imperfection factor", "0.9", Double(0.01, 1.0),
                    "Cohesion multiplier inside the weaker zone (drucker-prager: of Y(kappa); nikolaevsky: of every "
                    "strength, sigma_y and sigma_c, hence of Y(kappa)).");
  prm.declare_entry("imperfection centre", "0.5, 0.5, 0.5", List(Double(0, 1), 3, 3),
                    "Centre of the weaker zone, as fractions of L0.");
  prm.declare_entry("linear solver", "gmres", Selection("gmres|cg|direct"),
                    "PETSc solver of the Newton systems (direct = MUMPS).");
  prm.declare_entry("preconditioner", "amg", Selection("amg|jacobi"),
                    "Preconditioner of the Krylov solvers: algebraic multigrid (Trilinos ML, or Hypre "
                    "BoomerAMG in a PETSc build) or Jacobi.");
  prm.declare_entry("near null space", "rigid-body", Selection("rigid-body|translations"),
                    "Near-null space of the algebraic multigrid (Trilinos ML): the six rigid-body modes "
                    "(Krylov iterations nearly independent of the mesh; a costlier set-up) or the three "
                    "translations (cheaper per solve on meshes up to ~64^3, iterations grow with the mesh). "
                    "docs/continuum-fe.md, Performance.");
  prm.declare_entry("newton tolerance", "1e-9", Double(1e-14, 1e-2),
                    "Newton converges when |R_free| <= tolerance * max(|F_int|, |F_ext|).");
  prm.declare_entry("load steps per sample", "2", Integer(1, 10000),
                    "Initial load steps per sampling interval (halved on non-convergence).");
  prm.declare_entry("point substeps per sample", "20", Integer(1, 100000),
                    "Load increments per sampling interval of the material-point engine.");
  prm.declare_entry("regularization", "none", Selection("crack-band|none"),
                    "Softening regularization: scale the softening by element size (crack band) or none "
                    "(nikolaevsky hardens linearly and never softens: nothing to scale). The cube's solution stays "
                    "diffuse on the meshes tested (docs/continuum-fe.md), where the unregularized curves already "
                    "agree across meshes.");
  prm.declare_entry("reference element size", "0", Double(0, 1e3),
                    "Crack-band reference width [m]: the softening table holds as written for elements of this size "
                    "and is stretched by width/h_e elsewhere; 0 = the cube edge L0 (the table describes the whole "
                    "specimen, as a material-point calibration from DEM does).");
  declare_nikolaevsky(prm);
  prm.leave_subsection();
}

HardeningTable parse_table(const std::string &text, const std::string &parameter, const Reader &r)
{
  HardeningTable t;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos)
      r.fail(parameter, "expected 'kappa:value' pairs separated by commas, got '" + item + "'");
    double k = 0, v = 0;
    try {
      std::size_t u1 = 0, u2 = 0;
      const std::string ks = item.substr(0, colon), vs = item.substr(colon + 1);
      k = std::stod(ks, &u1);
      v = std::stod(vs, &u2);
      if (ks.find_first_not_of(" \t", u1) != std::string::npos || vs.find_first_not_of(" \t", u2) != std::string::npos)
        throw std::invalid_argument(item);
    } catch (const std::exception &) {
      r.fail(parameter, "expected numbers in 'kappa:value', got '" + item + "'");
    }
    if (!std::isfinite(k) || !std::isfinite(v))
      r.fail(parameter, "expected finite numbers, got '" + item + "'");
    if (!t.points.empty() && !(k > t.points.back().first))
      r.fail(parameter, "kappa must increase strictly from one point to the next");
    t.points.emplace_back(k, v);
  }
  if (t.points.empty())
    r.fail(parameter, "expected at least one 'kappa:value' point");
  if (t.points.front().first != 0.0)
    r.fail(parameter, "the first point must be at kappa = 0");
  return t;
}

ContinuumParameters parse_continuum(dealii::ParameterHandler &prm, const Reader &r)
{
  ContinuumParameters p;
  prm.enter_subsection("continuum");
  p.model = prm.get("model");
  p.dp_matching = prm.get("drucker prager matching");
  p.youngs_modulus = prm.get_double("youngs modulus");
  p.poisson_ratio = prm.get_double("poisson ratio");
  p.cohesion = parse_table(prm.get("cohesion"), "continuum/cohesion", r);
  p.friction_angle = parse_table(prm.get("friction angle"), "continuum/friction angle", r);
  p.dilatancy_angle = parse_table(prm.get("dilatancy angle"), "continuum/dilatancy angle", r);
  p.cells_per_edge = prm.get_integer("cells per edge");
  p.degree = prm.get_integer("degree");
  p.volumetric_integration = prm.get("volumetric integration");
  p.kinematics = prm.get("kinematics");
  p.imperfection_radius = prm.get_double("imperfection radius");
  p.imperfection_factor = prm.get_double("imperfection factor");
  p.imperfection_centre = dealii::Utilities::string_to_double(
    dealii::Utilities::split_string_list(prm.get("imperfection centre")));
  p.regularization = prm.get("regularization");
  p.linear_solver = prm.get("linear solver");
  p.preconditioner = prm.get("preconditioner");
  p.near_null_space = prm.get("near null space");
  p.newton_tolerance = prm.get_double("newton tolerance");
  p.load_steps_per_sample = prm.get_integer("load steps per sample");
  p.point_substeps = prm.get_integer("point substeps per sample");
  p.reference_element_size = prm.get_double("reference element size");
  p.nikolaevsky = parse_nikolaevsky(prm, r);
  prm.leave_subsection();
  if (p.volumetric_integration == "b-bar" && p.kinematics == "finite strain")
    r.fail("continuum/volumetric integration", "b-bar is a small-strain method: set kinematics = small strain");
  for (const auto &[k, c] : p.cohesion.points)
    if (c < 0)
      r.fail("continuum/cohesion", "cohesion must be >= 0 Pa");
  for (const auto &[k, phi] : p.friction_angle.points)
    if (phi < 0 || phi >= 90)
      r.fail("continuum/friction angle", "expected angles in [0, 90) degrees");
  for (const auto &[k, psi] : p.dilatancy_angle.points)
    if (psi < 0 || psi >= 90)
      r.fail("continuum/dilatancy angle", "expected angles in [0, 90) degrees");
  for (const auto &[k, psi] : p.dilatancy_angle.points)
    if (psi > p.friction_angle(k) + 1e-12)
      r.fail("continuum/dilatancy angle", "psi must not exceed phi at the same kappa (got psi > phi at kappa = " +
                                            std::to_string(k) + ")");
  return p;
}

} // namespace geocomp::sections

namespace geocomp {

double HardeningTable::operator()(double kappa) const
{
  if (points.empty())
    return 0.0;
  if (kappa <= points.front().first)
    return points.front().second;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (kappa <= points[i].first) {
      const auto &[k0, v0] = points[i - 1];
      const auto &[k1, v1] = points[i];
      return v0 + (v1 - v0) * (kappa - k0) / (k1 - k0);
    }
  return points.back().second;
}

} // namespace geocomp
