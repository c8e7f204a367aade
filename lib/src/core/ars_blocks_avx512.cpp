// The VAES ARS-4x32-7 kernel: four blocks per ZMM register (VAES runs AESENC on each 128-bit lane),
// eight registers in flight to cover the rounds' latency. The register's 64-bit lanes are then, in
// order, word 0 and word 1 of each block: exactly the order of the uniforms, so one AVX512DQ
// conversion and one store per register. Compiled with -mavx512f -mavx512dq -mvaes
// (lib/CMakeLists.txt) and called only when the CPU has all three (ars_blocks.cpp).
#if defined(__x86_64__)
#include "ars_constants.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

constexpr int groups = 8;
constexpr std::size_t lanes = 4;  // blocks per register

// The counters of blocks first … first + 3: (block, stream) in each 128-bit lane.
__m512i counters(std::uint64_t first, __m512i stream) {
  const __m512i block = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(first)),
                                         _mm512_set_epi64(0, 3, 0, 2, 0, 1, 0, 0));
  return _mm512_mask_blend_epi64(0xAA, block, stream);
}

// The top 53 bits of each 64-bit lane as a double in [0, 1) (random_stream::to_unit): below
// 2⁵³, so the unsigned conversion is exact.
__m512d to_unit(__m512i v) {
  return _mm512_mul_pd(_mm512_cvtepu64_pd(_mm512_srli_epi64(v, 11)), _mm512_set1_pd(0x1.0p-53));
}

}  // namespace

void ars_uniform_blocks_avx512(const ars_counter_key& k, std::uint64_t first_block,
                               std::size_t blocks, double* out) noexcept {
  const auto keys = ars_round_keys(k.seed);
  __m512i rk[ars_rounds + 1];
  for (unsigned r = 0; r <= ars_rounds; ++r) {
    rk[r] = _mm512_broadcast_i32x4(
        _mm_set_epi64x(static_cast<long long>(keys[r][1]), static_cast<long long>(keys[r][0])));
  }
  const __m512i stream = _mm512_set1_epi64(static_cast<long long>(k.stream));
  constexpr std::size_t step = lanes * groups;
  std::size_t b = 0;
  for (; b + step <= blocks; b += step) {
    __m512i v[groups];
#pragma GCC unroll 8
    for (int g = 0; g < groups; ++g) {
      v[g] = _mm512_xor_si512(
          counters(first_block + b + lanes * static_cast<std::size_t>(g), stream), rk[0]);
    }
#pragma GCC unroll 6
    for (unsigned r = 1; r < ars_rounds; ++r) {
#pragma GCC unroll 8
      for (int g = 0; g < groups; ++g) v[g] = _mm512_aesenc_epi128(v[g], rk[r]);
    }
#pragma GCC unroll 8
    for (int g = 0; g < groups; ++g) {
      _mm512_storeu_pd(out + 2 * (b + lanes * static_cast<std::size_t>(g)),
                       to_unit(_mm512_aesenclast_epi128(v[g], rk[ars_rounds])));
    }
  }
  // The rest, four blocks at a time; the last register stores only the blocks that remain.
  for (; b < blocks; b += lanes) {
    __m512i v = _mm512_xor_si512(counters(first_block + b, stream), rk[0]);
    for (unsigned r = 1; r < ars_rounds; ++r) v = _mm512_aesenc_epi128(v, rk[r]);
    const std::size_t left = blocks - b < lanes ? blocks - b : lanes;
    const auto mask = static_cast<__mmask8>((1u << (2 * left)) - 1);
    _mm512_mask_storeu_pd(out + 2 * b, mask, to_unit(_mm512_aesenclast_epi128(v, rk[ars_rounds])));
  }
}

}  // namespace quadmc::detail
#endif
