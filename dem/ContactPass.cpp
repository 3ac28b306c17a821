#include "dem/ContactPass.h"

#include "dem/ContactKinematics.h"
#include "dem/ParticleSweepKernel.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <variant>

namespace geocomp::dem {

namespace {
static_assert(sizeof(Vec3) == 3 * sizeof(double), "PairBatchKernel reads Vec3 arrays as 3 doubles each");
static_assert(kBlock % 4 == 0, "batches of four slots start at block starts");
static_assert(sizeof(WallSlot) == sizeof(PairSlot) && offsetof(WallSlot, wall) == offsetof(PairSlot, i) &&
                  offsetof(WallSlot, particle) == offsetof(PairSlot, j) &&
                  offsetof(WallSlot, overlap) == offsetof(PairSlot, overlap) &&
                  offsetof(WallSlot, shear) == offsetof(PairSlot, shear),
              "the batched kernel reads wall slots with the pair slots' layout");
static_assert(offsetof(PairSlot, shear) == offsetof(PairSlot, overlap) + sizeof(double),
              "the batched kernel reads and writes a slot's overlap and spring as four consecutive doubles");
static_assert(sizeof(SlotLoad) == 6 * sizeof(double) && offsetof(SlotLoad, lever) == 3 * sizeof(double),
              "the batched kernel writes a SlotLoad as six doubles: force, lever");

/// S0's k_n(m*, R*) of a LinearNormal, for the batched kernel.
double linear_normal_stiffness(const void* part, double m_eff, double r_eff)
{
  return static_cast<const LinearNormal*>(part)->stiffness(m_eff, r_eff);
}

/// The batched kernel's view of the particles, the slots and a LinearSpringDashpot law.
PairBatchArgs pair_batch_args(const LinearSpringDashpot& law, const ParticleStore& store, ContactLists& lists,
                              double mu, double dt_h, bool track)
{
  PairBatchArgs a;
  a.omega = store.omega.front().data();
  a.slots = reinterpret_cast<unsigned char*>(lists.pairs.data());
  const PairSlot probe;
  const auto at = [&](const void* member) {
    return std::size_t(static_cast<const unsigned char*>(member) - reinterpret_cast<const unsigned char*>(&probe));
  };
  a.layout = PairSlotLayout{sizeof(PairSlot), at(&probe.i), at(&probe.j), at(&probe.overlap)};
  a.loads = reinterpret_cast<double*>(lists.pair_loads.data());
  const LinearNormal::Parameters& np = law.normal().parameters();
  LinearLawConstants& c = a.law;
  c.stiffness_direct = np.stiffness_input == LinearNormal::Stiffness::direct;
  c.k_n = np.k_n;
  c.stiffness = &linear_normal_stiffness;
  c.normal_part = &law.normal();
  c.damping = np.damping_input == LinearNormal::Damping::direct          ? LinearLawConstants::Damping::direct
              : np.damping_input == LinearNormal::Damping::per_unit_mass ? LinearLawConstants::Damping::per_unit_mass
                                                                         : LinearLawConstants::Damping::restitution;
  c.c_n = np.c_n;
  c.gamma_n = np.gamma_n;
  c.zeta = law.normal().damping_ratio();
  c.clamp_tensile = np.clamp_tensile;
  const LinearTangential::Parameters& tp = law.tangential().parameters();
  c.k_t_is_ratio = tp.stiffness_is_ratio;
  c.k_t = tp.k_t;
  c.c_t_is_ratio = tp.damping_is_ratio;
  c.c_t = tp.c_t;
  a.mu = mu;
  a.dt = dt_h;
  a.track_losses = track;
  return a;
}

/// Pass A's result of one contact: the overlap into its slot (pair or wall slot: the same
/// fields), and its load.
template <class Slot>
inline SlotLoad store_contact(Slot& s, const ContactKinematics& k, const ContactForce& f)
{
  s.overlap = k.overlap;
  return SlotLoad{f.normal * k.normal + f.tangential, k.normal.cross(f.tangential)};
}

/// A contact of a law with memory whose bodies left the interaction range: springs
/// reset, an intact bond breaks (it is beyond its limit), adhesion ruptures.
inline void separate(ContactMemory& m)
{
  if (!m.active()) return;
  m.rolling.setZero();
  m.placement = 0.0;  // apart: no placement overlap is left to release
  m.placement_rate = 0.0;
  if (m.has(ContactMemory::bonded)) {
    m.state = (m.state & ~ContactMemory::bonded) | ContactMemory::bond_broken;
    m.bond.setZero();
    m.bond_origin = 0.0;
  }
  m.state &= ~ContactMemory::adhesion_active;
}

template <class Law>
constexpr bool kLinear = std::is_same_v<Law, LinearSpringDashpot>;
}  // namespace

// @sect4{The stages of one evaluation}
//
// One object per evaluation, on the stack: the serial set-up (prepare_batches,
// prepare_rows) and, inside one OpenMP parallel region, the stages whose worksharing
// loops bind to it (each ends at the loop's implicit barrier): the rows' start, pass A
// over the pair and the wall slots, pass B1 and pass B2; then the serial reductions.
template <class Law, bool Track>
class ContactPass::Stages
{
public:
  Stages(ContactPass& pass, const Law& law, const ContactPassInput& in, const ForceRequest& request)
    : pass_(pass), law_(law), in_(in), dt_h_(request.dt_history), kick_dt_(request.kick_dt),
      record_(request.record), store_(in.store), lists_(in.lists), scatter_(pass.scatter_), n_(in.store.size()),
      nbp_(n_blocks(lists_.pairs.size())), nbw_(n_blocks(lists_.walls.size())), nb_particles_(n_blocks(n_)),
      mu_(in.mu), g_(in.gravity), workers_(in.threads)
  {}

