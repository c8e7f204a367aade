// The AVX2 leaf of detail::weighted_pairwise_sum (rules/weighted_sum.hpp): the eight
// accumulators of pairwise_sum's leaf as two registers of 4, a product and an add per lane, in
// the same order, so the same bits. No FMA: -mavx2 does not enable it, and a fused multiply-add
// would round once where the reference rounds twice (tests/rules/weighted_row_sum_test.cpp
// compares every level bitwise). Compiled with -mavx2 (lib/CMakeLists.txt), called only when the
// CPU has AVX2 (weighted_row_sum.cpp).
#if defined(__x86_64__)
#include "weighted_row_sum_kernels.hpp"

#include <immintrin.h>

namespace quadmc::detail {

double weighted_leaf_sum_avx2(const double* w, const double* y, std::size_t n) noexcept {
  __m256d low = _mm256_setzero_pd();   // acc[0..3]
  __m256d high = _mm256_setzero_pd();  // acc[4..7]
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    low = _mm256_add_pd(low, _mm256_mul_pd(_mm256_loadu_pd(w + i), _mm256_loadu_pd(y + i)));
    high =
        _mm256_add_pd(high, _mm256_mul_pd(_mm256_loadu_pd(w + i + 4), _mm256_loadu_pd(y + i + 4)));
  }
  double acc[8];
  _mm256_storeu_pd(acc, low);
  _mm256_storeu_pd(acc + 4, high);
  for (std::size_t k = 0; k < n % 8; ++k) acc[k] += w[i + k] * y[i + k];
  return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

}  // namespace quadmc::detail
#endif
