// The AVX2 Sobol' kernel: the AVX-512 kernel's walk (sobol_avx512_kernel.hpp, the block algebra
// in sampling/sobol_blocks.hpp) on 4 coordinates per register, for CPUs with AVX2 but no
// AVX-512DQ. Compiled with -mavx2 (lib/CMakeLists.txt) and called only after the run-time check
// in sobol_blocks.cpp.
//
// AVX2 has no 64-bit multiply, no unsigned 64-bit conversion, no bit-select and no lane masks, so
// each is built from what it has, exactly: a·c mod 2^64 from three 32×32→64 multiplies, the
// 53-bit integer v >> 11 as the sum of two exactly converted halves, bit reversal from a nibble
// table. Every value is the integer of the scalar randomizers in sampling/sobol_points.hpp, and
// the doubles are bitwise those of the scalar path (tests/sampling/sobol_points_test.cpp runs
// every simd level the CPU offers).
#if defined(__x86_64__)
#include "avx2_lane_slices.hpp"
#include "sobol_kernels.hpp"

#include <immintrin.h>

#include <bit>

namespace quadmc::detail {
namespace {

// The helpers below are forced inline: at -O2 GCC kept mix64 and the scrambles out of line, and
// each call spilled the run's live registers (perf on fast_owen at s = 2: mix64 36 % of the time
// as a symbol of its own).

// a·c mod 2^64 per lane: lo(a)·lo(c) + ((hi(a)·lo(c) + lo(a)·hi(c)) << 32), the product of the
// high halves falling out of the 64 bits.
[[gnu::always_inline]] inline __m256i mullo64(__m256i a, std::uint64_t c) noexcept {
  const __m256i c_low = _mm256_set1_epi64x(static_cast<long long>(c & 0xffffffffu));
  const __m256i c_high = _mm256_set1_epi64x(static_cast<long long>(c >> 32));
  const __m256i cross = _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(a, 32), c_low),
                                         _mm256_mul_epu32(a, c_high));
  return _mm256_add_epi64(_mm256_mul_epu32(a, c_low), _mm256_slli_epi64(cross, 32));
}

// core/rng.hpp's mix64 on 4 lanes.
[[gnu::always_inline]] inline __m256i mix64(__m256i z) noexcept {
  z = mullo64(_mm256_xor_si256(z, _mm256_srli_epi64(z, 30)), 0xbf58476d1ce4e5b9ULL);
  z = mullo64(_mm256_xor_si256(z, _mm256_srli_epi64(z, 27)), 0x94d049bb133111ebULL);
  return _mm256_xor_si256(z, _mm256_srli_epi64(z, 31));
}

// The bit reversal of every 32-bit lane (fast_owen_scramble::reverse): each byte's two nibbles
// reversed by table lookup (vpshufb) and swapped, then the bytes of each lane in reverse order.
[[gnu::always_inline]] inline __m256i reverse32(__m256i x) noexcept {
  const __m256i nibble = _mm256_set1_epi8(0x0f);
  // Byte n of each table: the 4 bits of n backwards, in the high nibble (for a byte's low
  // nibble) or the low one (for its high nibble); then the byte order 3 2 1 0 within each lane.
  const auto table = [](std::uint64_t first8, std::uint64_t last8) {
    return _mm256_setr_epi64x(static_cast<long long>(first8), static_cast<long long>(last8),
                              static_cast<long long>(first8), static_cast<long long>(last8));
  };
  const __m256i reversed_high = table(0xe060a020c0408000ULL, 0xf070b030d0509010ULL);
  const __m256i reversed_low = table(0x0e060a020c040800ULL, 0x0f070b030d050901ULL);
  const __m256i bytes = _mm256_or_si256(
      _mm256_shuffle_epi8(reversed_high, _mm256_and_si256(x, nibble)),
      _mm256_shuffle_epi8(reversed_low, _mm256_and_si256(_mm256_srli_epi16(x, 4), nibble)));
  return _mm256_shuffle_epi8(bytes, table(0x0405060700010203ULL, 0x0c0d0e0f08090a0bULL));
}

