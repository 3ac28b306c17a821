// The `dem rve` section: the RVE that the fem-dem engine puts at every quadrature point.
#include "coupled/case/RveSection.h"

#include "dem/program/DemEngine.h"

#include <stdexcept>

namespace geocomp::sections {

using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void declare_dem_rve(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("dem rve");
  prm.declare_entry("particles", "60", Integer(10, 100000),
                    "Spheres in the periodic cell (RVE) of every quadrature point (continuum/model = dem rve; "
                    "docs/coupled.md). Its grains and state are the DEM specimen's: specimen radius, radius spread, "
                    "density and isotropic pressure (the RVE is prepared to it), the contact law and particle "
                    "friction, the dem time step safety.");
  prm.declare_entry("seed", "1", Integer(0, 2147483647), "Seed of the RVE's random placement.");
  prm.declare_entry("placement packing fraction", "0.3", Double(0.01, 0.4),
                    "Packing fraction of the random sequential placement before the radius growth.");
  prm.declare_entry("local damping", "0.2", Double(0, 0.99),
                    "Cundall local damping of the RVE's fluctuations (preparation and loading).");
  prm.declare_entry("growth pressure fraction", "0.1", Double(0.01, 1),
                    "The preparation's frictionless radius growth ends when the cell carries this fraction of "
                    "the isotropic pressure; friction then goes on and the servo compresses the cell to the "
                    "pressure. It sets the packing's density: 1 = grown frictionless to the pressure (the "
                    "densest, dilatant under shear), 0.1 = the last 90 % of the pressure taken with friction "
                    "(looser, contractive; docs/coupled.md).");
  prm.declare_entry("steps per increment", "200", Integer(1, 100000000),
                    "DEM steps over which one FE strain increment is applied (L = d eps / (n dt)); sets the "
                    "RVE's strain rate, hence how quasi-static its response is.");
  prm.declare_entry("newton tolerance", "2e-3", Double(1e-14, 1e-1),
                    "The fem-dem engine's Newton converges when |R_free| <= tolerance * max(|F_int|, |F_ext|) "
                    "(continuum/newton tolerance is the continuum engine's); a step that no longer halves |R| "
                    "below twice the tolerance is accepted (extra relaxed_steps). The cells' answer is not smooth "
                    "below about 2e-3 of the load once their grains slide (500-sphere cells past the peak; "
                    "docs/coupled.md, 'Newton with the cells'): below that floor a step only stalls and is cut back.");
  prm.declare_entry("secant pairs", "8", Integer(0, 100),
                    "The fem-dem engine's quasi-Newton: the BFGS pairs (Matthies & Strang) of a load step's "
                    "iterations, at most this many, update the cells' contact-stiffness tangent assembled once "
                    "per step; 0 = the tangent of every iterate, unchanged (linear convergence).");
  prm.declare_entry("tangent", "branch secant", Selection("branch secant|contact stiffness"),
                    "The tangent every cell answers with (coupled/RveMaterial.h): 'contact stiffness' = the "
                    "normal-spring stiffness of its contact network (the branch of no sliding, too stiff where "
                    "the grains slide); 'branch secant' = that stiffness updated (damped BFGS) to carry the "
                    "cell's secant from its committed state along the increment, the derivative along the "
                    "increment of a rate-independent answer, measured by the run the iterate needs anyway.");
  prm.leave_subsection();
}

coupled::RveCaseParameters parse_dem_rve(dealii::ParameterHandler &prm, const Reader &r)
{
  coupled::RveCaseParameters p;
  read_section(prm, r, "dem rve", p);
  return p;
}

} // namespace geocomp::sections

namespace geocomp::coupled {

RveGrains rve_grains(const dem::DemCase &c)
{
  RveGrains g;
  g.law = dem::make_contact_model(c.contact);
  g.radius = c.specimen.radius;
  if (c.specimen.size_distribution == "uniform")
    g.radius_spread = c.specimen.radius_spread;
  else if (c.specimen.size_distribution != "monodisperse")
    throw std::invalid_argument("dem rve: the RVE draws monodisperse or uniform radii, not the specimen's '" +
                                c.specimen.size_distribution + "' distribution");
  g.density = c.specimen.density;
  g.friction = c.contact.particle_friction;
  g.time_step_safety = c.dem.time_step_safety;
  return g;
}

RvePreparationSettings rve_settings(const dem::DemCase &c, const RveCaseParameters &p)
{
  RvePreparationSettings s;
  s.pressure = c.specimen.isotropic_pressure;
  s.particles = p.particles;
  s.seed = p.seed;
  s.placement_packing_fraction = p.placement_packing_fraction;
  s.local_damping = p.local_damping;
  s.growth_pressure_fraction = p.growth_pressure_fraction;
  return s;
}

std::shared_ptr<const RveMaterial> make_rve_material(const dem::DemCase &c, const RveCaseParameters &p)
{
  RveParameters rp;
  rp.steps_per_increment = p.steps_per_increment;
  rp.tangent = p.tangent == "contact stiffness" ? RveTangent::contact_stiffness : RveTangent::branch_secant;
  return std::make_shared<const RveMaterial>(prepare_rve(rve_grains(c), rve_settings(c, p)), rp);
}

} // namespace geocomp::coupled
