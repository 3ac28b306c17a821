#include "coupled/wall/WallSpecimen.h"

#include "dem/case/DemParameters.h"
#include "dem/program/DemEngine.h"
#include "dem/program/RadiusGrowth.h"
#include "dem/program/SpecimenPreparation.h"
#include "dem/specimen/SizeDistribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace geocomp::coupled {

namespace {

/// Step 1's radii R_i: uniform in R(1 +- a), drawn from the seed.
std::vector<double> drawn_radii(const RveGrains &g, const RvePreparationSettings &s)
{
  dem::SizeDistribution sizes;
  sizes.kind = g.radius_spread > 0.0 ? dem::SizeDistribution::Kind::Uniform : dem::SizeDistribution::Kind::Monodisperse;
  sizes.mean_radius = g.radius;
  sizes.spread = g.radius_spread;
  return sizes.sample(s.particles, s.seed);
}

/// Step 1: the spheres of `radii`, placed at f_0 times them, at rest, in their fixed frictionless box.
dem::DemSystem placed_specimen(const RveGrains &g, const RvePreparationSettings &s, const std::vector<double> &radii,
                               int threads)
{
  double solid = 0.0, diameter = 0.0;
  for (double r : radii) {
    solid += 4.0 / 3.0 * M_PI * r * r * r;
    diameter += 2.0 * r;
  }
  const double edge = std::cbrt(solid / s.placement_packing_fraction);
  // Random sequential addition jams near 0.38 of the volume its centres can reach, which
  // walls shrink to (L - 2R)^3: the RVE's eta_0 = 0.3 does not fit in a box of 1 000 spheres.
  // The spheres are placed at the wall box's own fraction (PreparationCriteria), shrunk by
  // f_0 in the RVE's box; the growth makes up f_0 first (a gas: nothing touches).
  const double eta_placed = std::min(s.placement_packing_fraction, dem::PreparationCriteria{}.initial_packing_fraction);
  const double f0 = std::cbrt(eta_placed / s.placement_packing_fraction);
  std::vector<double> placed(radii);
  for (double &r : placed)
    r *= f0;
  const std::vector<dem::Vec3> x = dem::place_at_random(placed, dem::Vec3::Zero(), dem::Vec3::Constant(edge), s.seed);

  dem::DemSystem system;
  system.reserve(radii.size());
  system.add_box(dem::Vec3::Zero(), dem::Vec3::Constant(edge), 0.0);
  for (std::size_t i = 0; i < radii.size(); ++i)
    system.add_sphere(x[i], placed[i], g.density);
  system.set_contact_model(g.law);
  system.set_friction(0.0);
  system.set_skin(dem::DemParameters{}.skin * diameter / double(radii.size()));
  system.set_num_threads(threads);
  system.set_local_damping(s.local_damping);
  system.set_time_step(rve_time_step(g));
  return system;
}

/// Step 2: radii times (1 + r n) every n steps until the walls carry the pressure.
WallPreparation grow_to_pressure(dem::DemSystem &system, double pressure, const RveProtocol &k)
{
  WallPreparation rec;
  const double factor = 1.0 + k.growth_rate * double(k.growth_interval);
  std::vector<double> radii(system.n_particles());
  system.evaluate_forces();
  while (mean_wall_pressure(system) < pressure) {
    if (rec.growth_steps == k.growth_max_steps)
      throw std::runtime_error("wall specimen: the radius growth did not reach " + std::to_string(pressure) +
                               " Pa in " + std::to_string(rec.growth_steps) + " steps");
    if (rec.growth_steps % k.growth_interval == 0) {
      for (dem::ParticleId id = 0; id < system.n_particles(); ++id)
        radii[id] = factor * system.particles().radius[system.index_of(id)];
      system.set_radii(radii);
    }
    system.step();
    ++rec.growth_steps;
  }
  rec.grown_packing_fraction = dem::packing_fraction(system);
  rec.grown_pressure = mean_wall_pressure(system);
  return rec;
}

} // namespace

double at_case_radii(dem::DemSystem &grown, const std::vector<double> &radii)
{
  if (radii.size() != grown.n_particles() || radii.empty())
    throw std::invalid_argument("at_case_radii: one radius per sphere of the grown specimen");
  const double g = grown.particles().radius[grown.index_of(0)] / radii[0];
  for (std::size_t w = 0; w < grown.n_walls(); ++w) {
    grown.set_wall_position(w, grown.wall(w).point / g);
    grown.set_wall_velocity(w, dem::Vec3::Zero());
  }
  for (dem::ParticleId id = 0; id < grown.n_particles(); ++id) {
    grown.set_position(id, grown.position(id) / g);
    grown.set_velocity(id, dem::Vec3::Zero());
    grown.set_angular_velocity(id, dem::Vec3::Zero());
  }
  grown.set_radii(radii);
  return g;
}

WallSpecimen prepare_wall_specimen(const RveGrains &g, const RvePreparationSettings &s, const RveProtocol &k,
                                   int threads)
{
  const std::vector<double> radii = drawn_radii(g, s);
  dem::DemSystem system = placed_specimen(g, s, radii, threads);
  WallPreparation rec = grow_to_pressure(system, s.growth_pressure_fraction * s.pressure, k);
  rec.growth_factor = at_case_radii(system, radii);

  system.set_friction(g.friction);
  dem::DemEngineParameters servo = dem::DemEngineParameters::from_case(dem::DemParameters{});
  servo.check_interrupts = false;
  const double dt = system.time_step();
  const std::uint64_t steps0 = system.n_steps();
  dem::DemEngine engine(std::move(system), servo);
  const dem::HoldResult held =
    dem::hold_isotropic(engine, s.pressure, k.stress_tolerance, k.unbalanced, double(k.compression_max_steps) * dt,
                        double(k.compression_check_interval) * dt);
  rec.compression_steps = engine.system().n_steps() - steps0;
  rec.stress_error = held.stress_error;
  rec.unbalanced = held.unbalanced;
  if (!held.converged)
    throw std::runtime_error("wall specimen: the isotropic compression to " + std::to_string(s.pressure) +
                             " Pa did not converge in " + std::to_string(rec.compression_steps) +
                             " steps (stress error " + std::to_string(held.stress_error) + ", unbalanced " +
                             std::to_string(held.unbalanced) + ")");
  WallSpecimen out{engine.system(), rec};
  for (std::size_t w = 0; w < out.system.n_walls(); ++w)
    out.system.set_wall_velocity(w, dem::Vec3::Zero());
  return out;
}

} // namespace geocomp::coupled
