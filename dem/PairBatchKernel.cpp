// The batched pair kernel (PairBatchKernel.h). Compiled with -mavx2 and without FMA
// contraction when GEOCOMP_PAIR_BATCH_AVX2 is defined (dem/CMakeLists.txt); no Eigen here.
//
// Every line below mirrors a line of the scalar law; the comment names it. Lane masks
// replace the branches: both sides are computed and `select` keeps the one the scalar
// code would have taken (values in the discarded side may be inf or NaN; they are never
// stored).
#include "dem/PairBatchKernel.h"

#include <cstring>

#if defined(GEOCOMP_PAIR_BATCH_AVX2)
#include <immintrin.h>
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

/// 4x4 transpose: rows (one per lane) <-> packs (one per quantity).
inline void transpose4(__m256d& a, __m256d& b, __m256d& c, __m256d& d)
{
  const __m256d t0 = _mm256_unpacklo_pd(a, b), t1 = _mm256_unpackhi_pd(a, b);
  const __m256d t2 = _mm256_unpacklo_pd(c, d), t3 = _mm256_unpackhi_pd(c, d);
  a = _mm256_permute2f128_pd(t0, t2, 0x20);
  b = _mm256_permute2f128_pd(t1, t3, 0x20);
  c = _mm256_permute2f128_pd(t0, t2, 0x31);
  d = _mm256_permute2f128_pd(t1, t3, 0x31);
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

/// One batch of four slots between the stages of evaluate_linear_pairs_batched.
struct Batch
{
  unsigned char* slot[kLanes];
  std::uint32_t ii[kLanes], jj[kLanes];
  int lanes;
  // Stage 1: the kinematics (1a: the geometry; 1b: the velocities).
  Mask touching;
  P3 n, v_t;
  Pack delta, v_n, m_eff, r_eff, spin, arm_i, arm_j;
  // Stage 2: the normal law and the spring turned into the tangent plane.
  Pack f_n, elastic, c_t, inv_k_t, k_t;
  P3 xi;
};

/// Batches per stage sweep: each stage runs over kChunk independent batches, so the
/// processor overlaps their dependency chains (one batch's chain, roots and divisions in
/// series, is several hundred cycles long).
constexpr int kChunk = 8;

}  // namespace

