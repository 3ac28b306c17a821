// @sect3{The EnergyAccounting class: what the step dissipated, and the ledger}
//
// Why it exists: the energy balance (EnergyLedger.h, DEM-NOTES section 10.3) is the
// cheapest global check of a run, and it must not depend on the thread count. The
// dissipated energy of a step comes from three places: the contact dashpots, Coulomb
// sliding and bonds (pass A, per slot), local damping or first-order dynamics (the
// kicks), and the walls' work. The contact losses are summed per fixed block of 256
// slots, each block in slot order, into three entries (damping, friction, bonds) and the
// blocks added in block order afterwards (DEM-NOTES section 5), so the sums are the same
// bits for any number of threads. The stored energy is computed on request (ledger()):
//   $E_{kin} = \sum \tfrac12 m v^2 + \tfrac12 I\omega^2$ (clumps as rigid bodies),
//   $E_{grav} = -\sum m\,g\cdot x$, $E_{el}$ the law's springs of every listed slot.
#pragma once

#include "dem/ClumpSet.h"
#include "dem/ContactLaw.h"
#include "dem/ContactLists.h"
#include "dem/EnergyLedger.h"
#include "dem/ParticleStore.h"
#include "dem/WallSet.h"

#include <cstddef>
#include <vector>

namespace geocomp::dem {

/// Entries per block of the fixed-block reduction.
constexpr std::size_t kBlockTerms = 4;

/// The energy a block of slots dissipated, summed in slot order; `store` writes the
/// block's entries (damping, friction, bonds, placement-release work) of the fixed-block
/// reduction.
struct BlockLosses
{
  double damping = 0.0, friction = 0.0, bonds = 0.0, release = 0.0;
  void add(const ContactForce& f)
  {
    damping += f.damping_loss;
    friction += f.friction_loss;
    bonds += f.bond_loss;
    release += f.release_work;
  }
  void store(double* block) const
  {
    block[0] = damping;
    block[1] = friction;
    block[2] = bonds;
    block[3] = release;
  }
};

/// What the ledger's stored energy is computed from.
struct EnergySources
{
  const ParticleStore& store;
  const ClumpSet& clumps;
  const ContactLists& lists;
  const WallSet& walls;
  const ContactModel& model;
  Vec3 gravity;
  double mu;  ///< particle-particle Coulomb coefficient
};

class EnergyAccounting
{
public:
  /// The accumulated terms: dissipated_* and wall_work (the rest stays zero).
  const EnergyLedger& losses() const { return losses_; }
  EnergyLedger& losses() { return losses_; }
  void add_local(double loss) { losses_.dissipated_local += loss; }

  /// Zeroes the entries of each of n contact blocks (pair blocks, then wall blocks).
  void begin_contact_blocks(std::size_t n) { blocks_.assign(kBlockTerms * n, 0.0); }
  /// Block b's entries (BlockLosses::store).
  double* contact_block(std::size_t b) { return &blocks_[kBlockTerms * b]; }
  /// Adds the n blocks' losses into the ledger, in block order.
  void add_contact_blocks(std::size_t n);
  /// Drops the scratch (after a checkpoint is read).
  void clear_scratch() { blocks_.clear(); }

  /// The complete ledger: the accumulated terms plus the kinetic, gravitational and
  /// elastic energy of the current state.
  EnergyLedger ledger(const EnergySources& s) const;

  std::size_t memory_bytes() const { return blocks_.capacity() * sizeof(double); }

private:
  EnergyLedger losses_{};       // dissipated_* and wall_work accumulate here
  std::vector<double> blocks_;  // per fixed-size block of contact slots, summed in order
};

}  // namespace geocomp::dem
