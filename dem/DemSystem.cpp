#include "dem/DemSystem.h"

#include "common/BinaryState.h"
#include "dem/LegacyState.h"
#include "dem/TimeStep.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace geocomp::dem {

DemSystem::DemSystem() : model_(LinearSpringDashpot(LinearNormal::with_stiffness(1.0, 1.0), LinearTangential())) {}

// @sect4{Particles and walls}

ParticleId DemSystem::add_sphere(const Vec3& x, double radius, double density, const Vec3& v, const Vec3& omega)
{
  if (!(density > 0.0)) throw std::invalid_argument("DemSystem::add_sphere: density must be positive");
  if (!x.allFinite()) throw std::invalid_argument("DemSystem::add_sphere: non-finite position");
  const double mass = 4.0 / 3.0 * M_PI * radius * radius * radius * density;
  const ParticleId id = index_of_.add_sphere(store_, x, radius, mass);
  const Index k = index_of_[id];
  store_.v[k] = v;
  store_.omega[k] = omega;
  rebuild_requested_ = true;
  invalidate();
  return id;
}

void DemSystem::set_position(ParticleId id, const Vec3& x)
{
  store_.x.at(index_of_.at(id)) = x;
  rebuild_requested_ = true;
  invalidate();
}

namespace {
/// Radius, mass (constant density) and inverse mass and inertia of storage index k;
/// returns the increase of the radius.
double change_radius(ParticleStore& p, Index k, double radius)
{
  if (!(radius > 0.0) || !std::isfinite(radius)) throw std::invalid_argument("DemSystem::set_radius: radius must be positive");
  const double r_old = p.radius[k];
  const double ratio = radius / r_old;
  const double mass = p.mass[k] * ratio * ratio * ratio;  // constant density
  p.radius[k] = radius;
  p.mass[k] = mass;
  if (!p.is_fixed(k)) {
    p.inv_mass[k] = 1.0 / mass;
    p.inv_inertia[k] = 1.0 / (0.4 * mass * radius * radius);  // sphere: I = 2/5 m R^2
  }
  return radius - r_old;
}
}  // namespace

void DemSystem::set_radius(ParticleId id, double radius)
{
  if (store_.flags.at(index_of_.at(id)) & flag::member)
    throw std::invalid_argument("DemSystem::set_radius: the sphere is a clump member");
  radius_growth_ += std::max(0.0, change_radius(store_, index_of_.at(id), radius));
  invalidate();
}

void DemSystem::set_radii(const std::vector<double>& radii)
{
  if (radii.size() != index_of_.size()) throw std::invalid_argument("DemSystem::set_radii: one radius per particle");
  double growth = 0.0;
  if (!clumps_.empty()) throw std::logic_error("DemSystem::set_radii: not available with clumps");
  for (ParticleId id = 0; id < radii.size(); ++id)
    if (index_of_.alive(id)) growth = std::max(growth, change_radius(store_, index_of_[id], radii[id]));
  radius_growth_ += growth;  // a bound on each particle's increase since the build
  invalidate();
}

void DemSystem::set_overdamped(double beta)
{
  if (!(beta >= 0.0)) throw std::invalid_argument("DemSystem::set_overdamped: beta must be >= 0");
  integrator_.set_overdamped(beta);
  invalidate();
}

void DemSystem::set_velocity(ParticleId id, const Vec3& v)
{
  store_.v.at(index_of_.at(id)) = v;
  invalidate();
}

void DemSystem::set_angular_velocity(ParticleId id, const Vec3& w)
{
  store_.omega.at(index_of_.at(id)) = w;
  invalidate();
}

void DemSystem::set_fixed(ParticleId id, bool fixed)
{
  if (store_.flags.at(index_of_.at(id)) & flag::member)
    throw std::invalid_argument("DemSystem::set_fixed: the sphere is a clump member");
  store_.set_fixed(index_of_.at(id), fixed);
  rebuild_requested_ = true;  // pairs of two fixed particles are not listed
  invalidate();
}

std::size_t DemSystem::add_wall(const PlaneWall& w)
{
  const std::size_t k = walls_.add(w);
  rebuild_requested_ = true;
  invalidate();
  return k;
}

