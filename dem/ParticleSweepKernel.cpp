// The batched kick-drift sweep (ParticleSweepKernel.h). Compiled with -mavx2 and without
// FMA contraction when GEOCOMP_PAIR_BATCH_AVX2 is defined (dem/CMakeLists.txt); no Eigen.
// Each line mirrors a line of DemSystem::kick_drift; the comments name them.
#include "dem/ParticleSweepKernel.h"

#if defined(GEOCOMP_PAIR_BATCH_AVX2)
#include <immintrin.h>

#include "dem/Avx2Transpose.h"
#endif

namespace geocomp::dem {

#if defined(GEOCOMP_PAIR_BATCH_AVX2)

namespace {

using Pack = __m256d;

/// Lane l of `a` four times per sphere's three doubles: the factors of four consecutive
/// spheres laid over their 12 doubles (x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3).
inline void spread(Pack a, Pack& f0, Pack& f1, Pack& f2)
{
  f0 = _mm256_permute4x64_pd(a, 0b01000000);  // a0 a0 a0 a1
  f1 = _mm256_permute4x64_pd(a, 0b10100101);  // a1 a1 a2 a2
  f2 = _mm256_permute4x64_pd(a, 0b11111110);  // a2 a3 a3 a3
}

/// The x, y and z of four spheres from their 12 doubles (the inverse layout of spread).
inline void components(Pack a, Pack b, Pack c, Pack& x, Pack& y, Pack& z)
{
  x = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(a, b, 0b0100), c, 0b0010), 0b01101100);  // a0 a3 b2 c1
  y = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(a, b, 0b1001), c, 0b0100), 0b10110001);  // a1 b0 b3 c2
  z = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(a, b, 0b0010), c, 0b1001), 0b11000110);  // a2 b1 c0 c3
}

using avx2::transpose4;  // Avx2Transpose.h

inline Pack add(Pack a, Pack b) { return _mm256_add_pd(a, b); }
inline Pack sub(Pack a, Pack b) { return _mm256_sub_pd(a, b); }
inline Pack mul(Pack a, Pack b) { return _mm256_mul_pd(a, b); }

/// v += (s * inv) * f for four spheres' 12 doubles at v, f given as three packs (kick_particle).
inline void kick(double* v, Pack f0, Pack f1, Pack f2, Pack s, const double* inv)
{
  Pack a0, a1, a2;
  spread(mul(s, _mm256_loadu_pd(inv)), a0, a1, a2);
  _mm256_storeu_pd(v, add(_mm256_loadu_pd(v), mul(a0, f0)));
  _mm256_storeu_pd(v + 4, add(_mm256_loadu_pd(v + 4), mul(a1, f1)));
  _mm256_storeu_pd(v + 8, add(_mm256_loadu_pd(v + 8), mul(a2, f2)));
}
inline void kick(double* v, const double* f, Pack s, const double* inv)
{
  kick(v, _mm256_loadu_pd(f), _mm256_loadu_pd(f + 4), _mm256_loadu_pd(f + 8), s, inv);
}

/// Four rows' (x, y, z, 0) as the 12 doubles of four spheres (x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3).
inline void packed(Pack r0, Pack r1, Pack r2, Pack r3, Pack& o0, Pack& o1, Pack& o2)
{
  o0 = _mm256_blend_pd(r0, _mm256_permute4x64_pd(r1, 0b00000000), 0b1000);                  // x0 y0 z0 x1
  o1 = _mm256_permute2f128_pd(_mm256_permute4x64_pd(r1, 0b00001001), r2, 0x20);            // y1 z1 x2 y2
  o2 = _mm256_blend_pd(_mm256_permute4x64_pd(r3, 0b10010000), _mm256_permute4x64_pd(r2, 0b00000010), 0b0001);  // z2 x3 y3 z3
}

}  // namespace

bool kick_drift_kernel_available()
{
  static const bool ok = __builtin_cpu_supports("avx2");
  return ok;
}

void close_and_kick4(const ClosingKickArgs& a, std::size_t p)
{
  const double* r = a.rows + 8 * p;
  const Pack half_dt = _mm256_set1_pd(0.5 * a.dt);
  Pack f0, f1, f2, t0, t1, t2;
  packed(_mm256_load_pd(r), _mm256_load_pd(r + 8), _mm256_load_pd(r + 16), _mm256_load_pd(r + 24), f0, f1, f2);
  packed(_mm256_load_pd(r + 4), _mm256_load_pd(r + 12), _mm256_load_pd(r + 20), _mm256_load_pd(r + 28), t0, t1, t2);
  double* const f = a.force + 3 * p;
  double* const t = a.torque + 3 * p;
  _mm256_storeu_pd(f, f0);
  _mm256_storeu_pd(f + 4, f1);
  _mm256_storeu_pd(f + 8, f2);
  _mm256_storeu_pd(t, t0);
  _mm256_storeu_pd(t + 4, t1);
  _mm256_storeu_pd(t + 8, t2);
  kick(a.v + 3 * p, f0, f1, f2, half_dt, a.inv_mass + p);
  kick(a.omega + 3 * p, t0, t1, t2, half_dt, a.inv_inertia + p);
}

