#include "dem/program/LatticePacking.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace geocomp::dem {

Packing jittered_lattice(int n, double radius, double spread, double gap, double density, std::uint64_t seed)
{
  if (n < 1 || !(radius > 0.0) || !(spread >= 0.0 && spread < 1.0) || !(gap >= 0.0))
    throw std::invalid_argument("jittered_lattice: need n >= 1, R > 0, 0 <= spread < 1, gap >= 0");
  std::mt19937_64 rng(seed);
  // Uniform in [-1, 1] from the top 53 bits (independent of the library's distributions).
  auto u = [&rng]() { return double(rng() >> 11) * 0x1.0p-52 - 1.0; };
  const double h = 2.0 * radius * (1.0 + spread) * (1.0 + gap);
  Packing p;
  p.density = density;
  p.box_min = Eigen::Vector3d::Zero();
  p.box_max = Eigen::Vector3d::Constant(n * h);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double r = radius * (1.0 + spread * u());
        const double slack = 0.5 * h - r;
        p.radius.push_back(r);
        p.position.emplace_back((i + 0.5) * h + slack * u(), (j + 0.5) * h + slack * u(), (k + 0.5) * h + slack * u());
      }
  return p;
}

Packing fcc_lattice(int n, double radius, double density)
{
  if (n < 1 || !(radius > 0.0))
    throw std::invalid_argument("fcc_lattice: need n >= 1 cells per edge and R > 0");
  const double half = std::sqrt(2.0) * radius; // a / 2
  Packing p;
  p.density = density;
  p.box_min = Eigen::Vector3d::Zero();
  p.box_max = Eigen::Vector3d::Constant(2.0 * n * half + 2.0 * radius);
  for (int k = 0; k <= 2 * n; ++k)
    for (int j = 0; j <= 2 * n; ++j)
      for (int i = 0; i <= 2 * n; ++i)
        if ((i + j + k) % 2 == 0) {
          p.radius.push_back(radius);
          p.position.emplace_back(radius + i * half, radius + j * half, radius + k * half);
        }
  return p;
}

} // namespace geocomp::dem