std::size_t DemSystem::add_box(const Vec3& lo, const Vec3& hi, double mu_p)
{
  if (!((hi - lo).minCoeff() > 0.0)) throw std::invalid_argument("DemSystem::add_box: empty box");
  const std::size_t first = walls_.size();
  for (int f = 0; f < 6; ++f) add_wall(box_face(lo, hi, f, mu_p));
  return first;
}

void DemSystem::set_contact_model(const ContactModel& m)
{
  model_ = m;
  // Memory arrays and list range must follow the law: rebuild when they change.
  if (law_has_memory() != lists_.with_memory || law_reach() != search_.reach()) rebuild_requested_ = true;
  invalidate();
}

bool DemSystem::law_has_memory() const
{
  return std::visit([](const auto& law) { return std::decay_t<decltype(law)>::has_memory; }, model_);
}

double DemSystem::law_reach() const
{
  double r_max = 0.0;
  for (double r : store_.radius) r_max = std::max(r_max, r);
  // reach grows with R*; R* <= R_max for any pair or wall contact.
  return std::visit([&](const auto& law) { return law.reach(r_max); }, model_);
}

void DemSystem::set_friction(double mu)
{
  if (!(mu >= 0.0)) throw std::invalid_argument("DemSystem::set_friction: mu must be >= 0");
  mu_ = mu;
  invalidate();
}

void DemSystem::set_time_step(double dt)
{
  if (!(dt > 0.0)) throw std::invalid_argument("DemSystem::set_time_step: dt must be positive");
  dt_ = dt;
}

// The count given is kept as given; the automatic one is never more than the size pays for
// (ThreadCount.h), nor the OpenMP maximum (OMP_NUM_THREADS, else the cores).
void DemSystem::set_num_threads(int n)
{
  threads_setting_ = std::max(0, n);
  threads_ = num_threads();
}

int DemSystem::num_threads() const
{
  if (threads_setting_ > 0) return threads_setting_;
#ifdef _OPENMP
  return threads_for(store_.size(), omp_get_max_threads());
#else
  return 1;
#endif
}

double DemSystem::critical_time_step() const
{
  double m_min = std::numeric_limits<double>::infinity(), r_min = m_min;
  Index k_min = 0;
  for (Index k = 0; k < store_.size(); ++k) {
    if (store_.inv_mass[k] == 0.0) continue;
    if (store_.mass[k] < m_min) { m_min = store_.mass[k]; k_min = k; }
    r_min = std::min(r_min, store_.radius[k]);
  }
  if (!std::isfinite(m_min)) throw std::logic_error("DemSystem::critical_time_step: no dynamic particles");
  return std::visit(
    [&](const auto& law) -> double {
      using L = std::decay_t<decltype(law)>;
      if constexpr (std::is_same_v<typename L::NormalPart, LinearNormal>) {
        // Wall contact (m* = m, R* = R) is the stiffest for S0's stiffness formula.
        const double kn = std::max(law.normal().stiffness(0.5 * m_min, 0.5 * r_min),
                                   law.normal().stiffness(m_min, r_min));
        double kt = kn;  // S3's anchor spring: mu F_n / delta*_tau, below k_n for small overlaps
        if constexpr (std::is_same_v<typename L::TangentialPart, LinearTangential>)
          kt = law.tangential().stiffness_for(kn);
        return spring_time_scale(m_min, std::max(kn, 3.5 * kt));
      } else {
        const auto& p = law.normal().parameters();
        const double R = store_.radius[k_min];
        const double rho = store_.mass[k_min] / (4.0 / 3.0 * M_PI * R * R * R);
        const double G = p.youngs_modulus / (2.0 * (1.0 + p.poisson_ratio));
        return rayleigh_time_step(r_min, rho, G, p.poisson_ratio);  // S4 Rayleigh step
      }
    },
    model_);
}

// @sect4{Time stepping}

void DemSystem::refresh_index()
{
  index_of_.refresh(store_);
}