// fast_owen_scramble::operator() on 4 lanes, the 32-bit arithmetic in the low half of each 64-bit
// lane with the high half zero, as in the AVX-512 kernel.
[[gnu::always_inline]] inline __m256i fast_owen(__m256i v, __m256i seed) noexcept {
  const __m256i low32 = _mm256_set1_epi64x(0xffffffffLL);
  __m256i x = reverse32(_mm256_srli_epi64(v, 32));
  x = _mm256_add_epi32(x, _mm256_and_si256(seed, low32));
  for (const unsigned c : {0x6c50b47cu, 0xb82f1e52u, 0xc7afe638u, 0x8d22f6e6u}) {
    const __m256i constant = _mm256_set1_epi64x(static_cast<long long>(c));
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, constant));
  }
  const __m256i high = reverse32(x);
  // fast_owen_scramble::low_digits: the 32-bit finaliser of the high digits ⊕ the seed's top half.
  __m256i h = _mm256_xor_si256(high, _mm256_srli_epi64(seed, 32));
  h = _mm256_mullo_epi32(_mm256_xor_si256(h, _mm256_srli_epi32(h, 16)),
                         _mm256_set1_epi64x(0x85ebca6bLL));
  h = _mm256_mullo_epi32(_mm256_xor_si256(h, _mm256_srli_epi32(h, 13)),
                         _mm256_set1_epi64x(0xc2b2ae35LL));
  h = _mm256_xor_si256(h, _mm256_srli_epi32(h, 16));
  return _mm256_or_si256(_mm256_slli_epi64(high, 32), h);
}

[[gnu::always_inline]] inline __m256i shift_right(__m256i v, unsigned count) noexcept {
  return _mm256_srl_epi64(v, _mm_cvtsi32_si128(static_cast<int>(count)));
}

// owen_scramble::operator() on 4 lanes (depth ≤ 32), as the AVX-512 kernel's owen(): the prefix
// table, one hash per six levels of the tree (owen_scramble::flips), the tail.
[[gnu::always_inline]] inline __m256i owen(__m256i v, __m256i seed, __m256i base,
                                           const sobol_block_tables& t) noexcept {
  const auto word = [](std::uint64_t x) { return _mm256_set1_epi64x(static_cast<long long>(x)); };
  const auto prefix = [&](unsigned b) {  // owen_scramble::prefix(v, b)
    const __m256i length = word(std::uint64_t{1} << b);
    return b == 0 ? length : _mm256_or_si256(shift_right(v, 64 - b), length);
  };
  const unsigned depth = t.depth;
  const unsigned k = t.table_digits;
  __m256i out = v;
  if (k > 0) {
    const __m256i index = _mm256_add_epi64(base, shift_right(v, 64 - k));
    const auto* flips = reinterpret_cast<const long long*>(t.flips.data());
    out = _mm256_xor_si256(out, _mm256_i64gather_epi64(flips, index, 8));
  }
  // Digit b = b0 + d (d < 6) flips by bit node = 2^d − 1 + (digits b0 … b − 1) of the subtree's
  // hash (owen_scramble::flips).
  const __m256i one = word(1);
  __m256i tree = _mm256_setzero_si256(), digits = _mm256_setzero_si256();
  for (unsigned b = k; b < depth; ++b) {
    const unsigned d = b % owen_levels_per_hash;
    const unsigned b0 = b - d;
    if (d == 0 || b == k) {
      tree = mix64(_mm256_xor_si256(seed, prefix(b0)));
      // The subtree's six digits b0 … b0 + 5 as an integer, the first one highest.
      digits = _mm256_and_si256(shift_right(v, 58 - b0), word(63));
    }
    const __m256i node =
        _mm256_add_epi64(shift_right(digits, 6 - d), word((std::uint64_t{1} << d) - 1));
    const __m256i flip = _mm256_and_si256(_mm256_srlv_epi64(tree, node), one);
    out =
        _mm256_xor_si256(out, _mm256_sll_epi64(flip, _mm_cvtsi32_si128(static_cast<int>(63 - b))));
  }
  if (depth < 64) {
    const __m256i tail =
        mix64(_mm256_xor_si256(_mm256_xor_si256(seed, prefix(depth)), word(0xa0761d6478bd642fULL)));
    const __m256i low = word(~std::uint64_t{0} >> depth);
    out = _mm256_or_si256(_mm256_and_si256(low, tail), _mm256_andnot_si256(low, out));
  }
  return out;
}

