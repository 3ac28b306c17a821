// @sect3{geocomp-bench-packing: more specimens like the shared benchmark's}
//
// Why it exists: the shared benchmark has packings of 10 000 and 50 000 spheres; the
// scaling target (cost per step from 10k to 100k) needs a 100 000-sphere point made the
// same way, and tiling the 50 000 packing is not that (its faces were pressed by walls,
// and two of them put together spring apart). This program makes one as the README of
// ../shared/bench describes the shared ones: monodisperse spheres of R = 11.8 mm placed at
// random (RadiusGrowth.h: place_at_random) at a fraction f0 of their size in a cube box
// whose edge gives the nominal packing fraction $\eta = N \tfrac43\pi R^3 / L^3$, grown
// frictionless to full size with the benchmark's own law (BenchLaw.h, walls fixed and
// frictionless), then relaxed with Cundall local damping until the unbalanced-force ratio
// is below 1e-3 or a DEM-time limit has passed. The same N, eta and seed give the same file.
//
// Usage: geocomp-bench-packing N ETA SEED OUT.xyzr [THREADS]
//   e.g. geocomp-bench-packing 100000 0.636 7 /tmp/bench_100000.xyzr 2
#include "bench/BenchLaw.h"
#include "dem/program/RadiusGrowth.h"
#include "dem/specimen/Packing.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

using namespace geocomp::dem;

namespace {

int usage(const char *self, const std::string &why)
{
  std::cerr << self << ": " << why << "\nusage: " << self << " N ETA SEED OUT.xyzr [THREADS]\n";
  return 2;
}

} // namespace

int main(int argc, char **argv)
{
  if (argc < 5 || argc > 6)
    return usage(argv[0], "expected 4 or 5 arguments");
  char *end = nullptr;
  const long n = std::strtol(argv[1], &end, 10);
  if (*end != '\0' || n < 8)
    return usage(argv[0], std::string("N: expected an integer >= 8, got '") + argv[1] + "'");
  const double eta = std::strtod(argv[2], &end);
  if (*end != '\0' || !(eta >= 0.3 && eta <= 0.7))
    return usage(argv[0], std::string("ETA: expected a packing fraction in [0.3, 0.7], got '") + argv[2] + "'");
  const unsigned long long seed = std::strtoull(argv[3], &end, 10);
  if (*end != '\0')
    return usage(argv[0], std::string("SEED: expected a non-negative integer, got '") + argv[3] + "'");
  const std::string out = argv[4];
  long threads = 1;
  if (argc > 5) {
    threads = std::strtol(argv[5], &end, 10);
    if (*end != '\0' || threads < 1 || threads > 1024)
      return usage(argv[0], std::string("THREADS: expected an integer in [1, 1024], got '") + argv[5] + "'");
  }

  geocomp::bench::BenchParameters b;
  b.mu = 0.0; // frictionless growth and rest, as the shared packings
  const double R = b.radius, f0 = 0.6;
  const double L = std::cbrt(double(n) * 4.0 / 3.0 * M_PI * R * R * R / eta);
  const Vec3 lo = Vec3::Zero(), hi = Vec3::Constant(L);
  const std::vector<double> target(std::size_t(n), R), start(std::size_t(n), f0 * R);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Vec3> centres = place_at_random(start, lo, hi, seed);

  DemSystem sys;
  geocomp::bench::set_bench_law(sys, b);
  sys.reserve(centres.size());
  for (std::size_t k = 0; k < centres.size(); ++k) sys.add_sphere(centres[k], start[k], b.rho);
  sys.add_box(lo, hi, 0.0);
  sys.set_skin(b.skin);
  sys.set_num_threads(int(threads));
  sys.set_local_damping(0.3);

  GrowthSettings gs;
  gs.rate = 5.0; // [1/s]: f from 0.6 to 1 in about 0.1 s of DEM time, 4 000 steps
  gs.time_step_safety = 0.2; // the benchmark's dt = 0.2 sqrt(m / k_n) at full size
  const GrowthResult g = grow_radii(sys, target, gs);
  RestCriteria rest;
  rest.unbalanced = 1e-3;
  rest.kinetic_ratio = 1e-4;
  rest.max_time = 0.1;
  const RelaxResult r = relax(sys, rest, "rest (frictionless)");

  Packing p;
  p.box_min = lo;
  p.box_max = hi;
  p.density = b.rho;
  for (ParticleId id = 0; id < sys.n_particles(); ++id) {
    p.position.push_back(sys.position(id));
    p.radius.push_back(target[id]);
  }
  try {
    write_xyzr(out, p); // a temporary file renamed when complete
  } catch (const PackingFileError &e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  std::printf("geocomp-bench-packing N=%ld eta=%.4f L=%.9g m: growth %llu steps, rest %llu steps (%s: unbalanced %.2e, "
              "K/E %.2e), %.1f s; wrote %s\n",
              n, p.packing_fraction(), L, (unsigned long long)g.cost.steps, (unsigned long long)r.cost.steps,
              r.converged ? "converged" : "time limit", r.rest.unbalanced, r.rest.kinetic_ratio(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), out.c_str());
  return 0;
}
