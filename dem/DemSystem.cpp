#include "dem/DemSystem.h"

#include "common/BinaryState.h"
#include "dem/ContactKinematics.h"
#include "dem/LegacyState.h"
#include "dem/LocalDamping.h"
#include "dem/ParticleSweepKernel.h"
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

namespace {
/// Fixed block size of every parallel reduction: block sums do not depend on the
/// number of threads, and are added in block order (DEM-NOTES section 5).
constexpr std::size_t kBlock = 256;

std::size_t n_blocks(std::size_t n) { return (n + kBlock - 1) / kBlock; }

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

/// The energy a block of slots dissipated, summed in slot order; `store` writes the
/// block's three entries (damping, friction, bonds) of the fixed-block reduction.
struct BlockLosses
{
  double damping = 0.0, friction = 0.0, bonds = 0.0;
  void add(const ContactForce& f)
  {
    damping += f.damping_loss;
    friction += f.friction_loss;
    bonds += f.bond_loss;
  }
  void store(double* block) const
  {
    block[0] = damping;
    block[1] = friction;
    block[2] = bonds;
  }
};

/// q <- exp(dt omega / 2) (x) q with the exact axis-angle quaternion; for the small
/// angles of DEM steps (theta < 1e-2) a 5th-order series equals sin/cos to round-off. The
/// Hamilton product is written out, in the order the batched sweep (ParticleSweepKernel.h)
/// repeats.
inline void rotate_orientation(Quat& q, const Vec3& omega, double dt)
{
  const Vec3 h = (0.5 * dt) * omega;
  const double t2 = h.squaredNorm();
  double c, s;
  if (t2 < 1e-4) {
    c = 1.0 - t2 * (0.5 - t2 * (1.0 / 24.0));
    s = 1.0 - t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0));
  } else {
    const double t = std::sqrt(t2);
    c = std::cos(t);
    s = std::sin(t) / t;
  }
  const double ux = s * h.x(), uy = s * h.y(), uz = s * h.z();
  const double qx = q.x(), qy = q.y(), qz = q.z(), qw = q.w();
  q.w() = c * qw - ux * qx - uy * qy - uz * qz;
  q.x() = c * qx + ux * qw + uy * qz - uz * qy;
  q.y() = c * qy - ux * qz + uy * qw + uz * qx;
  q.z() = c * qz + ux * qy - uy * qx + uz * qw;
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
}  // namespace

DemSystem::DemSystem() : model_(LinearSpringDashpot(LinearNormal::with_stiffness(1.0, 1.0), LinearTangential())) {}

// @sect4{Particles and walls}

ParticleId DemSystem::add_sphere(const Vec3& x, double radius, double density, const Vec3& v, const Vec3& omega)
{
  if (!(density > 0.0)) throw std::invalid_argument("DemSystem::add_sphere: density must be positive");
  if (!x.allFinite()) throw std::invalid_argument("DemSystem::add_sphere: non-finite position");
  const ParticleId id = ParticleId(index_of_.size());
  const double mass = 4.0 / 3.0 * M_PI * radius * radius * radius * density;
  const Index k = store_.add_sphere(id, x, radius, mass);
  store_.v[k] = v;
  store_.omega[k] = omega;
  index_of_.push_back(k);
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
    if (index_of_[id] != kNoIndex) growth = std::max(growth, change_radius(store_, index_of_[id], radii[id]));
  radius_growth_ += growth;  // a bound on each particle's increase since the build
  invalidate();
}

