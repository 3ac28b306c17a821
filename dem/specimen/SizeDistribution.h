#pragma once
// Sphere radii for a specimen: equal (S0's reference), uniform in radius, or lognormal by
// mass (S4: ln m ~ N(mu, sigma), here with the mean radius fixing mu). Drawn from a
// seeded std::mt19937_64 so a seed always gives the same radii on every machine
// (the distributions are computed here from uniform draws, not with the standard
// library's distribution classes, whose algorithms are implementation-defined).
#include <cstdint>
#include <string>
#include <vector>

namespace geocomp::dem {

struct SizeDistribution {
  enum class Kind { Monodisperse, Uniform, LognormalMass };
  Kind kind = Kind::Monodisperse;
  double mean_radius = 0.0118;  ///< [m]
  double spread = 0.0;          ///< Uniform: half-width / mean radius
  double sigma = 0.432;         ///< LognormalMass: sigma of ln m (S4)

  static Kind parse(const std::string &name); ///< monodisperse | uniform | lognormal-mass
  /// n radii; deterministic in (seed, n, parameters).
  std::vector<double> sample(std::size_t n, std::uint64_t seed) const;
};

} // namespace geocomp::dem
