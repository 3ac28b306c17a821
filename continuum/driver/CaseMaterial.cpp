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

/// A row of S1's table, or the custom values (the case reader checked their ranges).
kinetic::S1Material s1_material(const NikolaevskyParameters &p)
{
  if (p.material != "custom")
    return kinetic::S1Material::preset(p.material);
  kinetic::S1Material m; // density, sigma_t, rate constants: not used by the quasi-static model
  m.name = "custom";
  m.youngs_modulus = p.youngs_modulus;
  m.poisson_ratio = p.poisson_ratio;
  m.yield_stress = p.yield_stress;
  m.compressive_strength = p.compressive_strength;
  m.internal_friction = p.internal_friction;
  m.dilatancy = p.dilatancy;
  m.plastic_strain_at_strength = p.plastic_strain_at_strength;
  return m;
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
  if (m.model == "nikolaevsky") {
    m.nikolaevsky = s1_material(p.nikolaevsky);
    m.nikolaevsky.validate_plasticity();
  }
  return m;
}

} // namespace geocomp::continuum
