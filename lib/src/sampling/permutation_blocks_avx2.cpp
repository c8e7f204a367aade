// The AVX2 permutation kernel: 4 indices per register. AVX2 has no 64-bit multiply, so the
// product mod 2^64 is built from 32-bit ones: a·b = a_lo·b_lo + ((a_hi·b_lo + a_lo·b_hi) << 32)
// (the a_hi·b_hi term falls beyond bit 63). Values stay below 2^62 (n ≤ 2^62), so the signed
// 64-bit compare tests x ≥ n. Compiled with -mavx2 (lib/CMakeLists.txt), called only when the CPU
// has AVX2 (permutation_blocks.cpp).
#if defined(__x86_64__)
#include "permutation_kernels.hpp"

#include <immintrin.h>

#include <numeric>

namespace quadmc::detail {
namespace {

__m256i multiply_low64(__m256i a, __m256i b) noexcept {
  const __m256i low = _mm256_mul_epu32(a, b);
  const __m256i cross = _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(a, 32), b),
                                         _mm256_mul_epu32(a, _mm256_srli_epi64(b, 32)));
  return _mm256_add_epi64(low, _mm256_slli_epi64(cross, 32));
}

struct avx2_schedule {
  __m256i keys[2 * permutation_schedule::rounds];
  __m256i mask;
  __m128i shift;

  explicit avx2_schedule(const permutation_schedule& p)
      : mask(_mm256_set1_epi64x(static_cast<long long>(p.mask))),
        shift(_mm_cvtsi32_si128(p.shift)) {
    for (int k = 0; k < 2 * permutation_schedule::rounds; ++k) {
      keys[k] = _mm256_set1_epi64x(static_cast<long long>(p.keys[k]));
    }
  }

  __m256i bijection(__m256i x) const noexcept {
    for (int r = 0; r < permutation_schedule::rounds; ++r) {
      x = _mm256_xor_si256(x, keys[2 * r]);
      x = _mm256_and_si256(multiply_low64(x, keys[2 * r + 1]), mask);
      x = _mm256_xor_si256(x, _mm256_srl_epi64(x, shift));
    }
    return x;
  }
};

}  // namespace

void permutation_blocks_avx2(const permutation_schedule& p, std::uint64_t first, std::size_t count,
                             std::uint64_t* out) noexcept {
  const avx2_schedule v(p);
  const __m256i n_minus_1 = _mm256_set1_epi64x(static_cast<long long>(p.n - 1));
  const __m256i step = _mm256_set1_epi64x(4);
  __m256i index = _mm256_add_epi64(_mm256_set1_epi64x(static_cast<long long>(first)),
                                   _mm256_set_epi64x(3, 2, 1, 0));
  std::size_t k = 0;
  for (; k + 4 <= count; k += 4) {
    __m256i x = v.bijection(index);
    // Lanes with x > n − 1 walk on; each further round updates only them.
    for (__m256i out_of_range = _mm256_cmpgt_epi64(x, n_minus_1);
         !_mm256_testz_si256(out_of_range, out_of_range);
         out_of_range = _mm256_cmpgt_epi64(x, n_minus_1)) {
      x = _mm256_blendv_epi8(x, v.bijection(x), out_of_range);
    }
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + k), x);
    index = _mm256_add_epi64(index, step);
  }
  if (k < count) permutation_blocks_scalar(p, first + k, count - k, out + k);
}

// Lanes in the batch's layout (latin_hypercube_lanes), 8 lanes of 32 bits per register:
// lcm(s, 8) lanes = lcm(s, 8)/s points fill lcm(s, 8)/8 registers; lane l evaluates axis l mod s
// at point l / s with that axis's keys (from the 32-bit table, as memory operands). n ≤ 2^31, so
// every index and value is below 2^31 and w ≤ 31: x·key mod 2^w is the low 32 bits of the
// product (vpmulld) masked, the signed compare tests x ≥ n, and vcvtdq2pd converts a row
// exactly, as the scalar conversion does.
void latin_hypercube_place_avx2(const latin_hypercube_lanes& table, std::uint64_t first,
                                std::size_t count, double* x) noexcept {
  // A copy: x and the tables are not known apart, so every store to x would reload the pointers.
  const latin_hypercube_lanes lanes = table;
  const std::size_t s = lanes.s;
  const std::size_t block_lanes = lanes.period;  // lcm(s, 8)
  const std::size_t block_points = block_lanes / s;
  const __m256i mask = _mm256_set1_epi32(static_cast<int>(lanes.mask));
  const __m128i shift = _mm_cvtsi32_si128(lanes.shift);
  const __m256i n_minus_1 = _mm256_set1_epi32(static_cast<int>(lanes.n - 1));
  const __m256d scale = _mm256_set1_pd(lanes.inv_n);
  const __m256d below_one = _mm256_set1_pd(largest_below_one);
  const std::size_t period = lanes.period;
  const auto key = [&](int k, std::size_t l) {
    return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(lanes.keys32 + k * period + l));
  };
  const auto bijection = [&](__m256i v, std::size_t l) {
    for (int r = 0; r < permutation_schedule::rounds; ++r) {
      v = _mm256_xor_si256(v, key(2 * r, l));
      v = _mm256_and_si256(_mm256_mullo_epi32(v, key(2 * r + 1, l)), mask);
      v = _mm256_xor_si256(v, _mm256_srl_epi32(v, shift));
    }
    return v;
  };
  const auto place = [&](double* out, __m128i rows) {
    const __m256d row = _mm256_cvtepi32_pd(rows);
    const __m256d u = _mm256_loadu_pd(out);
    _mm256_storeu_pd(out, _mm256_min_pd(_mm256_mul_pd(_mm256_add_pd(row, u), scale), below_one));
  };
  std::size_t p = 0;
  for (; p + block_points <= count; p += block_points) {
    const __m256i base = _mm256_set1_epi32(static_cast<int>(first + p));
    double* block = x + p * s;
    for (std::size_t l = 0; l < block_lanes; l += 8) {
      const __m256i point = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(lanes.point32 + l));
      __m256i v = bijection(_mm256_add_epi32(base, point), l);
      for (__m256i out_of_range = _mm256_cmpgt_epi32(v, n_minus_1);
           !_mm256_testz_si256(out_of_range, out_of_range);
           out_of_range = _mm256_cmpgt_epi32(v, n_minus_1)) {
        v = _mm256_blendv_epi8(v, bijection(v, l), out_of_range);
      }
      place(block + l, _mm256_castsi256_si128(v));
      place(block + l + 4, _mm256_extracti128_si256(v, 1));
    }
  }
  latin_hypercube_place_scalar(lanes, first + p, count - p, x + p * s);
}

}  // namespace quadmc::detail
#endif
