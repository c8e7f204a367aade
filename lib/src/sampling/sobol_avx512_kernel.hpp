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
  // fast_owen_scramble::low_digits: the 32-bit finaliser of the high digits ⊕ the seed's top half.
  __m512i h = _mm512_xor_si512(high, _mm512_srli_epi64(seed, 32));
  h = _mm512_mullo_epi32(_mm512_xor_si512(h, _mm512_srli_epi32(h, 16)),
                         _mm512_set1_epi64(0x85ebca6bLL));
  h = _mm512_mullo_epi32(_mm512_xor_si512(h, _mm512_srli_epi32(h, 13)),
                         _mm512_set1_epi64(0xc2b2ae35LL));
  h = _mm512_xor_si512(h, _mm512_srli_epi32(h, 16));
  return _mm512_or_si512(_mm512_slli_epi64(high, 32), h);
}

// fast_owen on two registers at once: their 32-bit work (Burley's rounds, the finaliser) on the
// 16 lanes of one, where fast_owen() leaves half of every register's lanes empty. `low` and
// `high` hold the two halves of the seeds of a's 8 lanes, then b's (fast_owen_seeds).
[[gnu::always_inline]] inline void fast_owen_pair(__m512i& a, __m512i& b, __m512i low,
                                                  __m512i high) noexcept {
  const __m512i odd = _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
  __m512i x = reverse32(_mm512_permutex2var_epi32(a, odd, b));  // digits 1…32, reversed
  x = _mm512_add_epi32(x, low);
  for (const unsigned c : {0x6c50b47cu, 0xb82f1e52u, 0xc7afe638u, 0x8d22f6e6u}) {
    x = _mm512_xor_si512(x, _mm512_mullo_epi32(x, _mm512_set1_epi32(static_cast<int>(c))));
  }
  const __m512i digits = reverse32(x);
  __m512i h = _mm512_xor_si512(digits, high);
  h = _mm512_mullo_epi32(_mm512_xor_si512(h, _mm512_srli_epi32(h, 16)),
                         _mm512_set1_epi32(static_cast<int>(0x85ebca6bu)));
  h = _mm512_mullo_epi32(_mm512_xor_si512(h, _mm512_srli_epi32(h, 13)),
                         _mm512_set1_epi32(static_cast<int>(0xc2b2ae35u)));
  h = _mm512_xor_si512(h, _mm512_srli_epi32(h, 16));
  // Back to 64-bit words: the finaliser's word low, the scrambled digits high.
  a = _mm512_permutex2var_epi32(
      h, _mm512_setr_epi32(0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23), digits);
  b = _mm512_permutex2var_epi32(
      h, _mm512_setr_epi32(8, 24, 9, 25, 10, 26, 11, 27, 12, 28, 13, 29, 14, 30, 15, 31), digits);
}

// The seeds of fast_owen_pair(a, b) from the 8-lane keys of a and b: low halves, high halves.
inline void fast_owen_seeds(__m512i key_a, __m512i key_b, __m512i& low, __m512i& high) noexcept {
  low = _mm512_permutex2var_epi32(
      key_a, _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30), key_b);
  high = _mm512_permutex2var_epi32(
      key_a, _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31), key_b);
}

