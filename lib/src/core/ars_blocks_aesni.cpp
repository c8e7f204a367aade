// The AES-NI ARS-4x32-7 kernel: one block per XMM register, eight registers in flight, since each
// AESENC waits for the one before it on the same block (latency 3–4 cycles) while the unit starts
// one or two per cycle. Compiled with -maes (lib/CMakeLists.txt) and called only when the CPU
// has AES-NI (ars_blocks.cpp). ars_constants.hpp gives the algorithm.
#if defined(__x86_64__)
#include "ars_constants.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

constexpr int groups = 8;

__m128i lanes(std::uint64_t low, std::uint64_t high) {
  return _mm_set_epi64x(static_cast<long long>(high), static_cast<long long>(low));
}

// A 32-bit integer in each 64-bit lane as a double, exactly: the bits of 2⁵² + v, minus 2⁵².
__m128d to_double(__m128i v) {
  const __m128i magic = _mm_set1_epi64x(0x4330000000000000);
  return _mm_sub_pd(_mm_castsi128_pd(_mm_or_si128(v, magic)), _mm_set1_pd(0x1p52));
}

// The top 53 bits of each 64-bit lane as a double in [0, 1) (random_stream::to_unit), as
// hi·2⁻³² + (lo ≫ 11)·2⁻⁵³: both parts and their sum are exact. SSE2 has no 64-bit integer
// conversion, and two scalar ones per block cost more than the block's AES rounds.
void store_unit(double* out, __m128i v) {
  const __m128d high = _mm_mul_pd(to_double(_mm_srli_epi64(v, 32)), _mm_set1_pd(0x1p-32));
  const __m128i low = _mm_srli_epi64(_mm_and_si128(v, _mm_set1_epi64x(0xffffffff)), 11);
  _mm_storeu_pd(out, _mm_add_pd(high, _mm_mul_pd(to_double(low), _mm_set1_pd(0x1p-53))));
}

}  // namespace

void ars_uniform_blocks_aesni(const ars_counter_key& k, std::uint64_t first_block,
                              std::size_t blocks, double* out) noexcept {
  const auto keys = ars_round_keys(k.seed);
  __m128i rk[ars_rounds + 1];
  for (unsigned r = 0; r <= ars_rounds; ++r) rk[r] = lanes(keys[r][0], keys[r][1]);
  std::size_t b = 0;
  for (; b + groups <= blocks; b += groups) {
    __m128i v[groups];
#pragma GCC unroll 8
    for (int g = 0; g < groups; ++g) {
      v[g] = _mm_xor_si128(lanes(first_block + b + static_cast<std::size_t>(g), k.stream), rk[0]);
    }
#pragma GCC unroll 6
    for (unsigned r = 1; r < ars_rounds; ++r) {
#pragma GCC unroll 8
      for (int g = 0; g < groups; ++g) v[g] = _mm_aesenc_si128(v[g], rk[r]);
    }
#pragma GCC unroll 8
    for (int g = 0; g < groups; ++g) {
      store_unit(out + 2 * (b + static_cast<std::size_t>(g)),
                 _mm_aesenclast_si128(v[g], rk[ars_rounds]));
    }
  }
  for (; b < blocks; ++b) {
    __m128i v = _mm_xor_si128(lanes(first_block + b, k.stream), rk[0]);
    for (unsigned r = 1; r < ars_rounds; ++r) v = _mm_aesenc_si128(v, rk[r]);
    store_unit(out + 2 * b, _mm_aesenclast_si128(v, rk[ars_rounds]));
  }
}

std::array<std::uint32_t, 4> ars4x32_7_aesni(const std::array<std::uint32_t, 4>& counter,
                                             const std::array<std::uint32_t, 4>& key) noexcept {
  const __m128i weyl = lanes(ars_w0, ars_w1);
  __m128i kk = _mm_loadu_si128(reinterpret_cast<const __m128i*>(key.data()));
  __m128i v = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(counter.data())), kk);
  for (unsigned r = 1; r < ars_rounds; ++r) {
    kk = _mm_add_epi64(kk, weyl);
    v = _mm_aesenc_si128(v, kk);
  }
  kk = _mm_add_epi64(kk, weyl);
  v = _mm_aesenclast_si128(v, kk);
  std::array<std::uint32_t, 4> out;
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out.data()), v);
  return out;
}

}  // namespace quadmc::detail
#endif
