// Small periodic cells shared by the periodic-cell tests.
#pragma once

#include "dem/periodic/PeriodicPreparation.h"
#include "dem/periodic/PeriodicProgram.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace geocomp::dem::test {

/// Linear spring-dashpot, k_n [N/m], restitution e, k_t = 2/7 k_n (S0's benchmark ratio).
inline LinearSpringDashpot periodic_linear_law(double k_n, double e)
{
  return LinearSpringDashpot(LinearNormal::with_stiffness(k_n, e), LinearTangential::with_ratio(2.0 / 7.0));
}

/// The RVE of the program tests: R = 1 mm +- 20 %, rho = 2650, k_n = 1e5 N/m,
/// dt = 0.2 sqrt(m_min / k_n).
struct RveSetup
{
  std::size_t particles = 200;
  std::uint64_t seed = 7;
  double k_n = 1e5;
  double pressure = 1e5;  ///< [Pa]
};

inline double rve_time_step(const RveSetup& s)
{
  const double r_min = 0.8e-3;
  const double m_min = 2650.0 * 4.0 / 3.0 * M_PI * r_min * r_min * r_min;
  return 0.2 * std::sqrt(m_min / s.k_n);
}

/// Placement at eta_0 = 0.3, frictionless radius growth to p/10 with local damping 0.3:
/// a loose packing that just carries load, friction still off.
inline PeriodicCell grown_rve(const RveSetup& s)
{
  RandomPlacement place;
  place.particles = s.particles;
  place.seed = s.seed;
  PeriodicCell::Parameters cp;
  cp.time_step = rve_time_step(s);
  cp.friction = 0.0;
  cp.local_damping = 0.3;
  PeriodicCell cell = place_spheres(place, periodic_linear_law(s.k_n, 0.5), cp);
  RadiusGrowth g;
  g.pressure = 0.1 * s.pressure;
  g.rate = 2e-5;
  const GrowthResult r = grow_radii(cell, g);
  if (!r.reached) throw std::runtime_error("grown_rve: the growth did not reach its pressure");
  return cell;
}

struct Consolidated
{
  PeriodicCell cell;
  CompressionResult compression;
};

/// grown_rve(), then friction 0.5, local damping 0.2 and servo isotropic compression to
/// the pressure (1 % on every stress component, unbalanced-force ratio 0.02).
inline Consolidated consolidated_rve(const RveSetup& s)
{
  PeriodicCell cell = grown_rve(s);
  PeriodicCell::Parameters cp = cell.parameters();
  cp.friction = 0.5;
  cp.local_damping = 0.2;
  cell.set_parameters(cp);
  cell.control().set_parameters(MixedControl::Parameters{0.2, 3.0});
  IsotropicCompression iso;
  iso.pressure = s.pressure;
  iso.tolerance = 0.01;
  iso.unbalanced = 0.02;
  const CompressionResult r = compress_isotropic(cell, iso);
  return Consolidated{std::move(cell), r};
}

}  // namespace geocomp::dem::test
