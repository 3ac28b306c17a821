// @sect3{The StepProfile struct: where a step's time goes}
//
// Why it exists: on many cores a DEM step is only as fast as its slowest serial section
// and its worst-balanced loop, and neither shows in a total time. A StepProfile handed to
// DemSystem::set_profile() accumulates wall-clock seconds per phase of step():
//   sweep    the opening half kick and drift (Integrator, one parallel loop);
//   rebuild  the neighbour-list builds (NeighbourSearch::rebuild);
//   setup    the force evaluation's serial set-up (kernel arguments, scatter plan);
//   rows     the rows' start and the packed bodies (first stage of the parallel region);
//   pairs    pass A over the pair slots, up to the slowest thread;
//   walls    pass A over the wall slots (ends at the region's first barrier);
//   shared   pass B1, the gather of the shared bodies;
//   bodies   pass B2, every body's row and its closing kick;
//   finish   the serial sums after the region (kick losses, energy, the walls' records);
//   other    the rest of step() (walls moved, the rebuild test, counters);
// the rebuild's own parts (build_seconds: the histories kept, the cell grid, the sort, the
// pair lists, the gather index, the wall lists, the references);
// and, per thread, the seconds it spent in pass A's pair blocks, whose spread is the pair
// pass's imbalance (pairs - mean busy time is what the others waited). Timing costs two
// clock reads per stage per step; without a profile (the default) nothing is timed.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace geocomp::dem {

struct StepProfile
{
  enum Phase : std::size_t { sweep, rebuild, setup, rows, pairs, walls, shared, bodies, finish, other, n_phases };
  static constexpr std::array<const char*, n_phases> names{
    {"sweep", "rebuild", "setup", "rows", "pairs", "walls", "shared", "bodies", "finish", "other"}};

  std::array<double, n_phases> seconds{};  ///< accumulated wall-clock seconds per phase
  /// The rebuild's parts (NeighbourSearch::rebuild), accumulated seconds.
  enum BuildPart : std::size_t { keep, grid, sort, pair_lists, gather_index, wall_lists, references, n_build_parts };
  static constexpr std::array<const char*, n_build_parts> build_part_names{
    {"keep", "grid", "sort", "pair_lists", "gather_index", "wall_lists", "references"}};
  std::array<double, n_build_parts> build_seconds{};
  std::vector<double> pair_busy;           ///< per thread: seconds in its pair blocks
  std::size_t steps = 0;                   ///< steps profiled
  std::size_t shared_bodies = 0;           ///< bodies pass B1 gathered at the last step (LoadScatter.h)

  /// Sum over the phases.
  double total() const
  {
    double t = 0.0;
    for (double s : seconds) t += s;
    return t;
  }
};

/// Adds the wall-clock time since its last mark to one of an array of accumulated seconds
/// (StepProfile::seconds or build_seconds); reads no clock without one.
class PhaseClock
{
public:
  explicit PhaseClock(double* seconds) : seconds_(seconds), last_(seconds ? now() : 0.0) {}
  void mark(std::size_t phase)
  {
    if (!seconds_) return;
    const double t = now();
    seconds_[phase] += t - last_;
    last_ = t;
  }
  /// Starts anew without adding (after a phase another clock timed).
  void restart()
  {
    if (seconds_) last_ = now();
  }
  static double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

private:
  double* seconds_;
  double last_;
};

}  // namespace geocomp::dem
