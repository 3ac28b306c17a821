// @sect3{The DemSystem class: the facade of the DEM engine}
//
// Why it exists: drivers (the loading program, servo control, packing, output, the
// CLI) need one object that owns particles, walls, the contact law, the neighbour
// lists and the integrator, and answers questions about contacts and energy. It runs
// velocity Verlet with rotations (DEM-NOTES section 4):
//   1. half kick: $v \mathrel{+}= \tfrac{\Delta t}{2}F/m$, $\omega \mathrel{+}= \tfrac{\Delta t}{2}T/I$;
//   2. drift: $x \mathrel{+}= \Delta t\,v$, $q \leftarrow \exp(\Delta t\,\omega/2)\otimes q$; move walls;
//   3. rebuild the lists if needed; contact forces $F, T$ at $x(t+\Delta t)$;
//   4. half kick again.
// Optional Cundall local damping (off by default) replaces each force component by
// $F_k - \lambda|F_k|\,\mathrm{sign}(v_k)$ in both half kicks (preparation only: it is not
// frame invariant).
//
// Contact forces are computed once per contact into per-contact slots (pass A, parallel
// over contacts) and summed per particle in a fixed order, the slot order: added into the
// bodies as the slots are computed, or gathered afterwards (pass B) for the bodies two
// threads' slot ranges share (LoadScatter.h); so the same input gives bitwise the same
// trajectory for any thread count.
// The law is a `ContactModel` (std::variant); the step dispatches on it once, and the
// contact loop is compiled for the concrete law.
//
// Structure: this class is the facade; each concept lives in a component of its own,
// held by value (no back-references, so a DemSystem copies like its parts):
//   ParticleStore + ParticleIndex  the particles (structure of arrays) and id -> index;
//   WallSet                        the walls, their packing for the batched kernel, records, work;
//   NeighbourSearch, ContactLists  the Verlet lists and the contact slots (histories);
//   ContactPass                    pass A / pass B over the slots, the law dispatch;
//   Integrator                     kicks, drifts, first-order dynamics, FIRE;
//   EnergyAccounting               the dissipated energy (fixed blocks) and the ledger;
//   ClumpSet                       rigid clumps (DemSystemClumps.cpp).
// step() reads as the scheme above: advance_positions() (1, 2), the walls move, the lists
// are rebuilt if needed, close_step() (3, 4), the walls' work.
//
// Walls: `add_box()` adds six inward-facing planes (x-, x+, y-, y+, z-, z+), each with its
// own velocity (`set_wall_velocity`, any time) and friction mu_p; after each step
// `wall(k)` holds the force the particles exert on it, its torque, contact count,
// stiffness and cumulative work.
//
// Contacts: `contacts()` lists touching contacts with ids, normal, overlap, forces,
// branch vector and contact point (for Love-Weber stress, fabric, coordination);
// `export_contact_state()` / `import_contact_state()` save and restore all tangential
// histories and contact memories (rolling springs, bonds), keyed by stable ids, for
// checkpoints.
//
// Clumps (ClumpSet.h): `add_clump()` adds a rigid cluster of spheres whose mass, centre
// of mass and principal inertia come from voxel integration; its members are spheres in
// the store (flag::member) that the clump moves rigidly, and contacts are generated only
// between members of different clumps (and with free spheres and walls).
#pragma once

#include "dem/ClumpSet.h"
#include "dem/ContactPass.h"
#include "dem/ContactLaw.h"
#include "dem/ContactLists.h"
#include "dem/LoadScatter.h"
#include "dem/EnergyAccounting.h"
#include "dem/EnergyLedger.h"
#include "dem/Integrator.h"
#include "dem/Fragment.h"
#include "dem/NeighbourSearch.h"
#include "dem/PairBatchKernel.h"
#include "dem/ParticleIndex.h"
#include "dem/ParticleSweepKernel.h"
#include "dem/ParticleStore.h"
#include "dem/PlaneWall.h"
#include "dem/StepProfile.h"
#include "dem/ThreadCount.h"
#include "dem/WallSet.h"

#include <cstdint>
#include <iosfwd>
#include <vector>

