#include "dem/periodic/PeriodicPreparation.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace geocomp::dem {

namespace {
/// Uniform in [0, 1) from the generator's top 53 bits (portable).
double uniform(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

/// Squared minimum-image distance between two points of the cell.
double image_distance2(const CellMatrix& cell, const Vec3& a, const Vec3& b)
{
  Vec3 s = cell.reduced(b - a);
  for (int k = 0; k < 3; ++k) s[k] -= std::round(s[k]);
  return (cell.h() * s).squaredNorm();
}
}  // namespace

PeriodicCell place_spheres(const RandomPlacement& p, const ContactModel& law, const PeriodicCell::Parameters& params)
{
  if (p.particles == 0 || !(p.mean_radius > 0.0) || !(p.radius_spread >= 0.0 && p.radius_spread < 1.0) ||
      !(p.packing_fraction > 0.0 && p.packing_fraction < 0.5))
    throw std::invalid_argument("place_spheres: needs N > 0, R > 0, spread in [0, 1) and a packing fraction in (0, 0.5)");
  std::mt19937_64 rng(p.seed);
  std::vector<double> radius(p.particles);
  double solid = 0.0;
  for (double& r : radius) {
    r = p.mean_radius * (1.0 + p.radius_spread * (2.0 * uniform(rng) - 1.0));
    solid += 4.0 / 3.0 * M_PI * r * r * r;
  }
  const double edge = std::cbrt(solid / p.packing_fraction);
  const CellMatrix box = CellMatrix::box(Vec3::Constant(edge));
  std::vector<Vec3> x;
  x.reserve(p.particles);
  for (std::size_t i = 0; i < p.particles; ++i) {
    std::size_t attempt = 0;
    for (;; ++attempt) {
      if (attempt == p.max_attempts)
        throw std::runtime_error("place_spheres: no free place for sphere " + std::to_string(i) + " after " +
                                 std::to_string(attempt) + " attempts (lower the placement's packing fraction)");
      const Vec3 c = edge * Vec3(uniform(rng), uniform(rng), uniform(rng));
      bool free = true;
      for (std::size_t j = 0; j < i && free; ++j) {
        const double touch = radius[i] + radius[j];
        free = image_distance2(box, x[j], c) >= touch * touch;
      }
      if (free) {
        x.push_back(c);
        break;
      }
    }
  }
  PeriodicCell cell(box, law, params);
  for (std::size_t i = 0; i < p.particles; ++i) cell.add_sphere(x[i], radius[i], p.density);
  return cell;
}

GrowthResult grow_radii(PeriodicCell& cell, const RadiusGrowth& g)
{
  if (!(g.pressure > 0.0) || !(g.rate > 0.0) || g.interval == 0)
    throw std::invalid_argument("grow_radii: needs a positive pressure, rate and interval");
  cell.set_velocity_gradient(Mat3::Zero());
  GrowthResult r;
  const double factor = 1.0 + g.rate * double(g.interval);
  cell.refresh();
  while (r.steps < g.max_steps) {
    if (cell.stress().pressure() >= g.pressure) {
      r.reached = true;
      break;
    }
    if (r.steps % g.interval == 0) cell.scale_radii(factor);
    cell.step();
    ++r.steps;
  }
  r.packing_fraction = cell.packing_fraction();
  r.pressure = cell.stress().pressure();
  return r;
}

PeriodicCell cell_from_packing(const Packing& packing, const ContactModel& law, const PeriodicCell::Parameters& params)
{
  if (packing.size() == 0) throw std::invalid_argument("cell_from_packing: the packing holds no sphere");
  PeriodicCell cell(CellMatrix::box(packing.box_max - packing.box_min), law, params);
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const Vec3 u = packing.velocity.empty() ? Vec3::Zero() : Vec3(packing.velocity[i]);
    const Vec3 w = packing.angular_velocity.empty() ? Vec3::Zero() : Vec3(packing.angular_velocity[i]);
    cell.add_sphere(packing.position[i] - packing.box_min, packing.radius[i], packing.density, u, w);
  }
  return cell;
}

}  // namespace geocomp::dem
