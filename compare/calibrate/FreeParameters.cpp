#include "compare/calibrate/FreeParameters.h"

#include <algorithm>
#include <regex>

namespace geocomp::calibration {

namespace {
using Family = FreeParameter::Family;

struct FamilyInfo {
  const char *name;
  Family family;
  double lower, upper; ///< default bounds (Pa, degrees)
};
const FamilyInfo families[] = {{"E", Family::E, 1e5, 1e12},
                               {"nu", Family::Nu, 0.0, 0.49},
                               {"cohesion", Family::Cohesion, 0.0, 1e9},
                               {"friction", Family::Friction, 0.5, 85.0},
                               {"dilatancy", Family::Dilatancy, 0.0, 60.0},
                               {"yield stress", Family::YieldStress, 1.0, 1e10},
                               {"compressive strength", Family::CompressiveStrength, 1.0, 1e10},
                               {"internal friction", Family::InternalFriction, 0.0, 1.7},
                               {"lambda", Family::Lambda, 0.0, 1.7}};

bool nikolaevsky(const ContinuumParameters &p) { return p.model == "nikolaevsky"; }

/// The number a non-table family stands for in `p` (E, nu: the nikolaevsky subsection's
/// on a Nikolaevsky section).
double *scalar_of(ContinuumParameters &p, Family f)
{
  NikolaevskyParameters &n = p.nikolaevsky;
  switch (f) {
  case Family::E: return nikolaevsky(p) ? &n.youngs_modulus : &p.youngs_modulus;
  case Family::Nu: return nikolaevsky(p) ? &n.poisson_ratio : &p.poisson_ratio;
  case Family::YieldStress: return &n.yield_stress;
  case Family::CompressiveStrength: return &n.compressive_strength;
  case Family::InternalFriction: return &n.internal_friction;
  case Family::Lambda: return &n.dilatancy;
  default: return nullptr;
  }
}

const HardeningTable *table_of(const ContinuumParameters &p, Family f)
{
  switch (f) {
  case Family::Cohesion: return &p.cohesion;
  case Family::Friction: return &p.friction_angle;
  case Family::Dilatancy: return &p.dilatancy_angle;
  default: return nullptr;
  }
}

HardeningTable *table_of(ContinuumParameters &p, Family f)
{
  return const_cast<HardeningTable *>(table_of(static_cast<const ContinuumParameters &>(p), f));
}
} // namespace

FreeParameters::FreeParameters(const ContinuumParameters &base, const CalibrationParameters &c)
{
  const std::regex form("(E|nu|cohesion|friction|dilatancy|yield stress|compressive strength|internal friction|"
                        "lambda)(?:\\[([0-9]+)\\])?");
  for (const auto &text : c.free_parameters) {
    std::smatch m;
    if (!std::regex_match(text, m, form))
      throw CalibrationError(text, "'" + text + "' is not a parameter (E, nu, cohesion, friction, dilatancy, name[k])");
    const std::string family = m[1];
    const FamilyInfo &info = *std::find_if(std::begin(families), std::end(families),
                                           [&](const FamilyInfo &f) { return family == f.name; });
    const bool table_family = info.family == Family::Cohesion || info.family == Family::Friction ||
                              info.family == Family::Dilatancy;
    const bool s1_family = !table_family && info.family != Family::E && info.family != Family::Nu;
    if (s1_family != nikolaevsky(base) && (s1_family || table_family))
      throw CalibrationError(text, "'" + text + "' is not a parameter of the " + base.model + " model");
    FreeParameter p;
    p.family = info.family;
    p.lower = info.lower;
    p.upper = info.upper;
    for (const auto &b : c.bounds)
      if (b.name == family) {
        p.lower = b.lower;
        p.upper = b.upper;
      }
    const HardeningTable *t = table_of(base, info.family);
    std::vector<int> knots;
    if (!t)
      knots = {-1};
    else if (m[2].matched)
      knots = {std::stoi(m[2])};
    else
      for (std::size_t k = 0; k < t->points.size(); ++k)
        knots.push_back(int(k));
    for (int k : knots) {
      if (t && (k < 0 || k >= int(t->points.size())))
        throw CalibrationError(text, "'" + text + "': the " + family + " table has " +
                                       std::to_string(t->points.size()) + " knots (0 ... " +
                                       std::to_string(t->points.size() - 1) + ")");
      p.knot = k;
      p.name = t ? family + "[" + std::to_string(k) + "]" : family;
      if (std::none_of(list_.begin(), list_.end(), [&](const FreeParameter &q) { return q.name == p.name; }))
        list_.push_back(p);
    }
  }
  if (list_.empty())
    throw CalibrationError("free parameters", "no free parameter: nothing to calibrate");
}

FreeParameters FreeParameters::all(const ContinuumParameters &p)
{
  CalibrationParameters every;
  every.free_parameters.clear();
  for (const FamilyInfo &f : families) {
    const bool s1 = f.family != Family::E && f.family != Family::Nu && !table_of(p, f.family);
    if (s1 == nikolaevsky(p) || f.family == Family::E || f.family == Family::Nu)
      every.free_parameters.push_back(f.name);
  }
  return FreeParameters(p, every);
}

bool FreeParameters::contains(const std::string &name) const
{
  return std::any_of(list_.begin(), list_.end(), [&](const FreeParameter &p) { return p.name == name; });
}

std::vector<double> FreeParameters::values(const ContinuumParameters &p) const
{
  std::vector<double> v;
  ContinuumParameters copy = p;
  for (const auto &f : list_) {
    if (const double *x = scalar_of(copy, f.family))
      v.push_back(*x);
    else
      v.push_back(table_of(p, f.family)->points[f.knot].second);
  }
  return v;
}

ContinuumParameters FreeParameters::apply(const ContinuumParameters &p, const std::vector<double> &values) const
{
  ContinuumParameters out = p;
  for (std::size_t i = 0; i < list_.size(); ++i) {
    const FreeParameter &f = list_[i];
    if (double *x = scalar_of(out, f.family))
      *x = values[i];
    else
      table_of(out, f.family)->points[f.knot].second = values[i];
  }
  return out;
}

} // namespace geocomp::calibration
