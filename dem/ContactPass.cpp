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
      record_(request.record), store_(in.store), x_(in.store.x), v_(in.store.v), w_(in.store.omega),
      R_(in.store.radius), im_(in.store.inv_mass), pairs_(in.lists.pairs), wslots_(in.lists.walls),
      loads_(in.lists.pair_loads), wloads_(in.lists.wall_loads), pmem_(in.lists.pair_memory),
      wmem_(in.lists.wall_memory), scatter_(pass.scatter_), n_(in.store.size()), nbp_(n_blocks(pairs_.size())),
      nbw_(n_blocks(wslots_.size())), nb_particles_(n_blocks(n_)), mu_(in.mu), g_(in.gravity)
  {}

  /// The batched kernels' arguments (S0's law on an AVX2 processor: four slots at a
  /// time, PairBatchKernel.h, the same bits), the walls packed for them.
  void prepare_batches()
  {
    if constexpr (Track) in_.energy.begin_contact_blocks(nbp_ + nbw_);
    pass_.kick_losses_.assign(nb_particles_, 0.0);
    in_.walls.resize_terms(wslots_.size());
    if constexpr (kLinear<Law>) {
      batched_ = in_.batched_pairs && !pairs_.empty() && n_ > 0;
      if (batched_) {
        batch_ = pair_batch_args(law_, store_, in_.lists, mu_, dt_h_, Track);
        batch_.prefetch = in_.prefetch;
        batch_.record_loads = record_;
      }
      // Wall slots too when every wall is an unbounded plane.
      if (in_.batched_pairs && in_.walls.all_unbounded() && !wslots_.empty()) {
        wall_batch_ = pair_batch_args(law_, store_, in_.lists, 0.0, dt_h_, Track);
        wall_batch_.slots = reinterpret_cast<unsigned char*>(wslots_.data());
        wall_batch_.loads = reinterpret_cast<double*>(wloads_.data());
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
    scatter_.plan(in_.lists, n_, kBlock, workers_, in_.list_builds);
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
#pragma omp for schedule(static)
    for (std::int64_t p = 0; p < std::int64_t(n_); ++p) {
      const Vec3 weight = store_.mass[p] * g_;
      rows_[p] = LoadRow{{weight.x(), weight.y(), weight.z(), 0.0}, {0.0, 0.0, 0.0, 0.0}};
      if (packed_xr_) {
        packed_xr_[p] = PackedBody{{x_[p].x(), x_[p].y(), x_[p].z(), R_[p]}};
        packed_vm_[p] = PackedBody{{v_[p].x(), v_[p].y(), v_[p].z(), im_[p]}};
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
    for (int wk = thread; wk < workers_; wk += n_threads) {
      const auto [b_first, b_last] = LoadScatter::blocks_of(wk, workers_, nbp_);
      [[maybe_unused]] PairBatchArgs wbatch = batch_;
      wbatch.rows = reinterpret_cast<double*>(rows_);  // 8 doubles per row, 64-byte aligned
      wbatch.row_of = scatter_.targets();
      wbatch.shared = LoadScatter::kShared;
      wbatch.junk_row = scatter_.junk_row(wk);
      for (std::int64_t b = std::int64_t(b_first); b < std::int64_t(b_last); ++b) {
        BlockLosses lost;
        const std::size_t end = std::min(pairs_.size(), std::size_t(b + 1) * kBlock);
        if constexpr (kLinear<Law>) {
          if (batched_) {
            const PairBatchLosses l = evaluate_linear_pairs_batched(wbatch, std::size_t(b) * kBlock, end);
            if constexpr (Track) BlockLosses{l.damping, l.friction, 0.0}.store(in_.energy.contact_block(b));
            continue;
          }
        }
        for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c) pair_slot(c, wk, lost);
        if constexpr (Track) lost.store(in_.energy.contact_block(b));
      }
    }
  }

  /// Pass A: particle-wall contacts, through the same law, with their terms of the
  /// walls' records.
  void pass_a_walls()
  {
#pragma omp for schedule(static)
    for (std::int64_t b = 0; b < std::int64_t(nbw_); ++b) {
      BlockLosses lost;
      const std::size_t end = std::min(wslots_.size(), std::size_t(b + 1) * kBlock);
      if constexpr (kLinear<Law>) {
        if (wall_batch_.wall_point) {  // four slots at a time (PairBatchKernel.h, same bits)
          const PairBatchLosses l = evaluate_linear_walls_batched(wall_batch_, std::size_t(b) * kBlock, end);
          for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c)  // unbounded planes: gap's normal
            in_.walls.record_term(law_, store_, in_.lists, c, in_.walls[wslots_[c].wall].normal);
          if constexpr (Track) BlockLosses{l.damping, l.friction, 0.0}.store(in_.energy.contact_block(nbp_ + b));
          continue;
        }
      }
      for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c) wall_slot(c, lost);
      if constexpr (Track) lost.store(in_.energy.contact_block(nbp_ + b));
    }
  }

  /// Pass B1: the gather of each shared body's incident slots in ascending order, from
  /// its weight, into its row (the shared bodies, one layer of storage, split evenly).
  void pass_b_shared()
  {
    const auto& off = in_.lists.incident_offset;
    const auto& inc = in_.lists.incident;
    const std::vector<Index>& shared = scatter_.shared_bodies();
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < std::int64_t(shared.size()); ++k) {
      const Index p = shared[std::size_t(k)];
      const double Rp = R_[p];
      Vec3 f = store_.mass[p] * g_, t = Vec3::Zero();
      for (std::uint32_t e = off[p]; e < off[p + 1]; ++e) {
        const PairSlot& s = pairs_[inc[e] >> 1];
        const SlotLoad& load = loads_[inc[e] >> 1];
        // +F on j, -F on i, without a branch on the role; f + (-1 x F) and f - F are the
        // same IEEE operation (measured: no change in speed against the branch).
        const double sign = (inc[e] & 1u) ? 1.0 : -1.0;
        f += sign * load.force;
        t -= (Rp - 0.5 * s.overlap) * load.lever;  // T = -(R - delta/2) n x F_t
        if constexpr (Law::has_rolling) {          // M_r on j, -M_r on i
          if (inc[e] & 1u) t += pmem_[inc[e] >> 1].rolling;
          else t -= pmem_[inc[e] >> 1].rolling;
        }
      }
      rows_[p] = LoadRow{{f.x(), f.y(), f.z(), 0.0}, {t.x(), t.y(), t.z(), 0.0}};
    }
  }

  /// Pass B2: every body's row, its wall slots, then the closing half kick when asked for
  /// (four bodies at a time in vectors: ParticleSweepKernel.h).
  void pass_b_bodies()
  {
#pragma omp for schedule(static)
    for (std::int64_t b = 0; b < std::int64_t(nb_particles_); ++b) {
      double kick_loss = 0.0;
      const std::size_t p_end = std::min(n_, std::size_t(b + 1) * kBlock);
      for (std::size_t p = std::size_t(b) * kBlock; p < p_end; ++p) {
        if (closing_.rows && p + 4 <= p_end) {
          for (std::size_t q = p; q < p + 4; ++q) add_wall_loads(q);
          close_and_kick4(closing_, p);
          p += 3;
          continue;
        }
        add_wall_loads(p);
        store_.force[p] = Vec3(rows_[p].f[0], rows_[p].f[1], rows_[p].f[2]);
        store_.torque[p] = Vec3(rows_[p].t[0], rows_[p].t[1], rows_[p].t[2]);
        if (kick_dt_ > 0.0) kick_loss += in_.integrator.kick_particle(store_, p, kick_dt_);
      }
      pass_.kick_losses_[b] = kick_loss;
    }
  }

  /// The serial sums, in block and slot order: the closing kick's loss (returned), the
  /// contacts' dissipation, the walls' records.
  double finish()
  {
    double kick_loss = 0.0;
    for (std::size_t b = 0; b < nb_particles_; ++b) kick_loss += pass_.kick_losses_[b];
    if constexpr (Track) in_.energy.add_contact_blocks(nbp_ + nbw_);
    in_.walls.sum_records<Law::has_rolling>(in_.lists);
    return kick_loss;
  }

