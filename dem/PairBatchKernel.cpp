// The batched pair kernel (PairBatchKernel.h). Compiled with -mavx2 and without FMA
// contraction when GEOCOMP_PAIR_BATCH_AVX2 is defined (dem/CMakeLists.txt); no Eigen here.
//
// Every line below mirrors a line of the scalar law; the comment names it. Lane masks
// replace the branches: both sides are computed and `select` keeps the one the scalar
// code would have taken (values in the discarded side may be inf or NaN; they are never
// stored).
#include "dem/PairBatchKernel.h"

#include <algorithm>
#include <cstring>

#if defined(GEOCOMP_PAIR_BATCH_AVX2)
#include <immintrin.h>

#include "dem/Avx2Transpose.h"
#endif

namespace geocomp::dem {

#if defined(GEOCOMP_PAIR_BATCH_AVX2)

namespace {

using Pack = double __attribute__((vector_size(32)));
using Mask = long long __attribute__((vector_size(32)));
constexpr int kLanes = 4;

inline Pack splat(double a) { return Pack{a, a, a, a}; }
inline Pack select(Mask m, Pack a, Pack b) { return m ? a : b; }
inline Pack sqrt4(Pack a) { return Pack(_mm256_sqrt_pd(__m256d(a))); }
/// std::max(a, b) lane by lane: (a < b) ? b : a.
inline Pack max4(Pack a, Pack b) { return select(a < b, b, a); }
inline Pack abs4(Pack a) { return select(a < 0.0, -a, a); }
inline bool all(Mask m) { return _mm256_movemask_pd(__m256d(m)) == 0xf; }
inline bool any(Mask m) { return _mm256_movemask_pd(__m256d(m)) != 0; }

struct P3
{
  Pack x, y, z;
};
inline P3 operator+(const P3& a, const P3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline P3 operator-(const P3& a, const P3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline P3 operator*(Pack s, const P3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline P3 operator*(const P3& a, Pack s) { return {a.x * s, a.y * s, a.z * s}; }
inline P3 select(Mask m, const P3& a, const P3& b) { return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)}; }
// Eigen's order for 3-vectors: (x*x + y*y) + z*z, and the cross product component by component.
inline Pack dot(const P3& a, const P3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline P3 cross(const P3& a, const P3& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// Four Vec3 entries (3 contiguous doubles each) as three packs: one masked 256-bit load
/// per entry (the fourth double is never read) and a 4x4 transpose.
inline P3 gather3(const double* a, const std::uint32_t idx[kLanes])
{
  const __m256i xyz = _mm256_set_epi64x(0, -1, -1, -1);
  const __m256d r0 = _mm256_maskload_pd(a + 3 * std::size_t(idx[0]), xyz);
  const __m256d r1 = _mm256_maskload_pd(a + 3 * std::size_t(idx[1]), xyz);
  const __m256d r2 = _mm256_maskload_pd(a + 3 * std::size_t(idx[2]), xyz);
  const __m256d r3 = _mm256_maskload_pd(a + 3 * std::size_t(idx[3]), xyz);
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);  // x0 x1 z0 z1 | y0 y1 . .
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
  return {Pack(_mm256_permute2f128_pd(t0, t2, 0x20)), Pack(_mm256_permute2f128_pd(t1, t3, 0x20)),
          Pack(_mm256_permute2f128_pd(t0, t2, 0x31))};
}
inline Pack gather1(const double* a, const std::uint32_t idx[kLanes])
{
  return Pack{a[idx[0]], a[idx[1]], a[idx[2]], a[idx[3]]};
}

using avx2::transpose4;  // Avx2Transpose.h

/// Four packed bodies (PackedBody: 4 doubles, 32-byte aligned) as four packs: one aligned
/// 256-bit load per body and a 4x4 transpose; the fourth quantity comes with the vector.
inline void gather4(const PackedBody* a, const std::uint32_t idx[kLanes], P3& xyz, Pack& w)
{
  __m256d r0 = _mm256_load_pd(a[idx[0]].q), r1 = _mm256_load_pd(a[idx[1]].q);
  __m256d r2 = _mm256_load_pd(a[idx[2]].q), r3 = _mm256_load_pd(a[idx[3]].q);
  transpose4(r0, r1, r2, r3);
  xyz = P3{Pack(r0), Pack(r1), Pack(r2)};
  w = Pack(r3);
}

inline double& slot_double(unsigned char* slot, std::size_t offset)
{
  return *reinterpret_cast<double*>(slot + offset);
}

}  // namespace

bool pair_batch_kernel_available()
{
  static const bool ok = __builtin_cpu_supports("avx2");
  return ok;
}

namespace {

/// One batch of four touching slots between the stages of evaluate_linear_pairs_batched.
struct Batch
{
  unsigned char* slot[kLanes];
  std::size_t index[kLanes];  ///< the slots' indices (their loads' places)
  std::uint32_t ii[kLanes], jj[kLanes];
  int lanes;
  // Stage 1: the kinematics (1a: the geometry; 1b: the velocities and the effective mass
  // and radius, with the inverse masses packed with the velocities), the Coulomb coefficient.
  P3 n, v_t;
  Pack radius_i, radius_j, delta, v_n, m_eff, r_eff, spin, arm_i, arm_j, mu;
  // Stage 2: the normal law and the spring turned into the tangent plane.
  Pack f_n, elastic, c_t, inv_k_t, k_t;
  P3 xi;
};

/// Batches per stage sweep: each stage runs over kChunk independent batches, so the
/// processor overlaps their dependency chains (one batch's chain, roots and divisions in
/// series, is several hundred cycles long).
constexpr int kChunk = 8;
/// Touching slots per group: the stages run over one group of kChunk full batches.
constexpr int kGroup = kChunk * kLanes;

/// The touching slots found by the contact test, in ascending slot order, waiting for the
/// stages: a ring of kRing entries (the test appends at most one group while less than
/// one group waits, and writes up to kLanes - 1 spare entries past its end, so kRing =
/// 4 groups never overwrites a waiting entry). Groups start at multiples of kGroup, so a
/// batch never wraps. Each entry keeps what the test computed (d, r^2, the radii), so
/// the stages read it with plain vector loads instead of gathers.
struct TouchingRing
{
  static constexpr int kRing = 4 * kGroup;
  alignas(32) double dx[kRing + kLanes], dy[kRing + kLanes], dz[kRing + kLanes], r2[kRing + kLanes];
  alignas(32) double ri[kRing + kLanes], rj[kRing + kLanes];
  alignas(32) std::uint64_t ij[kRing + kLanes];   ///< i | j << 32
  alignas(32) std::uint64_t slot[kRing + kLanes]; ///< slot index
  std::size_t head = 0, tail = 0;                 ///< entries appended, entries taken

  /// Permutations that move the lanes of a 4-bit mask to the front (as 8 x 32-bit indices).
  static const __m256i* left_pack()
  {
    alignas(32) static std::int32_t table[16][8];
    static const bool made = [] {
      for (int m = 0; m < 16; ++m) {
        int k = 0;
        for (int l = 0; l < kLanes; ++l)
          if (m & (1 << l)) {
            table[m][2 * k] = 2 * l;
            table[m][2 * k + 1] = 2 * l + 1;
            ++k;
          }
        for (; k < kLanes; ++k) table[m][2 * k] = table[m][2 * k + 1] = 0;
      }
      return true;
    }();
    (void)made;
    return reinterpret_cast<const __m256i*>(table);
  }

  static void put(double* dst, __m256i perm, Pack v)
  {
    _mm256_storeu_pd(dst, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(__m256d(v)), perm)));
  }
  static void put(std::uint64_t* dst, __m256i perm, __m256i v)
  {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst), _mm256_permutevar8x32_epi32(v, perm));
  }

