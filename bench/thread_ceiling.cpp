// geocomp-bench-ceiling: what a machine's cores give together, without the DEM.
//
// Why it exists: the DEM step's phases that have neither a serial part nor an imbalance
// (the kick-drift sweep, the rows' start, pass B2: streams over the particle arrays; the
// pair pass: loads and arithmetic) can only scale as far as the machine lets OpenMP
// threads scale. This probe measures that ceiling at 1, 2, 4, ... threads:
//   - triad bandwidth a = b + s c over three arrays of the given total size (each thread
//     first-touches its own part), the best of several sweeps, GB/s counted as 3 x 8 bytes
//     per element; at about the DEM's working set (100 MB: 100 000 spheres) and beyond the
//     last-level cache (1 GB);
//   - arithmetic: every thread runs eight independent multiply-add chains in registers
//     (no memory traffic), Gflop/s; its speed-up against one thread is what the clock
//     frequency with all cores busy leaves of the cores' count.
// Usage: geocomp-bench-ceiling [MAX_THREADS]   (default: the OpenMP maximum)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

namespace {

double seconds_now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

/// Best triad bandwidth (GB/s) over `mb` megabytes at `threads` threads.
double triad(std::size_t mb, int threads)
{
  const std::size_t n = mb * (std::size_t(1) << 20) / (3 * sizeof(double));
  const std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
  double* const pa = a.get();
  double* const pb = b.get();
  double* const pc = c.get();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < std::int64_t(n); ++i) {
    pa[i] = 0.0;
    pb[i] = 1.0;
    pc[i] = 2.0;
  }
  double best = 1e30;
  for (int sweep = 0; sweep < 8; ++sweep) {
    const double t0 = seconds_now();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < std::int64_t(n); ++i) pa[i] = pb[i] + 0.5 * pc[i];
    best = std::min(best, seconds_now() - t0);
  }
  if (pa[n / 2] != 2.0) std::printf("triad: wrong result\n");
  return 3.0 * sizeof(double) * double(n) / best * 1e-9;
}

/// Gflop/s of eight independent multiply-add chains per thread at `threads` threads.
double arithmetic(int threads)
{
  constexpr long kIterations = 200000000;
  double sink = 0.0;
  const double t0 = seconds_now();
#pragma omp parallel num_threads(threads) reduction(+ : sink)
  {
    double x[8];
    for (int k = 0; k < 8; ++k) x[k] = 1.0 + 1e-3 * (k + omp_get_thread_num());
    for (long i = 0; i < kIterations; ++i)
      for (int k = 0; k < 8; ++k) x[k] = x[k] * 0.999999 + 1e-6;
    for (int k = 0; k < 8; ++k) sink += x[k];
  }
  const double t = seconds_now() - t0;
  if (sink == 0.0) std::printf("arithmetic: no result\n");
  return 2.0 * 8.0 * double(kIterations) * threads / t * 1e-9;
}

}  // namespace

int main(int argc, char** argv)
{
  const int max_threads = argc > 1 ? std::atoi(argv[1]) : omp_get_max_threads();
  if (max_threads < 1) {
    std::fprintf(stderr, "geocomp-bench-ceiling: MAX_THREADS: expected a positive integer\n");
    return 2;
  }
  double triad_small_1 = 0.0, triad_large_1 = 0.0, flops_1 = 0.0;
  for (int t = 1; t <= max_threads; t = t < max_threads && 2 * t > max_threads ? max_threads : 2 * t) {
    const double small = triad(96, t), large = triad(1024, t), flops = arithmetic(t);
    if (t == 1) {
      triad_small_1 = small;
      triad_large_1 = large;
      flops_1 = flops;
    }
    std::printf("ceiling threads=%d triad_96MB=%.1f GB/s (x%.2f) triad_1GB=%.1f GB/s (x%.2f) multiply-add=%.1f Gflop/s (x%.2f)\n",
                t, small, small / triad_small_1, large, large / triad_large_1, flops, flops / flops_1);
    if (t == max_threads) break;
  }
  return 0;
}
