#include "coupled/RvePreparation.h"

#include "dem/DemSystem.h"
#include "dem/periodic/PeriodicPreparation.h"
#include "dem/periodic/PeriodicProgram.h"

#include <stdexcept>
#include <string>

namespace geocomp::coupled {

double rve_critical_time_step(const dem::ContactModel &law, double radius, double density)
{
  dem::DemSystem probe;
  probe.set_contact_model(law);
  probe.add_sphere(dem::Vec3::Zero(), radius, density);
  return probe.critical_time_step();
}

dem::PeriodicCell prepare_rve(const RveGrains &g, const RvePreparationSettings &s)
{
  dem::RandomPlacement place;
  place.particles = s.particles;
  place.mean_radius = g.radius;
  place.radius_spread = g.radius_spread;
  place.density = g.density;
  place.packing_fraction = s.placement_packing_fraction;
  place.seed = s.seed;
  dem::PeriodicCell::Parameters cp;
  cp.time_step = g.time_step_safety * rve_critical_time_step(g.law, g.radius * (1.0 - g.radius_spread), g.density);
  cp.friction = 0.0;
  cp.local_damping = s.local_damping;
  dem::PeriodicCell cell = dem::place_spheres(place, g.law, cp);

  dem::RadiusGrowth growth;
  growth.pressure = 0.1 * s.pressure;
  growth.rate = 2e-5;
  const dem::GrowthResult grown = dem::grow_radii(cell, growth);
  if (!grown.reached)
    throw std::runtime_error("dem rve: the radius growth did not reach " + std::to_string(growth.pressure) +
                             " Pa in " + std::to_string(grown.steps) + " steps");
  cp.friction = g.friction;
  cell.set_parameters(cp);
  cell.control().set_parameters(dem::MixedControl::Parameters{0.2, 3.0});
  dem::IsotropicCompression iso;
  iso.pressure = s.pressure;
  iso.tolerance = 0.01;
  iso.unbalanced = 0.02;
  const dem::CompressionResult compressed = dem::compress_isotropic(cell, iso);
  if (!compressed.converged)
    throw std::runtime_error("dem rve: the isotropic compression to " + std::to_string(s.pressure) +
                             " Pa did not converge in " + std::to_string(compressed.steps) + " steps");
  return cell;
}

} // namespace geocomp::coupled
