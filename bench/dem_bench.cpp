// @sect3{geocomp-dem-bench: the shared DEM benchmark, geocomp's side}
//
// Why it exists: the engine's speed is only meaningful next to an established engine
// running the same specimen, law and loading on the same machine. This program runs
// ../shared/bench (README.md, params.sh) exactly: monodisperse dense packing read from
// bench_N.xyzr (box [0, L]^3 in the header; geocomp-bench-packing makes more N the same
// way, e.g. the 100 000-sphere scaling point), the law of BenchLaw.h,
// Coulomb mu = 0.4 between particles,
// six frictionless walls with the same normal law moving inward at 0.01 m/s,
// dt = 2.70097e-5 s, skin 2.36 mm; 500 untimed steps, then 2000 timed steps.
//
// Usage: geocomp-dem-bench FILE.xyzr THREADS [N_EQ N_TIMED]
// Prints diagnostics, a memory line, and last a line ending "ns/particle-step: X".
#include "bench/BenchLaw.h"
#include "bench/PeakResident.h"
#include "dem/specimen/Packing.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

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

  const geocomp::bench::BenchParameters b; // params.sh

  Packing packing;
  try {
    packing = read_xyzr(path); // box "[lo,hi]^3" (the shared data) or "[lo,hi]x[lo,hi]x[lo,hi]"
  } catch (const PackingFileError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }

  DemSystem sys;
  geocomp::bench::set_bench_law(sys, b);
  sys.reserve(packing.size());
  for (std::size_t k = 0; k < packing.size(); ++k) sys.add_sphere(packing.position[k], packing.radius[k], b.rho);
  const std::size_t n = sys.n_particles();
  sys.add_box(packing.box_min, packing.box_max, 0.0);
  for (std::size_t w = 0; w < 6; ++w) sys.set_wall_velocity(w, b.v_wall * sys.wall(w).normal);
  sys.set_time_step(b.dt);
  sys.set_skin(b.skin);
  sys.set_num_threads(threads);
  // GEOCOMP_SCALAR_PAIRS=1: the scalar pair path instead of the batched AVX2 kernel (same bits).
  if (const char* e = std::getenv("GEOCOMP_SCALAR_PAIRS"); e && std::string(e) == "1") sys.set_batched_pairs(false);
  // GEOCOMP_PREFETCH=on|off: force the pair kernel's software prefetch (default: automatic,
  // on above DemSystem::kPrefetchFootprint).
  if (const char* e = std::getenv("GEOCOMP_PREFETCH"); e && (std::string(e) == "on" || std::string(e) == "off"))
    sys.set_prefetch(std::string(e) == "on" ? DemSystem::Prefetch::on : DemSystem::Prefetch::off);
  // The timed run reads no contact forces (the peer run writes no dump either): keep only
  // what the steps need (DemSystem::ContactForceRecording); GEOCOMP_RECORD_FORCES=1 keeps
  // every contact's force at every step, as a driver sampling each step would.
  if (const char* e = std::getenv("GEOCOMP_RECORD_FORCES"); !(e && std::string(e) == "1"))
    sys.set_contact_force_recording(DemSystem::ContactForceRecording::on_request);

  sys.run(std::size_t(n_eq));
  // GEOCOMP_PROFILE=1: the timed steps' seconds per phase (StepProfile.h) on a line
  // before the result; the pair stage then ends at a barrier of its own.
  StepProfile profile;
  if (const char* e = std::getenv("GEOCOMP_PROFILE"); e && std::string(e) == "1") sys.set_profile(&profile);
  const std::size_t rebuilds0 = sys.n_rebuilds();
  const auto t0 = std::chrono::steady_clock::now();
  sys.run(std::size_t(n_timed));
  const auto t1 = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(t1 - t0).count();

  const double z_mean = 2.0 * double(sys.n_touching_pairs()) / double(n);
  const EnergyLedger e = sys.energy();
  std::printf("geocomp N=%zu threads=%d rebuilds_timed=%zu listed_pairs/particle=%.2f coordination=%.3f KE=%.17g J batched=%d prefetch=%d\n",
              n, threads, sys.n_rebuilds() - rebuilds0, double(sys.contact_lists().pairs.size()) / double(n), z_mean,
              e.kinetic(), sys.batched_pairs() ? 1 : 0, sys.prefetching() ? 1 : 0);
  std::printf("geocomp N=%zu threads=%d bytes/particle: %.0f peak_resident_MB: %.0f\n", n, threads,
              double(sys.memory_bytes()) / double(n), geocomp::bench::peak_resident_mb());
  if (profile.steps > 0) {
    std::printf("geocomp N=%zu threads=%d profile us/step:", n, threads);
    for (std::size_t k = 0; k < StepProfile::n_phases; ++k)
      std::printf(" %s=%.1f", StepProfile::names[k], 1e6 * profile.seconds[k] / double(profile.steps));
    double busy_max = 0.0, busy_sum = 0.0;
    for (double b : profile.pair_busy) {
      busy_max = std::max(busy_max, b);
      busy_sum += b;
    }
    const double busy_mean = profile.pair_busy.empty() ? 0.0 : busy_sum / double(profile.pair_busy.size());
    std::printf(" pair_busy_max/mean=%.3f shared_bodies=%zu\n", busy_mean > 0.0 ? busy_max / busy_mean : 0.0,
                profile.shared_bodies);
    if (sys.n_rebuilds() > rebuilds0) {
      std::printf("geocomp N=%zu threads=%d ms/rebuild:", n, threads);
      for (std::size_t k = 0; k < StepProfile::n_build_parts; ++k)
        std::printf(" %s=%.2f", StepProfile::build_part_names[k],
                    1e3 * profile.build_seconds[k] / double(sys.n_rebuilds() - rebuilds0));
      std::printf("\n");
    }
  }
  std::printf("geocomp N=%zu threads=%d steps=%ld seconds=%.3f ns/particle-step: %.1f\n", n, threads, n_timed, seconds,
              seconds / double(n_timed) / double(n) * 1e9);
  return 0;
}
