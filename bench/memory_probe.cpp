// geocomp-bench-memory: the memory hierarchy of the machine the DEM benchmark runs on.
//
// Why it exists: the DEM step's cost per particle grows with the specimen once its working
// set (about 515 bytes a sphere: docs/dem.md) leaves the last-level cache, and how far that
// cache reaches on a virtual machine is not what the processor's datasheet says. This probe
// measures it, for each working-set size:
//   - triad bandwidth: a = b + s c over three arrays of the given total size, the best of
//     several sweeps (GB/s counted as 3 x 8 bytes per element);
//   - dependent-load latency: a pointer chase through one 64-byte line after another in a
//     random cyclic order (every load waits for the one before), ns per load.
// `--huge-pages` asks the kernel for 2 MB pages (madvise MADV_HUGEPAGE, honoured when
// transparent huge pages are "madvise" or "always"), which separates the cache's reach from
// the TLB's (4 KB pages: 3 072 L2 TLB entries cover 12 MB on Zen 4).
//
// Usage: geocomp-bench-memory [--huge-pages] [MB ...]   (default sizes 0.5 to 96 MB)
#include <sys/mman.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kPage = std::size_t(2) << 20;

/// A buffer of at least `bytes`, 2 MB aligned, in huge pages when asked for.
struct Buffer
{
  Buffer(std::size_t bytes, bool huge) : size((bytes + kPage - 1) / kPage * kPage)
  {
    data = std::aligned_alloc(kPage, size);
    if (!data) throw std::bad_alloc();
    if (huge) madvise(data, size, MADV_HUGEPAGE);
  }
  ~Buffer() { std::free(data); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  std::size_t size;
  void* data;
};

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Best triad rate over arrays of `bytes` in all, GB/s.
double triad(std::size_t bytes, bool huge)
{
  const std::size_t n = std::max<std::size_t>(bytes / 3 / sizeof(double), 1);
  Buffer ba(n * sizeof(double), huge), bb(n * sizeof(double), huge), bc(n * sizeof(double), huge);
  double* a = static_cast<double*>(ba.data);
  double* b = static_cast<double*>(bb.data);
  double* c = static_cast<double*>(bc.data);
  std::fill(a, a + n, 0.0);
  std::fill(b, b + n, 1.0);
  std::fill(c, c + n, 2.0);
  const int sweeps = int(std::clamp<std::size_t>((std::size_t(1) << 31) / (3 * n * sizeof(double)), 5, 200));
  double best = 1e30;
  for (int s = 0; s < sweeps; ++s) {
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n; ++k) a[k] = b[k] + 1.5 * c[k];
    best = std::min(best, seconds_since(t0));
    std::swap(b, a);  // keep the loop from being hoisted; the same traffic
  }
  return 3.0 * double(n) * sizeof(double) / best / 1e9;
}

/// Mean latency of a dependent load through `bytes` of 64-byte lines in random cyclic order, ns.
double chase(std::size_t bytes, bool huge)
{
  struct alignas(64) Line
  {
    std::size_t next;
    char pad[64 - sizeof(std::size_t)];
  };
  const std::size_t n = std::max<std::size_t>(bytes / sizeof(Line), 2);
  Buffer buffer(n * sizeof(Line), huge);
  Line* line = static_cast<Line*>(buffer.data);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
  for (std::size_t k = 0; k < n; ++k) line[order[k]].next = order[(k + 1) % n];
  std::size_t p = order[0];
  for (std::size_t k = 0; k < n; ++k) p = line[p].next;  // warm: every line once
  const std::size_t loads = 20'000'000;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < loads; ++k) p = line[p].next;
  const double ns = seconds_since(t0) * 1e9 / double(loads);
  if (p == n) std::puts("");  // never: keeps the chase
  return ns;
}

}  // namespace

int main(int argc, char** argv)
{
  bool huge = false;
  std::vector<double> sizes;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--huge-pages") {
      huge = true;
      continue;
    }
    char* end = nullptr;
    const double mb = std::strtod(arg.c_str(), &end);
    if (end == arg.c_str() || *end != '\0' || !(mb > 0.0) || mb > 65536.0) {
      std::fprintf(stderr,
                   "geocomp-bench-memory: argument %d: expected a working-set size in MB (0 < MB <= 65536) or "
                   "--huge-pages, got '%s'\n",
                   k, argv[k]);
      return 2;
    }
    sizes.push_back(mb);
  }
  if (sizes.empty()) sizes = {0.5, 1, 2, 4, 8, 12, 16, 20, 24, 32, 48, 64, 96};
  std::printf("# working set (MB), triad (GB/s), dependent load (ns); %s pages\n", huge ? "2 MB" : "4 KB");
  for (const double mb : sizes) {
    const auto bytes = std::size_t(mb * 1024.0 * 1024.0);
    std::printf("%8.1f %8.1f %8.1f\n", mb, triad(bytes, huge), chase(bytes, huge));
    std::fflush(stdout);
  }
  return 0;
}
