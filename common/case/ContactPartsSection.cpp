// The optional contact parts of the `contact` section (rolling resistance, S3 bonds and
// adhesion, S3 friction) and the `clumps` section (S3/S4 rigid grains). Declared here,
// apart from the base contact entries, so that each part's inputs sit in one place.
#include "common/case/Sections.h"

namespace geocomp::sections {

using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Selection;

void declare_contact_parts(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("contact");
  prm.declare_entry("tangential model", "coulomb", Selection("coulomb|s3-stick-slip"),
                    "'coulomb': incremental spring with Coulomb cap (S0 eq. (2); Mindlin for hertz-mindlin); "
                    "'s3-stick-slip': S3 eq. (9) anchor spring mu F_n delta/delta*, re-placed at k_phi delta* on "
                    "slip (linear model only).");
  prm.declare_entry("slip displacement", "1e-4", Double(1e-12, 1.0),
                    "S3 friction: tangential displacement delta*_tau [m] at which the Coulomb limit is reached.");
  prm.declare_entry("slip retention", "1", Double(0.0, 1.0),
                    "S3 friction: k_phi, spring kept after a slip as a fraction of delta*_tau (1: Coulomb, "
                    "0: stick-slip).");
  prm.declare_entry("rolling friction", "0", Double(0.0, 100.0),
                    "Rolling resistance coefficient mu_r (S2, PFC's linear model: |M_r| <= mu_r R* F_n, "
                    "k_r = k_t R*^2); 0 = no rolling resistance (S2: 0.70).");
  prm.declare_entry("rolling stiffness ratio", "1", Double(1e-6, 1e6),
                    "k_r / (k_t R*^2) of the rolling spring (PFC: 1).");
  prm.declare_entry("cohesion", "0", Double(0.0, 1e12),
                    "S3 bond strength C_c [Pa]: a bond forms at first contact, pulls with E_c r_ij e and breaks "
                    "for good at |e| = r_ij C_c / E_c (S3 eq. (8)); 0 = no bonds.");
  prm.declare_entry("cohesion modulus", "1e6", Double(1e-3, 1e13),
                    "S3 bond spring modulus E_c [Pa] (S3: E_c << E).");
  prm.declare_entry("adhesion", "0", Double(0.0, 1e12),
                    "S3 adhesion C_a [Pa]: formed at contact, pulls with E_a r_ij (delta* + delta) while "
                    "delta > -delta* = -r_ij C_a / E_a, forms again at the next contact (S3 eq. (7)); 0 = none.");
  prm.declare_entry("adhesion modulus", "1e6", Double(1e-3, 1e13), "S3 adhesion spring modulus E_a [Pa].");
  prm.declare_entry("wall bonding", "false", Bool(), "Whether bonds and adhesion also form with walls.");
  prm.leave_subsection();
}

void parse_contact_parts(dealii::ParameterHandler &prm, const Reader &r, ContactParameters &p)
{
  prm.enter_subsection("contact");
  p.tangential_model = prm.get("tangential model");
  p.slip_displacement = prm.get_double("slip displacement");
  p.slip_retention = prm.get_double("slip retention");
  p.rolling_friction = prm.get_double("rolling friction");
  p.rolling_stiffness_ratio = prm.get_double("rolling stiffness ratio");
  p.cohesion = prm.get_double("cohesion");
  p.cohesion_modulus = prm.get_double("cohesion modulus");
  p.adhesion = prm.get_double("adhesion");
  p.adhesion_modulus = prm.get_double("adhesion modulus");
  p.wall_bonding = prm.get_bool("wall bonding");
  prm.leave_subsection();
  const bool bonds = p.cohesion > 0.0 || p.adhesion > 0.0;
  if (p.model == "hertz-mindlin" && p.tangential_model != "coulomb")
    r.fail("contact/tangential model", "'s3-stick-slip' needs the linear normal model");
  if (p.model == "hertz-mindlin" && bonds)
    r.fail("contact/cohesion", "S3 bonds and adhesion need the linear normal model");
}

void declare_clumps(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("clumps");
  prm.declare_entry("shape", "spheres", Selection("spheres|s4-clumps"),
                    "'spheres': single spheres; 's4-clumps': rigid clumps from S4's four templates with lognormal "
                    "mass (mass, centroid and inertia by voxel integration).");
  prm.declare_entry("log mass mean", "-0.117", Double(-20, 20), "S4: mean mu of ln(m / 1 g).");
  prm.declare_entry("log mass sigma", "0.432", Double(0, 10), "S4: sigma of ln(m / 1 g).");
  prm.declare_entry("mass min", "0.4e-3", Double(1e-15, 1e6), "Lightest grain [kg] (S4: 0.4 g); lighter draws are redrawn.");
  prm.declare_entry("mass max", "2.0e-3", Double(1e-15, 1e6), "Heaviest grain [kg] (S4: 2.0 g).");
  prm.declare_entry("max overlap", "0.5", Double(0, 0.99),
                    "Member overlaps drawn in [0, max overlap * D_min] (S4: 0.5).");
  prm.declare_entry("voxel fraction", "0.05", Double(1e-3, 0.5),
                    "Voxel cube side / D_min for mass properties (S4: 1/20).");
  prm.leave_subsection();
}

ClumpParameters parse_clumps(dealii::ParameterHandler &prm, const Reader &r)
{
  ClumpParameters p;
  prm.enter_subsection("clumps");
  p.shape = prm.get("shape");
  p.log_mass_mean = prm.get_double("log mass mean");
  p.log_mass_sigma = prm.get_double("log mass sigma");
  p.mass_min = prm.get_double("mass min");
  p.mass_max = prm.get_double("mass max");
  p.max_overlap = prm.get_double("max overlap");
  p.voxel_fraction = prm.get_double("voxel fraction");
  prm.leave_subsection();
  if (!(p.mass_min < p.mass_max)) r.fail("clumps/mass max", "expected mass max > mass min");
  return p;
}

} // namespace geocomp::sections