  /// Appends the lanes of `mask` (in lane order).
  void append(int mask, const P3& d, Pack r2_, Pack ri_, Pack rj_, __m256i ij_, __m256i slot_)
  {
    const __m256i perm = left_pack()[mask];
    const std::size_t at = head % kRing;
    put(dx + at, perm, d.x);
    put(dy + at, perm, d.y);
    put(dz + at, perm, d.z);
    put(r2 + at, perm, r2_);
    put(ri + at, perm, ri_);
    put(rj + at, perm, rj_);
    put(ij + at, perm, ij_);
    put(slot + at, perm, slot_);
    const int count = __builtin_popcount(unsigned(mask));
    for (std::size_t k = kRing; k < at + std::size_t(count); ++k) {  // wrapped past the end
      dx[k - kRing] = dx[k];
      dy[k - kRing] = dy[k];
      dz[k - kRing] = dz[k];
      r2[k - kRing] = r2[k];
      ri[k - kRing] = ri[k];
      rj[k - kRing] = rj[k];
      ij[k - kRing] = ij[k];
      slot[k - kRing] = slot[k];
    }
    head += std::size_t(count);
  }

  /// Fills entries [at + count, at + count rounded up to kLanes) with copies of the first
  /// entry of their batch (spare lanes of the last batch: computed, never stored).
  void pad(std::size_t at, int count)
  {
    for (int k = count; k % kLanes != 0; ++k) {
      const std::size_t to = at + std::size_t(k), from = at + std::size_t(k - k % kLanes);
      dx[to] = dx[from];
      dy[to] = dy[from];
      dz[to] = dz[from];
      r2[to] = r2[from];
      ri[to] = ri[from];
      rj[to] = rj[from];
      ij[to] = ij[from];
      slot[to] = slot[from];
    }
  }
};

