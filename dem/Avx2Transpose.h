// The 4x4 transpose of 256-bit double vectors (rows, one per lane <-> packs, one per
// quantity), shared by the AVX2 translation units (PairBatchKernel.cpp,
// ParticleSweepKernel.cpp). Include it only where -mavx2 is on (GEOCOMP_PAIR_BATCH_AVX2).
#pragma once

#include <immintrin.h>

namespace geocomp::dem::avx2 {

inline void transpose4(__m256d& a, __m256d& b, __m256d& c, __m256d& d)
{
  const __m256d t0 = _mm256_unpacklo_pd(a, b), t1 = _mm256_unpackhi_pd(a, b);
  const __m256d t2 = _mm256_unpacklo_pd(c, d), t3 = _mm256_unpackhi_pd(c, d);
  a = _mm256_permute2f128_pd(t0, t2, 0x20);
  b = _mm256_permute2f128_pd(t1, t3, 0x20);
  c = _mm256_permute2f128_pd(t0, t2, 0x31);
  d = _mm256_permute2f128_pd(t1, t3, 0x31);
}

}  // namespace geocomp::dem::avx2