  /// The batched kernels' arguments (S0's law on an AVX2 processor: four slots at a
  /// time, PairBatchKernel.h, the same bits), the walls packed for them.
  void prepare_batches()
  {
    if constexpr (Track) in_.energy.begin_contact_blocks(nbp_ + nbw_);
    pass_.kick_losses_.assign(nb_particles_, 0.0);
    in_.walls.resize_terms(lists_.walls.size());
    pass_.wall_groups_.plan(lists_, in_.walls.size(), in_.list_builds);
    if constexpr (kLinear<Law>) {
      batched_ = in_.batched_pairs && !lists_.pairs.empty() && n_ > 0;
      if (batched_) {
        batch_ = pair_batch_args(law_, store_, lists_, mu_, dt_h_, Track);
        batch_.prefetch = in_.prefetch;
        batch_.record_loads = record_;
      }
      // Wall slots too when every wall is an unbounded plane.
      if (in_.batched_pairs && in_.walls.all_unbounded() && !lists_.walls.empty()) {
        wall_batch_ = pair_batch_args(law_, store_, lists_, 0.0, dt_h_, Track);
        wall_batch_.slots = reinterpret_cast<unsigned char*>(lists_.walls.data());
        wall_batch_.loads = reinterpret_cast<double*>(lists_.wall_loads.data());
        wall_batch_.record_loads = true;  // the walls' records and pass B read every wall load
        in_.walls.pack(wall_batch_);
      }
    }
  }

  /// The packed bodies the batched kernels read (PairBatchKernel.h), the rows the loads
  /// are added into (LoadScatter.h), and the batched closing kick.
  void prepare_rows()
  {
    if (batched_ || wall_batch_.wall_point) {
      pass_.packed_position_radius_.resize(n_);
      pass_.packed_velocity_inv_mass_.resize(n_);
      packed_xr_ = pass_.packed_position_radius_.data();
      packed_vm_ = pass_.packed_velocity_inv_mass_.data();
      for (PairBatchArgs* args : {&batch_, &wall_batch_}) {
        args->position_radius = packed_xr_;
        args->velocity_inv_mass = packed_vm_;
      }
    }
    if (pass_.worker_seconds_.size() != std::size_t(workers_)) {
      pass_.worker_seconds_.assign(std::size_t(workers_), 0.0);
      pass_.measured_ = 0;
    }
    scatter_.plan(lists_, n_, kBlock, workers_, in_.list_builds);
    rows_ = scatter_.rows();
    if (kick_dt_ > 0.0 && n_ > 0 && in_.batched_sweeps) {
      closing_.rows = reinterpret_cast<const double*>(rows_);
      closing_.force = store_.force.front().data();
      closing_.torque = store_.torque.front().data();
      closing_.v = store_.v.front().data();
      closing_.omega = store_.omega.front().data();
      closing_.inv_mass = store_.inv_mass.data();
      closing_.inv_inertia = store_.inv_inertia.data();
      closing_.dt = kick_dt_;
    }
  }

