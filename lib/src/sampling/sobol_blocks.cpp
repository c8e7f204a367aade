// sobol_blocks' tables and the run-time choice of its kernel (sampling/sobol_blocks.hpp). The
// kernels compute the same integers as sobol_points' scalar Gray-code walk, so the choice changes
// only the speed (tests/sampling/sobol_points_test.cpp compares them bitwise).
#include "quadmc/sampling/sobol_blocks.hpp"

#include "quadmc/core/simd_level.hpp"
#include "quadmc/sampling/sobol_points.hpp"
#include "sobol_kernels.hpp"

#include <atomic>
#include <bit>
#include <numeric>

namespace quadmc::detail {

sobol_block_tables make_sobol_block_tables(std::span<const std::uint64_t> columns, std::size_t s,
                                           sobol_scramble scramble,
                                           std::span<const std::uint64_t> keys, unsigned depth) {
  sobol_block_tables t;
  t.s = s;
  const std::size_t block = s <= 8 ? 8 / std::gcd(s, std::size_t{8}) : 1;
  t.log2_block = static_cast<unsigned>(std::countr_zero(block));
  t.words = block * s;
  t.scramble = scramble;
  t.depth = depth;
  t.rows.resize(32 * t.words);
  t.offset.resize(t.words);
  t.key.resize(t.words);
  for (std::size_t r = 0; r < block; ++r) {
    const std::uint64_t gray = r ^ (r >> 1);
    for (std::size_t j = 0; j < s; ++j) {
      const std::uint64_t* c = columns.data() + 32 * j;
      const std::size_t lane = r * s + j;
      for (unsigned k = 0; k < 32; ++k) t.rows[k * t.words + lane] = c[k];
      std::uint64_t v = scramble == sobol_scramble::xor_constant ? keys[j] : 0;
      for (std::uint64_t g = gray; g != 0; g &= g - 1) v ^= c[std::countr_zero(g)];
      t.offset[lane] = v;
      t.key[lane] = scramble == sobol_scramble::xor_constant ? 0 : keys[j];
    }
  }
  if (scramble == sobol_scramble::owen) {
    // owen_scramble's own flips of the first k digits: 2^k·⌈k/6⌉ hashes per dimension, no more
    // than the points themselves cost when k = depth ≤ log2 N.
    unsigned k = depth < 12 ? depth : 12;
    while (k > 0 && (s << k) > (std::size_t{1} << 17)) --k;
    t.table_digits = k;
    t.flips.resize(s << k);
    for (std::size_t j = 0; j < s; ++j) {
      for (std::uint64_t p = 0; p < (std::uint64_t{1} << k); ++p) {
        // The prefix p as the top k digits (none for k = 0: one set, or many dimensions, whose
        // table is a single word of no flips, which the kernels do not read).
        const std::uint64_t digits = k == 0 ? 0 : p << (64 - k);
        t.flips[(j << k) + p] = owen_scramble::flips(keys[j], digits, 0, k);
      }
    }
    t.flip_base.resize(t.words);
    for (std::size_t w = 0; w < t.words; ++w) t.flip_base[w] = (w % s) << k;
  }
  if (t.log2_block > 0) {
    const unsigned b = t.log2_block;
    t.steps.resize((32 - b) * t.words);
    for (unsigned k = 0; k + b < 32; ++k) {
      for (std::size_t w = 0; w < t.words; ++w) {
        t.steps[k * t.words + w] = t.rows[(k + b) * t.words + w] ^ t.rows[(b - 1) * t.words + w];
      }
    }
  }
  return t;
}

namespace {
std::atomic<bool> gfni_allowed{true};
}  // namespace

void allow_sobol_gfni(bool allowed) noexcept {
  gfni_allowed.store(allowed, std::memory_order_relaxed);
}

bool sobol_blocks(const sobol_block_tables& t, std::uint64_t q, std::uint64_t blocks,
                  double* out) noexcept {
#if defined(__x86_64__)
  // vpmullq and vcvtuqq2pd are AVX-512DQ, which the avx512 level (AVX512F) does not imply.
  static const bool has_avx512dq = __builtin_cpu_supports("avx512dq");
  // The GFNI build also takes owen's tree six levels at a time with AVX512_VBMI and _BITALG, which
  // every CPU with GFNI and AVX-512 so far also has (Ice Lake, Zen 4).
  static const bool has_gfni =
      __builtin_cpu_supports("gfni") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vbmi") && __builtin_cpu_supports("avx512bitalg");
  if (active_simd_level() == simd_level::avx512 && has_avx512dq) {
    if (has_gfni && gfni_allowed.load(std::memory_order_relaxed)) {
      sobol_blocks_avx512_gfni(t, q, blocks, out);
    } else {
      sobol_blocks_avx512(t, q, blocks, out);
    }
    return true;
  }
  // AVX2 (or an avx512 level on a CPU without AVX512DQ): 4 lanes, the 64-bit multiply emulated.
  if (active_simd_level() >= simd_level::avx2) {
    sobol_blocks_avx2(t, q, blocks, out);
    return true;
  }
#else
  (void)t, (void)q, (void)blocks, (void)out;
#endif
  return false;
}

}  // namespace quadmc::detail
