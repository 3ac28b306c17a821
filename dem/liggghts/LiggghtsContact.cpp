#include "dem/liggghts/LiggghtsContact.h"

#include "common/case/CaseError.h"
#include "dem/program/DemEngine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geocomp::dem {

namespace {

/// The four linear constants of one pair as geocomp computes them.
struct LinearPair
{
  double kn, kt, cn, ct;
};

LinearPair linear_pair(const LinearSpringDashpot &law, double m_eff, double r_eff)
{
  NormalResponse nr;
  nr.stiffness = law.normal().stiffness(m_eff, r_eff);
  nr.damping = law.normal().damping(m_eff, nr.stiffness);
  const LinearTangential::Parameters &t = law.tangential().parameters();
  return {nr.stiffness, law.tangential().stiffness(nr), nr.damping, t.damping_is_ratio ? t.c_t * nr.damping : t.c_t};
}

bool same(const LinearPair &a, const LinearPair &b)
{
  auto eq = [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y)); };
  return eq(a.kn, b.kn) && eq(a.kt, b.kt) && eq(a.cn, b.cn) && eq(a.ct, b.ct);
}

std::string pair_matrix(const char *name, double spheres, double walls)
{
  std::ostringstream o;
  o.precision(17);
  o << "fix m_" << name << " all property/global " << name << " peratomtypepair 2 " << spheres << " " << walls << " "
    << walls << " " << walls;
  return o.str();
}

void refuse_unmapped_parts(const LiggghtsContactInput &in)
{
  const ContactParameters &c = *in.contact;
  const std::string why = ": LIGGGHTS 3.8's granular pair styles have no such part as geocomp defines it";
  if (c.tangential_model != "coulomb")
    throw CaseError(in.case_file, "contact/tangential model", "expected 'coulomb' (tangential history), got '" +
                                                                 c.tangential_model + "'" + why);
  if (c.rolling_friction != 0.0)
    throw CaseError(in.case_file, "contact/rolling friction", "expected 0 (no rolling resistance)" + why);
  if (c.cohesion != 0.0)
    throw CaseError(in.case_file, "contact/cohesion", "expected 0 (no bonds)" + why);
  if (c.adhesion != 0.0)
    throw CaseError(in.case_file, "contact/adhesion", "expected 0 (no adhesion)" + why);
  if (c.wall_bonding)
    throw CaseError(in.case_file, "contact/wall bonding", "expected false" + why);
  if (in.dem->local_damping != 0.0)
    throw CaseError(in.case_file, "dem/local damping", "expected 0: LIGGGHTS has no Cundall local damping");
}

/// Sphere masses and radii at the extremes of the specimen, for the pair checks.
struct Extremes
{
  double r_min, r_max, m_min, m_max;
};

Extremes extremes(const Packing &p)
{
  const auto [lo, hi] = std::minmax_element(p.radius.begin(), p.radius.end());
  const double f = p.density * 4.0 / 3.0 * M_PI;
  return {*lo, *hi, f * std::pow(*lo, 3), f * std::pow(*hi, 3)};
}