PairBatchLosses evaluate_linear_pairs_batched(const PairBatchArgs& a, std::size_t begin, std::size_t end)
{
  PairBatchLosses losses;
  const PairSlotLayout& L = a.layout;
  const LinearLawConstants& law = a.law;
  const Pack dt = splat(a.dt), mu = splat(a.mu), zero = splat(0.0), one = splat(1.0);
  // Memo of S0's k_n(m*, R*) (a pure function): one call per change of (m*, R*).
  double memo_m = -1.0, memo_r = -1.0, memo_k = 0.0;
  Batch chunk[kChunk];

  for (std::size_t chunk0 = begin; chunk0 < end; chunk0 += kChunk * kLanes) {
    const std::size_t chunk_slots = end - chunk0 < std::size_t(kChunk * kLanes) ? end - chunk0 : kChunk * kLanes;
    const int n_batches = int((chunk_slots + kLanes - 1) / kLanes);

    // Stage 1a: DemSystem pass A's test and sphere_sphere_kinematics' geometry.
    for (int b = 0; b < n_batches; ++b) {
      Batch& B = chunk[b];
      const std::size_t c0 = chunk0 + std::size_t(b) * kLanes;
      B.lanes = int(end - c0 < std::size_t(kLanes) ? end - c0 : std::size_t(kLanes));
      for (int l = 0; l < kLanes; ++l) {
        B.slot[l] = a.slots + (c0 + std::size_t(l < B.lanes ? l : 0)) * L.size;  // spare lanes repeat lane 0
        std::memcpy(&B.ii[l], B.slot[l] + L.i, sizeof(std::uint32_t));
        std::memcpy(&B.jj[l], B.slot[l] + L.j, sizeof(std::uint32_t));
      }
      // DemSystem pass A: d = x_j - x_i, r2, R_i + R_j; apart when r2 >= range^2 or r2 == 0.
      const P3 d = gather3(a.x, B.jj) - gather3(a.x, B.ii);
      const Pack r2 = dot(d, d);
      const Pack Ri = gather1(a.radius, B.ii), Rj = gather1(a.radius, B.jj);
      const Pack rs = Ri + Rj;
      B.touching = (r2 < rs * rs) & (r2 != 0.0);

      // sphere_sphere_kinematics: the geometry (a root and two divisions in series)
      const Pack r = sqrt4(r2);
      const Pack inv_m = gather1(a.inv_mass, B.ii) + gather1(a.inv_mass, B.jj);
      const Pack w_eff = one / (inv_m * rs);
      B.n = d * (one / r);
      B.delta = rs - r;
      B.m_eff = w_eff * rs;
      B.r_eff = Ri * Rj * inv_m * w_eff;
      // The lever arms R - delta/2, which are also the torque arms of the loads
      // (LoadScatter::add_pair); R for an apart slot (it holds overlap 0; stage 1b's
      // velocities of an apart lane are never stored).
      B.arm_i = select(B.touching, Ri - 0.5 * B.delta, Ri);
      B.arm_j = select(B.touching, Rj - 0.5 * B.delta, Rj);
    }
    // Stage 1b: sphere_sphere_kinematics, the velocities.
    for (int b = 0; b < n_batches; ++b) {
      Batch& B = chunk[b];
      const Pack li = B.arm_i, lj = B.arm_j;
      const P3 wi = gather3(a.omega, B.ii), wj = gather3(a.omega, B.jj);
      const P3 v_rel = (gather3(a.v, B.jj) - gather3(a.v, B.ii)) - cross(li * wi + lj * wj, B.n);
      B.v_n = dot(v_rel, B.n);
      B.v_t = v_rel - B.v_n * B.n;
      B.spin = 0.5 * dot(wi + wj, B.n);
    }

    // Stage 2: LinearNormal::evaluate, LinearTangential's stiffness and damping, and
    // rotate_into_tangent_plane(xi, n, spin * dt) plus the increment v_t dt.
    for (int b = 0; b < n_batches; ++b) {
      Batch& B = chunk[b];
      Pack k_n;
      if (law.stiffness_direct) {
        k_n = splat(law.k_n);
      } else {
        for (int l = 0; l < kLanes; ++l) {
          if (!(B.m_eff[l] == memo_m && B.r_eff[l] == memo_r)) {
            memo_m = B.m_eff[l];
            memo_r = B.r_eff[l];
            memo_k = law.stiffness(law.normal_part, memo_m, memo_r);
          }
          k_n[l] = memo_k;
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
      if (L.contiguous_outputs) {  // the slot's spring: (x, y, z, the next double of the slot) per lane, transposed
        __m256d a0 = _mm256_loadu_pd(&slot_double(B.slot[0], L.shear)), a1 = _mm256_loadu_pd(&slot_double(B.slot[1], L.shear));
        __m256d a2 = _mm256_loadu_pd(&slot_double(B.slot[2], L.shear)), a3 = _mm256_loadu_pd(&slot_double(B.slot[3], L.shear));
        transpose4(a0, a1, a2, a3);
        xi = {Pack(a0), Pack(a1), Pack(a2)};
      } else {
        for (int l = 0; l < kLanes; ++l) {
          xi.x[l] = slot_double(B.slot[l], L.shear);
          xi.y[l] = slot_double(B.slot[l], L.shear + 8);
          xi.z[l] = slot_double(B.slot[l], L.shear + 16);
        }
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
      const Pack f_max = mu * max4(B.f_n, zero);                  // S0 eq. (2), cap mu_s |F_n|
      const Pack f2 = dot(f_trial, f_trial);
      const Mask slide = (f2 > f_max * f_max) & B.touching;      // developed friction
      P3 f_t = f_trial, xi_new = xi, xi_slide = xi;
      if (any(slide)) {  // the root and the division only for a batch with a sliding contact
        const P3 f_slide = f_trial * (f_max / sqrt4(f2));
        xi_slide = P3{-(f_slide.x + B.c_t * v_t.x), -(f_slide.y + B.c_t * v_t.y), -(f_slide.z + B.c_t * v_t.z)} *
                   B.inv_k_t;
        f_t = select(slide, f_slide, f_trial);
        xi_new = select(slide, xi_slide, xi);
      }

      // ContactLaw::evaluate and the slot update of pass A; apart slots hold zeros.
      const P3 force = B.f_n * B.n + f_t;
      const P3 lever = cross(B.n, f_t);
      const P3 zero3{zero, zero, zero};
      const P3 out_force = select(B.touching, force, zero3), out_lever = select(B.touching, lever, zero3);
      const P3 out_shear = select(B.touching, xi_new, zero3);
      const Pack out_overlap = select(B.touching, B.delta, zero);
      if (L.contiguous_outputs) {
        // overlap, shear, force, lever are ten consecutive doubles of a slot: two 4x4
        // transposes and one 4x2 give each lane's row, stored with 256- and 128-bit stores.
        __m256d q0 = __m256d(out_overlap), q1 = __m256d(out_shear.x), q2 = __m256d(out_shear.y), q3 = __m256d(out_shear.z);
        __m256d h0 = __m256d(out_force.x), h1 = __m256d(out_force.y), h2 = __m256d(out_force.z), h3 = __m256d(out_lever.x);
        transpose4(q0, q1, q2, q3);
        transpose4(h0, h1, h2, h3);
        const __m256d ly = __m256d(out_lever.y), lz = __m256d(out_lever.z);
        const __m256d lo = _mm256_unpacklo_pd(ly, lz), hi = _mm256_unpackhi_pd(ly, lz);  // (y0 z0 y2 z2), (y1 z1 y3 z3)
        const __m256d rows[kLanes] = {q0, q1, q2, q3}, rows2[kLanes] = {h0, h1, h2, h3};
        const __m128d tail[kLanes] = {_mm256_castpd256_pd128(lo), _mm256_castpd256_pd128(hi), _mm256_extractf128_pd(lo, 1),
                                      _mm256_extractf128_pd(hi, 1)};
        for (int l = 0; l < B.lanes; ++l) {
          double* row = &slot_double(B.slot[l], L.overlap);
          _mm256_storeu_pd(row, rows[l]);
          _mm256_storeu_pd(row + 4, rows2[l]);
          _mm_storeu_pd(row + 8, tail[l]);
        }
      } else {
        for (int l = 0; l < B.lanes; ++l) {
          unsigned char* s = B.slot[l];
          slot_double(s, L.overlap) = out_overlap[l];
          slot_double(s, L.shear) = out_shear.x[l];
          slot_double(s, L.shear + 8) = out_shear.y[l];
          slot_double(s, L.shear + 16) = out_shear.z[l];
          slot_double(s, L.force) = out_force.x[l];
          slot_double(s, L.force + 8) = out_force.y[l];
          slot_double(s, L.force + 16) = out_force.z[l];
          slot_double(s, L.lever) = out_lever.x[l];
          slot_double(s, L.lever + 8) = out_lever.y[l];
          slot_double(s, L.lever + 16) = out_lever.z[l];
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
          const std::uint32_t ri = a.row_of[B.ii[l]], rj = a.row_of[B.jj[l]];
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
          if (!B.touching[l]) continue;
          losses.damping += damping[l];
          if (slide[l]) losses.friction += friction[l];
        }
      }
    }
  }
  return losses;
}

#else  // no AVX2 kernel in this build: DemSystem keeps the scalar path

bool pair_batch_kernel_available() { return false; }

PairBatchLosses evaluate_linear_pairs_batched(const PairBatchArgs&, std::size_t, std::size_t)
{
  return PairBatchLosses{};
}

#endif

}  // namespace geocomp::dem