void DemSystem::set_overdamped(double beta)
{
  if (!(beta >= 0.0)) throw std::invalid_argument("DemSystem::set_overdamped: beta must be >= 0");
  overdamped_ = beta;
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
  PlaneWall c = w;
  const double len = c.normal.norm();
  if (!(len > 0.0)) throw std::invalid_argument("DemSystem::add_wall: zero normal");
  if (!(c.mu >= 0.0)) throw std::invalid_argument("DemSystem::add_wall: friction must be >= 0");
  c.normal /= len;
  if (c.bounded()) {  // a rectangle (S4's split box): its axis must lie in the plane
    c.axis -= c.axis.dot(c.normal) * c.normal;
    if (!(c.axis.norm() > 1e-12) || !(c.half_u > 0.0) || !(c.half_v > 0.0))
      throw std::invalid_argument("DemSystem::add_wall: a bounded wall needs an in-plane axis and positive half-sizes");
    c.axis.normalize();
  }
  walls_.push_back(c);
  rebuild_requested_ = true;
  invalidate();
  return walls_.size() - 1;
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

void DemSystem::set_num_threads(int n)
{
#ifdef _OPENMP
  if (n <= 0)
    n = omp_get_max_threads(); // 0: the OpenMP default (OMP_NUM_THREADS, else the cores)
#endif
  threads_ = std::max(1, n);
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
  for (Index k = 0; k < store_.size(); ++k) index_of_[store_.id[k]] = k;
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
  if (search_.rebuild(store_, walls_, lists_, threads_)) refresh_index();
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
  if (search_.skin() <= 0.0) {
    double r_max = 0.0;
    for (double r : store_.radius) r_max = std::max(r_max, r);
    search_.set_skin(r_max > 0.0 ? 0.2 * r_max : 1.0);  // 0.1 of the largest diameter
  }
  if (rebuild_requested_ ||
      (radius_growth_ > 0.0 && search_.needs_rebuild(with_growth(moved2_, radius_growth_), walls_)))
    rebuild();
  if (!ready_) {
    compute_forces(0.0, 0.0, true);  // forces at the current state, histories not advanced, all kept
    ready_ = true;
  }
}

template <class BlockBody>
std::pair<double, double> DemSystem::sweep_blocks(BlockBody body)
{
  const std::size_t n = store_.size();
  const std::size_t nb = n_blocks(n);
  block_losses_.assign(2 * nb, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads_)
  for (std::int64_t b = 0; b < std::int64_t(nb); ++b) {
    double sum = 0.0, max = 0.0;
    body(std::size_t(b) * kBlock, std::min(n, std::size_t(b + 1) * kBlock), sum, max);
    block_losses_[2 * b] = sum;
    block_losses_[2 * b + 1] = max;
  }
  double sum = 0.0, max = 0.0;
  for (std::size_t b = 0; b < nb; ++b) {
    sum += block_losses_[2 * b];
    max = std::max(max, block_losses_[2 * b + 1]);
  }
  return {sum, max};
}

template <class Body>
std::pair<double, double> DemSystem::sweep_particles(Body body)
{
  return sweep_blocks([&](std::size_t begin, std::size_t end, double& sum, double& max) GEOCOMP_SWEEP_BODY {
    for (std::size_t p = begin; p < end; ++p) body(p, sum, max);
  });
}

GEOCOMP_CONTACT_KERNEL double DemSystem::kick_particle(std::size_t p, double dt)  // inlined in the three hot loops
{
  const double lambda = local_damping_;
  Vec3 f = store_.force[p], t = store_.torque[p];
  double loss = 0.0;
  if (lambda > 0.0 && store_.inv_mass[p] != 0.0)
    loss = 0.5 * dt * (local_damping(f, store_.v[p], lambda) + local_damping(t, store_.omega[p], lambda));
  store_.v[p] += (0.5 * dt * store_.inv_mass[p]) * f;
  store_.omega[p] += (0.5 * dt * store_.inv_inertia[p]) * t;
  return loss;
}

double DemSystem::kick(double dt)
{
  return sweep_particles([&](std::size_t p, double& loss, double&) GEOCOMP_SWEEP_BODY { loss += kick_particle(p, dt); }).first;
}

double DemSystem::kick_drift(double dt)
{
  if (batched_sweeps() && store_.size() > 0) {
    // Four spheres at a time (ParticleSweepKernel.h, the same bits as the loop below).
    KickDriftArgs args;
    args.x = store_.x.front().data();
    args.v = store_.v.front().data();
    args.omega = store_.omega.front().data();
    args.orientation = store_.orientation.front().coeffs().data();
    args.force = store_.force.front().data();
    args.torque = store_.torque.front().data();
    args.inv_mass = store_.inv_mass.data();
    args.inv_inertia = store_.inv_inertia.data();
    args.x_ref = search_.reference_positions().front().data();
    args.dt = dt;
    args.owner = this;
    args.turn_scalar = [](const KickDriftArgs& a, std::size_t p) {
      DemSystem& self = *static_cast<DemSystem*>(a.owner);
      rotate_orientation(self.store_.orientation[p], self.store_.omega[p], a.dt);
    };
    args.kick_drift_scalar = [](const KickDriftArgs& a, std::size_t p) {
      DemSystem& self = *static_cast<DemSystem*>(a.owner);
      self.kick_particle(p, a.dt);  // no local damping on this path (batched_sweeps())
      return self.drift_particle(p, a.dt);
    };
    return sweep_blocks([&](std::size_t begin, std::size_t end, double&, double& max_d2) GEOCOMP_SWEEP_BODY {
             max_d2 = std::max(max_d2, kick_drift_batched(args, begin, end));
           }).second;
  }
  const auto [loss, max_d2] = sweep_particles([&](std::size_t p, double& loss, double& max_d2) GEOCOMP_SWEEP_BODY {
    loss += kick_particle(p, dt);
    max_d2 = std::max(max_d2, drift_particle(p, dt));
  });
  losses_.dissipated_local += loss;
  return max_d2;
}

GEOCOMP_CONTACT_KERNEL double DemSystem::drift_particle(std::size_t p, double dt)
{
  const std::vector<Vec3>& x_ref = search_.reference_positions();
  const Vec3 x = store_.x[p] + dt * store_.v[p];
  store_.x[p] = x;
  rotate_orientation(store_.orientation[p], store_.omega[p], dt);
  return (x - x_ref[p]).squaredNorm();
}

double DemSystem::drift_overdamped(double dt)
{
  // S0 "Aristotelian" packing dynamics: v = F / gamma with gamma = m / (beta dt).
  const double mobility = overdamped_ * dt;
  const auto [loss, max_d2] = sweep_particles([&](std::size_t p, double& loss, double& max_d2) GEOCOMP_SWEEP_BODY {
    if (store_.inv_mass[p] != 0.0) {  // kinematic particles keep their set velocity
      store_.v[p] = (mobility * store_.inv_mass[p]) * store_.force[p];
      store_.omega[p] = (mobility * store_.inv_inertia[p]) * store_.torque[p];
      loss += dt * (store_.force[p].dot(store_.v[p]) + store_.torque[p].dot(store_.omega[p]));
    }
    max_d2 = std::max(max_d2, drift_particle(p, dt));
  });
  losses_.dissipated_local += loss;
  return max_d2;
}

// @sect4{FIRE velocity control (preparation)}

double DemSystem::fire_velocities(double alpha)
{
  // One serial pass in storage order (fixed: the same bits for any thread count) for the
  // power and the four global norms, then the update.
  const std::size_t n = store_.size();
  double power = 0.0, v2 = 0.0, f2 = 0.0, w2 = 0.0, t2 = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (store_.inv_mass[k] == 0.0) continue;
    power += store_.force[k].dot(store_.v[k]) + store_.torque[k].dot(store_.omega[k]);
    v2 += store_.v[k].squaredNorm();
    f2 += store_.force[k].squaredNorm();
    w2 += store_.omega[k].squaredNorm();
    t2 += store_.torque[k].squaredNorm();
  }
  // P > 0: v <- (1 - alpha) v + alpha |v| F/|F|; otherwise every particle stops.
  const bool downhill = power > 0.0;
  const double keep = downhill ? 1.0 - alpha : 0.0;
  const double sv = downhill && f2 > 0.0 ? alpha * std::sqrt(v2 / f2) : 0.0;
  const double sw = downhill && t2 > 0.0 ? alpha * std::sqrt(w2 / t2) : 0.0;
#pragma omp parallel for schedule(static) num_threads(threads_)
  for (std::int64_t k = 0; k < std::int64_t(n); ++k) {
    if (store_.inv_mass[k] == 0.0) continue;
    if (!downhill) {
      store_.v[k].setZero();
      store_.omega[k].setZero();
      continue;
    }
    store_.v[k] = keep * store_.v[k] + sv * store_.force[k];
    store_.omega[k] = keep * store_.omega[k] + sw * store_.torque[k];
  }
  return power;
}