void DemSystem::set_prefetch(Prefetch p)
{
  prefetch_mode_ = p;
  prefetch_ = p == Prefetch::on || (p == Prefetch::automatic && memory_bytes() > kPrefetchFootprint);
}

void DemSystem::rebuild()
{
  lists_.with_memory = law_has_memory();
  search_.set_reach(law_reach());
  if (search_.rebuild(store_, walls_.planes(), lists_, threads_)) refresh_index();
  set_prefetch(prefetch_mode_);
  rebuild_requested_ = false;
  radius_growth_ = 0.0;
  moved2_ = 0.0;
}

namespace {
/// The displacement the rebuild criterion sees: motion plus radius growth since the build.
inline double with_growth(double max_d2, double growth)
{
  const double d = std::sqrt(max_d2) + growth;
  return d * d;
}
}  // namespace

void DemSystem::prepare()
{
  threads_ = num_threads();  // the automatic count follows the particles (set_num_threads)
  if (search_.skin() <= 0.0) {
    double r_max = 0.0;
    for (double r : store_.radius) r_max = std::max(r_max, r);
    search_.set_skin(r_max > 0.0 ? 0.2 * r_max : 1.0);  // 0.1 of the largest diameter
  }
  if (rebuild_requested_ ||
      (radius_growth_ > 0.0 && search_.needs_rebuild(with_growth(moved2_, radius_growth_), walls_.planes())))
    rebuild();
  if (!ready_) {
    compute_forces(0.0, 0.0, true);  // forces at the current state, histories not advanced, all kept
    ready_ = true;
  }
}

double DemSystem::fire_velocities(double alpha) { return integrator_.fire_velocities(store_, alpha, threads_); }

void DemSystem::step()
{
  if (!(dt_ > 0.0)) throw std::logic_error("DemSystem::step: time step not set");
  PhaseClock clock(profile_ ? profile_->seconds.data() : nullptr);
  prepare();
  walls_.remember_forces();
  if (integrator_.overdamped() > 0.0 && !clumps_.empty())
    throw std::logic_error("DemSystem::step: first-order dynamics is not available with clumps");
  clock.mark(StepProfile::other);
  const double max_d2 = advance_positions();
  moved2_ = max_d2;
  clock.mark(StepProfile::sweep);
  walls_.move(dt_);
  const bool build = rebuild_requested_ || search_.needs_rebuild(with_growth(max_d2, radius_growth_), walls_.planes());
  clock.mark(StepProfile::other);
  if (build) {
    rebuild();
    clock.mark(StepProfile::rebuild);
  }
  // Every contact's load is kept for contacts() at every step, or at the requested ones.
  const bool record = recording_ == ContactForceRecording::every_step || record_requested_;
  record_requested_ = false;
  close_step(record);  // the contact pass times its own stages
  clock.restart();
  walls_.add_work(dt_, energy_.losses());
  time_ += dt_;
  ++steps_;
  clock.mark(StepProfile::other);
  if (profile_) ++profile_->steps;
}

double DemSystem::advance_positions()
{
  const SweepResult r = integrator_.overdamped() > 0.0 ? integrator_.drift_overdamped(sweep_target(), dt_)
                                                       : integrator_.kick_drift(sweep_target(), dt_, batched_sweeps());
  energy_.add_local(r.loss);
  double max_d2 = r.max_d2;
  if (!clumps_.empty()) max_d2 = std::max(max_d2, kick_drift_clumps(dt_));
  return max_d2;
}

void DemSystem::close_step(bool record)
{
  if (integrator_.overdamped() == 0.0 && clumps_.empty()) {
    energy_.add_local(compute_forces(dt_, dt_, record));  // with the closing half kick
    return;
  }
  compute_forces(dt_, 0.0, record);
  if (integrator_.overdamped() == 0.0) energy_.add_local(integrator_.kick(sweep_target(), dt_));
  if (!clumps_.empty()) kick_clumps(dt_);
}

void DemSystem::run(std::size_t n)
{
  for (std::size_t s = 0; s < n; ++s) step();
}

// @sect4{Contact forces: pass A per contact, pass B per particle}