LiggghtsContact map_linear(const LiggghtsContactInput &in, const LinearSpringDashpot &law)
{
  const Extremes e = extremes(*in.packing);
  auto sphere = [&](double ri, double mi, double rj, double mj) {
    return linear_pair(law, mi * mj / (mi + mj), ri * rj / (ri + rj));
  };
  const LinearPair ss = sphere(e.r_min, e.m_min, e.r_min, e.m_min);
  const LinearPair sw = linear_pair(law, e.m_min, e.r_min); // a wall: infinite mass and radius
  if (!same(ss, sphere(e.r_max, e.m_max, e.r_max, e.m_max)) || !same(ss, sphere(e.r_min, e.m_min, e.r_max, e.m_max)) ||
      !same(sw, linear_pair(law, e.m_max, e.r_max)))
    throw CaseError(in.case_file, "specimen/size distribution",
                    "the linear law's constants differ between this specimen's pairs (radii " + std::to_string(e.r_min) +
                      " to " + std::to_string(e.r_max) +
                      " m) and LIGGGHTS' hooke/stiffness takes one k_n, k_t, gamma_n, gamma_t per type pair: expected "
                      "equal radii, or 'normal stiffness', 'normal damping' (N s/m) and 'tangential stiffness' given in "
                      "N/m");
  LiggghtsContact out;
  out.model = "hooke/stiffness";
  out.options = "absolute_damping on limitForce on";
  out.properties = {pair_matrix("kn", ss.kn, sw.kn), pair_matrix("kt", ss.kt, sw.kt),
                    pair_matrix("gamman_abs", ss.cn, sw.cn), pair_matrix("gammat_abs", ss.ct, sw.ct)};
  std::ostringstream k;
  k.precision(17);
  k << sw.kn;
  out.wall_stiffness_expression = k.str();
  return out;
}

LiggghtsContact map_hertz(const LiggghtsContactInput &in)
{
  const ContactParameters &c = *in.contact;
  std::ostringstream o;
  o.precision(17);
  LiggghtsContact out;
  out.model = "hertz";
  out.options = "limitForce on";
  o << "fix m_youngsModulus all property/global youngsModulus peratomtype " << c.youngs_modulus << " "
    << c.youngs_modulus;
  out.properties.push_back(o.str());
  o.str("");
  o << "fix m_poissonsRatio all property/global poissonsRatio peratomtype " << c.poisson_ratio << " " << c.poisson_ratio;
  out.properties.push_back(o.str());
  out.properties.push_back(pair_matrix("coefficientRestitution", c.restitution, c.restitution));
  o.str("");
  const double e_star = c.youngs_modulus / (2.0 * (1.0 - c.poisson_ratio * c.poisson_ratio)); // like materials
  o << 2.0 * e_star << "*sqrt(c_rad*DELTA)"; // S_n = 2 E* sqrt(R delta), as HertzNormal reports it
  out.wall_stiffness_expression = o.str();
  return out;
}

double dashpot_time(const ContactModel &model, const Packing &p)
{
  double mass = 0.0, diameter = 0.0;
  for (double r : p.radius) {
    mass += p.density * 4.0 / 3.0 * M_PI * r * r * r;
    diameter += 2.0 * r;
  }
  ContactKinematics k; // as DemEngine: the mean sphere against a wall at 0.1 % of R
  k.r_eff = 0.5 * diameter / double(p.size());
  k.m_eff = mass / double(p.size());
  k.overlap = 1e-3 * k.r_eff;
  k.v_n = 0.0;
  return std::visit(
    [&](const auto &law) {
      const NormalResponse r = law.normal().evaluate(k);
      return r.stiffness > 0.0 ? r.damping / r.stiffness : 0.0;
    },
    model);
}

} // namespace

LiggghtsContact map_contact_to_liggghts(const LiggghtsContactInput &in)
{
  refuse_unmapped_parts(in);
  const ContactParameters &c = *in.contact;
  if (in.packing->size() == 0)
    throw CaseError(in.case_file, "specimen", "the specimen has no sphere to export");
  ContactModel model;
  try {
    model = make_contact_model(c);
  } catch (const std::invalid_argument &e) {
    throw CaseError(in.case_file, "contact/model", e.what());
  }
  LiggghtsContact out;
  if (const auto *law = std::get_if<LinearSpringDashpot>(&model))
    out = map_linear(in, *law);
  else if (c.model == "hertz-mindlin")
    out = map_hertz(in);
  else
    throw CaseError(in.case_file, "contact/model", "expected 'linear' or 'hertz-mindlin' for LIGGGHTS, got '" +
                                                     c.model + "'");
  out.properties.push_back(pair_matrix("coefficientFriction", c.particle_friction, c.wall_friction));
  out.dashpot_time = dashpot_time(model, *in.packing);
  return out;
}

} // namespace geocomp::dem
