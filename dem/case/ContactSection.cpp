// The base entries of the `contact` section: the normal and tangential law, its
// stiffnesses, damping and friction (the optional parts: ContactPartsSection.cpp).
#include "dem/case/DemSections.h"

#include <cmath>

namespace geocomp::sections {

using dealii::Patterns::Double;
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
  read_section(prm, r, "contact", p); // the base entries and the optional parts
  check_linear_contact_entries(p, r);
  check_contact_parts(p, r);
  return p;
}

} // namespace geocomp::sections
