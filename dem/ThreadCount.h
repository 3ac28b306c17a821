#pragma once
// @sect3{The thread count from the problem size}
//
// Why it exists: every parallel region and barrier of the DEM step costs the same
// microseconds at 200 spheres as at 200 000, and a thread whose core is busy with another
// process holds up each barrier by a time slice. So a thread pays for itself only above a
// number of particles, measured (docs/dem.md, "Thread count from the problem size"). The
// rule lives here, without dependencies, so that the case file's help text states the same
// number that DemSystem uses (one home).
#include <algorithm>
#include <cstddef>

namespace geocomp::dem {

/// The fewest particles that pay for a thread of the step. Measured on the project's 2-core
/// machine with geocomp-dem-bench (the shared benchmark's law, walls and packing recipe,
/// 2000 timed steps; ns per particle-step, min of 3, 1 / 2 threads): 250 spheres 93 / 105,
/// 500 87 / 74, 1 000 85 / 60, 2 000 82 / 52, 4 000 82 / 46, 10 000 80 / 43. Two threads
/// break even near 350 spheres and pay clearly (1.4x) from 1 000, i.e. 500 per thread; the
/// constant is twice that, for machines whose barriers cost more (many cores) or whose
/// other cores are busy, so two threads start at 2 000 spheres (1.6x on a quiet machine).
inline constexpr std::size_t kMinParticlesPerThread = 1000;

/// The automatic count: min(max_threads, max(1, n_particles / kMinParticlesPerThread)).
constexpr int threads_for(std::size_t n_particles, int max_threads)
{
  const std::size_t paid = std::max<std::size_t>(1, n_particles / kMinParticlesPerThread);
  return int(std::min<std::size_t>(std::size_t(std::max(1, max_threads)), paid));
}

}  // namespace geocomp::dem
