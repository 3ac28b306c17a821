#include "dem/ClumpGenerator.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace geocomp::dem {

namespace {
/// Uniform in [0, 1) from 53 random bits (portable, unlike std::uniform_real_distribution).
double uniform(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

/// Standard normal by Box-Muller (one of the pair).
double normal(std::mt19937_64& rng)
{
  double u1 = uniform(rng);
  while (u1 <= 0.0) u1 = uniform(rng);
  const double u2 = uniform(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

/// Uniformly distributed rotation (Shoemake 1992).
Quat random_rotation(std::mt19937_64& rng)
{
  const double u1 = uniform(rng), u2 = 2.0 * M_PI * uniform(rng), u3 = 2.0 * M_PI * uniform(rng);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return Quat(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
}
}  // namespace

std::vector<ClumpMember> s4_template(int t, double d, double o1, double o2)
{
  const double r = 0.5 * d;
  switch (t) {
    case 0: return {{Vec3::Zero(), r}, {Vec3(d - o1, 0, 0), r}};
    case 1: return {{Vec3::Zero(), r}, {Vec3(d - o1, 0, 0), r}, {Vec3(2.0 * d - o1 - o2, 0, 0), r}};
    case 2: {
      const double s = d - o1;
      return {{Vec3::Zero(), r}, {Vec3(s, 0, 0), r}, {Vec3(0.5 * s, 0.5 * std::sqrt(3.0) * s, 0), r}};
    }
    case 3: return {{Vec3::Zero(), d}, {Vec3(1.5 * d - o1, 0, 0), r}};
    default: throw std::invalid_argument("s4_template: template index must be 0..3");
  }
}

std::vector<ClumpShape> generate_s4_clumps(std::size_t n, const ClumpGenerationParameters& p, std::uint64_t seed)
{
  if (!(p.density > 0.0) || !(p.log_mass_sigma >= 0.0) || !(p.mass_min < p.mass_max) || !(p.mass_min > 0.0))
    throw std::invalid_argument("generate_s4_clumps: need density > 0, sigma >= 0 and 0 < m_min < m_max");
  if (!(p.max_overlap >= 0.0 && p.max_overlap < 1.0))
    throw std::invalid_argument("generate_s4_clumps: max overlap must be in [0, 1)");
  std::mt19937_64 rng(seed);
  std::vector<ClumpShape> out(n);
  for (ClumpShape& g : out) {
    g.template_index = int(rng() % 4u);
    const double o1 = p.max_overlap * uniform(rng), o2 = p.max_overlap * uniform(rng);
    double m = 0.0;
    do {  // S4: ln(m / 1 g) ~ N(mu, sigma), truncated to [m_min, m_max]
      m = 1e-3 * std::exp(p.log_mass_mean + p.log_mass_sigma * normal(rng));
    } while (m < p.mass_min || m > p.mass_max);
    std::vector<ClumpMember> unit = s4_template(g.template_index, 1.0, o1, o2);
    const ClumpMassProperties props = voxel_mass_properties(unit);
    const double d = std::cbrt(m / (p.density * props.volume));
    g.members.resize(unit.size());
    for (std::size_t k = 0; k < unit.size(); ++k)
      g.members[k] = {d * (unit[k].centre - props.centroid), d * unit[k].radius};
    g.mass = p.density * props.volume * d * d * d;
  }
  return out;
}

std::vector<std::vector<ClumpMember>> place_clumps(const std::vector<ClumpShape>& shapes, const Vec3& lo,
                                                   const Vec3& hi, double scale, std::uint64_t seed, int attempts)
{
  if (!(scale > 0.0)) throw std::invalid_argument("place_clumps: scale must be positive");
  std::mt19937_64 rng(seed);
  std::vector<std::vector<ClumpMember>> out;
  std::vector<Vec3> centres;
  std::vector<double> bounds;
  for (const ClumpShape& g : shapes) {
    double rb = 0.0;  // bounding sphere about the centroid
    for (const ClumpMember& m : g.members) rb = std::max(rb, scale * (m.centre.norm() + m.radius));
    const Vec3 room = (hi - lo) - Vec3::Constant(2.0 * rb);
    if (room.minCoeff() <= 0.0) throw std::runtime_error("place_clumps: a grain does not fit in the box");
    bool placed = false;
    for (int a = 0; a < attempts && !placed; ++a) {
      const Vec3 x = lo + Vec3::Constant(rb) + Vec3(uniform(rng) * room.x(), uniform(rng) * room.y(),
                                                    uniform(rng) * room.z());
      bool free = true;
      for (std::size_t k = 0; k < centres.size() && free; ++k)
        free = (x - centres[k]).norm() >= rb + bounds[k];
      if (!free) continue;
      const Quat q = random_rotation(rng);
      std::vector<ClumpMember> world(g.members.size());
      for (std::size_t k = 0; k < g.members.size(); ++k)
        world[k] = {x + scale * (q * g.members[k].centre), scale * g.members[k].radius};
      out.push_back(std::move(world));
      centres.push_back(x);
      bounds.push_back(rb);
      placed = true;
    }
    if (!placed) throw std::runtime_error("place_clumps: no free place found (box too full)");
  }
  return out;
}

}  // namespace geocomp::dem