  /// Every row starts from the body's weight; the packed copies of the bodies.
  void start_rows()
  {
    const Arrays a = arrays();
    PackedBody* const packed_xr = packed_xr_;
    PackedBody* const packed_vm = packed_vm_;
    const Vec3 g = g_;
#pragma omp for schedule(static)
    for (std::int64_t p = 0; p < std::int64_t(n_); ++p) {
      const Vec3 weight = a.mass[p] * g;
      a.rows[p] = LoadRow{{weight.x(), weight.y(), weight.z(), 0.0}, {0.0, 0.0, 0.0, 0.0}};
      if (packed_xr) {
        packed_xr[p] = PackedBody{{a.x[p].x(), a.x[p].y(), a.x[p].z(), a.R[p]}};
        packed_vm[p] = PackedBody{{a.v[p].x(), a.v[p].y(), a.v[p].z(), a.im[p]}};
      }
    }
  }

  /// Pass A: particle pairs, worker wk's contiguous blocks (LoadScatter::blocks_of).
  void pass_a_pairs()
  {
#ifdef _OPENMP
    const int n_threads = omp_get_num_threads(), thread = omp_get_thread_num();
#else
    const int n_threads = 1, thread = 0;
#endif
    const Arrays a = arrays();
    const std::size_t n_pairs = lists_.pairs.size();
    for (int wk = thread; wk < workers_; wk += n_threads) {
      const double t0 = PhaseClock::now();
      const auto [b_first, b_last] = scatter_.blocks_of(wk);
      [[maybe_unused]] PairBatchArgs wbatch = batch_;
      wbatch.rows = reinterpret_cast<double*>(a.rows);  // 8 doubles per row, 64-byte aligned
      wbatch.row_of = scatter_.targets();
      wbatch.shared = LoadScatter::kShared;
      wbatch.junk_row = scatter_.junk_row(wk);
      for (std::int64_t b = std::int64_t(b_first); b < std::int64_t(b_last); ++b) {
        BlockLosses lost;
        const std::size_t end = std::min(n_pairs, std::size_t(b + 1) * kBlock);
        if constexpr (kLinear<Law>) {
          if (batched_) {
            const PairBatchLosses l = evaluate_linear_pairs_batched(wbatch, std::size_t(b) * kBlock, end);
            if constexpr (Track) BlockLosses{l.damping, l.friction, 0.0, 0.0}.store(in_.energy.contact_block(b));
            continue;
          }
        }
        for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c) pair_slot(a, c, wk, lost);
        if constexpr (Track) lost.store(in_.energy.contact_block(b));
      }
      pass_.worker_seconds_[std::size_t(wk)] += PhaseClock::now() - t0;
    }
  }