void clear_slot(const PairBatchArgs& a, std::size_t c);

/// True when slot c holds history (an overlap or a spring other than zero): an apart slot
/// is cleared only then (as the scalar path), so the settled apart slots cost one vector
/// compare and no write.
[[gnu::always_inline]] inline bool holds_history(const PairBatchArgs& a, std::size_t c)
{
  const PairSlotLayout& L = a.layout;
  unsigned char* s = a.slots + c * L.size;
  const __m256d h = _mm256_loadu_pd(&slot_double(s, L.history));  // overlap, spring
  return _mm256_movemask_pd(_mm256_cmp_pd(h, _mm256_setzero_pd(), _CMP_NEQ_UQ)) != 0;
}

/// A batch of slots under the contact test: the slots' bodies and what the test computed.
struct TestedBatch
{
  std::size_t c0 = 0;  ///< the first slot
  int lanes = 0;       ///< slots c0 .. c0 + lanes - 1 (spare lanes repeat lane 0)
  std::uint32_t i[kLanes], j[kLanes];
  P3 d;
  Pack r2, ri, rj;
  Mask touching;
};

/// The bodies i and j of slots [c0, c0 + lanes).
[[gnu::always_inline]] inline void read_indices(const PairBatchArgs& a, std::size_t c0, int lanes, TestedBatch& t)
{
  const PairSlotLayout& L = a.layout;
  t.c0 = c0;
  t.lanes = lanes;
  for (int l = 0; l < kLanes; ++l) {
    const unsigned char* s = a.slots + (c0 + std::size_t(l < lanes ? l : 0)) * L.size;  // spare lanes repeat lane 0
    std::memcpy(&t.i[l], s + L.i, sizeof(std::uint32_t));
    std::memcpy(&t.j[l], s + L.j, sizeof(std::uint32_t));
  }
}

/// Appends the touching slots of a tested batch to the ring and clears the apart ones.
[[gnu::always_inline]] inline void keep_touching(const PairBatchArgs& a, const TestedBatch& t, TouchingRing& ring)
{
  const int valid = (1 << t.lanes) - 1;
  const int mask = _mm256_movemask_pd(__m256d(t.touching)) & valid;
  if (mask != 0) {
    std::int64_t ij[kLanes];
    for (int l = 0; l < kLanes; ++l) ij[l] = std::int64_t(std::uint64_t(t.i[l]) | std::uint64_t(t.j[l]) << 32);
    const __m256i slots = _mm256_add_epi64(_mm256_set1_epi64x(std::int64_t(t.c0)), _mm256_set_epi64x(3, 2, 1, 0));
    ring.append(mask, t.d, t.r2, t.ri, t.rj, _mm256_set_epi64x(ij[3], ij[2], ij[1], ij[0]), slots);
  }
  for (int apart = valid & ~mask; apart != 0; apart &= apart - 1) {
    const std::size_t c = t.c0 + std::size_t(__builtin_ctz(unsigned(apart)));
    if (holds_history(a, c)) clear_slot(a, c);
  }
}

/// The contact test of DemSystem pass A on slots [c0, c0 + lanes): appends the touching
/// ones to the ring and gives the others (apart) zeros, written only when the slot did not
/// already hold them (as the scalar path).
void test_batch(const PairBatchArgs& a, std::size_t c0, int lanes, TouchingRing& ring)
{
  TestedBatch t;
  read_indices(a, c0, lanes, t);
  // d = x_j - x_i, r2, R_i + R_j; apart when r2 >= range^2 or r2 == 0.
  P3 xi, xj;
  gather4(a.position_radius, t.i, xi, t.ri);
  gather4(a.position_radius, t.j, xj, t.rj);
  t.d = xj - xi;
  t.r2 = dot(t.d, t.d);
  const Pack rs = t.ri + t.rj;
  t.touching = (t.r2 < rs * rs) & (t.r2 != 0.0);
  keep_touching(a, t, ring);
}

