// The AVX2 Philox kernel: 4 blocks per register (philox_lanes.hpp). Compiled with -mavx2
// (lib/CMakeLists.txt) and called only when the CPU has AVX2 (simd_level.hpp).
#if defined(__x86_64__)
#include "philox_lanes.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

struct avx2_lanes {
  using reg = __m256i;
  static constexpr std::size_t lanes = 4;
  static reg broadcast(std::uint64_t v) { return _mm256_set1_epi64x(static_cast<long long>(v)); }
  static reg iota(std::uint64_t first) {
    return _mm256_add_epi64(broadcast(first), _mm256_set_epi64x(3, 2, 1, 0));
  }
  static reg low32(reg v) { return _mm256_and_si256(v, broadcast(0xffffffffu)); }
  static reg high32(reg v) { return _mm256_srli_epi64(v, 32); }
  static reg mul32(reg a, reg b) { return _mm256_mul_epu32(a, b); }
  static reg xor_(reg a, reg b) { return _mm256_xor_si256(a, b); }
  // A 32-bit integer v as a double, exactly: the bits of 2⁵² + v, minus 2⁵².
  static __m256d to_double(reg v) {
    const reg magic = broadcast(0x4330000000000000u);
    return _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(v, magic)), _mm256_set1_pd(0x1p52));
  }
  static __m256d to_unit(reg hi, reg lo) {
    return _mm256_add_pd(
        _mm256_mul_pd(to_double(hi), _mm256_set1_pd(0x1p-32)),
        _mm256_mul_pd(to_double(_mm256_srli_epi64(lo, 11)), _mm256_set1_pd(0x1p-53)));
  }
  // out = a₀ b₀ a₁ b₁ a₂ b₂ a₃ b₃ (unpack works within 128-bit halves; permute joins them).
  static void store_unit(double* out, __m256d a, __m256d b) {
    const __m256d lo = _mm256_unpacklo_pd(a, b);  // a₀ b₀ | a₂ b₂
    const __m256d hi = _mm256_unpackhi_pd(a, b);  // a₁ b₁ | a₃ b₃
    _mm256_storeu_pd(out, _mm256_permute2f128_pd(lo, hi, 0x20));
    _mm256_storeu_pd(out + 4, _mm256_permute2f128_pd(lo, hi, 0x31));
  }
};

}  // namespace

void philox_uniform_blocks_avx2(const philox_counter_key& k, std::uint64_t first_block,
                                std::size_t blocks, double* out) noexcept {
  philox_uniform_tiles<avx2_lanes, 4>(k, first_block, blocks, out);
}

}  // namespace quadmc::detail
#endif