// owen_scramble::operator() on U registers of 8 lanes in lockstep (depth ≤ 32): the first
// table_digits flips by one gather from the prefix table (sobol_blocks.hpp), the others from one
// hash per six levels of the tree as owen_scramble::flips draws them, then the tail. Lockstep,
// because one register's chain (gather, hash, bit picks, hash) is latency bound: U independent
// chains interleaved keep the multiplier and the load ports busy. The loops over the U registers
// are unrolled by pragma: rolled, GCC kept the registers in memory and ran the chains in turn.
template <int U>
[[gnu::always_inline]] inline void owen(__m512i (&w)[U], const __m512i (&seed)[U],
                                        const __m512i (&base)[U],
                                        const sobol_block_tables& t) noexcept {
  const auto shift = [](unsigned count) { return _mm_cvtsi32_si128(static_cast<int>(count)); };
  const auto word = [](std::uint64_t x) { return _mm512_set1_epi64(static_cast<long long>(x)); };
  const auto prefix = [&](__m512i v, unsigned b) {  // owen_scramble::prefix(v, b)
    const __m512i length = word(std::uint64_t{1} << b);
    return b == 0 ? length : _mm512_or_si512(_mm512_srl_epi64(v, shift(64 - b)), length);
  };
  const unsigned depth = t.depth;
  const unsigned k = t.table_digits;
  __m512i out[U];
#pragma GCC unroll 8
  for (int u = 0; u < U; ++u) out[u] = w[u];
  if (k > 0) {
#pragma GCC unroll 8
    for (int u = 0; u < U; ++u) {
      const __m512i index = _mm512_add_epi64(base[u], _mm512_srl_epi64(w[u], shift(64 - k)));
      out[u] = _mm512_xor_si512(out[u], _mm512_i64gather_epi64(index, t.flips.data(), 8));
    }
  }
#if defined(__AVX512VBMI__) && defined(__AVX512BITALG__)
  // A subtree's six flips at once. Digit b0 + d flips by bit node_d = 2^d − 1 + (digits b0 …
  // b0 + d − 1) of the subtree's hash: vpmultishiftqb puts 8 digits ending at digit b0 + d − 1
  // into byte d (rotating the word right by 64 − b0 − d), the mask keeps d of them and 2^d − 1
  // is added; vpshufbitqmb picks bit node_d of the hash into mask bit d; the flips of the
  // digits in [k, depth) become bits 7 − d of a byte each, summed into one byte per lane
  // (vpsadbw; distinct bits, so the sum is their OR) and shifted to bits 63 − b0 − d.
  for (unsigned b0 = k - k % owen_levels_per_hash; b0 < depth; b0 += owen_levels_per_hash) {
    std::uint64_t control = 0, keep = 0, place = 0;
    for (unsigned d = 0; d < owen_levels_per_hash; ++d) {
      control |= static_cast<std::uint64_t>((64 - b0 - d) & 63) << (8 * d);
      keep |= ((std::uint64_t{1} << d) - 1) << (8 * d);
      if (b0 + d >= k && b0 + d < depth) place |= std::uint64_t{0x80} >> d << (8 * d);
    }
#pragma GCC unroll 8
    for (int u = 0; u < U; ++u) {
      const __m512i tree = mix64(_mm512_xor_si512(seed[u], prefix(w[u], b0)));
      const __m512i digits = _mm512_multishift_epi64_epi8(word(control), w[u]);
      const __m512i node = _mm512_add_epi8(_mm512_and_si512(digits, word(keep)), word(keep));
      const __mmask64 flips = _mm512_bitshuffle_epi64_mask(tree, node);
      const __m512i bits =
          _mm512_sad_epu8(_mm512_maskz_mov_epi8(flips, word(place)), _mm512_setzero_si512());
      out[u] = _mm512_xor_si512(out[u], _mm512_sll_epi64(bits, shift(56 - b0)));
    }
  }
#else
  // Digit b = b0 + d (d < 6) flips by bit node = 2^d − 1 + (digits b0 … b − 1) of the subtree's
  // hash, moved to bit 63 − b by one rotation: left by (63 − b − node) mod 64, which vprolvq
  // takes from the low 6 bits of its count, so the count is K − (digits b0 … b − 1) with
  // K = 63 − b − 2^d + 1, unreduced.
  __m512i tree[U], digits[U];
  for (unsigned b = k; b < depth; ++b) {
    const unsigned d = b % owen_levels_per_hash;
    const unsigned b0 = b - d;
    if (d == 0 || b == k) {
#pragma GCC unroll 8
      for (int u = 0; u < U; ++u) {
        tree[u] = mix64(_mm512_xor_si512(seed[u], prefix(w[u], b0)));
        // The subtree's six digits b0 … b0 + 5 as an integer, the first one highest.
        digits[u] = _mm512_and_si512(_mm512_srl_epi64(w[u], shift(58 - b0)), word(63));
      }
    }
    const __m512i at = word(std::uint64_t{1} << (63 - b));
    const std::uint64_t count = (63 - b) - ((std::uint64_t{1} << d) - 1);
#pragma GCC unroll 8
    for (int u = 0; u < U; ++u) {
      const __m512i above = _mm512_srl_epi64(digits[u], shift(6 - d));
      const __m512i flip = _mm512_rolv_epi64(tree[u], _mm512_sub_epi64(word(count), above));
      out[u] = _mm512_ternarylogic_epi64(out[u], flip, at, 0x78);  // out ^ (flip & at)
    }
  }
#endif
  if (depth < 64) {
    const __m512i low = word(~std::uint64_t{0} >> depth);
#pragma GCC unroll 8
    for (int u = 0; u < U; ++u) {
      const __m512i tail = mix64(_mm512_xor_si512(_mm512_xor_si512(seed[u], prefix(w[u], depth)),
                                                  word(0xa0761d6478bd642fULL)));
      out[u] = _mm512_ternarylogic_epi64(tail, out[u], low, 0xe4);  // low ? tail : out
    }
  }
#pragma GCC unroll 8
  for (int u = 0; u < U; ++u) w[u] = out[u];
}

