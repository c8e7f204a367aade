// The AVX2 row kernel of tensor_rows (rules/tensor_product_rows.hpp): 4 doubles per register.
// Per row, the weights w_lead·w_k four at a time; per point, the leading coordinates stored from
// registers loaded once per row, and the last coordinate blended in. s = 1 is a copy of the
// table, s = 2 interleaves 4 points per step (unpack, then swap the 128-bit halves). Only
// copies, blends and the one multiply the portable loop also does, so the same bits. Compiled
// with -mavx2 (lib/CMakeLists.txt), called only when the CPU has AVX2 (tensor_product_rows.cpp).
#if defined(__x86_64__)
#include "tensor_product_rows_kernels.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

struct avx2_rows {
  template <std::size_t S>
  static void row(std::size_t s, const double* lead, double w_lead, const double* last_x,
                  const double* last_w, std::size_t run, double* x, double* weights) noexcept {
    const __m256d wl = _mm256_set1_pd(w_lead);
    std::size_t r = 0;
    for (; r + 4 <= run; r += 4) {
      _mm256_storeu_pd(weights + r, _mm256_mul_pd(wl, _mm256_loadu_pd(last_w + r)));
    }
    for (; r < run; ++r) weights[r] = w_lead * last_w[r];

    if constexpr (S == 1) {
      r = 0;
      for (; r + 4 <= run; r += 4) _mm256_storeu_pd(x + r, _mm256_loadu_pd(last_x + r));
      for (; r < run; ++r) x[r] = last_x[r];
    } else if constexpr (S == 2) {
      const __m256d c = _mm256_set1_pd(lead[0]);
      r = 0;
      for (; r + 4 <= run; r += 4) {
        const __m256d v = _mm256_loadu_pd(last_x + r);                          // r0 r1 r2 r3
        const __m256d lo = _mm256_unpacklo_pd(c, v);                            // c r0 c r2
        const __m256d hi = _mm256_unpackhi_pd(c, v);                            // c r1 c r3
        _mm256_storeu_pd(x + 2 * r, _mm256_permute2f128_pd(lo, hi, 0x20));      // c r0 c r1
        _mm256_storeu_pd(x + 2 * r + 4, _mm256_permute2f128_pd(lo, hi, 0x31));  // c r2 c r3
      }
      const __m128d c1 = _mm_set1_pd(lead[0]);
      for (; r < run; ++r) _mm_storeu_pd(x + 2 * r, _mm_loadh_pd(c1, last_x + r));
    } else if constexpr (S == 0) {
      const std::size_t last = s - 1;
      for (r = 0; r < run; ++r) {
        double* p = x + r * s;
        std::size_t j = 0;
        for (; j + 4 <= last; j += 4) _mm256_storeu_pd(p + j, _mm256_loadu_pd(lead + j));
        for (; j < last; ++j) p[j] = lead[j];
        p[last] = last_x[r];
      }
    } else {
      // Groups of 4 coordinates; the last group holds q = 1…4 of them, the last coordinate among
      // them. lead has room for whole registers (tensor_row_lead_padding).
      constexpr std::size_t groups = (S + 3) / 4;
      constexpr std::size_t b = 4 * (groups - 1);
      constexpr std::size_t q = S - b;
      __m256d lead_regs[groups];
      for (std::size_t g = 0; g < groups; ++g) lead_regs[g] = _mm256_loadu_pd(lead + 4 * g);
      const __m128d tail_pair = _mm256_castpd256_pd128(lead_regs[groups - 1]);
#pragma GCC unroll 4
      for (r = 0; r < run; ++r) {
        double* p = x + r * S;
        for (std::size_t g = 0; g + 1 < groups; ++g) _mm256_storeu_pd(p + 4 * g, lead_regs[g]);
        if constexpr (q == 4) {
          _mm256_storeu_pd(p + b, _mm256_blend_pd(lead_regs[groups - 1],
                                                  _mm256_broadcast_sd(last_x + r), 0b1000));
        } else if constexpr (q == 3) {
          _mm_storeu_pd(p + b, tail_pair);
          p[b + 2] = last_x[r];
        } else if constexpr (q == 2) {
          _mm_storeu_pd(p + b, _mm_loadh_pd(tail_pair, last_x + r));
        } else {
          p[b] = last_x[r];
        }
      }
    }
  }
};

}  // namespace

void tensor_rows_avx2(const tensor_row_tables& t, std::uint64_t first, std::size_t count, double* x,
                      double* weights) noexcept {
  tensor_walk_rows_by_dimension<avx2_rows>(t, first, count, x, weights);
}

}  // namespace quadmc::detail
#endif
