#include "continuum/driver/CaseMaterial.h"

#include <cmath>

namespace geocomp::continuum {

namespace {
PiecewiseLinear table(const HardeningTable &t, double scale)
{
  std::vector<std::pair<double, double>> points;
  for (const auto &[k, v] : t.points)
    points.emplace_back(k, v * scale);
  return PiecewiseLinear(points);
}
} // namespace

MaterialParameters material_from_case(const ContinuumParameters &p)
{
  MaterialParameters m;
  m.model = p.model;
  m.mohr_coulomb.youngs_modulus = p.youngs_modulus;
  m.mohr_coulomb.poisson_ratio = p.poisson_ratio;
  m.mohr_coulomb.cohesion = table(p.cohesion, 1.0);
  m.mohr_coulomb.friction_angle = table(p.friction_angle, M_PI / 180.0);
  m.mohr_coulomb.dilatancy_angle = table(p.dilatancy_angle, M_PI / 180.0);
  m.drucker_prager_matching = p.dp_matching == "inner"   ? DruckerPragerMatching::inner_cone
                              : p.dp_matching == "outer" ? DruckerPragerMatching::outer_cone
                                                         : DruckerPragerMatching::plane_strain;
  m.mohr_coulomb.validate();
  return m;
}

} // namespace geocomp::continuum
