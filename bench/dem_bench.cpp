// @sect3{geocomp-dem-bench: the shared DEM benchmark, geocomp's side}
//
// Why it exists: the engine's speed is only meaningful next to an established engine
// running the same specimen, law and loading on the same machine. This program runs
// ../shared/bench (README.md, params.sh) exactly: monodisperse dense packing read from
// bench_N.xyzr (box [0, L]^3 in the header; bench/tile-packing.sh writes a box
// [lo,hi]x[lo,hi]x[lo,hi]), linear spring-dashpot with k_n = 1e6 N/m,
// k_t = 285714.2857 N/m, c_n = gamma_n m* (gamma_n = 4512.4128 1/s, no clamp, as
// LIGGGHTS hooke/stiffness), no tangential damping, Coulomb mu = 0.4 between particles,
// six frictionless walls with the same normal law moving inward at 0.01 m/s,
// dt = 2.70097e-5 s, skin 2.36 mm; 500 untimed steps, then 2000 timed steps.
//
// Usage: geocomp-dem-bench FILE.xyzr THREADS [N_EQ N_TIMED]
// Prints diagnostics, a memory line, and last a line ending "ns/particle-step: X".
#include "dem/DemSystem.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace geocomp::dem;

int main(int argc, char** argv)
{
  if (argc < 3) {
    std::cerr << "usage: " << argv[0] << " FILE.xyzr THREADS [N_EQ N_TIMED]\n";
    return 2;
  }
  const std::string path = argv[1];
  const int threads = std::atoi(argv[2]);
  const long n_eq = argc > 3 ? std::atol(argv[3]) : 500;
  const long n_timed = argc > 4 ? std::atol(argv[4]) : 2000;

  // params.sh
  const double rho = 2650.0, kn = 1.0e6, kt = 285714.2857, gamma_n = 4512.4128, mu = 0.4;
  const double dt = 2.70097e-5, skin = 0.00236, v_wall = 0.01;

  std::ifstream in(path);
  if (!in) {
    std::cerr << "cannot open " << path << "\n";
    return 1;
  }
  std::string header;
  std::getline(in, header);
  // "box [lo,hi]^3" (the shared data) or "box [lo,hi]x[lo,hi]x[lo,hi]" (bench/tile-packing.sh).
  Vec3 box_lo, box_hi;
  int axes = 0;
  for (std::size_t at = header.find("box"); at != std::string::npos && axes < 3; ++axes) {
    const auto lb = header.find('[', at), comma = header.find(',', lb), rb = header.find(']', lb);
    if (lb == std::string::npos || comma == std::string::npos || rb == std::string::npos) break;
    box_lo[axes] = std::stod(header.substr(lb + 1, comma - lb - 1));
    box_hi[axes] = std::stod(header.substr(comma + 1, rb - comma - 1));
    at = rb + 1;
    if (axes == 0 && header.compare(at, 2, "^3") == 0) {
      box_lo.setConstant(box_lo[0]);
      box_hi.setConstant(box_hi[0]);
      axes = 2;
    } else if (axes < 2 && (at >= header.size() || header[at] != 'x')) {
      break;
    }
  }
  if (axes != 3) {
    std::cerr << path << ": header: expected \"box [lo,hi]^3\" or \"box [lo,hi]x[lo,hi]x[lo,hi]\"\n";
    return 2;
  }

  DemSystem sys;
  LinearNormal::Parameters np;
  np.k_n = kn;
  np.damping_input = LinearNormal::Damping::per_unit_mass;
  np.gamma_n = gamma_n;
  np.clamp_tensile = false;
  LinearTangential::Parameters tp;
  tp.stiffness_is_ratio = false;
  tp.k_t = kt;
  tp.damping_is_ratio = false;
  tp.c_t = 0.0;
  // GEOCOMP_BENCH_LAW=s0: S0's normal law instead (k_n from E = 7 GPa, nu = 0.25, V_c = 1 m/s,
  // c_n from restitution 0.5: k_n ~ 2.4e6 N/m here, still stable at this dt), to time the
  // law of the S0 cases; not the shared benchmark's figure.
  if (const char* e = std::getenv("GEOCOMP_BENCH_LAW"); e && std::string(e) == "s0") {
    np.stiffness_input = LinearNormal::Stiffness::from_impact_velocity;
    np.youngs_modulus = 7e9;
    np.poisson_ratio = 0.25;
    np.impact_velocity = 1.0;
    np.damping_input = LinearNormal::Damping::restitution;
    np.restitution = 0.5;
  }
  sys.set_contact_model(LinearSpringDashpot(LinearNormal(np), LinearTangential(tp)));
  sys.set_friction(mu);
  std::vector<Vec3> centres;
  std::vector<double> radii;
  double x, y, z, r;
  while (in >> x >> y >> z >> r) {
    centres.emplace_back(x, y, z);
    radii.push_back(r);
  }
  sys.reserve(centres.size());
  for (std::size_t k = 0; k < centres.size(); ++k) sys.add_sphere(centres[k], radii[k], rho);
  const std::size_t n = sys.n_particles();
  sys.add_box(box_lo, box_hi, 0.0);
  for (std::size_t w = 0; w < 6; ++w) sys.set_wall_velocity(w, v_wall * sys.wall(w).normal);
  sys.set_time_step(dt);
  sys.set_skin(skin);
  sys.set_num_threads(threads);
  // GEOCOMP_SCALAR_PAIRS=1: the scalar pair path instead of the batched AVX2 kernel (same bits).
  if (const char* e = std::getenv("GEOCOMP_SCALAR_PAIRS"); e && std::string(e) == "1") sys.set_batched_pairs(false);

  sys.run(std::size_t(n_eq));
  const std::size_t rebuilds0 = sys.n_rebuilds();
  const auto t0 = std::chrono::steady_clock::now();
  sys.run(std::size_t(n_timed));
  const auto t1 = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(t1 - t0).count();

  const double z_mean = 2.0 * double(sys.n_touching_pairs()) / double(n);
  const EnergyLedger e = sys.energy();
  std::printf("geocomp N=%zu threads=%d rebuilds_timed=%zu listed_pairs/particle=%.2f coordination=%.3f KE=%.17g J batched=%d\n",
              n, threads, sys.n_rebuilds() - rebuilds0, double(sys.contact_lists().pairs.size()) / double(n), z_mean,
              e.kinetic(), sys.batched_pairs() ? 1 : 0);
  std::printf("geocomp N=%zu threads=%d bytes/particle: %.0f\n", n, threads, double(sys.memory_bytes()) / double(n));
  std::printf("geocomp N=%zu threads=%d steps=%ld seconds=%.3f ns/particle-step: %.1f\n", n, threads, n_timed, seconds,
              seconds / double(n_timed) / double(n) * 1e9);
  return 0;
}