double DemSystem::compute_forces(double dt_history, double kick_dt, bool record)
{
  ContactPassInput in{store_, lists_, walls_, energy_, integrator_};
  in.list_builds = search_.n_builds();
  in.mu = mu_;
  in.wall_bonding = wall_bonding_;
  in.bonding_walls = bonding_walls_;
  in.gravity = gravity_;
  in.threads = threads_;
  in.batched_pairs = batched_pairs();
  in.batched_sweeps = batched_sweeps();
  in.prefetch = prefetch_;
  in.track_energy = track_energy_;
  in.profile = profile_;
  const double kick_loss = contact_pass_.run(model_, in, ForceRequest{dt_history, kick_dt, record});
  loads_current_ = record;
  if (!clumps_.empty()) gather_clump_loads();
  return kick_loss;
}

// @sect4{Contacts and energy}

std::vector<ContactRecord> DemSystem::contacts() const
{
  if (!contact_forces_current())
    throw std::logic_error("DemSystem::contacts: the last step did not record the contact forces "
                           "(ContactForceRecording::on_request: call record_contact_forces() before that step)");
  std::vector<ContactRecord> out;
  const auto& x = store_.x;
  const auto& R = store_.radius;
  for (std::size_t k = 0; k < lists_.pairs.size(); ++k) {
    const PairSlot& s = lists_.pairs[k];
    const Vec3& force = lists_.pair_loads[k].force;
    if (!(s.overlap > 0.0) && force.squaredNorm() == 0.0) continue;  // apart (a bond may pull across a gap)
    // Reported with i the lower id (the slot's i is the earlier one in storage).
    const bool keep = store_.id[s.i] < store_.id[s.j];
    const Index a = keep ? s.i : s.j, b = keep ? s.j : s.i;
    ContactRecord c;
    c.i = store_.id[a];
    c.j = store_.id[b];
    c.branch = x[b] - x[a];
    c.normal = c.branch.normalized();
    c.overlap = s.overlap;
    c.force = keep ? force : Vec3(-force);
    c.normal_force = c.force.dot(c.normal);
    c.tangential_force = c.force - c.normal_force * c.normal;
    c.point = x[a] + (R[a] - 0.5 * s.overlap) * c.normal;
    out.push_back(c);
  }
  for (std::size_t k = 0; k < lists_.walls.size(); ++k) {
    const WallSlot& s = lists_.walls[k];
    const Vec3& force = lists_.wall_loads[k].force;
    if (!(s.overlap > 0.0) && force.squaredNorm() == 0.0) continue;
    const PlaneWall& wall = walls_[s.wall];
    ContactRecord c;
    c.wall = true;
    c.i = s.wall;
    c.j = store_.id[s.particle];
    wall.gap(x[s.particle], c.normal);
    c.overlap = s.overlap;
    c.force = force;
    c.normal_force = force.dot(c.normal);
    c.tangential_force = force - c.normal_force * c.normal;
    c.point = x[s.particle] - (R[s.particle] - s.overlap) * c.normal;
    c.branch = x[s.particle] - c.point;
    out.push_back(c);
  }
  return out;
}

std::size_t DemSystem::n_touching_pairs() const
{
  std::size_t c = 0;
  for (const PairSlot& s : lists_.pairs) c += (s.overlap > 0.0) ? 1 : 0;
  return c;
}