namespace geocomp::dem {

/// One touching contact, as read by post-processing.
struct ContactRecord
{
  bool wall = false;         ///< true: body i is wall number `i`
  std::uint32_t i = 0;       ///< particle id (or wall index), the lower id of a pair
  ParticleId j = 0;          ///< particle id
  Vec3 normal;               ///< unit, from i to j
  double overlap = 0.0;      ///< delta > 0
  double normal_force = 0.0; ///< F . n (> 0 repulsive)
  Vec3 tangential_force;     ///< on j
  Vec3 force;                ///< total, on j (i receives -force)
  Vec3 branch;               ///< x_j - x_i; wall: x_j - contact point
  Vec3 point;                ///< contact point (mid-overlap; on the plane for walls)
};

/// Persistent state of one contact (tangential history), for checkpoints.
struct ContactState
{
  bool wall = false;
  std::uint32_t i = 0;  ///< lower particle id, or wall index
  ParticleId j = 0;
  double overlap = 0.0;
  Vec3 shear = Vec3::Zero();
  ContactMemory memory{};  ///< rolling spring and bonds (laws with memory; else empty)
};

class DemSystem
{
public:
  DemSystem();

  // --- particles
  /// Adds a sphere of radius R and density rho (mass 4/3 pi R^3 rho); returns its id.
  ParticleId add_sphere(const Vec3& x, double radius, double density, const Vec3& v = Vec3::Zero(),
                        const Vec3& omega = Vec3::Zero());
  std::size_t n_particles() const { return store_.size(); }
  /// One past the largest id handed out (ids of removed particles included).
  std::size_t id_bound() const { return index_of_.size(); }
  /// False for an id whose sphere was replaced by fragments (replace_spheres).
  bool alive(ParticleId id) const { return index_of_.alive(id); }
  /// Reserves storage for n particles (avoids over-allocation when adding many).
  void reserve(std::size_t n) { store_.reserve(n); index_of_.reserve(n); }
  /// Current storage index of a particle id.
  Index index_of(ParticleId id) const { return index_of_[id]; }
  /// Read access to all particle arrays (storage order; see index_of()).
  const ParticleStore& particles() const { return store_; }
  void set_position(ParticleId id, const Vec3& x);
  void set_velocity(ParticleId id, const Vec3& v);
  void set_angular_velocity(ParticleId id, const Vec3& omega);
  /// Kinematic particle: infinite mass and inertia, moves with its set velocity.
  void set_fixed(ParticleId id, bool fixed);
  Vec3 position(ParticleId id) const { return store_.x[index_of_[id]]; }
  Vec3 velocity(ParticleId id) const { return store_.v[index_of_[id]]; }
  Vec3 angular_velocity(ParticleId id) const { return store_.omega[index_of_[id]]; }
  Vec3 force(ParticleId id) const { return store_.force[index_of_[id]]; }
  Vec3 torque(ParticleId id) const { return store_.torque[index_of_[id]]; }
  Quat orientation(ParticleId id) const { return store_.orientation[index_of_[id]]; }
  /// Changes a sphere's radius at constant density: mass $m (R'/R)^3$, inertia
  /// $\tfrac25 m' R'^2$ (a kinematic particle stays kinematic). For radius growth (S0
  /// packing): the lists stay valid through growth, since a rebuild follows when
  /// $\max|\Delta x| + \max \Delta R > s/2$ since the last build (DEM-NOTES section 5).
  /// Forces are recomputed with the new radii before the next step.
  void set_radius(ParticleId id, double radius);
  /// All radii at once, `radii[id]` (same rules as set_radius; the rebuild criterion
  /// counts the largest increase of the batch once).
  void set_radii(const std::vector<double>& radii);

  // --- breakage (S2; DemSystemBreakage.cpp)
  /// Replaces each parent sphere of `batch` by its children (new ids, returned in batch
  /// order). A child moves with its parent's motion as a rigid body about the children's
  /// centre of mass, $v_c = v + \omega\times(x_c - x_G)$, $\omega_c = \omega$, so the linear
  /// momentum of the children equals the parent's times their mass fraction (exactly the
  /// parent's when mass is conserved). The parent's contact histories are dropped; all
  /// others are carried over by id. The parent's id is never reused (alive() turns false).
  /// With `options.release_speed` = u > 0 every contact of a child starts with its overlap
  /// as placement overlap, released at the speed u (ContactLaw.h; needs a law with memory). With `options.shelter_siblings`, the children of one parent
  /// share a sibling group (Types.h) and do not touch each other until
  /// release_separated_siblings() frees the group.
  /// Refuses clump members and kinematic particles. The lists are rebuilt and forces
  /// recomputed before it returns, so contacts() is valid at once. With energy tracking,
  /// the mechanical energy removed is booked as EnergyLedger::dissipated_breakage.
  /// Nothing of this runs in step(): a run without breakage costs the same as before.
  std::vector<ParticleId> replace_spheres(const std::vector<Replacement>& batch, const ReplacementOptions& options = {});
  /// The single-parent form of replace_spheres.
  std::vector<ParticleId> replace_sphere(ParticleId parent, const std::vector<Fragment>& children,
                                         const ReplacementOptions& options = {})
  {
    return replace_spheres({Replacement{parent, children}}, options);
  }
  /// Frees every sibling group none of whose members overlap each other any more (they
  /// interact normally from the next step); returns the number of groups freed.
  std::size_t release_separated_siblings();
  /// Number of spheres still in a sibling group.
  std::size_t n_sheltered() const;

