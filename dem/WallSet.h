// @sect3{The WallSet class: the walls of a DemSystem and their records}
//
// Why it exists: the walls are a concept of their own between the drivers and the
// contact pass. Drivers move them and read what the particles did to them; the contact
// pass reads their geometry (as PlaneWall::gap, or packed into arrays for the batched
// kernel) and leaves, per wall slot, the slot's terms of its wall's record. This class
// holds the planes, those per-slot terms and the packed copies, and sums the records.
//
// Records (PlaneWall.h): after each force evaluation wall k holds
//   $F_k = -\sum_c F_c$ over its slots c (the particles receive $F_c$),
//   $T_k = \sum_c (x_c - p_k)\times(-F_c) - M_{r,c}$ (contact point $x_c$ on the plane,
//   rolling moment $M_r$ where the law has one),
//   $K_k = \sum k_{n,c}$ and the count over the touching slots,
// each summed over its own slots in slot order (pass A computes each slot's terms in
// parallel, record_term; then each wall's sum runs on one thread, sum_record, the walls
// on different threads), so they do not depend on the thread count. Over a step the wall does
// the work $W \mathrel{+}= -\tfrac12(F^{old} + F^{new})\cdot V\Delta t$ (trapezoidal rule,
// DEM-NOTES section 10.3), see add_work().
#pragma once

#include "dem/ContactKinematics.h"
#include "dem/ContactLists.h"
#include "dem/EnergyLedger.h"
#include "dem/PairBatchKernel.h"
#include "dem/ParticleStore.h"
#include "dem/PlaneWall.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace geocomp::dem {

class WallSet
{
public:
  /// A wall slot's terms of its wall's record, computed in pass A (in parallel) and summed
  /// in slot order afterwards (the same bits as summing them there).
  struct Term
  {
    Vec3 torque = Vec3::Zero();  ///< (x_c - wall point) x (-F)
    double stiffness = 0.0;      ///< k_n of the contact (touching only)
    bool recorded = false, touching = false;
  };

  /// Appends a wall with a unit normal (and, for a rectangle, a unit in-plane axis);
  /// returns its index. Throws std::invalid_argument for a degenerate wall.
  std::size_t add(const PlaneWall& w);

  std::size_t size() const { return walls_.size(); }
  bool empty() const { return walls_.empty(); }
  const PlaneWall& operator[](std::size_t k) const { return walls_[k]; }
  PlaneWall& operator[](std::size_t k) { return walls_[k]; }
  const PlaneWall& at(std::size_t k) const { return walls_.at(k); }
  PlaneWall& at(std::size_t k) { return walls_.at(k); }
  /// The planes as one array (neighbour search, checkpoints).
  const std::vector<PlaneWall>& planes() const { return walls_; }
  std::vector<PlaneWall>& planes() { return walls_; }
  /// The forces at the start of the step (for the work), kept in checkpoints.
  const std::vector<Vec3>& previous_forces() const { return force_old_; }
  std::vector<Vec3>& previous_forces() { return force_old_; }

  // --- the step
  /// Keeps every wall's force for the work of this step.
  void remember_forces();
  /// Translates every wall by dt times its velocity.
  void move(double dt);
  /// The work of the step, $-\tfrac12(F^{old} + F)\cdot V\Delta t$, into each wall's and the
  /// ledger's total (wall by wall, in wall order).
  void add_work(double dt, EnergyLedger& losses);

  // --- the contact pass
  /// True when no wall is a bounded rectangle (the batched kernel handles only planes).
  bool all_unbounded() const;
  /// Points the batched kernel's wall arrays of `a` at the walls packed here (point,
  /// normal, velocity: 3 doubles per wall; mu_p: one), refreshed now.
  void pack(PairBatchArgs& a);
  /// One Term per wall slot (no allocation once the lists have settled).
  void resize_terms(std::size_t n_slots) { terms_.resize(n_slots); }
  /// Slot c's terms of its wall's record from its load; n_w: the contact normal
  /// PlaneWall::gap gave for the slot.
  template <class Law>
  void record_term(const Law& law, const ParticleStore& store, const ContactLists& lists, std::size_t c,
                   const Vec3& n_w);
  /// Wall w's force, torque, stiffness and count from the loads and terms of its slots
  /// `slots[0 .. count)`, ascending: every wall slot of w in slot order.
  template <bool Rolling>
  void sum_record(const ContactLists& lists, std::size_t w, const std::uint32_t* slots, std::size_t count);

  std::size_t memory_bytes() const;

private:
  std::vector<PlaneWall> walls_;
  std::vector<Vec3> force_old_;  // each wall's force at the start of the step
  std::vector<Term> terms_;      // one per wall slot
  std::vector<double> packed_;   // the walls as the batched kernel reads them
};

template <class Law>
inline void WallSet::record_term(const Law& law, const ParticleStore& store, const ContactLists& lists,
                                                 std::size_t c, const Vec3& n_w)
{
  const WallSlot& s = lists.walls[c];
  const Vec3& force = lists.wall_loads[c].force;
  Term& term = terms_[c];
  term.recorded = term.touching = false;
  if (!(s.overlap > 0.0) && force.squaredNorm() == 0.0) return;  // apart
  const PlaneWall& wall = walls_[s.wall];
  const Index p = s.particle;
  term.recorded = true;
  const Vec3 xc = store.x[p] - (store.radius[p] - s.overlap) * n_w;
  term.torque = (xc - wall.point).cross(-force);
  if (!(s.overlap > 0.0)) return;  // a bond across a gap: force, but no contact
  term.touching = true;
  ContactKinematics kw;
  kw.overlap = s.overlap;
  kw.m_eff = store.mass[p];
  kw.r_eff = store.radius[p];
  term.stiffness = law.normal().evaluate(kw).stiffness;
}

template <bool Rolling>
void WallSet::sum_record(const ContactLists& lists, std::size_t w, const std::uint32_t* slots, std::size_t count)
{
  // Summed in locals and stored once: the walls share cache lines, and other threads sum
  // the other walls at the same time.
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double stiffness = 0.0;
  std::size_t n_contacts = 0;
  for (std::size_t e = 0; e < count; ++e) {
    const std::size_t c = slots[e];
    const Term& term = terms_[c];
    if (!term.recorded) continue;
    force -= lists.wall_loads[c].force;
    torque += term.torque;
    if constexpr (Rolling) torque -= lists.wall_memory[c].rolling;  // the wall receives -M_r
    if (!term.touching) continue;
    stiffness += term.stiffness;
    ++n_contacts;
  }
  PlaneWall& wall = walls_[w];
  wall.force = force;
  wall.torque = torque;
  wall.stiffness = stiffness;
  wall.n_contacts = n_contacts;
}

}  // namespace geocomp::dem