/// The law's constants, the memo of k_n and the losses shared by the groups of one call.
struct KernelState
{
  const PairBatchArgs& a;
  Pack dt, mu, zero, one;
  // Memo of S0's k_n(m*, R*) (a pure function): one call per change of (m*, R*).
  double memo_m = -1.0, memo_r = -1.0, memo_k = 0.0;
  PairBatchLosses losses;
};

void law_stages(KernelState& st, Batch* chunk, int n_batches);

/// Batch b of the `count` ring entries from `at`: its slots and bodies and its lane count;
/// returns the ring index of its first entry.
std::size_t take_batch(const PairBatchArgs& a, const TouchingRing& ring, std::size_t at, int count, int b, Batch& B)
{
  const std::size_t e = at + std::size_t(b) * kLanes;
  B.lanes = count - b * kLanes < kLanes ? count - b * kLanes : kLanes;
  for (int l = 0; l < kLanes; ++l) {
    B.index[l] = std::size_t(ring.slot[e + l]);
    B.slot[l] = a.slots + B.index[l] * a.layout.size;
    B.ii[l] = std::uint32_t(ring.ij[e + l]);
    B.jj[l] = std::uint32_t(ring.ij[e + l] >> 32);
  }
  return e;
}

/// Stages 1a (after the test) to 3 on `count` <= kGroup touching slots of the ring from
/// entry `at` (a multiple of kGroup).
void run_group(KernelState& st, TouchingRing& ring, std::size_t at, int count)
{
  const PairBatchArgs& a = st.a;
  const Pack mu = st.mu, one = st.one;
  Batch chunk[kChunk];
  ring.pad(at, count);
  const int n_batches = (count + kLanes - 1) / kLanes;

  // Stage 1a: sphere_sphere_kinematics' geometry (a root and two divisions in series).
  for (int b = 0; b < n_batches; ++b) {
    Batch& B = chunk[b];
    const std::size_t e = take_batch(a, ring, at, count, b, B);
    const P3 d{Pack(_mm256_load_pd(ring.dx + e)), Pack(_mm256_load_pd(ring.dy + e)), Pack(_mm256_load_pd(ring.dz + e))};
    const Pack r2 = Pack(_mm256_load_pd(ring.r2 + e));
    const Pack Ri = Pack(_mm256_load_pd(ring.ri + e)), Rj = Pack(_mm256_load_pd(ring.rj + e));
    const Pack rs = Ri + Rj;
    const Pack r = sqrt4(r2);
    B.radius_i = Ri;
    B.radius_j = Rj;
    B.n = d * (one / r);
    B.delta = rs - r;
    // The lever arms R - delta/2, which are also the torque arms of the loads
    // (LoadScatter::add_pair).
    B.arm_i = Ri - 0.5 * B.delta;
    B.arm_j = Rj - 0.5 * B.delta;
    B.mu = mu;
  }
  // Stage 1b: sphere_sphere_kinematics, the velocities, then m* and R* (the inverse masses
  // come packed with the velocities).
  for (int b = 0; b < n_batches; ++b) {
    Batch& B = chunk[b];
    const Pack li = B.arm_i, lj = B.arm_j;
    const P3 wi = gather3(a.omega, B.ii), wj = gather3(a.omega, B.jj);
    P3 vi, vj;
    Pack inv_mi, inv_mj;
    gather4(a.velocity_inv_mass, B.ii, vi, inv_mi);
    gather4(a.velocity_inv_mass, B.jj, vj, inv_mj);
    // m* = 1/(1/m_i + 1/m_j) and R* = R_i R_j/(R_i + R_j) through one division, in
    // sphere_sphere_kinematics' order.
    const Pack inv_m = inv_mi + inv_mj;
    const Pack rs = B.radius_i + B.radius_j;
    const Pack w_eff = one / (inv_m * rs);
    B.m_eff = w_eff * rs;
    B.r_eff = B.radius_i * B.radius_j * inv_m * w_eff;
    const P3 v_rel = (vj - vi) - cross(li * wi + lj * wj, B.n);
    B.v_n = dot(v_rel, B.n);
    B.v_t = v_rel - B.v_n * B.n;
    B.spin = 0.5 * dot(wi + wj, B.n);
  }

  law_stages(st, chunk, n_batches);
}