  /// Pass A: particle-wall contacts, through the same law, with their terms of the
  /// walls' records.
  void pass_a_walls()
  {
    const Arrays a = arrays();
    const std::size_t n_slots = lists_.walls.size();
    WallSet& walls = in_.walls;
#pragma omp for schedule(static)
    for (std::int64_t b = 0; b < std::int64_t(nbw_); ++b) {
      BlockLosses lost;
      const std::size_t end = std::min(n_slots, std::size_t(b + 1) * kBlock);
      if constexpr (kLinear<Law>) {
        if (wall_batch_.wall_point) {  // four slots at a time (PairBatchKernel.h, same bits)
          const PairBatchLosses l = evaluate_linear_walls_batched(wall_batch_, std::size_t(b) * kBlock, end);
          for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c)  // unbounded planes: gap's normal
            walls.record_term(law_, store_, lists_, c, walls[a.wslots[c].wall].normal);
          if constexpr (Track) BlockLosses{l.damping, l.friction, 0.0, 0.0}.store(in_.energy.contact_block(nbp_ + b));
          continue;
        }
      }
      for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c) wall_slot(a, c, lost);
      if constexpr (Track) lost.store(in_.energy.contact_block(nbp_ + b));
    }
  }

  /// The walls' records, one wall per thread (no barrier: pass B does not read them).
  void sum_walls()
  {
    const WallGroups& g = pass_.wall_groups_;
    const std::int64_t n_walls = std::int64_t(in_.walls.size());
#pragma omp for schedule(static, 1) nowait
    for (std::int64_t w = 0; w < n_walls; ++w)
      in_.walls.sum_record<Law::has_rolling>(lists_, std::size_t(w), g.slots.data() + g.offset[w],
                                              g.offset[w + 1] - g.offset[w]);
  }

  /// Pass B1: the gather of each shared body's incident slots in ascending order, from
  /// its weight, into its row (the shared bodies, one layer of storage, split evenly).
  void pass_b_shared()
  {
    const Arrays a = arrays();
    const auto& off = lists_.incident_offset;
    const auto& inc = lists_.incident;
    const std::vector<Index>& shared = scatter_.shared_bodies();
    const Vec3 g = g_;
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < std::int64_t(shared.size()); ++k) {
      const Index p = shared[std::size_t(k)];
      const double Rp = a.R[p];
      Vec3 f = a.mass[p] * g, t = Vec3::Zero();
      for (std::uint32_t e = off[p]; e < off[p + 1]; ++e) {
        const PairSlot& s = a.pairs[inc[e] >> 1];
        const SlotLoad& load = a.loads[inc[e] >> 1];
        // +F on j, -F on i, without a branch on the role; f + (-1 x F) and f - F are the
        // same IEEE operation (measured: no change in speed against the branch).
        const double sign = (inc[e] & 1u) ? 1.0 : -1.0;
        f += sign * load.force;
        t -= (Rp - 0.5 * s.overlap) * load.lever;  // T = -(R - delta/2) n x F_t
        if constexpr (Law::has_rolling) {          // M_r on j, -M_r on i
          if (inc[e] & 1u) t += a.pmem[inc[e] >> 1].rolling;
          else t -= a.pmem[inc[e] >> 1].rolling;
        }
      }
      a.rows[p] = LoadRow{{f.x(), f.y(), f.z(), 0.0}, {t.x(), t.y(), t.z(), 0.0}};
    }
  }

  /// Pass B2: every body's row, its wall slots, then the closing half kick when asked for
  /// (four bodies at a time in vectors: ParticleSweepKernel.h).
  void pass_b_bodies()
  {
    const Arrays a = arrays();
    const ClosingKickArgs closing = closing_;
    const double kick_dt = kick_dt_;
    const std::size_t n = n_;
    double* const kick_losses = pass_.kick_losses_.data();
#pragma omp for schedule(static)
    for (std::int64_t b = 0; b < std::int64_t(nb_particles_); ++b) {
      double kick_loss = 0.0;
      const std::size_t p_end = std::min(n, std::size_t(b + 1) * kBlock);
      for (std::size_t p = std::size_t(b) * kBlock; p < p_end; ++p) {
        if (closing.rows && p + 4 <= p_end) {
          for (std::size_t q = p; q < p + 4; ++q) add_wall_loads(a, q);
          close_and_kick4(closing, p);
          p += 3;
          continue;
        }
        add_wall_loads(a, p);
        a.force[p] = Vec3(a.rows[p].f[0], a.rows[p].f[1], a.rows[p].f[2]);
        a.torque[p] = Vec3(a.rows[p].t[0], a.rows[p].t[1], a.rows[p].t[2]);
        if (kick_dt > 0.0) kick_loss += in_.integrator.kick_particle(store_, p, kick_dt);
      }
      kick_losses[b] = kick_loss;
    }
  }

  /// The serial sums, in block order: the closing kick's loss (returned) and the
  /// contacts' dissipation.
  double finish()
  {
    double kick_loss = 0.0;
    for (std::size_t b = 0; b < nb_particles_; ++b) kick_loss += pass_.kick_losses_[b];
    if constexpr (Track) in_.energy.add_contact_blocks(nbp_ + nbw_);
    return kick_loss;
  }