void DemSystem::step()
{
  if (!(dt_ > 0.0)) throw std::logic_error("DemSystem::step: time step not set");
  prepare();
  wall_force_old_.resize(walls_.size());
  for (std::size_t w = 0; w < walls_.size(); ++w) wall_force_old_[w] = walls_[w].force;

  if (overdamped_ > 0.0 && !clumps_.empty())
    throw std::logic_error("DemSystem::step: first-order dynamics is not available with clumps");
  double max_d2 = overdamped_ > 0.0 ? drift_overdamped(dt_) : kick_drift(dt_);
  if (!clumps_.empty()) max_d2 = std::max(max_d2, kick_drift_clumps(dt_));
  moved2_ = max_d2;
  for (PlaneWall& w : walls_) w.point += dt_ * w.velocity;
  if (rebuild_requested_ || search_.needs_rebuild(with_growth(max_d2, radius_growth_), walls_)) rebuild();
  // Every contact's load is kept for contacts() at every step, or at the requested ones.
  const bool record = recording_ == ContactForceRecording::every_step || record_requested_;
  record_requested_ = false;
  if (overdamped_ == 0.0 && clumps_.empty()) {
    losses_.dissipated_local += compute_forces(dt_, dt_, record);  // with the closing half kick
  } else {
    compute_forces(dt_, 0.0, record);
    if (overdamped_ == 0.0) losses_.dissipated_local += kick(dt_);
    if (!clumps_.empty()) kick_clumps(dt_);
  }

  for (std::size_t k = 0; k < walls_.size(); ++k) {
    PlaneWall& w = walls_[k];
    // The particles receive -F from the wall; trapezoidal rule over the step.
    const double dw = -0.5 * (wall_force_old_[k] + w.force).dot(w.velocity) * dt_;
    w.work += dw;
    losses_.wall_work += dw;
  }
  time_ += dt_;
  ++steps_;
}

void DemSystem::run(std::size_t n)
{
  for (std::size_t s = 0; s < n; ++s) step();
}

// @sect4{Contact forces: pass A per contact, pass B per particle}

double DemSystem::compute_forces(double dt_history, double kick_dt, bool record)
{
  const double kick_loss = std::visit(
    [&](const auto& law) {
      using Law = std::decay_t<decltype(law)>;
      if (track_energy_) return compute_forces_with<Law, true>(law, dt_history, kick_dt, record);
      return compute_forces_with<Law, false>(law, dt_history, kick_dt, record);
    },
    model_);
  loads_current_ = record;
  if (!clumps_.empty()) gather_clump_loads();
  return kick_loss;
}

