// The optional contact parts of the `contact` section (rolling resistance, S3 bonds and
// adhesion, S3 friction). Declared here, apart from the base contact entries, so that each
// part's inputs sit in one place.
#include "dem/case/DemSections.h"

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
  prm.declare_entry("bonding walls", "all", Selection("all|z"),
                    "With wall bonding: the walls that bond, 'all' six or the 'z' walls only (the loading platens "
                    "of a direct tension test; the lateral walls then confine without gripping).");
  prm.leave_subsection();
}

void check_contact_parts(const ContactParameters &p, const Reader &r)
{
  const bool bonds = p.cohesion > 0.0 || p.adhesion > 0.0;
  if (p.model == "hertz-mindlin" && p.tangential_model != "coulomb")
    r.fail("contact/tangential model", "'s3-stick-slip' needs the linear normal model");
  if (p.model == "hertz-mindlin" && bonds)
    r.fail("contact/cohesion", "S3 bonds and adhesion need the linear normal model");
}

} // namespace geocomp::sections