// (v >> 11)·2^-53 exactly, without a 64-bit conversion: x = v >> 11 < 2^53 is hi·2^32 + lo. The
// double with exponent 31 and mantissa hi is 2^31 + hi·2^-21, the one with exponent −1 and
// mantissa lo is 0.5 + lo·2^-53 (both ulps fit: hi < 2^21, lo < 2^32). Subtracting 2^31 + 0.5
// from the first leaves hi·2^-21 − 0.5, a multiple of 2^-21 below 1 in magnitude: exact; adding
// the second gives x·2^-53, a double, so that sum is exact too.
[[gnu::always_inline]] inline __m256d to_unit(__m256i v) noexcept {
  const __m256i high = _mm256_or_si256(_mm256_srli_epi64(v, 43),
                                       _mm256_set1_epi64x(0x41e0000000000000LL));  // 2^31
  const __m256i low =
      _mm256_or_si256(_mm256_and_si256(_mm256_srli_epi64(v, 11), _mm256_set1_epi64x(0xffffffffLL)),
                      _mm256_set1_epi64x(0x3fe0000000000000LL));  // 0.5
  return _mm256_add_pd(_mm256_sub_pd(_mm256_castsi256_pd(high), _mm256_set1_pd(0x1.0p31 + 0.5)),
                       _mm256_castsi256_pd(low));
}

// Lanes [w0, w0 + 4·V) of `blocks` blocks from block q on; the last register keeps only the
// lanes set in `tail` (all ones per kept lane). Otherwise the AVX-512 kernel's run().
template <int V, sobol_scramble S>
void run(const sobol_block_tables& t, std::size_t w0, __m256i tail, std::uint64_t q,
         std::uint64_t blocks, double* out) noexcept {
  const auto load = [tail](const std::uint64_t* p, int v) {
    const auto* q64 = reinterpret_cast<const long long*>(p + 4 * v);
    return v + 1 == V ? _mm256_maskload_epi64(q64, tail)
                      : _mm256_loadu_si256(reinterpret_cast<const __m256i*>(q64));
  };
  const std::size_t words = t.words;
  const std::uint64_t* rows = t.rows.data() + w0;
  // y = C·g(B·q + r) ⊕ offset: the constant XOR folded into the start, since every step is an XOR.
  __m256i y[V], key[V], base[V];
  for (int v = 0; v < V; ++v) {
    y[v] = load(t.offset.data() + w0, v);
    key[v] = load(t.key.data() + w0, v);
    base[v] = S == sobol_scramble::owen ? load(t.flip_base.data() + w0, v) : _mm256_setzero_si256();
  }
  const std::uint64_t start = q << t.log2_block;
  for (std::uint64_t g = start ^ (start >> 1); g != 0; g &= g - 1) {
    const std::uint64_t* row = rows + std::countr_zero(g) * words;
    for (int v = 0; v < V; ++v) y[v] = _mm256_xor_si256(y[v], load(row, v));
  }
  const std::uint64_t* steps = (t.log2_block > 0 ? t.steps.data() : t.rows.data()) + w0;
  for (std::uint64_t b = 0;; ++b) {
    for (int v = 0; v < V; ++v) {
      __m256i w = y[v];
      if constexpr (S == sobol_scramble::fast_owen) w = fast_owen(w, key[v]);
      if constexpr (S == sobol_scramble::owen) w = owen(w, key[v], base[v], t);
      const __m256d x = to_unit(w);
      if (v + 1 == V) {
        _mm256_maskstore_pd(out + 4 * v, tail, x);
      } else {
        _mm256_storeu_pd(out + 4 * v, x);
      }
    }
    if (b + 1 == blocks) break;
    out += words;
    const std::uint64_t* row = steps + std::countr_zero(q + b + 1) * words;
    for (int v = 0; v < V; ++v) y[v] = _mm256_xor_si256(y[v], load(row, v));
  }
}

template <sobol_scramble S>
void run_all(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
             double* out) noexcept {
  for_each_avx2_slice(t.words, [&](auto registers, std::size_t w0, __m256i tail) {
    run<decltype(registers)::value, S>(t, w0, tail, q, blocks, out + w0);
  });
}

}  // namespace

void sobol_blocks_avx2(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
                       double* out) noexcept {
  if (blocks == 0) return;
  switch (t.scramble) {
    case sobol_scramble::xor_constant:
      return run_all<sobol_scramble::xor_constant>(t, q, blocks, out);
    case sobol_scramble::fast_owen:
      return run_all<sobol_scramble::fast_owen>(t, q, blocks, out);
    case sobol_scramble::owen:
      return run_all<sobol_scramble::owen>(t, q, blocks, out);
  }
}

}  // namespace quadmc::detail
#endif
