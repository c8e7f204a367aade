// The AVX-512 Philox kernel: 8 blocks per register (philox_lanes.hpp). Compiled with -mavx512f
// (lib/CMakeLists.txt) and called only when the CPU has AVX512F (simd_level.hpp).
#if defined(__x86_64__)
#include "philox_lanes.hpp"

#include <immintrin.h>

namespace quadmc::detail {
namespace {

struct avx512_lanes {
  using reg = __m512i;
  static constexpr std::size_t lanes = 8;
  static reg broadcast(std::uint64_t v) { return _mm512_set1_epi64(static_cast<long long>(v)); }
  static reg iota(std::uint64_t first) {
    return _mm512_add_epi64(broadcast(first), _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0));
  }
  static reg low32(reg v) { return _mm512_and_si512(v, broadcast(0xffffffffu)); }
  static reg high32(reg v) { return _mm512_srli_epi64(v, 32); }
  static reg mul32(reg a, reg b) { return _mm512_mul_epu32(a, b); }
  static reg xor_(reg a, reg b) { return _mm512_xor_si512(a, b); }
  // A 32-bit integer v as a double, exactly: the bits of 2⁵² + v, minus 2⁵².
  static __m512d to_double(reg v) {
    const reg magic = broadcast(0x4330000000000000u);
    return _mm512_sub_pd(_mm512_castsi512_pd(_mm512_or_si512(v, magic)), _mm512_set1_pd(0x1p52));
  }
  static __m512d to_unit(reg hi, reg lo) {
    return _mm512_add_pd(
        _mm512_mul_pd(to_double(hi), _mm512_set1_pd(0x1p-32)),
        _mm512_mul_pd(to_double(_mm512_srli_epi64(lo, 11)), _mm512_set1_pd(0x1p-53)));
  }
  // out = a₀ b₀ a₁ b₁ … a₇ b₇: lanes picked from the pair (a, b) by index (bit 3 selects b).
  static void store_unit(double* out, __m512d a, __m512d b) {
    const __m512i first = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
    const __m512i second = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
    _mm512_storeu_pd(out, _mm512_permutex2var_pd(a, first, b));
    _mm512_storeu_pd(out + 8, _mm512_permutex2var_pd(a, second, b));
  }
};

}  // namespace

void philox_uniform_blocks_avx512(const philox_counter_key& k, std::uint64_t first_block,
                                  std::size_t blocks, double* out) noexcept {
  philox_uniform_tiles<avx512_lanes, 4>(k, first_block, blocks, out);
}

}  // namespace quadmc::detail
#endif