template <class Law, bool Track>
double DemSystem::compute_forces_with(const Law& law, double dt_h, double kick_dt, bool record)
{
  const auto& x = store_.x;
  const auto& v = store_.v;
  const auto& w = store_.omega;
  const auto& R = store_.radius;
  const auto& im = store_.inv_mass;
  auto& pairs = lists_.pairs;
  auto& wslots = lists_.walls;
  auto& loads = lists_.pair_loads;
  auto& wloads = lists_.wall_loads;
  const std::size_t n = store_.size();
  const std::size_t nbp = n_blocks(pairs.size());
  const std::size_t nbw = n_blocks(wslots.size());
  const std::size_t nb_particles = n_blocks(n);
  if constexpr (Track) block_losses_.assign(3 * (nbp + nbw), 0.0);
  kick_losses_.assign(nb_particles, 0.0);
  wall_terms_.resize(wslots.size());
  const double mu = mu_;
  [[maybe_unused]] auto& pmem = lists_.pair_memory;
  [[maybe_unused]] auto& wmem = lists_.wall_memory;
  [[maybe_unused]] const bool wall_bonding = wall_bonding_;
  // S0's law on an AVX2 processor: four slots at a time (PairBatchKernel.h, same bits).
  [[maybe_unused]] bool batched = false;
  [[maybe_unused]] PairBatchArgs batch;
  [[maybe_unused]] PairBatchArgs wall_batch;
  if constexpr (std::is_same_v<Law, LinearSpringDashpot>) {
    batched = batched_pairs() && !pairs.empty() && n > 0;
    if (batched) {
      batch = pair_batch_args(law, store_, lists_, mu, dt_h, Track);
      batch.prefetch = prefetch_;
      batch.record_loads = record;
    }
    // Wall slots too when every wall is an unbounded plane.
    const bool planes = std::none_of(walls_.begin(), walls_.end(), [](const PlaneWall& w) { return w.bounded(); });
    if (batched_pairs() && planes && !wslots.empty()) {
      wall_batch = pair_batch_args(law, store_, lists_, 0.0, dt_h, Track);
      wall_batch.slots = reinterpret_cast<unsigned char*>(wslots.data());
      wall_batch.loads = reinterpret_cast<double*>(wloads.data());
      wall_batch.record_loads = true;  // the walls' records and pass B read every wall load
      wall_arrays_.resize(10 * walls_.size());
      double* const a = wall_arrays_.data();
      const std::size_t nw = walls_.size();
      for (std::size_t k = 0; k < nw; ++k)
        for (int d = 0; d < 3; ++d) {
          a[3 * k + d] = walls_[k].point[d];
          a[3 * (nw + k) + d] = walls_[k].normal[d];
          a[3 * (2 * nw + k) + d] = walls_[k].velocity[d];
        }
      for (std::size_t k = 0; k < nw; ++k) a[9 * nw + k] = walls_[k].mu;
      wall_batch.wall_point = a;
      wall_batch.wall_normal = a + 3 * nw;
      wall_batch.wall_velocity = a + 6 * nw;
      wall_batch.wall_mu = a + 9 * nw;
    }
  }
  // The batched kernels read the bodies packed by fours (PairBatchKernel.h), written with
  // the rows' weights below.
  PackedBody* packed_xr = nullptr;  // x, y, z, R
  PackedBody* packed_vm = nullptr;  // v_x, v_y, v_z, 1/m
  if (batched || wall_batch.wall_point) {
    packed_position_radius_.resize(n);
    packed_velocity_inv_mass_.resize(n);
    packed_xr = packed_position_radius_.data();
    packed_vm = packed_velocity_inv_mass_.data();
    for (PairBatchArgs* args : {&batch, &wall_batch}) {
      args->position_radius = packed_xr;
      args->velocity_inv_mass = packed_vm;
    }
  }
  // Loads are added into the bodies' rows as the slots are computed (LoadScatter.h).
  const int workers = threads_;
  scatter_.plan(lists_, n, kBlock, workers, search_.n_builds());
  LoadRow* const rows = scatter_.rows();
  const Vec3 g = gravity_;
  // The batched closing kick.
  ClosingKickArgs closing;
  if (kick_dt > 0.0 && n > 0 && batched_sweeps()) {
    closing.rows = reinterpret_cast<const double*>(rows);
    closing.force = store_.force.front().data();
    closing.torque = store_.torque.front().data();
    closing.v = store_.v.front().data();
    closing.omega = store_.omega.front().data();
    closing.inv_mass = store_.inv_mass.data();
    closing.inv_inertia = store_.inv_inertia.data();
    closing.dt = kick_dt;
  }

#pragma omp parallel num_threads(threads_)
  {
#pragma omp for schedule(static)
    for (std::int64_t p = 0; p < std::int64_t(n); ++p) {
      const Vec3 weight = store_.mass[p] * g;
      rows[p] = LoadRow{{weight.x(), weight.y(), weight.z(), 0.0}, {0.0, 0.0, 0.0, 0.0}};
      if (packed_xr) {
        packed_xr[p] = PackedBody{{x[p].x(), x[p].y(), x[p].z(), R[p]}};
        packed_vm[p] = PackedBody{{v[p].x(), v[p].y(), v[p].z(), im[p]}};
      }
    }
    // Pass A: particle pairs, worker w's contiguous blocks (LoadScatter::blocks_of).
#ifdef _OPENMP
    const int n_threads = omp_get_num_threads(), thread = omp_get_thread_num();
#else
    const int n_threads = 1, thread = 0;
#endif
    for (int wk = thread; wk < workers; wk += n_threads) {
      const auto [b_first, b_last] = LoadScatter::blocks_of(wk, workers, nbp);
      [[maybe_unused]] PairBatchArgs wbatch = batch;
      wbatch.rows = reinterpret_cast<double*>(rows);  // 8 doubles per row, 64-byte aligned
      wbatch.row_of = scatter_.targets();
      wbatch.shared = LoadScatter::kShared;
      wbatch.junk_row = scatter_.junk_row(wk);
      // The scalar path's loads of slot c (the kernel adds its own), kept beside the slot
      // when recording, when a body is shared (pass B1 gathers those) or when `keep` (the
      // zeros of a slot that came apart).
      const auto scatter_pair = [&](std::size_t c, const SlotLoad& load, bool keep) {
        const PairSlot& s = pairs[c];
        const std::uint32_t ri = scatter_.row_of(s.i, wk), rj = scatter_.row_of(s.j, wk);
        scatter_.add_pair(ri, rj, load, s.overlap, R[s.i], R[s.j]);
        if constexpr (Law::has_rolling) scatter_.add_rolling(ri, rj, pmem[c].rolling);
        if (keep || record || scatter_.shared(s.i) || scatter_.shared(s.j)) loads[c] = load;
      };
      for (std::int64_t b = std::int64_t(b_first); b < std::int64_t(b_last); ++b) {
        BlockLosses lost;
        const std::size_t end = std::min(pairs.size(), std::size_t(b + 1) * kBlock);
        if constexpr (std::is_same_v<Law, LinearSpringDashpot>) {
          if (batched) {
            const PairBatchLosses l = evaluate_linear_pairs_batched(wbatch, std::size_t(b) * kBlock, end);
            if constexpr (Track) BlockLosses{l.damping, l.friction, 0.0}.store(&block_losses_[3 * b]);
            continue;
          }
        }
        for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c) {
          PairSlot& s = pairs[c];
          const Index i = s.i, j = s.j;
          const Vec3 d = x[j] - x[i];
          const double r2 = d.squaredNorm();
          const double rs = R[i] + R[j];
          double range = rs;
          if constexpr (Law::has_cohesion) range += law.reach(R[i] * R[j] / rs);
          if (r2 >= range * range || r2 == 0.0) {
            // Apart: the slot and its load hold zeros (written only when it did not already).
            const bool came_apart = s.overlap != 0.0 || s.shear.squaredNorm() != 0.0;
            if (came_apart) {
              s.overlap = 0.0;
              s.shear.setZero();
            }
            if constexpr (Law::has_memory) separate(pmem[c]);
            scatter_pair(c, SlotLoad{}, came_apart);
            continue;
          }
          ContactKinematics k;
          sphere_sphere_kinematics(k, d, std::sqrt(r2), R[i], R[j], v[i], v[j], w[i], w[j], im[i], im[j]);
          k.overlap_old = s.overlap;
          k.dt = dt_h;
          k.mu = mu;
          ContactForce f;
          if constexpr (Law::has_memory) {
            if constexpr (Law::has_rolling) k.w_rel = w[j] - w[i];
            f = law.evaluate(k, s.shear, pmem[c]);
          } else {
            f = law.evaluate(k, s.shear);
          }
          scatter_pair(c, store_contact(s, k, f), false);
          if constexpr (Track) lost.add(f);
        }
        if constexpr (Track) lost.store(&block_losses_[3 * b]);
      }
    }
    // Pass A: particle-wall contacts, through the same law.
    // The slot's terms of the wall's record (summed below in slot order): the torque of
    // -F about the wall's point from the contact point on the plane, the servo's stiffness.
    // n_w: the contact normal PlaneWall::gap gave for the slot.
    const auto record_wall_term = [&](std::size_t c, const Vec3& n_w) {
      const WallSlot& s = wslots[c];
      const Vec3& force = wloads[c].force;
      WallTerm& term = wall_terms_[c];
      term.recorded = term.touching = false;
      if (!(s.overlap > 0.0) && force.squaredNorm() == 0.0) return;  // apart
      const PlaneWall& wall = walls_[s.wall];
      const Index p = s.particle;
      term.recorded = true;
      const Vec3 xc = x[p] - (R[p] - s.overlap) * n_w;
      term.torque = (xc - wall.point).cross(-force);
      if (!(s.overlap > 0.0)) return;  // a bond across a gap: force, but no contact
      term.touching = true;
      ContactKinematics kw;
      kw.overlap = s.overlap;
      kw.m_eff = store_.mass[p];
      kw.r_eff = R[p];
      term.stiffness = law.normal().evaluate(kw).stiffness;
    };
#pragma omp for schedule(static)
    for (std::int64_t b = 0; b < std::int64_t(nbw); ++b) {
      BlockLosses lost;
      const std::size_t end = std::min(wslots.size(), std::size_t(b + 1) * kBlock);
      if constexpr (std::is_same_v<Law, LinearSpringDashpot>) {
        if (wall_batch.wall_point) {  // four slots at a time (PairBatchKernel.h, same bits)
          const PairBatchLosses l = evaluate_linear_walls_batched(wall_batch, std::size_t(b) * kBlock, end);
          for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c)
            record_wall_term(c, walls_[wslots[c].wall].normal);  // unbounded planes: gap's normal
          if constexpr (Track) BlockLosses{l.damping, l.friction, 0.0}.store(&block_losses_[3 * (nbp + b)]);
          continue;
        }
      }
      for (std::size_t c = std::size_t(b) * kBlock; c < end; ++c) {
        WallSlot& s = wslots[c];
        const PlaneWall& wall = walls_[s.wall];
        const Index p = s.particle;
        Vec3 n_w;
        const double h = wall.gap(x[p], n_w);  // plane distance for unbounded walls
        double range = R[p];
        if constexpr (Law::has_cohesion) range += wall_bonding ? law.reach(R[p]) : 0.0;
        if (h >= range) {
          s.overlap = 0.0;
          s.shear.setZero();
          wloads[c] = SlotLoad{};
          if constexpr (Law::has_memory) separate(wmem[c]);
          record_wall_term(c, n_w);
          continue;
        }
        ContactKinematics k;
        sphere_wall_kinematics(k, n_w, h, R[p], v[p], w[p], wall.velocity, im[p]);
        k.overlap_old = s.overlap;
        k.dt = dt_h;
        k.mu = wall.mu;
        ContactForce f;
        if constexpr (Law::has_memory) {
          if constexpr (Law::has_rolling) k.w_rel = w[p];  // the wall does not spin
          k.bonding = wall_bonding;
          f = law.evaluate(k, s.shear, wmem[c]);
        } else {
          f = law.evaluate(k, s.shear);
        }
        wloads[c] = store_contact(s, k, f);
        if constexpr (Track) lost.add(f);
        record_wall_term(c, n_w);
      }
      if constexpr (Track) lost.store(&block_losses_[3 * (nbp + b)]);
    }
    // Pass B1: the gather of each shared body's incident slots in ascending order, from
    // its weight, into its row (the shared bodies, one layer of storage, split evenly).
    const auto& off = lists_.incident_offset;
    const auto& inc = lists_.incident;
    const auto& woff = lists_.wall_offset;
    const std::vector<Index>& shared = scatter_.shared_bodies();
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < std::int64_t(shared.size()); ++k) {
      const Index p = shared[std::size_t(k)];
      const double Rp = R[p];
      Vec3 f = store_.mass[p] * g, t = Vec3::Zero();
      for (std::uint32_t e = off[p]; e < off[p + 1]; ++e) {
        const PairSlot& s = pairs[inc[e] >> 1];
        const SlotLoad& load = loads[inc[e] >> 1];
        // +F on j, -F on i, without a branch on the role; f + (-1 x F) and f - F are the
        // same IEEE operation (measured: no change in speed against the branch).
        const double sign = (inc[e] & 1u) ? 1.0 : -1.0;
        f += sign * load.force;
        t -= (Rp - 0.5 * s.overlap) * load.lever;  // T = -(R - delta/2) n x F_t
        if constexpr (Law::has_rolling) {          // M_r on j, -M_r on i
          if (inc[e] & 1u) t += pmem[inc[e] >> 1].rolling;
          else t -= pmem[inc[e] >> 1].rolling;
        }
      }
      rows[p] = LoadRow{{f.x(), f.y(), f.z(), 0.0}, {t.x(), t.y(), t.z(), 0.0}};
    }
    // Pass B2: every body's row, its wall slots, then the closing half kick when asked for
    // (four bodies at a time in vectors: ParticleSweepKernel.h). The wall slots' loads go
    // into the body's row first, in slot order.
    const auto add_wall_loads = [&](std::size_t p) {
      if (woff[p] == woff[p + 1]) return;
      const double Rp = R[p];
      Vec3 f(rows[p].f[0], rows[p].f[1], rows[p].f[2]);
      Vec3 t(rows[p].t[0], rows[p].t[1], rows[p].t[2]);
      for (std::uint32_t e = woff[p]; e < woff[p + 1]; ++e) {
        f += wloads[e].force;
        t -= (Rp - 0.5 * wslots[e].overlap) * wloads[e].lever;
        if constexpr (Law::has_rolling) t += wmem[e].rolling;
      }
      rows[p] = LoadRow{{f.x(), f.y(), f.z(), 0.0}, {t.x(), t.y(), t.z(), 0.0}};
    };
