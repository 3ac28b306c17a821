#include "dem/specimen/SizeDistribution.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace geocomp::dem {

SizeDistribution::Kind SizeDistribution::parse(const std::string &name)
{
  if (name == "monodisperse")
    return Kind::Monodisperse;
  if (name == "uniform")
    return Kind::Uniform;
  if (name == "lognormal-mass")
    return Kind::LognormalMass;
  throw std::invalid_argument("unknown size distribution '" + name + "'");
}

std::vector<double> SizeDistribution::sample(std::size_t n, std::uint64_t seed) const
{
  std::mt19937_64 rng(seed);
  // u in (0, 1) from 53 random bits: the same on every platform.
  auto uniform01 = [&rng]() { return ((rng() >> 11) + 0.5) * 0x1.0p-53; };
  std::vector<double> r(n, mean_radius);
  switch (kind) {
  case Kind::Monodisperse:
    break;
  case Kind::Uniform:
    for (auto &x : r)
      x = mean_radius * (1.0 + spread * (2.0 * uniform01() - 1.0));
    break;
  case Kind::LognormalMass:
    // ln m ~ N(mu, sigma); r ~ m^(1/3), so ln r ~ N(mu/3, sigma/3) up to a constant. The
    // median radius is set to the mean radius given (S4 gives the law of ln m in grams).
    for (std::size_t i = 0; i < n; i += 2) {
      const double u1 = uniform01(), u2 = uniform01();
      const double rad = std::sqrt(-2.0 * std::log(u1));
      const double z[2] = {rad * std::cos(2.0 * M_PI * u2), rad * std::sin(2.0 * M_PI * u2)}; // Box-Muller
      for (int k = 0; k < 2 && i + k < n; ++k)
        r[i + k] = mean_radius * std::exp(sigma * z[k] / 3.0);
    }
    break;
  }
  return r;
}

} // namespace geocomp::dem
