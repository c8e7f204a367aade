// The AVX-512 Sobol' kernel, included by sobol_blocks_avx512.cpp (AVX512F + DQ) and
// sobol_blocks_avx512_gfni.cpp (also GFNI + AVX512BW, for fast_owen's bit reversals): 8
// coordinates per register, up to 8 registers (64 coordinates) held across a run of blocks
// (sampling/sobol_blocks.hpp). Every operation is the integer operation of the scalar randomizers
// in sampling/sobol_points.hpp on one 64-bit lane, and the conversion to double is exact
// ((v >> 11)·2^-53, both steps exact), so the doubles are bitwise those of the scalar path.
#pragma once

#include "sobol_kernels.hpp"

#include <immintrin.h>

#include <algorithm>
#include <bit>

namespace quadmc::detail {
namespace {

// The helpers below are forced inline, as in the AVX2 kernel (sobol_blocks_avx2.cpp): at -O2 GCC
// may keep them out of line, and each call then spills the run's live registers.

// core/rng.hpp's mix64 on 8 lanes.
[[gnu::always_inline]] inline __m512i mix64(__m512i z) noexcept {
  z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 30)),
                         _mm512_set1_epi64(static_cast<long long>(0xbf58476d1ce4e5b9ULL)));
  z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 27)),
                         _mm512_set1_epi64(static_cast<long long>(0x94d049bb133111ebULL)));
  return _mm512_xor_si512(z, _mm512_srli_epi64(z, 31));
}

// The bit reversal of every 32-bit lane (fast_owen_scramble::reverse).
#if defined(__GFNI__) && defined(__AVX512BW__)
// GFNI: one affine transform over GF(2) with the anti-diagonal matrix reverses the bits of every
// byte, one byte shuffle reverses the bytes of every 32-bit lane.
[[gnu::always_inline]] inline __m512i reverse32(__m512i x) noexcept {
  const __m512i bytes = _mm512_gf2p8affine_epi64_epi8(
      x, _mm512_set1_epi64(static_cast<long long>(0x8040201008040201ULL)), 0);
  const __m512i order =
      _mm512_broadcast_i32x4(_mm_set_epi8(12, 13, 14, 15, 8, 9, 10, 11, 4, 5, 6, 7, 0, 1, 2, 3));
  return _mm512_shuffle_epi8(bytes, order);
}
#else
// ((x >> k) & m) | ((x << k) & ~m), one ternary-logic select (0xe4: c ? a : b).
[[gnu::always_inline]] inline __m512i reverse32(__m512i x) noexcept {
  const auto step = [](__m512i v, unsigned k, unsigned m) {
    return _mm512_ternarylogic_epi32(_mm512_srli_epi32(v, k), _mm512_slli_epi32(v, k),
                                     _mm512_set1_epi32(static_cast<int>(m)), 0xe4);
  };
  x = step(x, 1, 0x55555555u);
  x = step(x, 2, 0x33333333u);
  x = step(x, 4, 0x0f0f0f0fu);
  x = step(x, 8, 0x00ff00ffu);
  return _mm512_rol_epi32(x, 16);
}
#endif

// fast_owen_scramble::operator() on 8 lanes. The 32-bit arithmetic runs in the low half of each
// 64-bit lane with the high half zero (32-bit adds and multiplies keep it zero).
[[gnu::always_inline]] inline __m512i fast_owen(__m512i v, __m512i seed) noexcept {
  const __m512i low32 = _mm512_set1_epi64(0xffffffffLL);
  __m512i x = reverse32(_mm512_srli_epi64(v, 32));
  x = _mm512_add_epi32(x, _mm512_and_si512(seed, low32));
  for (const unsigned c : {0x6c50b47cu, 0xb82f1e52u, 0xc7afe638u, 0x8d22f6e6u}) {
    const __m512i constant = _mm512_set1_epi64(static_cast<long long>(c));
    x = _mm512_xor_si512(x, _mm512_mullo_epi32(x, constant));
  }
  const __m512i high = reverse32(x);
  const __m512i low =
      _mm512_srli_epi64(mix64(_mm512_xor_si512(_mm512_srli_epi64(seed, 32), mix64(high))), 32);
  return _mm512_or_si512(_mm512_slli_epi64(high, 32), low);
}

// owen_scramble::operator() on 8 lanes (depth ≤ 64): the first table_digits flips by one gather
// from the prefix table (sobol_blocks.hpp), the others hashed as the scalar code does.
[[gnu::always_inline]] inline __m512i owen(__m512i v, __m512i seed, __m512i base,
                                           const sobol_block_tables& t) noexcept {
  const unsigned depth = t.depth;
  const unsigned k = t.table_digits;
  __m512i out = v;
  if (k > 0) {
    const __m512i index =
        _mm512_add_epi64(base, _mm512_srl_epi64(v, _mm_cvtsi32_si128(static_cast<int>(64 - k))));
    out = _mm512_xor_si512(out, _mm512_i64gather_epi64(index, t.flips.data(), 8));
  }
  const __m512i top = _mm512_set1_epi64(static_cast<long long>(std::uint64_t{1} << 63));
  for (unsigned b = k; b < depth; ++b) {
    const __m512i length = _mm512_set1_epi64(static_cast<long long>(std::uint64_t{1} << b));
    const __m512i prefix =
        b == 0 ? length : _mm512_or_si512(_mm512_srl_epi64(v, _mm_cvtsi32_si128(64 - b)), length);
    const __m512i flip = _mm512_and_si512(mix64(_mm512_xor_si512(seed, prefix)), top);
    out = _mm512_xor_si512(out, _mm512_srl_epi64(flip, _mm_cvtsi32_si128(static_cast<int>(b))));
  }
  if (depth < 64) {
    const __m512i length = _mm512_set1_epi64(static_cast<long long>(std::uint64_t{1} << depth));
    const __m512i prefix =
        depth == 0
            ? length
            : _mm512_or_si512(_mm512_srl_epi64(v, _mm_cvtsi32_si128(static_cast<int>(64 - depth))),
                              length);
    const __m512i tail = mix64(_mm512_xor_si512(
        seed, mix64(_mm512_xor_si512(
                  prefix, _mm512_set1_epi64(static_cast<long long>(0xa0761d6478bd642fULL))))));
    const __m512i low = _mm512_set1_epi64(static_cast<long long>(~std::uint64_t{0} >> depth));
    out = _mm512_ternarylogic_epi64(tail, out, low, 0xe4);  // low ? tail : out
  }
  return out;
}

