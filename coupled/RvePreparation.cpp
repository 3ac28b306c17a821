#include "coupled/RvePreparation.h"

#include "dem/DemSystem.h"
#include "dem/periodic/PeriodicPreparation.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace geocomp::coupled {

double rve_critical_time_step(const dem::ContactModel &law, double radius, double density)
{
  dem::DemSystem probe;
  probe.set_contact_model(law);
  probe.add_sphere(dem::Vec3::Zero(), radius, density);
  return probe.critical_time_step();
}

double rve_time_step(const RveGrains &g)
{
  return g.time_step_safety * rve_critical_time_step(g.law, g.radius * (1.0 - g.radius_spread), g.density);
}

dem::CompressionResult compress_rve(dem::PeriodicCell &cell, double pressure, const RveProtocol &k)
{
  cell.control().set_parameters(dem::MixedControl::Parameters{k.servo_gain, k.servo_max_strain_rate});
  dem::IsotropicCompression iso;
  iso.pressure = pressure;
  iso.tolerance = k.stress_tolerance;
  iso.unbalanced = k.unbalanced;
  iso.check_interval = k.compression_check_interval;
  iso.max_steps = k.compression_max_steps;
  return dem::compress_isotropic(cell, iso);
}

dem::PeriodicCell at_placed_radii(const dem::PeriodicCell &grown, const std::vector<double> &placed, double density)
{
  if (placed.size() != grown.n_particles() || placed.empty())
    throw std::invalid_argument("at_placed_radii: one placed radius per sphere of the grown cell");
  const double scale = placed[0] / grown.particles().radius[0]; // the growth multiplied every radius alike
  dem::PeriodicCell cell(dem::CellMatrix(scale * grown.cell().h()), grown.contact_model(), grown.parameters());
  for (std::size_t i = 0; i < placed.size(); ++i)
    cell.add_sphere(scale * grown.position(dem::Index(i)), placed[i], density);
  return cell;
}

dem::PeriodicCell prepare_rve(const RveGrains &g, const RvePreparationSettings &s, const RveProtocol &k)
{
  dem::RandomPlacement place;
  place.particles = s.particles;
  place.mean_radius = g.radius;
  place.radius_spread = g.radius_spread;
  place.density = g.density;
  place.packing_fraction = s.placement_packing_fraction;
  place.seed = s.seed;
  dem::PeriodicCell::Parameters cp;
  cp.time_step = rve_time_step(g);
  cp.friction = 0.0;
  cp.local_damping = s.local_damping;
  dem::PeriodicCell cell = dem::place_spheres(place, g.law, cp);
  const std::vector<double> placed = cell.particles().radius;

  dem::RadiusGrowth growth;
  growth.pressure = s.growth_pressure_fraction * s.pressure;
  growth.rate = k.growth_rate;
  growth.interval = k.growth_interval;
  growth.max_steps = k.growth_max_steps;
  const dem::GrowthResult grown = dem::grow_radii(cell, growth);
  if (!grown.reached)
    throw std::runtime_error("dem rve: the radius growth did not reach " + std::to_string(growth.pressure) +
                             " Pa in " + std::to_string(grown.steps) + " steps");
  cp.friction = g.friction;
  cell.set_parameters(cp);
  cell = at_placed_radii(cell, placed, g.density);
  const dem::CompressionResult compressed = compress_rve(cell, s.pressure, k);
  if (!compressed.converged)
    throw std::runtime_error("dem rve: the isotropic compression to " + std::to_string(s.pressure) +
                             " Pa did not converge in " + std::to_string(compressed.steps) + " steps");
  return cell;
}

} // namespace geocomp::coupled