private:
  /// The arrays the loops read and write, bound in each stage's locals (as the lambdas'
  /// captures were): members of this object would be read again after every call out of
  /// line (the kernels).
  struct Arrays
  {
    const std::vector<Vec3>&x, &v, &w;
    const std::vector<double>&R, &im, &mass;
    std::vector<Vec3>&force, &torque;
    std::vector<PairSlot>& pairs;
    std::vector<WallSlot>& wslots;
    std::vector<SlotLoad>&loads, &wloads;
    std::vector<ContactMemory>&pmem, &wmem;
    const std::vector<std::uint32_t>& woff;  // each body's wall slots: [woff[p], woff[p + 1])
    LoadRow* rows;
  };
  Arrays arrays() const
  {
    return Arrays{store_.x,           store_.v,          store_.omega,       store_.radius,
                  store_.inv_mass,    store_.mass,       store_.force,       store_.torque,
                  lists_.pairs,       lists_.walls,      lists_.pair_loads,  lists_.wall_loads,
                  lists_.pair_memory, lists_.wall_memory, lists_.wall_offset, rows_};
  }

  /// The scalar path's loads of slot c into the bodies' rows (the kernel adds its own),
  /// kept beside the slot when recording, when a body is shared (pass B1 gathers those) or
  /// when `keep` (the zeros of a slot that came apart).
  GEOCOMP_CONTACT_KERNEL void scatter_pair(const Arrays& a, std::size_t c, int wk, const SlotLoad& load, bool keep)
  {
    const PairSlot& s = a.pairs[c];
    const std::uint32_t ri = scatter_.row_of(s.i, wk), rj = scatter_.row_of(s.j, wk);
    scatter_.add_pair(ri, rj, load, s.overlap, a.R[s.i], a.R[s.j]);
    if constexpr (Law::has_rolling) scatter_.add_rolling(ri, rj, a.pmem[c].rolling);
    if (keep || record_ || scatter_.shared(s.i) || scatter_.shared(s.j)) a.loads[c] = load;
  }

  /// Pair slot c on the scalar path (worker wk).
  GEOCOMP_CONTACT_KERNEL void pair_slot(const Arrays& a, std::size_t c, int wk, BlockLosses& lost)
  {
    PairSlot& s = a.pairs[c];
    const Index i = s.i, j = s.j;
    const Vec3 d = a.x[j] - a.x[i];
    const double r2 = d.squaredNorm();
    const double rs = a.R[i] + a.R[j];
    double range = rs;
    if constexpr (Law::has_cohesion) range += law_.reach(a.R[i] * a.R[j] / rs);
    if (r2 >= range * range || r2 == 0.0) {
      // Apart: the slot and its load hold zeros (written only when it did not already).
      const bool came_apart = s.overlap != 0.0 || s.shear.squaredNorm() != 0.0;
      if (came_apart) {
        s.overlap = 0.0;
        s.shear.setZero();
      }
      if constexpr (Law::has_memory) separate(a.pmem[c]);
      scatter_pair(a, c, wk, SlotLoad{}, came_apart);
      return;
    }
    ContactKinematics k;
    sphere_sphere_kinematics(k, d, std::sqrt(r2), a.R[i], a.R[j], a.v[i], a.v[j], a.w[i], a.w[j], a.im[i], a.im[j]);
    k.overlap_old = s.overlap;
    k.dt = dt_h_;
    k.mu = mu_;
    ContactForce f;
    if constexpr (Law::has_memory) {
      if constexpr (Law::has_rolling) k.w_rel = a.w[j] - a.w[i];
      f = law_.evaluate(k, s.shear, a.pmem[c]);
    } else {
      f = law_.evaluate(k, s.shear);
    }
    scatter_pair(a, c, wk, store_contact(s, k, f), false);
    if constexpr (Track) lost.add(f);
  }

  /// Wall slot c on the scalar path.
  GEOCOMP_CONTACT_KERNEL void wall_slot(const Arrays& a, std::size_t c, BlockLosses& lost)
  {
    WallSlot& s = a.wslots[c];
    const PlaneWall& wall = in_.walls[s.wall];
    const Index p = s.particle;
    Vec3 n_w;
    const double h = wall.gap(a.x[p], n_w);  // plane distance for unbounded walls
    double range = a.R[p];
    if constexpr (Law::has_cohesion) range += in_.bonds_with(s.wall) ? law_.reach(a.R[p]) : 0.0;
    if (h >= range) {
      s.overlap = 0.0;
      s.shear.setZero();
      a.wloads[c] = SlotLoad{};
      if constexpr (Law::has_memory) separate(a.wmem[c]);
      in_.walls.record_term(law_, store_, lists_, c, n_w);
      return;
    }
    ContactKinematics k;
    sphere_wall_kinematics(k, n_w, h, a.R[p], a.v[p], a.w[p], wall.velocity, a.im[p]);
    k.overlap_old = s.overlap;
    k.dt = dt_h_;
    k.mu = wall.mu;
    ContactForce f;
    if constexpr (Law::has_memory) {
      if constexpr (Law::has_rolling) k.w_rel = a.w[p];  // the wall does not spin
      k.bonding = in_.bonds_with(s.wall);
      f = law_.evaluate(k, s.shear, a.wmem[c]);
    } else {
      f = law_.evaluate(k, s.shear);
    }
    a.wloads[c] = store_contact(s, k, f);
    if constexpr (Track) lost.add(f);
    in_.walls.record_term(law_, store_, lists_, c, n_w);
  }

  /// Body p's wall slots' loads into its row, in slot order.
  GEOCOMP_CONTACT_KERNEL static void add_wall_loads(const Arrays& a, std::size_t p)
  {
    if (a.woff[p] == a.woff[p + 1]) return;
    const double Rp = a.R[p];
    Vec3 f(a.rows[p].f[0], a.rows[p].f[1], a.rows[p].f[2]);
    Vec3 t(a.rows[p].t[0], a.rows[p].t[1], a.rows[p].t[2]);
    for (std::uint32_t e = a.woff[p]; e < a.woff[p + 1]; ++e) {
      f += a.wloads[e].force;
      t -= (Rp - 0.5 * a.wslots[e].overlap) * a.wloads[e].lever;
      if constexpr (Law::has_rolling) t += a.wmem[e].rolling;
    }
    a.rows[p] = LoadRow{{f.x(), f.y(), f.z(), 0.0}, {t.x(), t.y(), t.z(), 0.0}};
  }

  ContactPass& pass_;
  const Law& law_;
  const ContactPassInput& in_;
  const double dt_h_, kick_dt_;
  const bool record_;
  ParticleStore& store_;
  ContactLists& lists_;
  LoadScatter& scatter_;
  const std::size_t n_, nbp_, nbw_, nb_particles_;
  const double mu_;
  const Vec3 g_;
  const int workers_;  // the scatter's workers: one range of pair blocks each
  bool batched_ = false;
  PairBatchArgs batch_;
  PairBatchArgs wall_batch_;
  PackedBody* packed_xr_ = nullptr;  // x, y, z, R
  PackedBody* packed_vm_ = nullptr;  // v_x, v_y, v_z, 1/m
  LoadRow* rows_ = nullptr;
  ClosingKickArgs closing_;
};