#pragma omp for schedule(static)
    for (std::int64_t b = 0; b < std::int64_t(nb_particles); ++b) {
      double kick_loss = 0.0;
      const std::size_t p_end = std::min(n, std::size_t(b + 1) * kBlock);
      for (std::size_t p = std::size_t(b) * kBlock; p < p_end; ++p) {
        if (closing.rows && p + 4 <= p_end) {
          for (std::size_t q = p; q < p + 4; ++q) add_wall_loads(q);
          close_and_kick4(closing, p);
          p += 3;
          continue;
        }
        add_wall_loads(p);
        store_.force[p] = Vec3(rows[p].f[0], rows[p].f[1], rows[p].f[2]);
        store_.torque[p] = Vec3(rows[p].t[0], rows[p].t[1], rows[p].t[2]);
        if (kick_dt > 0.0) kick_loss += kick_particle(p, kick_dt);
      }
      kick_losses_[b] = kick_loss;
    }
  }
  double kick_loss = 0.0;
  for (std::size_t b = 0; b < nb_particles; ++b) kick_loss += kick_losses_[b];

  if constexpr (Track) {
    for (std::size_t b = 0; b < nbp + nbw; ++b) {
      losses_.dissipated_damping += block_losses_[3 * b];
      losses_.dissipated_friction += block_losses_[3 * b + 1];
      losses_.dissipated_bonds += block_losses_[3 * b + 2];
    }
  }

  // Wall records, in slot order (serial: only the sums; pass A computed the terms).
  for (PlaneWall& wall : walls_) {
    wall.force.setZero();
    wall.torque.setZero();
    wall.stiffness = 0.0;
    wall.n_contacts = 0;
  }
  for (std::size_t c = 0; c < wslots.size(); ++c) {
    const WallTerm& term = wall_terms_[c];
    if (!term.recorded) continue;
    const WallSlot& s = wslots[c];
    PlaneWall& wall = walls_[s.wall];
    wall.force -= wloads[c].force;
    wall.torque += term.torque;
    if constexpr (Law::has_rolling) wall.torque -= wmem[c].rolling;  // the wall receives -M_r
    if (!term.touching) continue;
    wall.stiffness += term.stiffness;
    ++wall.n_contacts;
  }
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
  EnergyLedger e = losses_;
  for (std::size_t c = 0; c < clumps_.size(); ++c) {
    e.kinetic_translational += 0.5 * clumps_.mass[c] * clumps_.v[c].squaredNorm();
    e.kinetic_rotational += clumps_.kinetic_energy(c) - 0.5 * clumps_.mass[c] * clumps_.v[c].squaredNorm();
    e.gravitational -= clumps_.mass[c] * gravity_.dot(clumps_.x[c]);
  }
  for (Index p = 0; p < store_.size(); ++p) {
    if (store_.inv_mass[p] == 0.0 || (store_.flags[p] & flag::member)) continue;
    e.kinetic_translational += 0.5 * store_.mass[p] * store_.v[p].squaredNorm();
    e.kinetic_rotational += 0.5 / store_.inv_inertia[p] * store_.omega[p].squaredNorm();
    e.gravitational -= store_.mass[p] * gravity_.dot(store_.x[p]);
  }
  std::visit(
    [&](const auto& law) {
      using L = std::decay_t<decltype(law)>;
      const auto add = [&e](const ContactEnergy& c) {
        e.elastic_normal += c.normal;
        e.elastic_tangential += c.tangential;
        e.elastic_rolling += c.rolling;
        e.elastic_bonds += c.bond;
      };
      for (std::size_t c = 0; c < lists_.pairs.size(); ++c) {
        const PairSlot& s = lists_.pairs[c];
        const double m_eff = 1.0 / (store_.inv_mass[s.i] + store_.inv_mass[s.j]);
        const double Ri = store_.radius[s.i], Rj = store_.radius[s.j];
        if constexpr (L::has_memory) {
          ContactKinematics k;
          k.overlap = s.overlap;
          k.m_eff = m_eff;
          k.r_eff = Ri * Rj / (Ri + Rj);
          k.mu = mu_;
          add(law.elastic_energy(k, s.shear, lists_.pair_memory[c]));
        } else if (s.overlap > 0.0) {
          add(law.elastic_energy(s.overlap, m_eff, Ri * Rj / (Ri + Rj), s.shear));
        }
      }
      for (std::size_t c = 0; c < lists_.walls.size(); ++c) {
        const WallSlot& s = lists_.walls[c];
        if constexpr (L::has_memory) {
          ContactKinematics k;
          k.overlap = s.overlap;
          k.m_eff = store_.mass[s.particle];
          k.r_eff = store_.radius[s.particle];
          k.mu = walls_[s.wall].mu;
          add(law.elastic_energy(k, s.shear, lists_.wall_memory[c]));
        } else if (s.overlap > 0.0) {
          add(law.elastic_energy(s.overlap, store_.mass[s.particle], store_.radius[s.particle], s.shear));
        }
      }
    },
    model_);
  return e;
}