// Lanes [w0, w0 + 8·V) of `blocks` blocks from block q on; the last register keeps only the
// lanes of `tail`. out points at lane w0 of block q; consecutive blocks are t.words apart.
template <int V, sobol_scramble S>
void run(const sobol_block_tables& t, std::size_t w0, __mmask8 tail, std::uint64_t q,
         std::uint64_t blocks, double* out) noexcept {
  const std::size_t words = t.words;
  const std::uint64_t* rows = t.rows.data() + w0;
  __m512i y[V], offset[V], key[V], base[V];
  for (int v = 0; v < V; ++v) {
    const __mmask8 m = v + 1 == V ? tail : __mmask8{0xff};
    offset[v] = _mm512_maskz_loadu_epi64(m, t.offset.data() + w0 + 8 * v);
    key[v] = _mm512_maskz_loadu_epi64(m, t.key.data() + w0 + 8 * v);
    base[v] = S == sobol_scramble::owen
                  ? _mm512_maskz_loadu_epi64(m, t.flip_base.data() + w0 + 8 * v)
                  : _mm512_setzero_si512();
    y[v] = _mm512_setzero_si512();
  }
  // C·g(B·q): the columns of the set bits of B·q's Gray code.
  const std::uint64_t start = q << t.log2_block;
  for (std::uint64_t g = start ^ (start >> 1); g != 0; g &= g - 1) {
    const std::uint64_t* row = rows + std::countr_zero(g) * words;
    for (int v = 0; v < V; ++v) {
      const __mmask8 m = v + 1 == V ? tail : __mmask8{0xff};
      y[v] = _mm512_xor_si512(y[v], _mm512_maskz_loadu_epi64(m, row + 8 * v));
    }
  }
  // From block q to q + 1: one step row (sobol_blocks.hpp); with B = 1 it is a column.
  const std::uint64_t* steps = (t.log2_block > 0 ? t.steps.data() : t.rows.data()) + w0;
  const __m512d scale = _mm512_set1_pd(0x1.0p-53);
  for (std::uint64_t b = 0;; ++b) {
    for (int v = 0; v < V; ++v) {
      __m512i w = _mm512_xor_si512(y[v], offset[v]);
      if constexpr (S == sobol_scramble::fast_owen) w = fast_owen(w, key[v]);
      if constexpr (S == sobol_scramble::owen) w = owen(w, key[v], base[v], t);
      const __m512d x = _mm512_mul_pd(_mm512_cvtepu64_pd(_mm512_srli_epi64(w, 11)), scale);
      if (v + 1 == V) {
        _mm512_mask_storeu_pd(out + 8 * v, tail, x);
      } else {
        _mm512_storeu_pd(out + 8 * v, x);
      }
    }
    if (b + 1 == blocks) break;
    out += words;
    const std::uint64_t* row = steps + std::countr_zero(q + b + 1) * words;
    for (int v = 0; v < V; ++v) {
      const __mmask8 m = v + 1 == V ? tail : __mmask8{0xff};
      y[v] = _mm512_xor_si512(y[v], _mm512_maskz_loadu_epi64(m, row + 8 * v));
    }
  }
}

template <sobol_scramble S>
void run_lanes(const sobol_block_tables& t, std::size_t w0, std::size_t lanes, std::uint64_t q,
               std::uint64_t blocks, double* out) noexcept {
  const int registers = static_cast<int>((lanes + 7) / 8);
  const auto tail = static_cast<__mmask8>(0xffu >> (8 * registers - lanes));
  switch (registers) {
    case 1:
      return run<1, S>(t, w0, tail, q, blocks, out);
    case 2:
      return run<2, S>(t, w0, tail, q, blocks, out);
    case 3:
      return run<3, S>(t, w0, tail, q, blocks, out);
    case 4:
      return run<4, S>(t, w0, tail, q, blocks, out);
    case 5:
      return run<5, S>(t, w0, tail, q, blocks, out);
    case 6:
      return run<6, S>(t, w0, tail, q, blocks, out);
    case 7:
      return run<7, S>(t, w0, tail, q, blocks, out);
    default:
      return run<8, S>(t, w0, tail, q, blocks, out);
  }
}

template <sobol_scramble S>
void run_all(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
             double* out) noexcept {
  // A block's lanes in slices of 64 (8 registers): one slice for s ≤ 8, ⌈s/64⌉ above, each slice
  // walking all blocks with its state in registers.
  for (std::size_t w0 = 0; w0 < t.words; w0 += 64) {
    run_lanes<S>(t, w0, std::min<std::size_t>(64, t.words - w0), q, blocks, out + w0);
  }
}

}  // namespace

}  // namespace quadmc::detail