  // --- clumps
  /// Adds a rigid clump of the spheres `members` (world positions) with density rho;
  /// mass properties by voxel integration with cube side `voxel` (0: S4's D_min/20).
  /// Returns the clump index; member particle ids are clump_members(index).
  std::size_t add_clump(const std::vector<ClumpMember>& members, double density, const Vec3& v = Vec3::Zero(),
                        const Vec3& omega = Vec3::Zero(), double voxel = 0.0);
  std::size_t n_clumps() const { return clumps_.size(); }
  const ClumpSet& clumps() const { return clumps_; }
  std::vector<ParticleId> clump_members(std::size_t c) const;
  void set_clump_velocity(std::size_t c, const Vec3& v);
  void set_clump_angular_velocity(std::size_t c, const Vec3& omega);

  // --- walls
  std::size_t add_wall(const PlaneWall& w);
  /// Six faces of the box [lo, hi] with friction mu_p; returns the index of the first
  /// (order x-, x+, y-, y+, z-, z+).
  std::size_t add_box(const Vec3& lo, const Vec3& hi, double mu_p);
  std::size_t n_walls() const { return walls_.size(); }
  const PlaneWall& wall(std::size_t k) const { return walls_.at(k); }
  void set_wall_velocity(std::size_t k, const Vec3& v) { walls_.at(k).velocity = v; }
  /// Moves a wall (takes effect at the next force evaluation).
  void set_wall_position(std::size_t k, const Vec3& point) { walls_.at(k).point = point; }
  void set_wall_friction(std::size_t k, double mu) { walls_.at(k).mu = mu; }

  // --- contact law
  void set_contact_model(const ContactModel& m);
  const ContactModel& contact_model() const { return model_; }
  /// Whether bonds and adhesion (cohesion parts) form with walls too (default false).
  void set_wall_bonding(bool on) { wall_bonding_ = on; invalidate(); }
  /// Which walls bond when wall bonding is on: bit k for wall k (walls past 63 always
  /// bond); default all. Direct tension bonds the loading platens only (z walls: 0b110000).
  void set_bonding_walls(std::uint64_t mask) { bonding_walls_ = mask; invalidate(); }
  std::uint64_t bonding_walls() const { return bonding_walls_; }
  /// Particle-particle Coulomb coefficient mu_s.
  void set_friction(double mu);
  double friction() const { return mu_; }