// @sect4{Running the stages}

double ContactPass::run(const ContactModel& model, const ContactPassInput& in, const ForceRequest& request)
{
  return std::visit(
    [&](const auto& law) {
      using Law = std::decay_t<decltype(law)>;
      if (in.track_energy) return run_with<Law, true>(law, in, request);
      return run_with<Law, false>(law, in, request);
    },
    model);
}

template <class Law, bool Track>
double ContactPass::run_with(const Law& law, const ContactPassInput& in, const ForceRequest& request)
{
  if (in.profile) return run_profiled<Law, Track>(law, in, request);
  Stages<Law, Track> s(*this, law, in, request);
  s.prepare_batches();
  s.prepare_rows();
#pragma omp parallel num_threads(in.threads)
  {
    s.start_rows();
    s.pass_a_pairs();
    s.pass_a_walls();
    s.sum_walls();
    s.pass_b_shared();
    s.pass_b_bodies();
  }
  const double kick_loss = s.finish();
  balance_workers();
  return kick_loss;
}

void ContactPass::balance_workers()
{
  if (worker_seconds_.size() < 2 || ++measured_ < kBalanceEvaluations) return;
  double longest = 0.0, total = 0.0;
  for (double t : worker_seconds_) {
    longest = std::max(longest, t);
    total += t;
  }
  if (longest * double(worker_seconds_.size()) > kBalanceTolerance * total) scatter_.rebalance(worker_seconds_);
  std::fill(worker_seconds_.begin(), worker_seconds_.end(), 0.0);
  measured_ = 0;
}

