// The AVX-512DQ permutation kernel: 8 indices per register, the 64-bit products by vpmullq, the
// cycle walk as masked rounds on the lanes still outside [0, n). Compiled with -mavx512f
// -mavx512dq (lib/CMakeLists.txt) and called only when the CPU has both (permutation_blocks.cpp).
#if defined(__x86_64__)
#include "permutation_kernels.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

struct avx512_schedule {
  __m512i keys[2 * permutation_schedule::rounds];
  __m512i mask;
  __m128i shift;

  explicit avx512_schedule(const permutation_schedule& p)
      : mask(_mm512_set1_epi64(static_cast<long long>(p.mask))), shift(_mm_cvtsi32_si128(p.shift)) {
    for (int k = 0; k < 2 * permutation_schedule::rounds; ++k) {
      keys[k] = _mm512_set1_epi64(static_cast<long long>(p.keys[k]));
    }
  }

  __m512i bijection(__m512i x) const noexcept {
    for (int r = 0; r < permutation_schedule::rounds; ++r) {
      x = _mm512_xor_si512(x, keys[2 * r]);
      x = _mm512_and_si512(_mm512_mullo_epi64(x, keys[2 * r + 1]), mask);
      x = _mm512_xor_si512(x, _mm512_srl_epi64(x, shift));
    }
    return x;
  }
};

}  // namespace

void permutation_blocks_avx512(const permutation_schedule& p, std::uint64_t first,
                               std::size_t count, std::uint64_t* out) noexcept {
  const avx512_schedule v(p);
  const __m512i n = _mm512_set1_epi64(static_cast<long long>(p.n));
  const __m512i step = _mm512_set1_epi64(8);
  __m512i index = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(first)),
                                   _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0));
  std::size_t k = 0;
  for (; k + 8 <= count; k += 8) {
    __m512i x = v.bijection(index);
    // Lanes with x ≥ n walk on; each further round touches only them.
    for (__mmask8 out_of_range = _mm512_cmpge_epu64_mask(x, n); out_of_range != 0;
         out_of_range = _mm512_cmpge_epu64_mask(x, n)) {
      x = _mm512_mask_mov_epi64(x, out_of_range, v.bijection(x));
    }
    _mm512_storeu_si512(out + k, x);
    index = _mm512_add_epi64(index, step);
  }
  if (k < count) permutation_blocks_scalar(p, first + k, count - k, out + k);
}

// Lanes in the batch's layout (latin_hypercube_lanes): lcm(s, 8) lanes = lcm(s, 8)/s points fill
// lcm(s, 8)/8 registers; lane l evaluates axis l mod s at point l / s with that axis's keys (from
// the table, as memory operands); vcvtqq2pd converts a row as the scalar conversion does.
void latin_hypercube_place_avx512(const latin_hypercube_lanes& table, std::uint64_t first,
                                  std::size_t count, double* x) noexcept {
  // A copy: x and the tables are not known apart, so every store to x would reload the pointers.
  const latin_hypercube_lanes lanes = table;
  const std::size_t s = lanes.s;
  const std::size_t block_lanes = lanes.period;  // lcm(s, 8)
  const std::size_t block_points = block_lanes / s;
  const __m512i mask = _mm512_set1_epi64(static_cast<long long>(lanes.mask));
  const __m128i shift = _mm_cvtsi32_si128(lanes.shift);
  const __m512i n = _mm512_set1_epi64(static_cast<long long>(lanes.n));
  const __m512d scale = _mm512_set1_pd(lanes.inv_n);
  const __m512d below_one = _mm512_set1_pd(largest_below_one);
  const std::size_t period = lanes.period;
  const auto key = [&](int k, std::size_t l) {
    return _mm512_loadu_si512(lanes.keys + k * period + l);
  };
  const auto bijection = [&](__m512i v, std::size_t l) {
    for (int r = 0; r < permutation_schedule::rounds; ++r) {
      v = _mm512_xor_si512(v, key(2 * r, l));
      v = _mm512_and_si512(_mm512_mullo_epi64(v, key(2 * r + 1, l)), mask);
      v = _mm512_xor_si512(v, _mm512_srl_epi64(v, shift));
    }
    return v;
  };
  std::size_t p = 0;
  for (; p + block_points <= count; p += block_points) {
    const __m512i base = _mm512_set1_epi64(static_cast<long long>(first + p));
    double* block = x + p * s;
    for (std::size_t l = 0; l < block_lanes; l += 8) {
      __m512i v = bijection(_mm512_add_epi64(base, _mm512_loadu_si512(lanes.point + l)), l);
      for (__mmask8 out_of_range = _mm512_cmpge_epu64_mask(v, n); out_of_range != 0;
           out_of_range = _mm512_cmpge_epu64_mask(v, n)) {
        v = _mm512_mask_mov_epi64(v, out_of_range, bijection(v, l));
      }
      const __m512d row = _mm512_cvtepi64_pd(v);
      const __m512d u = _mm512_loadu_pd(block + l);
      _mm512_storeu_pd(block + l,
                       _mm512_min_pd(_mm512_mul_pd(_mm512_add_pd(row, u), scale), below_one));
    }
  }
  latin_hypercube_place_scalar(lanes, first + p, count - p, x + p * s);
}

}  // namespace quadmc::detail
#endif