std::vector<ContactState> DemSystem::export_contact_state() const
{
  std::vector<ContactState> out;
  const bool mem = lists_.with_memory;
  std::vector<std::uint64_t> listed;  // pair keys exported from slots
  for (std::size_t c = 0; c < lists_.pairs.size(); ++c) {
    const PairSlot& s = lists_.pairs[c];
    const ContactMemory m = mem ? lists_.pair_memory[c] : ContactMemory{};
    if (s.overlap > 0.0 || s.shear.squaredNorm() > 0.0 || m.active()) {
      // Exported with i the lower id (the slot's i is the earlier one in storage).
      const ParticleId a = store_.id[s.i], b = store_.id[s.j];
      const bool keep = a < b;
      out.push_back({false, keep ? a : b, keep ? b : a, s.overlap, keep ? s.shear : Vec3(-s.shear), oriented(m, keep)});
      listed.push_back(pair_key(a, b));
    }
  }
  for (std::size_t c = 0; c < lists_.walls.size(); ++c) {
    const WallSlot& s = lists_.walls[c];
    const ContactMemory m = mem ? lists_.wall_memory[c] : ContactMemory{};
    if (s.overlap > 0.0 || s.shear.squaredNorm() > 0.0 || m.active())
      out.push_back({true, s.wall, store_.id[s.particle], s.overlap, s.shear, m});
  }
  // Broken bonds of pairs that left the lists stay broken.
  std::sort(listed.begin(), listed.end());
  for (std::uint64_t key : search_.broken_bonds()) {
    if (std::binary_search(listed.begin(), listed.end(), key)) continue;
    ContactState cs;
    cs.i = std::uint32_t(key >> 32);
    cs.j = ParticleId(key & 0xffffffffu);
    cs.memory.state = ContactMemory::bond_broken;
    out.push_back(cs);
  }
  return out;
}

DemSystem::BondCount DemSystem::bond_count() const
{
  BondCount n;
  const bool cohesive = std::visit([](const auto& law) { return std::decay_t<decltype(law)>::has_cohesion; }, model_);
  if (!cohesive) return n;  // no bonds to count (and no contact state to export)
  for (const ContactState& c : export_contact_state()) {
    if (c.memory.has(ContactMemory::bonded)) ++n.intact;
    if (c.memory.has(ContactMemory::bond_broken)) ++n.broken;
  }
  return n;
}

void DemSystem::import_contact_state(const std::vector<ContactState>& states)
{
  std::vector<HistoryEntry> pairs, walls;
  std::vector<MemoryEntry> pair_mem, wall_mem;
  for (const ContactState& c : states) {
    if (c.wall) {
      if (c.i >= walls_.size()) throw std::invalid_argument("import_contact_state: unknown wall");
      walls.push_back({wall_key(c.i, c.j), c.overlap, c.shear});
      if (c.memory.active()) wall_mem.push_back({wall_key(c.i, c.j), c.memory});
    } else {
      if (c.i >= index_of_.size() || c.j >= index_of_.size())
        throw std::invalid_argument("import_contact_state: unknown particle id");
      // Stored as acting on the higher id: flip if given the other way round.
      const bool keep = c.i < c.j;
      const Vec3 shear = keep ? c.shear : Vec3(-c.shear);
      pairs.push_back({pair_key(c.i, c.j), c.overlap, shear});
      if (c.memory.active()) pair_mem.push_back({pair_key(c.i, c.j), oriented(c.memory, keep)});
    }
  }
  search_.import_histories(std::move(pairs), std::move(walls));
  search_.import_memory(std::move(pair_mem), std::move(wall_mem));
  rebuild_requested_ = true;
  invalidate();
}

EnergyLedger DemSystem::energy() const
{
  return energy_.ledger(EnergySources{store_, clumps_, lists_, walls_, model_, gravity_, mu_});
}

// @sect4{Checkpoint state}
//
// Everything the next step reads is written, in storage order, as raw bytes (see
// BinaryState.h): then a system read back computes the same bits as the original. The
// law is a variant of trivially copyable parameter structs and is stored as its bytes.
// Version 3 added the contact memory (rolling springs, bonds) and the clumps; version 4
// moved the slots' loads beside them (ContactLists.h) and added the recording of contact
// forces; version 5 stores the thread setting (0: automatic) where the count was, in the
// same layout; version 6 adds the fragments' placement overlap to the contact memory and
// the breakage terms to the ledger (S2); version 7 adds which walls bond (S3 direct tension).
// Version 2 to 6 states (restart files, exact specimens in core stores) are
// still read, through their old layouts (LegacyState.h), and continue as they would have,
// with their count as given.