  // --- settings
  void set_time_step(double dt);
  double time_step() const { return dt_; }
  /// Verlet skin s (default 0.1 of the largest diameter, set at the first step).
  void set_skin(double s) { search_.set_skin(s); invalidate(); }
  /// Threads of the step loop. n > 0: exactly n (`dem/threads` overrides). n <= 0: automatic,
  /// from the problem size: threads_for(n_particles(), OpenMP max threads) (ThreadCount.h:
  /// one thread per kMinParticlesPerThread particles), re-evaluated as each step starts, so
  /// it follows the particles as they are added or removed. The trajectory is the same bits
  /// for any count.
  void set_num_threads(int n);
  /// The threads the step uses: the count given, or the automatic one for the particles now.
  int num_threads() const;
  /// True after set_num_threads(n <= 0): the count follows the problem size.
  bool automatic_threads() const { return threads_setting_ == 0; }
  void set_gravity(const Vec3& g) { gravity_ = g; invalidate(); }
  /// Cundall local damping coefficient lambda_d (0: off, default).
  void set_local_damping(double lambda) { integrator_.set_local_damping(lambda); }
  double local_damping_coefficient() const { return integrator_.local_damping(); }
  /// First-order ("Aristotelian", S0 packing; Klishin & Mikenina 2021) dynamics when
  /// beta > 0: each step sets $v = \beta\,\Delta t\,F/m$, $\omega = \beta\,\Delta t\,T/I$ and drifts
  /// $x \mathrel{+}= \Delta t\,v$ (overdamped, no inertia: explicit steepest descent, stable for
  /// $\beta\,\Delta t^2 k_{eff}/m < 2$). Local damping does not apply; the power $F\cdot v + T\cdot\omega$
  /// is counted as dissipated_local. beta = 0 (default): velocity Verlet.
  void set_overdamped(double beta);
  double overdamped() const { return integrator_.overdamped(); }
  /// FIRE (Bitzek et al. 2006, DEM-NOTES section 8), the velocity part, over the dynamic
  /// particles: the power $P = \sum F\cdot v + T\cdot\omega$ (summed in storage order); if
  /// P > 0, $v \leftarrow (1-\alpha)v + \alpha|v|\hat F$ with global norms (the same for
  /// $\omega$ and the torques), otherwise every velocity and spin is set to zero. Returns P.
  double fire_velocities(double alpha);
  /// Accumulate dissipated energy every step (small cost; off by default).
  void set_energy_tracking(bool on) { track_energy_ = on; }
  /// Evaluate the pairs of the linear spring-dashpot law four at a time with the AVX2
  /// kernel where the processor has it (default on; PairBatchKernel.h), and the spheres'
  /// kick and drift four at a time (ParticleSweepKernel.h). Both paths give the same
  /// bits; off forces the scalar paths (used by the test that compares them).
  void set_batched_pairs(bool on) { batched_pairs_ = on; }
  bool batched_pairs() const { return batched_pairs_ && pair_batch_kernel_available(); }
  /// The kick and drift sweeps four spheres at a time: batched, and no local damping
  /// (the vector sweeps have none).
  bool batched_sweeps() const { return batched_pairs() && integrator_.local_damping() == 0.0 && kick_drift_kernel_available(); }
  /// Software prefetch in the batched pair kernel (the slots 24 ahead of the test, the
  /// j bodies' position, velocities and load row 12 ahead). It saves about a seventh
  /// of the step when the particles and lists outgrow the last-level cache (100 000
  /// spheres in the shared benchmark's packing) and costs a few percent when they fit
  /// (10 000). `automatic` (the default) turns it on at each neighbour-list build when
  /// memory_bytes() exceeds kPrefetchFootprint. Same bits either way.
  enum class Prefetch { automatic, on, off };
  static constexpr std::size_t kPrefetchFootprint = std::size_t(16) << 20;
  void set_prefetch(Prefetch p);
  bool prefetching() const { return prefetch_; }
  /// Reorder particle storage by cell at rebuilds (default on).
  void set_spatial_sorting(bool on) { search_.set_spatial_sorting(on); }
  /// Critical-time-step estimate for the current law and particles: sqrt(m/k_max) for
  /// linear springs, the S4 Rayleigh step for Hertz; multiply by a safety factor.
  double critical_time_step() const;

  // --- running
  /// The contact and wall loads at the current state, as the next step starts from (lists
  /// built if needed, tangential histories not advanced, every contact's load kept): a
  /// specimen measured before its first step. Nothing moves; step() would do the same first.
  void evaluate_forces() { prepare(); }
  void step();
  void run(std::size_t n_steps);
  /// Accumulate the steps' time per phase into `p` (StepProfile.h; nullptr: off, the
  /// default). The profile is the caller's and must outlive the steps it times.
  void set_profile(StepProfile* p)
  {
    profile_ = p;
    search_.set_profile(p);
  }
  double time() const { return time_; }
  std::uint64_t n_steps() const { return steps_; }
  std::size_t n_rebuilds() const { return search_.n_builds(); }
  /// Forces a neighbour-list rebuild at the next step (histories are carried over).
  void request_rebuild() { rebuild_requested_ = true; }

  // --- contacts
  /// Which steps keep every contact's force for contacts(). `every_step` (the default):
  /// all. `on_request`: only the step after record_contact_forces() (and the evaluations
  /// that edits trigger outside step()); the other steps keep only what the step itself
  /// needs, so the pair pass streams the 40-byte history slots and not the 48-byte loads
  /// beside them (ContactLists.h): for drivers that sample contacts now and then (the
  /// loading programs, the benchmark). The trajectory is the same bits either way.
  enum class ContactForceRecording { every_step, on_request };
  void set_contact_force_recording(ContactForceRecording r) { recording_ = r; }
  ContactForceRecording contact_force_recording() const { return recording_; }
  /// The next step keeps every contact's force (ContactForceRecording::on_request).
  void record_contact_forces() { record_requested_ = true; }
  /// True when the last force evaluation kept every contact's force.
  bool contact_forces_current() const { return loads_current_; }
  /// Touching contacts of the last force evaluation; throws std::logic_error when that
  /// evaluation did not keep them (see ContactForceRecording).
  std::vector<ContactRecord> contacts() const;
  /// Touching particle-particle contacts (C of Z = 2C/N).
  std::size_t n_touching_pairs() const;
  std::vector<ContactState> export_contact_state() const;
  /// S3 bonds (cohesion parts) now intact and broken for good, particle-particle and wall.
  struct BondCount { std::size_t intact = 0, broken = 0; };
  BondCount bond_count() const;
  void import_contact_state(const std::vector<ContactState>& states);
  /// Listed pair slots (touching or within the skin), storage indices.
  const ContactLists& contact_lists() const { return lists_; }

