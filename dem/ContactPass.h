// @sect3{The ContactPass class: contact forces, pass A per contact and pass B per body}
//
// Why it exists: the contact loads are the bulk of a DEM step, and their sum must not
// depend on the thread count. This class evaluates them once per force evaluation:
//   pass A, per contact slot (parallel over slots): the law's force F on body j and
//     its lever $n\times F_t$, from the kinematics at the current state (ContactKinematics.h);
//     the pair slots' loads are added into the bodies' rows as they are computed
//     (LoadScatter.h), the wall slots' kept beside the slots with their terms of the
//     walls' records (WallSet.h);
//   pass B1, per shared body: the gather of its incident slots in ascending order;
//   pass B2, per body: its wall slots added into its row in slot order,
//     $F_p \mathrel{+}= F_c$, $T_p \mathrel{-}= (R_p - \delta/2)\,(n\times F_t)$ (DEM-NOTES
//     section 1), the row copied to the store, and the step's closing half kick when asked
//     for (Integrator::kick_particle, or four bodies at a time, ParticleSweepKernel.h).
// Every body's load is then the sum of its slots in slot order from its weight $m\,g$:
// the same bits for 1, 2 or more threads (DEM-NOTES section 5).
//
// The law is a `ContactModel` (std::variant); run() dispatches on it once, and every
// stage is compiled for the concrete law (ContactPass.cpp, one translation unit, so the
// law's evaluation inlines into the loops). S0's linear spring-dashpot law runs four
// slots at a time on an AVX2 processor (PairBatchKernel.h, the same bits).
#pragma once

#include "dem/ContactLaw.h"
#include "dem/ContactLists.h"
#include "dem/EnergyAccounting.h"
#include "dem/Integrator.h"
#include "dem/LoadScatter.h"
#include "dem/PairBatchKernel.h"
#include "dem/ParticleStore.h"
#include "dem/StepProfile.h"
#include "dem/WallSet.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace geocomp::dem {

/// What one force evaluation reads and writes, and how it may run.
struct ContactPassInput
{
  ParticleStore& store;
  ContactLists& lists;
  WallSet& walls;
  EnergyAccounting& energy;       ///< receives the contact losses when `track_energy`
  const Integrator& integrator;   ///< the closing half kick
  std::size_t list_builds = 0;    ///< NeighbourSearch::n_builds(): the scatter plan's key
  double mu = 0.0;                ///< particle-particle Coulomb coefficient
  bool wall_bonding = false;      ///< bonds and adhesion with walls too
  std::uint64_t bonding_walls = ~std::uint64_t(0); ///< bit k: wall k bonds (walls past 63 always)
  bool bonds_with(std::size_t wall) const { return wall_bonding && (wall >= 64 || ((bonding_walls >> wall) & 1u)); }
  Vec3 gravity = Vec3::Zero();
  int threads = 1;
  bool batched_pairs = false;     ///< the AVX2 pair kernel (S0's law only)
  bool batched_sweeps = false;    ///< the closing kick four bodies at a time
  bool prefetch = false;          ///< the pair kernel's software prefetch
  bool track_energy = false;      ///< sum the contacts' dissipation
  StepProfile* profile = nullptr; ///< times the stages when given (a barrier after the pairs)
};

/// What one force evaluation is asked to do.
struct ForceRequest
{
  double dt_history = 0.0;  ///< the histories' increment (0: evaluate without advancing)
  double kick_dt = 0.0;     ///< > 0: pass B gives each body the closing half kick
  bool record = true;       ///< keep every pair slot's load (ContactLists::pair_loads)
};

class ContactPass
{
public:
  /// The contact and wall loads at the current state into the store's force and torque,
  /// the walls' records and (tracking) the energy ledger; returns the closing half kick's
  /// local damping loss (0 without a kick).
  double run(const ContactModel& model, const ContactPassInput& in, const ForceRequest& request);
  /// The lists changed outside a rebuild (a checkpoint was read): plan the scatter anew.
  void invalidate()
  {
    scatter_.invalidate();
    wall_groups_.planned = false;
  }
  std::size_t memory_bytes() const;

private:
  template <class Law, bool Track>
  class Stages;  // the stages of one evaluation for one law (ContactPass.cpp)
  template <class Law, bool Track>
  double run_with(const Law& law, const ContactPassInput& in, const ForceRequest& request);
  template <class Law, bool Track>
  double run_profiled(const Law& law, const ContactPassInput& in, const ForceRequest& request);

  /// The wall slots grouped by wall, each group ascending (a counting sort of the slots),
  /// made once per list build: each wall's record is summed over its group on one thread.
  struct WallGroups
  {
    bool planned = false;
    std::uint64_t generation = 0;
    std::vector<std::uint32_t> offset, slots;  // wall w: slots[offset[w] .. offset[w + 1])
    std::vector<std::uint32_t> cursor;         // plan's fill position per wall (kept: no allocation)
    void plan(const ContactLists& lists, std::size_t n_walls, std::uint64_t generation);
  };

  /// Every kBalanceEvaluations force evaluations the workers' ranges of pair blocks are
  /// moved to equal shares of the time each worker spent on its range (LoadScatter::
  /// rebalance), when the slowest exceeded the mean by more than kBalanceTolerance: the
  /// slots' cost varies along the storage (walls, shared bodies, the touching fraction),
  /// and at 8-16 threads equal block counts left the slowest worker 12-19 % above the mean
  /// (docs/dem.md). The ranges do not change the bits.
  static constexpr std::size_t kBalanceEvaluations = 100;
  static constexpr double kBalanceTolerance = 1.05;
  void balance_workers();

  LoadScatter scatter_;
  WallGroups wall_groups_;
  std::vector<double> worker_seconds_;  // each worker's seconds in pass A's pairs since the last balance
  std::size_t measured_ = 0;            // force evaluations measured since then
  std::vector<PackedBody> packed_position_radius_;    // the batched pair kernel's copies,
  std::vector<PackedBody> packed_velocity_inv_mass_;  // packed before each pass A
  std::vector<double> kick_losses_;                   // the closing kick's, per particle block
};

}  // namespace geocomp::dem