/// Stages 2 and 3 (ContactLaw::evaluate of LinearSpringDashpot and the slot's outputs) on
/// batches whose kinematics stage 1 filled; the loads into rows for particle pairs.
void law_stages(KernelState& st, Batch* chunk, int n_batches)
{
  const PairBatchArgs& a = st.a;
  const PairSlotLayout& L = a.layout;
  const LinearLawConstants& law = a.law;
  const Pack dt = st.dt, zero = st.zero, one = st.one;
  // Stage 2: LinearNormal::evaluate, LinearTangential's stiffness and damping, and
  // rotate_into_tangent_plane(xi, n, spin * dt) plus the increment v_t dt.
  for (int b = 0; b < n_batches; ++b) {
    Batch& B = chunk[b];
    Pack k_n;
    if (law.stiffness_direct) {
      k_n = splat(law.k_n);
    } else {
      for (int l = 0; l < kLanes; ++l) {
        if (!(B.m_eff[l] == st.memo_m && B.r_eff[l] == st.memo_r)) {
          st.memo_m = B.m_eff[l];
          st.memo_r = B.r_eff[l];
          st.memo_k = law.stiffness(law.normal_part, st.memo_m, st.memo_r);
        }
        k_n[l] = st.memo_k;
      }
    }
    Pack c_n;
    switch (law.damping) {
      case LinearLawConstants::Damping::direct: c_n = splat(law.c_n); break;
      case LinearLawConstants::Damping::per_unit_mass: c_n = law.gamma_n * B.m_eff; break;
      case LinearLawConstants::Damping::restitution: default: c_n = 2.0 * law.zeta * sqrt4(B.m_eff * k_n); break;
    }
    B.elastic = k_n * B.delta;
    const Pack f_lin = B.elastic - c_n * B.v_n;                  // S0 eq. (1)
    B.f_n = law.clamp_tensile ? max4(f_lin, zero) : f_lin;

    // LinearTangential::evaluate
    B.k_t = law.k_t_is_ratio ? law.k_t * k_n : splat(law.k_t);
    B.c_t = law.c_t_is_ratio ? law.c_t * c_n : splat(law.c_t);
    // one / k_t, the same bits when k_t is one value for all lanes (then computed once).
    B.inv_k_t = law.k_t_is_ratio && !law.stiffness_direct ? one / B.k_t
                : law.k_t_is_ratio                        ? splat(1.0 / (law.k_t * law.k_n))
                                                          : splat(1.0 / law.k_t);
    P3 xi;
    {  // the slot's (overlap, spring) per lane, transposed
      __m256d a0 = _mm256_loadu_pd(&slot_double(B.slot[0], L.history)), a1 = _mm256_loadu_pd(&slot_double(B.slot[1], L.history));
      __m256d a2 = _mm256_loadu_pd(&slot_double(B.slot[2], L.history)), a3 = _mm256_loadu_pd(&slot_double(B.slot[3], L.history));
      transpose4(a0, a1, a2, a3);
      xi = {Pack(a1), Pack(a2), Pack(a3)};
    }
    {  // rotate_into_tangent_plane(xi, n, spin * dt)
      const P3& n = B.n;
      const Pack s2 = dot(xi, xi);
      P3 p = xi + (B.spin * dt) * cross(n, xi);
      p = p - dot(n, p) * n;
      const Pack p2 = dot(p, p);
      const Pack e = s2 / p2 - 1.0;
      const Pack series = 1.0 + e * (0.5 - e * (0.125 - e * 0.0625));
      const Mask small = abs4(e) < 1e-4;
      // The root only when a lane needs it (the frame turns little per step: rarely).
      const Pack f = all(small) ? series : select(small, series, sqrt4(1.0 + e));
      const P3 turned = select(p2 > 1e-24 * s2, p * f, P3{zero, zero, zero});
      xi = select(s2 == 0.0, xi, turned);
    }
    B.xi = xi + B.v_t * dt;
  }

  // Stage 3: the Coulomb cap, the slot's outputs and the loads.
  for (int b = 0; b < n_batches; ++b) {
    Batch& B = chunk[b];
    const P3& xi = B.xi;
    const P3& v_t = B.v_t;
    const P3 f_trial = (-B.k_t) * xi - B.c_t * v_t;             // S0 eq. (2), developing friction
    const Pack f_max = B.mu * max4(B.f_n, zero);                // S0 eq. (2), cap mu_s |F_n|
    const Pack f2 = dot(f_trial, f_trial);
    const Mask slide = f2 > f_max * f_max;                      // developed friction
    P3 f_t = f_trial, xi_new = xi, xi_slide = xi;
    if (any(slide)) {  // the root and the division only for a batch with a sliding contact
      const P3 f_slide = f_trial * (f_max / sqrt4(f2));
      xi_slide = P3{-(f_slide.x + B.c_t * v_t.x), -(f_slide.y + B.c_t * v_t.y), -(f_slide.z + B.c_t * v_t.z)} *
                 B.inv_k_t;
      f_t = select(slide, f_slide, f_trial);
      xi_new = select(slide, xi_slide, xi);
    }

    // ContactLaw::evaluate and the slot update of pass A.
    const P3 out_force = B.f_n * B.n + f_t;
    const P3 out_lever = cross(B.n, f_t);
    const P3& out_shear = xi_new;
    const Pack out_overlap = B.delta;
    // The slot's history: overlap and spring, one 4x4 transpose and a 256-bit store per lane.
    {
      __m256d q0 = __m256d(out_overlap), q1 = __m256d(out_shear.x), q2 = __m256d(out_shear.y), q3 = __m256d(out_shear.z);
      transpose4(q0, q1, q2, q3);
      const __m256d rows[kLanes] = {q0, q1, q2, q3};
      for (int l = 0; l < B.lanes; ++l) _mm256_storeu_pd(&slot_double(B.slot[l], L.history), rows[l]);
    }

    // The bodies' rows, and which lanes store their loads (all when recording; else the
    // lanes with a shared body, whose loads pass B gathers).
    std::uint32_t row_i[kLanes] = {}, row_j[kLanes] = {};
    int keep = a.record_loads ? (1 << B.lanes) - 1 : 0;
    if (a.rows)
      for (int l = 0; l < B.lanes; ++l) {
        row_i[l] = a.row_of[B.ii[l]];
        row_j[l] = a.row_of[B.jj[l]];
        if (row_i[l] == a.shared || row_j[l] == a.shared) keep |= 1 << l;
      }
    if (keep != 0) {
      // force and lever are six consecutive doubles of a load: a 4x4 transpose and a 4x2
      // give each lane's, stored with a 256- and a 128-bit store.
      __m256d h0 = __m256d(out_force.x), h1 = __m256d(out_force.y), h2 = __m256d(out_force.z), h3 = __m256d(out_lever.x);
      transpose4(h0, h1, h2, h3);
      const __m256d ly = __m256d(out_lever.y), lz = __m256d(out_lever.z);
      const __m256d lo = _mm256_unpacklo_pd(ly, lz), hi = _mm256_unpackhi_pd(ly, lz);  // (y0 z0 y2 z2), (y1 z1 y3 z3)
      const __m256d head[kLanes] = {h0, h1, h2, h3};
      const __m128d tail[kLanes] = {_mm256_castpd256_pd128(lo), _mm256_castpd256_pd128(hi), _mm256_extractf128_pd(lo, 1),
                                    _mm256_extractf128_pd(hi, 1)};
      for (int l = 0; l < B.lanes; ++l) {
        if (!(keep & (1 << l))) continue;
        double* load = a.loads + 6 * B.index[l];
        _mm256_storeu_pd(load, head[l]);
        _mm_storeu_pd(load + 4, tail[l]);
      }
    }

    if (a.rows) {
      // LoadScatter::add_pair: F_i -= F, F_j += F, T_k -= arm_k (n x F_t), lane by lane in
      // slot order.
      const P3 ti = B.arm_i * out_lever, tj = B.arm_j * out_lever;
      const __m256d z = _mm256_setzero_pd();
      __m256d f0 = __m256d(out_force.x), f1 = __m256d(out_force.y), f2v = __m256d(out_force.z), f3 = z;
      __m256d i0 = __m256d(ti.x), i1 = __m256d(ti.y), i2 = __m256d(ti.z), i3 = z;
      __m256d j0 = __m256d(tj.x), j1 = __m256d(tj.y), j2 = __m256d(tj.z), j3 = z;
      transpose4(f0, f1, f2v, f3);
      transpose4(i0, i1, i2, i3);
      transpose4(j0, j1, j2, j3);
      const __m256d F[kLanes] = {f0, f1, f2v, f3}, TI[kLanes] = {i0, i1, i2, i3}, TJ[kLanes] = {j0, j1, j2, j3};
      for (int l = 0; l < B.lanes; ++l) {
        const std::uint32_t ri = row_i[l], rj = row_j[l];
        double* const bi = a.rows + 8 * std::size_t(ri == a.shared ? a.junk_row + l : ri);
        double* const bj = a.rows + 8 * std::size_t(rj == a.shared ? a.junk_row + kLanes + l : rj);
        _mm256_store_pd(bi, _mm256_sub_pd(_mm256_load_pd(bi), F[l]));
        _mm256_store_pd(bi + 4, _mm256_sub_pd(_mm256_load_pd(bi + 4), TI[l]));
        _mm256_store_pd(bj, _mm256_add_pd(_mm256_load_pd(bj), F[l]));
        _mm256_store_pd(bj + 4, _mm256_sub_pd(_mm256_load_pd(bj + 4), TJ[l]));
      }
    }

    if (a.track_losses) {
      // -(F_n - F_n^el) v_n dt + c_t |v_t|^2 dt, and f_max |xi_trial - xi| when sliding;
      // summed slot by slot in slot order, as the scalar path does.
      const Pack damping = (-(B.f_n - B.elastic)) * B.v_n * dt + B.c_t * dot(v_t, v_t) * dt;
      const P3 slip = xi - xi_slide;
      const Pack friction = f_max * sqrt4(dot(slip, slip));
      for (int l = 0; l < B.lanes; ++l) {
        st.losses.damping += damping[l];
        if (slide[l]) st.losses.friction += friction[l];
      }
    }
  }
}