// The nonlinear scramble of R registers whose register i holds lanes of register i mod V of a
// block (R = U·V: U blocks in lockstep), its seeds arranged once per run: fast_owen in pairs of
// registers (fast_owen_pair), owen all R in lockstep.
template <int R, int V, sobol_scramble S>
class scrambler {
 public:
  scrambler(const __m512i (&key)[V], const __m512i (&base)[V], const sobol_block_tables& t) noexcept
      : t_(t) {
    for (int i = 0; i < R; ++i) {
      key_[i] = key[i % V];
      base_[i] = base[i % V];
    }
    for (int p = 0; p < R / 2; ++p)
      fast_owen_seeds(key_[2 * p], key_[2 * p + 1], low_[p], high_[p]);
  }
  [[gnu::always_inline]] void operator()(__m512i (&w)[R]) const noexcept {
    if constexpr (S == sobol_scramble::owen) {
      owen<R>(w, key_, base_, t_);
    } else {
#pragma GCC unroll 8
      for (int p = 0; p < R / 2; ++p) fast_owen_pair(w[2 * p], w[2 * p + 1], low_[p], high_[p]);
      if constexpr (R % 2 == 1) w[R - 1] = fast_owen(w[R - 1], key_[R - 1]);
    }
  }

 private:
  const sobol_block_tables& t_;
  __m512i key_[R], base_[R];
  __m512i low_[R / 2 > 0 ? R / 2 : 1], high_[R / 2 > 0 ? R / 2 : 1];
};

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
  const auto advance = [&](std::uint64_t b) {  // y: block q + b → q + b + 1
    const std::uint64_t* row = steps + std::countr_zero(q + b + 1) * words;
    for (int v = 0; v < V; ++v) {
      const __mmask8 m = v + 1 == V ? tail : __mmask8{0xff};
      y[v] = _mm512_xor_si512(y[v], _mm512_maskz_loadu_epi64(m, row + 8 * v));
    }
  };
  const auto store = [&](double* to, int v, __m512i w) {
    const __m512d x =
        _mm512_mul_pd(_mm512_cvtepu64_pd(_mm512_srli_epi64(w, 11)), _mm512_set1_pd(0x1.0p-53));
    if (v + 1 == V) {
      _mm512_mask_storeu_pd(to + 8 * v, tail, x);
    } else {
      _mm512_storeu_pd(to + 8 * v, x);
    }
  };
  std::uint64_t b = 0;
  if constexpr (S == sobol_scramble::xor_constant) {
    for (;; ++b) {
      for (int v = 0; v < V; ++v) store(out, v, _mm512_xor_si512(y[v], offset[v]));
      if (b + 1 == blocks) break;
      out += words;
      advance(b);
    }
  } else {
    // The scrambles run U blocks' registers in lockstep (four registers where a block has one or
    // two: s ≤ 8 with 8 | s, s in 9…16), the blocks left over one at a time.
    constexpr int U = V <= 2 ? 4 / V : 1;
    const scrambler<U * V, V, S> lockstep(key, base, t);
    for (; b + U <= blocks; b += U) {
      __m512i w[U * V];
#pragma GCC unroll 8
      for (int u = 0; u < U; ++u) {
        for (int v = 0; v < V; ++v) w[u * V + v] = _mm512_xor_si512(y[v], offset[v]);
        if (b + u + 1 < blocks) advance(b + u);
      }
      lockstep(w);
#pragma GCC unroll 8
      for (int u = 0; u < U; ++u) {
        for (int v = 0; v < V; ++v) store(out + u * words, v, w[u * V + v]);
      }
      out += U * words;
    }
    if constexpr (U > 1) {
      const scrambler<V, V, S> one(key, base, t);
      for (; b < blocks; ++b) {
        __m512i w[V];
        for (int v = 0; v < V; ++v) w[v] = _mm512_xor_si512(y[v], offset[v]);
        one(w);
        for (int v = 0; v < V; ++v) store(out, v, w[v]);
        out += words;
        if (b + 1 < blocks) advance(b);
      }
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