// @sect4{Checkpoint state}
//
// Everything the next step reads is written, in storage order, as raw bytes (see
// BinaryState.h): then a system read back computes the same bits as the original. The
// law is a variant of trivially copyable parameter structs and is stored as its bytes.
// Version 3 added the contact memory (rolling springs, bonds) and the clumps; version 4
// moved the slots' loads beside them (ContactLists.h) and added the recording of contact
// forces. Version 2 and 3 states (restart files, exact specimens in core stores) are still
// read, through their old layouts (LegacyState.h), and continue as they would have.

namespace {
constexpr std::uint32_t kStateVersion = 4;

/// Reads the DEMSYSTM tag; returns its version (2 to 4).
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
  binary::put_vector(out, index_of_);
  binary::put_vector(out, walls_);
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
  write_clumps(out, clumps_);
  binary::put(out, dt_);
  binary::put(out, threads_);
  binary::put(out, gravity_);
  binary::put(out, local_damping_);
  binary::put(out, track_energy_);
  binary::put(out, ready_);
  binary::put(out, rebuild_requested_);
  binary::put(out, overdamped_);
  binary::put(out, radius_growth_);
  binary::put(out, moved2_);
  binary::put(out, time_);
  binary::put(out, steps_);
  binary::put(out, losses_);
  binary::put_vector(out, wall_force_old_);
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
  binary::get_vector(in, index_of_);
  {  // walls: this layout, or the one before bounded walls (legacy::PlaneWallV3, unbounded)
    std::uint64_t n = 0, size = 0;
    binary::get(in, n);
    binary::get(in, size);
    if (n > (std::uint64_t(1) << 30)) throw binary::StateError("checkpoint: implausible array length");
    if (size == sizeof(PlaneWall)) {
      walls_.resize(n);
      if (n) in.read(reinterpret_cast<char*>(walls_.data()), std::streamsize(n * sizeof(PlaneWall)));
    } else if (size == sizeof(legacy::PlaneWallV3)) {
      std::vector<legacy::PlaneWallV3> old(n);
      if (n) in.read(reinterpret_cast<char*>(old.data()), std::streamsize(n * size));
      walls_.clear();
      for (const auto& o : old) walls_.push_back(legacy::convert(o));
    } else {
      throw binary::StateError("checkpoint: record size differs (written by another build)");
    }
    if (!in) throw binary::StateError("checkpoint: unexpected end of data");
  }
  binary::get(in, mu_);
  search_.read_state(in);
  get_slots(in, version, lists_.pairs, lists_.pair_loads);
  scatter_.invalidate();
  binary::get_vector(in, lists_.incident_offset);
  binary::get_vector(in, lists_.incident);
  get_slots(in, version, lists_.walls, lists_.wall_loads);
  binary::get_vector(in, lists_.wall_offset);
  if (version >= 3) {
    binary::get(in, lists_.with_memory);
    binary::get_vector(in, lists_.pair_memory);
    binary::get_vector(in, lists_.wall_memory);
    if (lists_.with_memory &&
        (lists_.pair_memory.size() != lists_.pairs.size() || lists_.wall_memory.size() != lists_.walls.size()))
      throw binary::StateError("checkpoint: contact memory does not match the contact lists");
    binary::get(in, wall_bonding_);
    read_clumps(in, clumps_);
  } else {  // version 2: plain laws, no clumps
    lists_.with_memory = false;
    lists_.pair_memory.clear();
    lists_.wall_memory.clear();
    wall_bonding_ = false;
    clumps_ = ClumpSet{};
  }
  binary::get(in, dt_);
  binary::get(in, threads_);
  binary::get(in, gravity_);
  binary::get(in, local_damping_);
  binary::get(in, track_energy_);
  binary::get(in, ready_);
  binary::get(in, rebuild_requested_);
  binary::get(in, overdamped_);
  binary::get(in, radius_growth_);
  binary::get(in, moved2_);
  binary::get(in, time_);
  binary::get(in, steps_);
  if (version >= 3) {
    binary::get(in, losses_);
  } else {
    legacy::EnergyLedgerV2 old;
    binary::get(in, old);
    losses_ = legacy::convert(old);
  }
  binary::get_vector(in, wall_force_old_);
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
  block_losses_.clear();
}

std::size_t DemSystem::memory_bytes() const
{
  return store_.memory_bytes() + index_of_.capacity() * sizeof(Index) + lists_.memory_bytes() +
         search_.memory_bytes() + block_losses_.capacity() * sizeof(double) +
         (walls_.capacity() * sizeof(PlaneWall)) + wall_force_old_.capacity() * sizeof(Vec3) +
         wall_terms_.capacity() * sizeof(WallTerm) + scatter_.memory_bytes() +
         (packed_position_radius_.capacity() + packed_velocity_inv_mass_.capacity()) * sizeof(PackedBody) +
         clumps_.memory_bytes();
}

}  // namespace geocomp::dem
