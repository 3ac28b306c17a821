// geocomp-bench-periodic N [seed] [axial strain] [strain rate]: the periodic RVE (dem/periodic) from
// placement to triaxial shear, with its cost. Placement at eta_0 = 0.3, frictionless
// radius growth to p/10 (local damping 0.3), friction 0.5, servo isotropic compression to
// p = 100 kPa, triaxial shear at 2 /s (or the rate given) with the lateral stresses at -p (the tests' RVE,
// tests/dem_periodic/TestCells.h, for any N). One thread; docs/dem.md, the periodic cell.
#include "dem/periodic/PeriodicPreparation.h"
#include "dem/periodic/PeriodicProgram.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace geocomp::dem;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::size_t(std::atol(argv[1])) : 500;
  const std::uint64_t seed = argc > 2 ? std::uint64_t(std::atoll(argv[2])) : 7;
  const double strain = argc > 3 ? std::atof(argv[3]) : 0.05;
  const double rate = argc > 4 ? std::atof(argv[4]) : 2.0;
  const double k_n = 1e5, pressure = 1e5;
  RandomPlacement place;
  place.particles = n;
  place.seed = seed;
  const double r_min = 0.8e-3;
  PeriodicCell::Parameters cp;
  cp.time_step = 0.2 * std::sqrt(2650.0 * 4.0 / 3.0 * M_PI * r_min * r_min * r_min / k_n);
  cp.friction = 0.0;
  cp.local_damping = 0.3;
  const LinearSpringDashpot law(LinearNormal::with_stiffness(k_n, 0.5), LinearTangential::with_ratio(2.0 / 7.0));
  auto t0 = std::chrono::steady_clock::now();
  PeriodicCell cell = place_spheres(place, law, cp);
  const double t_place = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  RadiusGrowth g;
  g.pressure = 0.1 * pressure;
  g.rate = 2e-5;
  const GrowthResult grown = grow_radii(cell, g);
  const double t_grow = seconds_since(t0);
  cp.friction = 0.5;
  cp.local_damping = 0.2;
  cell.set_parameters(cp);
  cell.control().set_parameters(MixedControl::Parameters{0.2, 3.0});
  IsotropicCompression iso;
  iso.pressure = pressure;
  iso.unbalanced = 0.02;
  t0 = std::chrono::steady_clock::now();
  const CompressionResult c = compress_isotropic(cell, iso);
  const double t_iso = seconds_since(t0);
  cell.control().set_parameters(MixedControl::Parameters{0.2, std::max(3.0, rate)});
  TriaxialShear t;
  t.lateral_pressure = pressure;
  t.strain_rate = rate;
  t.axial_strain = strain;
  t.record_interval = 500;
  const std::uint64_t s0 = cell.steps();
  t0 = std::chrono::steady_clock::now();
  const auto recs = shear_triaxial(cell, t);
  const double t_shear = seconds_since(t0);
  const std::uint64_t shear_steps = cell.steps() - s0;
  std::printf("N %zu seed %llu dt %.4g s: placement %.3f s; growth %llu steps %.2f s (phi %.4f); "
              "isotropic %s in %llu steps %.2f s (phi %.4f, Z %.2f)\n",
              n, (unsigned long long)seed, cp.time_step, t_place, (unsigned long long)grown.steps, t_grow,
              grown.packing_fraction, c.converged ? "converged" : "NOT converged", (unsigned long long)c.steps, t_iso,
              c.packing_fraction, cell.coordination());
  std::printf("triaxial at %g /s (inertial number %.2g): %llu steps %.2f s = %.2f us per step = %.3f us per sphere-step; list builds %zu\n",
              rate, rate * 2e-3 * std::sqrt(2650.0 / pressure), (unsigned long long)shear_steps, t_shear, 1e6 * t_shear / double(shear_steps),
              1e6 * t_shear / double(shear_steps) / double(n), cell.neighbours().builds());
  double q_max = 0.0;
  for (const TriaxialRecord& r : recs) q_max = std::max(q_max, r.deviator);
  std::printf("  eps_a   eps_v    q/p    lateral error\n");
  for (std::size_t k = 0; k < recs.size(); k += std::max<std::size_t>(1, recs.size() / 12))
    std::printf("  %.4f %.5f %.4f %.2e\n", recs[k].axial_strain, recs[k].volumetric_strain, recs[k].deviator / pressure,
                recs[k].lateral_error);
  std::printf("  end %.4f %.5f %.4f; peak q/p %.4f\n", recs.back().axial_strain, recs.back().volumetric_strain,
              recs.back().deviator / pressure, q_max / pressure);
  return c.converged ? 0 : 1;
}