namespace {
constexpr std::uint32_t kStateVersion = 7;

/// Reads the DEMSYSTM tag; returns its version (2 to 6).
std::uint32_t read_state_version(std::istream& in)
{
  char tag[8];
  in.read(tag, 8);
  std::uint32_t version = 0;
  if (in) binary::get(in, version);
  if (!in || std::string(tag, 8) != "DEMSYSTM") throw binary::StateError("checkpoint: section 'DEMSYSTM' not found");
  if (version < 2 || version > kStateVersion)
    throw binary::StateError("checkpoint: section 'DEMSYSTM' has another version");
  return version;
}

/// Reads a slot array and its loads: this version's two arrays, or the single array of
/// versions 2 and 3, whose 88-byte slots held the loads (legacy::SlotV3).
template <class Slot>
void get_slots(std::istream& in, std::uint32_t version, std::vector<Slot>& slots, std::vector<SlotLoad>& loads)
{
  if (version >= 4) {
    binary::get_vector(in, slots);
    binary::get_vector(in, loads);
    if (loads.size() != slots.size()) throw binary::StateError("checkpoint: contact loads do not match the contact lists");
    return;
  }
  static_assert(sizeof(legacy::SlotV3) == 88, "the slots of versions 2 and 3 were 88 bytes");
  std::vector<legacy::SlotV3> old;
  binary::get_vector(in, old);
  slots.resize(old.size());
  loads.resize(old.size());
  for (std::size_t k = 0; k < old.size(); ++k) legacy::convert(old[k], slots[k], loads[k]);
}

void write_clumps(std::ostream& out, const ClumpSet& c)
{
  binary::put_tag(out, "DEMCLUMP", 1);
  binary::put_vector(out, c.x);
  binary::put_vector(out, c.v);
  binary::put_vector(out, c.L_body);
  binary::put_vector(out, c.force);
  binary::put_vector(out, c.torque);
  binary::put_vector(out, c.q);
  binary::put_vector(out, c.mass);
  binary::put_vector(out, c.inv_mass);
  binary::put_vector(out, c.inertia);
  binary::put_vector(out, c.inv_inertia);
  binary::put_vector(out, c.member_offset);
  binary::put_vector(out, c.member_id);
  binary::put_vector(out, c.member_body);
}

void read_clumps(std::istream& in, ClumpSet& c)
{
  binary::expect_tag(in, "DEMCLUMP", 1);
  binary::get_vector(in, c.x);
  binary::get_vector(in, c.v);
  binary::get_vector(in, c.L_body);
  binary::get_vector(in, c.force);
  binary::get_vector(in, c.torque);
  binary::get_vector(in, c.q);
  binary::get_vector(in, c.mass);
  binary::get_vector(in, c.inv_mass);
  binary::get_vector(in, c.inertia);
  binary::get_vector(in, c.inv_inertia);
  binary::get_vector(in, c.member_offset);
  binary::get_vector(in, c.member_id);
  binary::get_vector(in, c.member_body);
  const std::size_t n = c.x.size();
  for (std::size_t a : {c.v.size(), c.L_body.size(), c.force.size(), c.torque.size(), c.q.size(), c.mass.size(),
                        c.inv_mass.size(), c.inertia.size(), c.inv_inertia.size()})
    if (a != n) throw binary::StateError("checkpoint: clump arrays of different lengths");
  if (c.member_offset.size() != n + 1 || c.member_id.size() != c.member_body.size() ||
      c.member_offset.back() != c.member_id.size())
    throw binary::StateError("checkpoint: inconsistent clump members");
}
}  // namespace