  // --- checkpoints
  /// The complete state (particles in storage order, walls, law, settings, contact lists
  /// with histories, neighbour-search references, counters, energy ledger) as raw binary:
  /// a system read back continues bit for bit as the original would, at the same thread
  /// count and with the same build (the format checks the struct sizes). Whoever adds a
  /// member to DemSystem or NeighbourSearch must add it here (DemSystem.cpp).
  void write_state(std::ostream& out) const;
  void read_state(std::istream& in);

  // --- energy and memory
  EnergyLedger energy() const;
  std::size_t memory_bytes() const;

private:
  void invalidate() { ready_ = false; }
  void prepare();
  void rebuild();
  /// The contact forces at the current positions (ContactPass); with `kick_dt` > 0 pass B
  /// also gives each particle the step's closing half kick (step 4) as soon as its load is
  /// summed, and the return value is that kick's local damping loss (0 otherwise).
  /// `record`: every pair slot's load is kept (ContactLists::pair_loads), so contacts()
  /// may read them.
  double compute_forces(double dt_history, double kick_dt = 0.0, bool record = true);
  /// The particles the integrator sweeps over, and what their drift compares against.
  SweepTarget sweep_target() { return SweepTarget{store_, search_.reference_positions(), threads_}; }
  /// The step's opening half kick and drift (or the first-order drift), particles and
  /// clumps; returns the largest squared displacement since the last neighbour build.
  double advance_positions();
  /// The step's forces at the new positions and its closing half kick.
  void close_step(bool record);
  void refresh_index();
  bool law_has_memory() const;
  /// Sets the placement overlap of every listed contact of `children` (sorted ids).
  void place_fragment_contacts(const std::vector<ParticleId>& children, double release_speed);
  double law_reach() const;
  double kick_drift_clumps(double dt);
  void kick_clumps(double dt);
  /// Half a kick of clump c with its current load; adds its local damping loss to `loss`.
  void kick_clump(std::size_t c, double dt, double& loss);
  void place_members(std::size_t c, bool positions);
  void gather_clump_loads();

  // The components (one concept each; docs/dem.md, the engine's structure).
  ParticleStore store_;           // the particles, structure of arrays
  ParticleIndex index_of_;        // particle id -> storage index, with add and remove
  WallSet walls_;                 // the walls and their records
  ContactModel model_;
  double mu_ = 0.0;
  bool wall_bonding_ = false;
  std::uint64_t bonding_walls_ = ~std::uint64_t(0);
  ClumpSet clumps_;
  NeighbourSearch search_;
  ContactLists lists_;
  ContactPass contact_pass_;      // pass A / pass B and the law dispatch
  Integrator integrator_;         // kicks, drifts, first-order dynamics, FIRE
  EnergyAccounting energy_;       // the dissipated energy and the ledger

  // Settings and state of the step.
  double dt_ = 0.0;
  int threads_setting_ = 1;  // set_num_threads(): n > 0 as given, 0 automatic (checkpointed)
  int threads_ = 1;          // the count the step uses: threads_setting_, or the automatic one
  Vec3 gravity_ = Vec3::Zero();
  bool track_energy_ = false;
  bool batched_pairs_ = true;
  Prefetch prefetch_mode_ = Prefetch::automatic;
  bool prefetch_ = false;        // prefetch_mode_ as decided at the last build
  bool ready_ = false;
  bool rebuild_requested_ = true;
  ContactForceRecording recording_ = ContactForceRecording::every_step;
  bool record_requested_ = false;  // record_contact_forces() before the next step
  bool loads_current_ = true;      // the last force evaluation kept every pair slot's load
  double radius_growth_ = 0.0;   // bound on any radius increase since the last build
  double moved2_ = 0.0;          // largest squared displacement since the last build (last step)

  double time_ = 0.0;
  std::uint64_t steps_ = 0;
  StepProfile* profile_ = nullptr;  // not part of the state: a measurement of this run
};

}  // namespace geocomp::dem