/// Gives an apart slot that still holds history zeros, and its load.
void clear_slot(const PairBatchArgs& a, std::size_t c)
{
  const PairSlotLayout& L = a.layout;
  unsigned char* s = a.slots + c * L.size;
  _mm256_storeu_pd(&slot_double(s, L.history), _mm256_setzero_pd());
  std::fill_n(a.loads + 6 * c, 6, 0.0);
}

/// The wall contact test of DemSystem pass A on wall slots [c0, c0 + lanes): PlaneWall::gap
/// of an unbounded wall, h = (x - p_w) . n_w, apart when h >= R. The ring's entries hold h
/// (as r2) and R (as ri); i is the wall, j the particle.
void test_wall_batch(const PairBatchArgs& a, std::size_t c0, int lanes, TouchingRing& ring)
{
  TestedBatch t;
  read_indices(a, c0, lanes, t);
  P3 x;
  gather4(a.position_radius, t.j, x, t.ri);        // x and R of the particle
  t.rj = t.ri;
  t.d = x - gather3(a.wall_point, t.i);
  t.r2 = dot(t.d, gather3(a.wall_normal, t.i));  // h
  t.touching = ~(t.r2 >= t.ri);
  keep_touching(a, t, ring);
}

/// Stage 1 of wall slots (sphere_wall_kinematics), then stages 2 and 3, on `count` <=
/// kGroup touching wall slots of the ring from entry `at`.
void run_wall_group(KernelState& st, TouchingRing& ring, std::size_t at, int count)
{
  const PairBatchArgs& a = st.a;
  const Pack one = st.one;
  Batch chunk[kChunk];
  ring.pad(at, count);
  const int n_batches = (count + kLanes - 1) / kLanes;
  for (int b = 0; b < n_batches; ++b) {
    Batch& B = chunk[b];
    const std::size_t e = take_batch(a, ring, at, count, b, B);  // ii: the wall, jj: the particle
    const Pack h = Pack(_mm256_load_pd(ring.r2 + e)), R = Pack(_mm256_load_pd(ring.ri + e));
    // sphere_wall_kinematics
    B.n = gather3(a.wall_normal, B.ii);
    B.delta = R - h;
    const Pack l = R - 0.5 * B.delta;
    const P3 w = gather3(a.omega, B.jj);
    P3 v;
    Pack inv_m;
    gather4(a.velocity_inv_mass, B.jj, v, inv_m);
    const P3 v_rel = (v - gather3(a.wall_velocity, B.ii)) - l * cross(w, B.n);
    B.v_n = dot(v_rel, B.n);
    B.v_t = v_rel - B.v_n * B.n;
    B.m_eff = one / inv_m;
    B.r_eff = R;
    B.spin = 0.5 * dot(w, B.n);
    B.arm_i = l;
    B.arm_j = l;
    B.mu = gather1(a.wall_mu, B.ii);
  }
  law_stages(st, chunk, n_batches);
}