void DemSystem::write_state(std::ostream& out) const
{
  static_assert(std::is_trivially_copyable_v<ContactModel>, "ContactModel is stored as its bytes");
  binary::put_tag(out, "DEMSYSTM", kStateVersion);
  binary::put<std::uint64_t>(out, sizeof(ContactModel));
  binary::put(out, model_);
  const ParticleStore& p = store_;
  binary::put_vector(out, p.x);
  binary::put_vector(out, p.v);
  binary::put_vector(out, p.omega);
  binary::put_vector(out, p.force);
  binary::put_vector(out, p.torque);
  binary::put_vector(out, p.orientation);
  binary::put_vector(out, p.radius);
  binary::put_vector(out, p.mass);
  binary::put_vector(out, p.inv_mass);
  binary::put_vector(out, p.inv_inertia);
  binary::put_vector(out, p.id);
  binary::put_vector(out, p.body);
  binary::put_vector(out, p.flags);
  binary::put_vector(out, index_of_.map());
  binary::put_vector(out, walls_.planes());
  binary::put(out, mu_);
  search_.write_state(out);
  binary::put_vector(out, lists_.pairs);
  binary::put_vector(out, lists_.pair_loads);
  binary::put_vector(out, lists_.incident_offset);
  binary::put_vector(out, lists_.incident);
  binary::put_vector(out, lists_.walls);
  binary::put_vector(out, lists_.wall_loads);
  binary::put_vector(out, lists_.wall_offset);
  binary::put(out, lists_.with_memory);
  binary::put_vector(out, lists_.pair_memory);
  binary::put_vector(out, lists_.wall_memory);
  binary::put(out, wall_bonding_);
  binary::put(out, bonding_walls_);
  write_clumps(out, clumps_);
  binary::put(out, dt_);
  binary::put(out, threads_setting_);
  binary::put(out, gravity_);
  binary::put(out, integrator_.local_damping());
  binary::put(out, track_energy_);
  binary::put(out, ready_);
  binary::put(out, rebuild_requested_);
  binary::put(out, integrator_.overdamped());
  binary::put(out, radius_growth_);
  binary::put(out, moved2_);
  binary::put(out, time_);
  binary::put(out, steps_);
  binary::put(out, energy_.losses());
  binary::put_vector(out, walls_.previous_forces());
  binary::put(out, recording_);
  binary::put(out, record_requested_);
  binary::put(out, loads_current_);
  if (!out) throw binary::StateError("DemSystem::write_state: write failed");
}