double kick_drift_batched(const KickDriftArgs& a, std::size_t begin, std::size_t end)
{
  const Pack half_dt = _mm256_set1_pd(0.5 * a.dt), dt = _mm256_set1_pd(a.dt);
  const Pack one = _mm256_set1_pd(1.0), series_max = _mm256_set1_pd(1e-4);
  const Pack c2 = _mm256_set1_pd(0.5), c4 = _mm256_set1_pd(1.0 / 24.0);
  const Pack s2 = _mm256_set1_pd(1.0 / 6.0), s4 = _mm256_set1_pd(1.0 / 120.0);
  Pack max_d2 = _mm256_setzero_pd();
  std::size_t p = begin;
  for (; p + 4 <= end; p += 4) {
    const std::size_t k3 = 3 * p;
    // kick_particle: v += (dt/2 / m) F, omega += (dt/2 / I) T.
    kick(a.v + k3, a.force + k3, half_dt, a.inv_mass + p);
    kick(a.omega + k3, a.torque + k3, half_dt, a.inv_inertia + p);
    // x = x + dt v, and |x - x_ref|^2.
    Pack d[3];
    for (int r = 0; r < 3; ++r) {
      const Pack x = add(_mm256_loadu_pd(a.x + k3 + 4 * r), mul(dt, _mm256_loadu_pd(a.v + k3 + 4 * r)));
      _mm256_storeu_pd(a.x + k3 + 4 * r, x);
      d[r] = sub(x, _mm256_loadu_pd(a.x_ref + k3 + 4 * r));
    }
    Pack dx, dy, dz;
    components(d[0], d[1], d[2], dx, dy, dz);
    const Pack d2 = add(add(mul(dx, dx), mul(dy, dy)), mul(dz, dz));
    max_d2 = _mm256_blendv_pd(max_d2, d2, _mm256_cmp_pd(max_d2, d2, _CMP_LT_OQ));  // std::max(max, d2)

    // rotate_orientation: h = (dt/2) omega, t2 = |h|^2, the series of cos t and sin t / t.
    Pack wx, wy, wz;
    components(_mm256_loadu_pd(a.omega + k3), _mm256_loadu_pd(a.omega + k3 + 4), _mm256_loadu_pd(a.omega + k3 + 8), wx,
               wy, wz);
    const Pack hx = mul(half_dt, wx), hy = mul(half_dt, wy), hz = mul(half_dt, wz);
    const Pack t2 = add(add(mul(hx, hx), mul(hy, hy)), mul(hz, hz));
    if (_mm256_movemask_pd(_mm256_cmp_pd(t2, series_max, _CMP_LT_OQ)) != 0xf) {
      for (std::size_t q = p; q < p + 4; ++q) a.turn_scalar(a, q);  // a large angle: sin and cos
      continue;
    }
    const Pack c = sub(one, mul(t2, sub(c2, mul(t2, c4))));
    const Pack s = sub(one, mul(t2, sub(s2, mul(t2, s4))));
    const Pack ux = mul(s, hx), uy = mul(s, hy), uz = mul(s, hz);
    double* const q = a.orientation + 4 * p;
    Pack qx = _mm256_loadu_pd(q), qy = _mm256_loadu_pd(q + 4), qz = _mm256_loadu_pd(q + 8), qw = _mm256_loadu_pd(q + 12);
    transpose4(qx, qy, qz, qw);  // rows (x y z w) per sphere -> one pack per component
    // q = (c, u) (x) q, the Hamilton product as rotate_orientation writes it.
    Pack nw = sub(sub(sub(mul(c, qw), mul(ux, qx)), mul(uy, qy)), mul(uz, qz));
    Pack nx = sub(add(add(mul(c, qx), mul(ux, qw)), mul(uy, qz)), mul(uz, qy));
    Pack ny = add(add(sub(mul(c, qy), mul(ux, qz)), mul(uy, qw)), mul(uz, qx));
    Pack nz = add(sub(add(mul(c, qz), mul(ux, qy)), mul(uy, qx)), mul(uz, qw));
    transpose4(nx, ny, nz, nw);
    _mm256_storeu_pd(q, nx);
    _mm256_storeu_pd(q + 4, ny);
    _mm256_storeu_pd(q + 8, nz);
    _mm256_storeu_pd(q + 12, nw);
  }
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, max_d2);
  double m = 0.0;
  for (double l : lanes) m = m < l ? l : m;
  for (; p < end; ++p) {  // the last spheres of the range, one at a time
    const double d2 = a.kick_drift_scalar(a, p);
    m = m < d2 ? d2 : m;
  }
  return m;
}

#else  // no AVX2 in this build: DemSystem keeps the scalar sweep

bool kick_drift_kernel_available() { return false; }

void close_and_kick4(const ClosingKickArgs&, std::size_t) {}

double kick_drift_batched(const KickDriftArgs&, std::size_t, std::size_t) { return 0.0; }

#endif

}  // namespace geocomp::dem