/// run_with() with each stage timed (StepProfile.h): the master thread marks the end of
/// every stage after its barrier; the pair stage, which has none, gets one here, and each
/// thread's time in its pair blocks is kept to show the imbalance.
template <class Law, bool Track>
double ContactPass::run_profiled(const Law& law, const ContactPassInput& in, const ForceRequest& request)
{
  StepProfile& profile = *in.profile;
  PhaseClock clock(profile.seconds.data());
  if (profile.pair_busy.size() < std::size_t(in.threads)) profile.pair_busy.resize(std::size_t(in.threads), 0.0);
  Stages<Law, Track> s(*this, law, in, request);
  s.prepare_batches();
  s.prepare_rows();
  profile.shared_bodies = scatter_.shared_bodies().size();
  clock.mark(StepProfile::setup);
#pragma omp parallel num_threads(in.threads)
  {
#ifdef _OPENMP
    const bool master = omp_get_thread_num() == 0;
    double& busy = profile.pair_busy[std::size_t(omp_get_thread_num())];
#else
    const bool master = true;
    double& busy = profile.pair_busy[0];
#endif
    s.start_rows();
    if (master) clock.mark(StepProfile::rows);
    const double t0 = PhaseClock::now();
    s.pass_a_pairs();
    busy += PhaseClock::now() - t0;
#pragma omp barrier
    if (master) clock.mark(StepProfile::pairs);
    s.pass_a_walls();
    s.sum_walls();
    if (master) clock.mark(StepProfile::walls);
    s.pass_b_shared();
    if (master) clock.mark(StepProfile::shared);
    s.pass_b_bodies();
    if (master) clock.mark(StepProfile::bodies);
  }
  const double kick_loss = s.finish();
  balance_workers();
  clock.mark(StepProfile::finish);
  return kick_loss;
}

void ContactPass::WallGroups::plan(const ContactLists& lists, std::size_t n_walls, std::uint64_t build)
{
  if (planned && generation == build && offset.size() == n_walls + 1 && slots.size() == lists.walls.size()) return;
  planned = true;
  generation = build;
  offset.assign(n_walls + 1, 0);
  for (const WallSlot& s : lists.walls) ++offset[s.wall + 1];
  for (std::size_t w = 0; w < n_walls; ++w) offset[w + 1] += offset[w];
  slots.resize(lists.walls.size());
  cursor.assign(offset.begin(), offset.end() - 1);
  for (std::size_t c = 0; c < lists.walls.size(); ++c) slots[cursor[lists.walls[c].wall]++] = std::uint32_t(c);
}

std::size_t ContactPass::memory_bytes() const
{
  return scatter_.memory_bytes() + (wall_groups_.offset.capacity() + wall_groups_.slots.capacity()) * 4 +
         (packed_position_radius_.capacity() + packed_velocity_inv_mass_.capacity()) * sizeof(PackedBody);
}

}  // namespace geocomp::dem