/// A prefetch of the line at p into all cache levels. (_mm_prefetch and __builtin_prefetch
/// left no prefetch instruction in this unit's object code with GCC 12; volatile asm does.)
inline void prefetch_line(const void* p)
{
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
}

/// Slots ahead of the test whose lines are prefetched, and slots ahead whose j bodies are
/// (their slot lines asked for 12 slots before). Measured at 100 000 spheres: 16 to 32
/// slots ahead time the same, 64 to 128 are 6-20 % slower; one burst of a whole group's lines
/// two groups ahead (the earlier scheme) 15 % slower.
constexpr std::size_t kPrefetchSlots = 24, kPrefetchBodies = 12;

/// Software prefetch ahead of the test of the batch at slot c (the slots and the bodies come
/// from DRAM once the specimen outgrows the last-level cache, 50 000 spheres and more here):
/// the lines of the slots kPrefetchSlots ahead, and the position, velocities and load row of
/// the j bodies kPrefetchBodies ahead. Spread over the batches, so the requests never queue
/// up in one burst. The i bodies ascend with the slots; the hardware's stream prefetch
/// follows them.
inline void prefetch_ahead(const PairBatchArgs& a, std::size_t c, std::size_t end)
{
  const std::size_t size = a.layout.size;
  if (c + kPrefetchSlots + kLanes <= end) {
    const auto first = reinterpret_cast<std::uintptr_t>(a.slots + (c + kPrefetchSlots) * size) & ~std::uintptr_t(63);
    const auto last = reinterpret_cast<std::uintptr_t>(a.slots + (c + kPrefetchSlots + kLanes) * size - 1);
    for (std::uintptr_t p = first; p <= last; p += 64) prefetch_line(reinterpret_cast<const void*>(p));
  }
  if (c + kPrefetchBodies + kLanes <= end)
    for (std::size_t l = 0; l < std::size_t(kLanes); ++l) {
      std::uint32_t j;
      std::memcpy(&j, a.slots + (c + kPrefetchBodies + l) * size + a.layout.j, sizeof j);
      const std::size_t k = 3 * std::size_t(j);
      prefetch_line(a.position_radius + j);
      prefetch_line(a.velocity_inv_mass + j);
      prefetch_line(a.omega + k);
      if (a.rows) prefetch_line(a.rows + 8 * std::size_t(j));
    }
}

