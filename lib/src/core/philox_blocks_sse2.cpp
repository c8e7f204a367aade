// The SSE2 Philox kernel: 2 blocks per register (philox_lanes.hpp). SSE2 is part of every
// x86-64, so this file needs no extra compiler flag.
#if defined(__x86_64__)
#include "philox_lanes.hpp"

#include <emmintrin.h>

namespace quadmc::detail {
namespace {

struct sse2_lanes {
  using reg = __m128i;
  static constexpr std::size_t lanes = 2;
  static reg broadcast(std::uint64_t v) { return _mm_set1_epi64x(static_cast<long long>(v)); }
  static reg iota(std::uint64_t first) {
    return _mm_set_epi64x(static_cast<long long>(first + 1), static_cast<long long>(first));
  }
  static reg low32(reg v) { return _mm_and_si128(v, broadcast(0xffffffffu)); }
  static reg high32(reg v) { return _mm_srli_epi64(v, 32); }
  static reg mul32(reg a, reg b) { return _mm_mul_epu32(a, b); }
  static reg xor_(reg a, reg b) { return _mm_xor_si128(a, b); }
  // A 32-bit integer v as a double, exactly: the bits of 2⁵² + v, minus 2⁵².
  static __m128d to_double(reg v) {
    const reg magic = broadcast(0x4330000000000000u);
    return _mm_sub_pd(_mm_castsi128_pd(_mm_or_si128(v, magic)), _mm_set1_pd(0x1p52));
  }
  static __m128d to_unit(reg hi, reg lo) {
    return _mm_add_pd(_mm_mul_pd(to_double(hi), _mm_set1_pd(0x1p-32)),
                      _mm_mul_pd(to_double(_mm_srli_epi64(lo, 11)), _mm_set1_pd(0x1p-53)));
  }
  // out = a₀ b₀ a₁ b₁: the two words of block 0, then of block 1.
  static void store_unit(double* out, __m128d a, __m128d b) {
    _mm_storeu_pd(out, _mm_unpacklo_pd(a, b));
    _mm_storeu_pd(out + 2, _mm_unpackhi_pd(a, b));
  }
};

}  // namespace

void philox_uniform_blocks_sse2(const philox_counter_key& k, std::uint64_t first_block,
                                std::size_t blocks, double* out) noexcept {
  philox_uniform_tiles<sse2_lanes, 4>(k, first_block, blocks, out);
}

}  // namespace quadmc::detail
#endif
