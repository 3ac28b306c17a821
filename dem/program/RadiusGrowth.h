// @sect3{Radius growth: the packing algorithm of S0's "digital core store"}
//
// Why it exists: random sequential placement stops near a packing fraction of 0.4, far
// below S0's 0.6-0.69 (SEED-DIGEST, S0 "Packing generation"). S0 therefore places the
// spheres at a fraction of their size, without overlap, and grows all radii uniformly
// while DEM runs with frictionless particles and walls, until the radii are those fixed
// by the target packing fraction; then friction is switched on and the specimen rests
// until it is in equilibrium. This file holds the three steps, each usable alone:
//  - place_at_random(): random sequential addition of spheres of given radii in a box,
//    no overlap with each other or the walls (cell grid; deterministic for a seed);
//  - grow_radii(): $R_i(t) = f(t)\,R_i^{target}$ with $f$ rising at the rate $\dot f/f$ given
//    (DEM-NOTES section 8) and the last value exactly 1, so that the nominal
//    $\eta = \sum_i \tfrac43\pi R_i^3 / V_{box}$ is the target to round-off;
//  - relax(): DEM at fixed radii and walls until at rest (rest_state() criteria).
// The dynamics (Newtonian velocity Verlet with local damping, or S0's first-order
// "Aristotelian" motion, DemSystem::set_overdamped) is whatever the system is set to.
#pragma once

#include "dem/DemSystem.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace geocomp::dem {

/// Centres for spheres of the given radii inside [lo, hi], none overlapping another or a
/// wall, drawn uniformly in [lo + r, hi - r] and rejected on overlap (at most
/// `max_attempts` draws per sphere, else std::runtime_error). Deterministic in the seed.
std::vector<Vec3> place_at_random(const std::vector<double> &radii, const Vec3 &lo, const Vec3 &hi,
                                  std::uint64_t seed, std::size_t max_attempts = 100000);

/// How far a specimen is from static equilibrium (DEM-NOTES section 6).
struct RestState
{
  double unbalanced = 0.0;    ///< mean |net force| / mean |contact force| (Yade), 0 with no contacts
  /// [J] translational + rotational, of the particles with two contacts or more: rattlers
  /// (0 or 1 contact) fly free in their cages, undamped, and carry no load.
  double kinetic = 0.0;
  std::size_t rattlers = 0;   ///< particles with fewer than two contacts (walls included)
  double elastic = 0.0;       ///< [J] stored in the contact springs
  double kinetic_ratio() const { return elastic > 0.0 ? kinetic / elastic : (kinetic > 0.0 ? 1.0 : 0.0); }
};
RestState rest_state(const DemSystem &system);

/// "At rest": unbalanced-force ratio and kinetic / elastic energy below the thresholds.
struct RestCriteria
{
  double unbalanced = 1e-4;     ///< Yade's acceptance of a prepared specimen
  double kinetic_ratio = 1e-6;  ///< kinetic / elastic energy
  double max_time = 1.0;        ///< [s] of DEM time before giving up
  std::uint64_t check_steps = 500;
  /// FIRE (Bitzek et al. 2006) instead of the system's own damping: after every step,
  /// if the power P = F.v > 0 the velocities are turned towards the forces,
  /// v <- (1 - a) v + a |v| F/|F|, and after `fire_delay` such steps dt grows by
  /// `fire_dt_growth` (up to `fire_dt_max` times the starting step) and a shrinks by
  /// `fire_alpha_decay`; if P <= 0 the particles stop, dt halves and a restarts at
  /// `fire_alpha`. Local damping is off meanwhile; the starting dt is restored at the end.
  /// For frictionless packings only: with friction the rest state depends on the path.
  bool fire = false;
  double fire_alpha = 0.1, fire_alpha_decay = 0.99, fire_dt_growth = 1.1, fire_dt_max = 2.0;
  unsigned fire_delay = 5;
  bool satisfied_by(const RestState &s) const
  {
    return s.unbalanced <= unbalanced && s.kinetic_ratio() <= kinetic_ratio;
  }
};

/// Steps, DEM time and wall time of one phase.
struct PhaseCost
{
  std::uint64_t steps = 0;
  double time = 0.0;          ///< [s] DEM time
  double wall_seconds = 0.0;
};

struct RelaxResult
{
  bool converged = false;
  /// Nothing touched at the start (no contact with an overlap above 1e-9 of the smallest
  /// radius: spheres apart, or an ordered array of touching ones): nothing can come to rest
  /// or move, so the phase ended at once (converged). Without this an ordered array ran
  /// each rest for its whole max_time: its round-off overlaps keep "at rest" from holding.
  bool nothing_touches = false;
  RestState rest;
  PhaseCost cost;
};

/// True when no contact of the system's current state overlaps by more than 1e-9 of the
/// smallest radius (the loads are evaluated first, DemSystem::evaluate_forces).
bool nothing_touches(DemSystem &system);

/// Called now and then with a phase name, the DEM time spent in it and the best estimate
/// of how far the phase is, in [0, 1] (1 when it ends): growth by its radius factor, rests
/// and consolidations by log_progress() of their residuals.
using PhaseProgress = std::function<void(const std::string &phase, double dem_time, double fraction)>;

/// How far a residual that falls roughly geometrically has come from `start` to `target`:
/// ln(start/now) / ln(start/target), in [0, 1] (0 when it has not fallen below start).
inline double log_progress(double start, double now, double target)
{
  if (!(now > target) )
    return 1.0;
  if (!(start > target) || !(now < start))
    return 0.0;
  return std::log(start / now) / std::log(start / target);
}

struct GrowthSettings
{
  double rate = 1.0;              ///< [1/s] growth rate f'/f of all radii
  std::uint64_t interval = 10;    ///< steps between radius updates
  double time_step_safety = 0.2;  ///< dt = safety x critical step of the current radii
};

struct GrowthResult
{
  PhaseCost cost;
  double initial_factor = 0.0;    ///< f at the start
  std::size_t rebuilds = 0;
};

/// Grows every sphere from its current radius to `target_radii[id]` (all current radii
/// must be the same fraction f0 <= 1 of the targets), in steps of
/// $f \leftarrow \min(1, f\,e^{\,rate\,\Delta t\,interval})$ between runs of `interval` steps; the
/// time step follows the radii. Ends with the radii equal to the targets, bit for bit.
GrowthResult grow_radii(DemSystem &system, const std::vector<double> &target_radii, const GrowthSettings &settings,
                        const PhaseProgress &progress = {});

/// Runs the system (walls as they are) until `criteria` hold or max_time has passed; ends
/// at once when nothing touches (RelaxResult::nothing_touches), and says so to `progress`.
RelaxResult relax(DemSystem &system, const RestCriteria &criteria, const std::string &phase = "relax",
                  const PhaseProgress &progress = {});

} // namespace geocomp::dem