void DemSystem::read_state(std::istream& in)
{
  const std::uint32_t version = read_state_version(in);
  std::uint64_t model_size = 0;
  binary::get(in, model_size);
  if (version == 2) {
    legacy::ContactModelV2 old;
    if (model_size != sizeof(old)) throw binary::StateError("checkpoint: contact law written by another build");
    binary::get(in, old);
    model_ = legacy::convert(old);
  } else {
    if (model_size != sizeof(ContactModel)) throw binary::StateError("checkpoint: contact law written by another build");
    binary::get(in, model_);
  }
  ParticleStore& p = store_;
  binary::get_vector(in, p.x);
  binary::get_vector(in, p.v);
  binary::get_vector(in, p.omega);
  binary::get_vector(in, p.force);
  binary::get_vector(in, p.torque);
  binary::get_vector(in, p.orientation);
  binary::get_vector(in, p.radius);
  binary::get_vector(in, p.mass);
  binary::get_vector(in, p.inv_mass);
  binary::get_vector(in, p.inv_inertia);
  binary::get_vector(in, p.id);
  binary::get_vector(in, p.body);
  binary::get_vector(in, p.flags);
  const std::size_t n = p.x.size();
  for (std::size_t a : {p.v.size(), p.omega.size(), p.force.size(), p.torque.size(), p.orientation.size(),
                        p.radius.size(), p.mass.size(), p.inv_mass.size(), p.inv_inertia.size(), p.id.size(),
                        p.body.size(), p.flags.size()})
    if (a != n) throw binary::StateError("checkpoint: particle arrays of different lengths");
  binary::get_vector(in, index_of_.map());
  {  // walls: this layout, or the one before bounded walls (legacy::PlaneWallV3, unbounded)
    std::uint64_t n = 0, size = 0;
    binary::get(in, n);
    binary::get(in, size);
    if (n > (std::uint64_t(1) << 30)) throw binary::StateError("checkpoint: implausible array length");
    std::vector<PlaneWall>& walls = walls_.planes();
    if (size == sizeof(PlaneWall)) {
      walls.resize(n);
      if (n) in.read(reinterpret_cast<char*>(walls.data()), std::streamsize(n * sizeof(PlaneWall)));
    } else if (size == sizeof(legacy::PlaneWallV3)) {
      std::vector<legacy::PlaneWallV3> old(n);
      if (n) in.read(reinterpret_cast<char*>(old.data()), std::streamsize(n * size));
      walls.clear();
      for (const auto& o : old) walls.push_back(legacy::convert(o));
    } else {
      throw binary::StateError("checkpoint: record size differs (written by another build)");
    }
    if (!in) throw binary::StateError("checkpoint: unexpected end of data");
  }
  binary::get(in, mu_);
  search_.read_state(in);
  get_slots(in, version, lists_.pairs, lists_.pair_loads);
  contact_pass_.invalidate();
  binary::get_vector(in, lists_.incident_offset);
  binary::get_vector(in, lists_.incident);
  get_slots(in, version, lists_.walls, lists_.wall_loads);
  binary::get_vector(in, lists_.wall_offset);
  if (version >= 3) {
    binary::get(in, lists_.with_memory);
    if (version >= 6) {
      binary::get_vector(in, lists_.pair_memory);
      binary::get_vector(in, lists_.wall_memory);
    } else {
      std::vector<legacy::ContactMemoryV5> pair_memory, wall_memory;
      binary::get_vector(in, pair_memory);
      binary::get_vector(in, wall_memory);
      legacy::convert_memory(pair_memory, lists_.pair_memory);
      legacy::convert_memory(wall_memory, lists_.wall_memory);
    }
    if (lists_.with_memory &&
        (lists_.pair_memory.size() != lists_.pairs.size() || lists_.wall_memory.size() != lists_.walls.size()))
      throw binary::StateError("checkpoint: contact memory does not match the contact lists");
    binary::get(in, wall_bonding_);
    bonding_walls_ = ~std::uint64_t(0);
    if (version >= 7) binary::get(in, bonding_walls_);
    read_clumps(in, clumps_);
  } else {  // version 2: plain laws, no clumps
    lists_.with_memory = false;
    lists_.pair_memory.clear();
    lists_.wall_memory.clear();
    wall_bonding_ = false;
    bonding_walls_ = ~std::uint64_t(0);
    clumps_ = ClumpSet{};
  }
  binary::get(in, dt_);
  binary::get(in, threads_setting_);  // before version 5 the count the step used, >= 1: kept as given
  if (threads_setting_ < 0 || (version < 5 && threads_setting_ == 0))
    throw binary::StateError("checkpoint: invalid thread count");
  binary::get(in, gravity_);
  double local_damping = 0.0, overdamped = 0.0;
  binary::get(in, local_damping);
  integrator_.set_local_damping(local_damping);
  binary::get(in, track_energy_);
  binary::get(in, ready_);
  binary::get(in, rebuild_requested_);
  binary::get(in, overdamped);
  integrator_.set_overdamped(overdamped);
  binary::get(in, radius_growth_);
  binary::get(in, moved2_);
  binary::get(in, time_);
  binary::get(in, steps_);
  if (version >= 6) {
    binary::get(in, energy_.losses());
  } else if (version >= 3) {
    legacy::EnergyLedgerV5 old;
    binary::get(in, old);
    energy_.losses() = legacy::convert(old);
  } else {
    legacy::EnergyLedgerV2 old;
    binary::get(in, old);
    energy_.losses() = legacy::convert(old);
  }
  binary::get_vector(in, walls_.previous_forces());
  if (version >= 4) {
    binary::get(in, recording_);
    binary::get(in, record_requested_);
    binary::get(in, loads_current_);
    if (recording_ != ContactForceRecording::every_step && recording_ != ContactForceRecording::on_request)
      throw binary::StateError("checkpoint: unknown contact force recording");
  } else {  // every step kept its loads in the slots
    recording_ = ContactForceRecording::every_step;
    record_requested_ = false;
    loads_current_ = true;
  }
  energy_.clear_scratch();
  threads_ = num_threads();
}

std::size_t DemSystem::memory_bytes() const
{
  return store_.memory_bytes() + index_of_.memory_bytes() + lists_.memory_bytes() +
         search_.memory_bytes() + integrator_.memory_bytes() + energy_.memory_bytes() + walls_.memory_bytes() +
         contact_pass_.memory_bytes() + clumps_.memory_bytes();
}

}  // namespace geocomp::dem