private:
  /// The scalar path's loads of slot c into the bodies' rows (the kernel adds its own),
  /// kept beside the slot when recording, when a body is shared (pass B1 gathers those) or
  /// when `keep` (the zeros of a slot that came apart).
  GEOCOMP_CONTACT_KERNEL void scatter_pair(std::size_t c, int wk, const SlotLoad& load, bool keep)
  {
    const PairSlot& s = pairs_[c];
    const std::uint32_t ri = scatter_.row_of(s.i, wk), rj = scatter_.row_of(s.j, wk);
    scatter_.add_pair(ri, rj, load, s.overlap, R_[s.i], R_[s.j]);
    if constexpr (Law::has_rolling) scatter_.add_rolling(ri, rj, pmem_[c].rolling);
    if (keep || record_ || scatter_.shared(s.i) || scatter_.shared(s.j)) loads_[c] = load;
  }

  /// Pair slot c on the scalar path (worker wk).
  GEOCOMP_CONTACT_KERNEL void pair_slot(std::size_t c, int wk, BlockLosses& lost)
  {
    PairSlot& s = pairs_[c];
    const Index i = s.i, j = s.j;
    const Vec3 d = x_[j] - x_[i];
    const double r2 = d.squaredNorm();
    const double rs = R_[i] + R_[j];
    double range = rs;
    if constexpr (Law::has_cohesion) range += law_.reach(R_[i] * R_[j] / rs);
    if (r2 >= range * range || r2 == 0.0) {
      // Apart: the slot and its load hold zeros (written only when it did not already).
      const bool came_apart = s.overlap != 0.0 || s.shear.squaredNorm() != 0.0;
      if (came_apart) {
        s.overlap = 0.0;
        s.shear.setZero();
      }
      if constexpr (Law::has_memory) separate(pmem_[c]);
      scatter_pair(c, wk, SlotLoad{}, came_apart);
      return;
    }
    ContactKinematics k;
    sphere_sphere_kinematics(k, d, std::sqrt(r2), R_[i], R_[j], v_[i], v_[j], w_[i], w_[j], im_[i], im_[j]);
    k.overlap_old = s.overlap;
    k.dt = dt_h_;
    k.mu = mu_;
    ContactForce f;
    if constexpr (Law::has_memory) {
      if constexpr (Law::has_rolling) k.w_rel = w_[j] - w_[i];
      f = law_.evaluate(k, s.shear, pmem_[c]);
    } else {
      f = law_.evaluate(k, s.shear);
    }
    scatter_pair(c, wk, store_contact(s, k, f), false);
    if constexpr (Track) lost.add(f);
  }

  /// Wall slot c on the scalar path.
  GEOCOMP_CONTACT_KERNEL void wall_slot(std::size_t c, BlockLosses& lost)
  {
    WallSlot& s = wslots_[c];
    const PlaneWall& wall = in_.walls[s.wall];
    const Index p = s.particle;
    Vec3 n_w;
    const double h = wall.gap(x_[p], n_w);  // plane distance for unbounded walls
    double range = R_[p];
    if constexpr (Law::has_cohesion) range += in_.wall_bonding ? law_.reach(R_[p]) : 0.0;
    if (h >= range) {
      s.overlap = 0.0;
      s.shear.setZero();
      wloads_[c] = SlotLoad{};
      if constexpr (Law::has_memory) separate(wmem_[c]);
      in_.walls.record_term(law_, store_, in_.lists, c, n_w);
      return;
    }
    ContactKinematics k;
    sphere_wall_kinematics(k, n_w, h, R_[p], v_[p], w_[p], wall.velocity, im_[p]);
    k.overlap_old = s.overlap;
    k.dt = dt_h_;
    k.mu = wall.mu;
    ContactForce f;
    if constexpr (Law::has_memory) {
      if constexpr (Law::has_rolling) k.w_rel = w_[p];  // the wall does not spin
      k.bonding = in_.wall_bonding;
      f = law_.evaluate(k, s.shear, wmem_[c]);
    } else {
      f = law_.evaluate(k, s.shear);
    }
    wloads_[c] = store_contact(s, k, f);
    if constexpr (Track) lost.add(f);
    in_.walls.record_term(law_, store_, in_.lists, c, n_w);
  }

  /// Body p's wall slots' loads into its row, in slot order.
  GEOCOMP_CONTACT_KERNEL void add_wall_loads(std::size_t p)
  {
    const auto& woff = in_.lists.wall_offset;
    if (woff[p] == woff[p + 1]) return;
    const double Rp = R_[p];
    Vec3 f(rows_[p].f[0], rows_[p].f[1], rows_[p].f[2]);
    Vec3 t(rows_[p].t[0], rows_[p].t[1], rows_[p].t[2]);
    for (std::uint32_t e = woff[p]; e < woff[p + 1]; ++e) {
      f += wloads_[e].force;
      t -= (Rp - 0.5 * wslots_[e].overlap) * wloads_[e].lever;
      if constexpr (Law::has_rolling) t += wmem_[e].rolling;
    }
    rows_[p] = LoadRow{{f.x(), f.y(), f.z(), 0.0}, {t.x(), t.y(), t.z(), 0.0}};
  }

  ContactPass& pass_;
  const Law& law_;
  const ContactPassInput& in_;
  const double dt_h_, kick_dt_;
  const bool record_;
  ParticleStore& store_;
  const std::vector<Vec3>& x_;
  const std::vector<Vec3>& v_;
  const std::vector<Vec3>& w_;
  const std::vector<double>& R_;
  const std::vector<double>& im_;
  std::vector<PairSlot>& pairs_;
  std::vector<WallSlot>& wslots_;
  std::vector<SlotLoad>& loads_;
  std::vector<SlotLoad>& wloads_;
  std::vector<ContactMemory>& pmem_;
  std::vector<ContactMemory>& wmem_;
  LoadScatter& scatter_;
  const std::size_t n_, nbp_, nbw_, nb_particles_;
  const double mu_;
  const Vec3 g_;
  const int workers_ = in_.threads;  // the scatter's workers: one range of pair blocks each
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
  Stages<Law, Track> s(*this, law, in, request);
  s.prepare_batches();
  s.prepare_rows();
#pragma omp parallel num_threads(in.threads)
  {
    s.start_rows();
    s.pass_a_pairs();
    s.pass_a_walls();
    s.pass_b_shared();
    s.pass_b_bodies();
  }
  return s.finish();
}

std::size_t ContactPass::memory_bytes() const
{
  return scatter_.memory_bytes() +
         (packed_position_radius_.capacity() + packed_velocity_inv_mass_.capacity()) * sizeof(PackedBody);
}

}  // namespace geocomp::dem
