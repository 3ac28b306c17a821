// @sect3{The BreakageMonitor: applies the crushing criterion to a running DemSystem}
//
// Why it exists: breakage is an event between steps, not a force law, so it lives beside
// the integrator and leaves the step loop untouched (a run without a monitor costs what
// it cost before). Every `interval` steps it
//   1. frees sibling groups whose members no longer overlap (sheltering only, DemSystem.h);
//   2. takes each free sphere's largest contact force $F_{max}$ (pairs and walls, the
//      magnitude of the total contact force) from DemSystem::contacts();
//   3. breaks every sphere with $d \ge d_L$ and $F_{max}/d^2 \ge \sigma_c(d)$ (S2 eq. (3)),
//      in increasing id order, by the fragment rules (BreakageModes.h) with its own
//      seeded generator, and replaces them in one batch; the fragments' overlaps at
//      placement are released at `replacement.release_speed` (ContactLaw.h).
// The force a parent reaches can exceed the threshold by at most the force increase of
// one interval: that is the resolution of the criterion.
#pragma once

#include "dem/BreakageCriterion.h"
#include "dem/BreakageModes.h"
#include "dem/DemSystem.h"

#include <cstdint>
#include <random>
#include <vector>

namespace geocomp::dem {

/// One breakage event, for output.
struct BreakageEvent
{
  double time = 0.0;
  ParticleId parent = 0;
  double diameter = 0.0;        ///< parent d [m]
  double max_force = 0.0;       ///< F_max at the check [N]
  int children = 0;
  double lost_mass = 0.0;       ///< [kg]
};

class BreakageMonitor
{
public:
  struct Settings
  {
    FragmentRules rules;
    CrushingCriterion criterion;
    std::uint64_t interval = 10;   ///< steps between checks
    std::uint64_t seed = 1;
    ReplacementOptions replacement; ///< overlap release (default) or sibling sheltering
  };

  explicit BreakageMonitor(const Settings& s);

  /// Call after every step: checks when the step count is a multiple of the interval.
  /// Returns the number of spheres broken.
  std::size_t after_step(DemSystem& sys)
  {
    return (sys.n_steps() % settings_.interval == 0) ? check(sys) : 0;
  }
  /// Checks now, whatever the step count.
  std::size_t check(DemSystem& sys);

  const std::vector<BreakageEvent>& events() const { return events_; }
  std::size_t n_broken() const { return events_.size(); }
  double lost_mass() const { return lost_mass_; }
  const Settings& settings() const { return settings_; }
  /// Largest contact force on each id (index: id; 0 for removed ids and no contact), as
  /// the last check saw it.
  const std::vector<double>& max_forces() const { return f_max_; }

private:
  Settings settings_;
  std::mt19937_64 rng_;
  std::vector<BreakageEvent> events_;
  std::vector<double> f_max_;
  double lost_mass_ = 0.0;
};

/// Largest contact-force magnitude on each particle id (size sys.id_bound()).
std::vector<double> max_contact_forces(const DemSystem& sys);

}  // namespace geocomp::dem