/// The test on groups of slots and the stages on each full group of touching slots.
template <class Test, class Group>
PairBatchLosses run_slots(const PairBatchArgs& a, std::size_t begin, std::size_t end, Test test, Group group)
{
  KernelState st{a, splat(a.dt), splat(a.mu), splat(0.0), splat(1.0), -1.0, -1.0, 0.0, {}};
  TouchingRing ring;
  for (std::size_t c0 = begin; c0 < end; c0 += kGroup) {
    // The contact test of a group of slots; the stages then run on each full group of
    // touching slots (apart slots, a quarter of a dense packing's list, skip them).
    const std::size_t group_end = end - c0 < std::size_t(kGroup) ? end : c0 + kGroup;
    for (std::size_t c = c0; c < group_end; c += kLanes) {
      if (a.prefetch) prefetch_ahead(a, c, end);
      test(a, c, group_end - c < std::size_t(kLanes) ? int(group_end - c) : kLanes, ring);
    }
    while (ring.head - ring.tail >= std::size_t(kGroup)) {
      group(st, ring, ring.tail % TouchingRing::kRing, kGroup);
      ring.tail += kGroup;
    }
  }
  if (ring.head > ring.tail) group(st, ring, ring.tail % TouchingRing::kRing, int(ring.head - ring.tail));
  return st.losses;
}

}  // namespace

PairBatchLosses evaluate_linear_pairs_batched(const PairBatchArgs& a, std::size_t begin, std::size_t end)
{
  // (lambdas, so that the test and the stages are inlined into the loop)
  return run_slots(
      a, begin, end, [](const PairBatchArgs& x, std::size_t c0, int lanes, TouchingRing& r) { test_batch(x, c0, lanes, r); },
      [](KernelState& st, TouchingRing& r, std::size_t at, int count) { run_group(st, r, at, count); });
}

PairBatchLosses evaluate_linear_walls_batched(const PairBatchArgs& a, std::size_t begin, std::size_t end)
{
  return run_slots(
      a, begin, end,
      [](const PairBatchArgs& x, std::size_t c0, int lanes, TouchingRing& r) { test_wall_batch(x, c0, lanes, r); },
      [](KernelState& st, TouchingRing& r, std::size_t at, int count) { run_wall_group(st, r, at, count); });
}

#else  // no AVX2 kernel in this build: DemSystem keeps the scalar path

bool pair_batch_kernel_available() { return false; }

PairBatchLosses evaluate_linear_pairs_batched(const PairBatchArgs&, std::size_t, std::size_t)
{
  return PairBatchLosses{};
}

PairBatchLosses evaluate_linear_walls_batched(const PairBatchArgs&, std::size_t, std::size_t)
{
  return PairBatchLosses{};
}

#endif

}  // namespace geocomp::dem
