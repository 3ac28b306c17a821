// Subsection `nikolaevsky` of `continuum`: the material of continuum/model = nikolaevsky,
// S1's quasi-static model (Grigoriev et al. 2017; continuum/kinetic/NikolaevskyModel.h).
//
// Why a subsection of its own: the model is parametrised by S1's table (sigma_y, sigma_c,
// alpha, Lambda), not by the Mohr-Coulomb tables of `continuum`, and S1 gives two complete
// rows. So `material` names a row (sandstone | concrete, taken from S1Material, the single
// source of those numbers) or `custom`; the custom entries are empty by default, required
// with `custom` and refused with a named row, so that no value is ever silently ignored.
// The case reader cannot see S1Material (common/ builds without continuum/), hence the
// checks here are those that need no row: ranges by pattern, and sigma_c > sigma_y below
// (common/S1StrengthOrder.h, the rule S1Material::validate_plasticity applies too).
#include "common/S1StrengthOrder.h"
#include "continuum/case/ContinuumSections.h"

#include <sstream>

namespace geocomp::sections {

using dealii::Patterns::Double;
using dealii::Patterns::List;
using dealii::Patterns::Selection;

namespace {
struct Entry {
  const char *name;
  double NikolaevskyParameters::*field;
  double lower, upper;
  const char *help;
};
// SI, stresses as magnitudes in uniaxial compression. Upper bounds 1.732 < sqrt(3): S1's
// omega = alpha/3 < 1/sqrt3 lets uniaxial compression yield; Lambda < sqrt3 keeps the
// axial plastic strain compressive (1/sqrt3 - Lambda/3 > 0).
const Entry entries[] = {
  {"youngs modulus", &NikolaevskyParameters::youngs_modulus, 1e3, 1e13, "Young's modulus E [Pa]."},
  {"poisson ratio", &NikolaevskyParameters::poisson_ratio, 0.0, 0.4999, "Poisson ratio nu."},
  {"yield stress", &NikolaevskyParameters::yield_stress, 1.0, 1e12,
   "sigma_y [Pa]: uniaxial compressive stress (magnitude) at first yield; Y0 = sigma_y (1/sqrt3 - omega)."},
  {"compressive strength", &NikolaevskyParameters::compressive_strength, 1.0, 1e12,
   "sigma_c [Pa]: static uniaxial compressive strength (magnitude), above sigma_y: the linear hardening reaches it "
   "at the plastic strain below (and goes on: fracture, S1 eq. (6), is not part of this model)."},
  {"internal friction", &NikolaevskyParameters::internal_friction, 0.0, 1.732,
   "alpha = 3 omega of the Mises-Schleicher yield Phi = omega J1 + sqrt(J2) = Y (S1 eq. (1)), in [0, sqrt3)."},
  {"dilatancy", &NikolaevskyParameters::dilatancy, 0.0, 1.732,
   "Lambda of Nikolaevsky's flow rule tr(d eps^p) = 2 Lambda sqrt(I2(d e^p)), I2 = e:e/2 (S1 eq. (2)), "
   "in [0, sqrt3)."},
  {"plastic strain at strength", &NikolaevskyParameters::plastic_strain_at_strength, 1e-9, 1.0,
   "Axial plastic strain eps_p* at sigma_c in uniaxial compression: sets the linear hardening Y = Y0 + H kappa "
   "(an assumption, not in S1's table; its rows use 0.1 (sigma_c - sigma_y)/E)."},
};
} // namespace

void declare_nikolaevsky(dealii::ParameterHandler &prm)
{
  prm.enter_subsection("nikolaevsky");
  prm.declare_entry("material", "sandstone", Selection("sandstone|concrete|custom"),
                    "Material of continuum/model = nikolaevsky: a row of S1's table (Grigoriev et al. 2017; "
                    "values in docs/s1-kinetic-model.md), or 'custom': the entries below, every one required. "
                    "Its E and nu replace continuum/youngs modulus and poisson ratio.");
  for (const Entry &e : entries)
    prm.declare_entry(e.name, "", List(Double(e.lower, e.upper), 0, 1),
                      std::string(e.help) + " Only with material = custom (empty otherwise).");
  prm.leave_subsection();
}

NikolaevskyParameters parse_nikolaevsky(dealii::ParameterHandler &prm, const Reader &r)
{
  NikolaevskyParameters p;
  prm.enter_subsection("nikolaevsky");
  p.material = prm.get("material");
  const bool custom = p.material == "custom";
  for (const Entry &e : entries) {
    const std::string where = std::string("continuum/nikolaevsky/") + e.name;
    const std::string value = prm.get(e.name); // empty or one number in range (the pattern)
    const bool given = value.find_first_not_of(" \t") != std::string::npos;
    if (custom && !given)
      r.fail(where, "material = custom needs every entry: expected " + std::string(e.help));
    if (!custom && given)
      r.fail(where, "set only with material = custom (material = " + p.material +
                      " takes S1's table values): expected it empty");
    if (given)
      p.*(e.field) = dealii::Utilities::string_to_double(value);
  }
  prm.leave_subsection();
  if (custom && !s1_strength_above_yield(p.compressive_strength, p.yield_stress)) {
    std::ostringstream got;
    got << p.compressive_strength << " Pa <= yield stress " << p.yield_stress << " Pa";
    r.fail("continuum/nikolaevsky/compressive strength",
           std::string("expected ") + s1_strength_expectation + ", got " + got.str());
  }
  return p;
}

} // namespace geocomp::sections
