// The AVX2 lattice kernel: the AVX-512 kernel's walk (rank1_lattice_blocks_avx512.cpp, the
// algebra in sampling/rank1_lattice_blocks.hpp) on 4 coordinates per register, for CPUs with AVX2
// but no AVX-512DQ. Compiled with -mavx2 (lib/CMakeLists.txt), called only after the run-time
// check in rank1_lattice_blocks.cpp.
//
// AVX2 has no 64-bit multiply and no 64-bit integer conversion: the start k = (first + r)·z mod N
// of each lane is computed once per call by the scalar code's integer product, and k < N ≤ 2^20
// converts exactly as (2^52 + k) − 2^52, the double whose mantissa is k (exponent bits 0x433)
// less 2^52. The doubles are then the scalar loop's, operation by operation
// (tests/sampling/rank1_lattice_points_test.cpp runs every simd level the CPU offers).
#if defined(__x86_64__)
#include "avx2_lane_slices.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "rank1_lattice_kernels.hpp"

#include <immintrin.h>

#include <algorithm>

namespace quadmc::detail {
namespace {

template <int V, lattice_periodization P>
void run(const rank1_lattice_block_tables& t, std::size_t w0, __m256i tail, std::uint64_t first,
         std::uint64_t blocks, double* out) noexcept {
  __m256i k[V], step[V];
  __m256d shift[V];
  for (int v = 0; v < V; ++v) {
    // Once per call: every register loaded under a mask, the last one's keeping its own lanes.
    const __m256i m = v + 1 == V ? tail : _mm256_set1_epi64x(-1);
    const std::size_t w = w0 + 4 * static_cast<std::size_t>(v);
    // The low 64 bits of the product suffice (N divides 2^64). Lanes past the tail stay 0.
    alignas(32) std::uint64_t start[4] = {};
    const std::size_t lanes = std::min<std::size_t>(4, t.words - w);
    for (std::size_t l = 0; l < lanes; ++l) {
      start[l] = ((first + t.point[w + l]) * t.z[w + l]) & t.mask;
    }
    k[v] = _mm256_load_si256(reinterpret_cast<const __m256i*>(start));
    step[v] = _mm256_maskload_epi64(reinterpret_cast<const long long*>(t.step.data() + w), m);
    shift[v] = _mm256_maskload_pd(t.shift.data() + w, m);
  }
  const __m256i mask = _mm256_set1_epi64x(static_cast<long long>(t.mask));
  const __m256i exponent = _mm256_set1_epi64x(0x4330000000000000LL);
  const __m256d two52 = _mm256_set1_pd(0x1.0p52);
  const __m256d inv_n = _mm256_set1_pd(t.inv_n);
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d two = _mm256_set1_pd(2.0);
  const __m256d below_one = _mm256_set1_pd(largest_below_one);
  const __m256d sign = _mm256_set1_pd(-0.0);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    for (int v = 0; v < V; ++v) {
      const __m256d kd = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(k[v], exponent)), two52);
      __m256d x = _mm256_add_pd(_mm256_mul_pd(kd, inv_n), shift[v]);
      // x ≥ 1 ? x − 1 : x, as x − (x ≥ 1 ? 1 : 0) (x − 0 is x: x ≥ 0 here).
      x = _mm256_sub_pd(x, _mm256_and_pd(_mm256_cmp_pd(x, one, _CMP_GE_OQ), one));
      if constexpr (P == lattice_periodization::baker) {
        // min(1 − |2x − 1|, largest_below_one), as baker_transform computes it.
        const __m256d centred = _mm256_sub_pd(_mm256_mul_pd(two, x), one);
        x = _mm256_min_pd(_mm256_sub_pd(one, _mm256_andnot_pd(sign, centred)), below_one);
      }
      if (v + 1 == V) {
        _mm256_maskstore_pd(out + 4 * v, tail, x);
      } else {
        _mm256_storeu_pd(out + 4 * v, x);
      }
      k[v] = _mm256_and_si256(_mm256_add_epi64(k[v], step[v]), mask);
    }
    out += t.words;
  }
}

template <lattice_periodization P>
void run_all(const rank1_lattice_block_tables& t, std::uint64_t first, std::uint64_t blocks,
             double* out) noexcept {
  for_each_avx2_slice(t.words, [&](auto registers, std::size_t w0, __m256i tail) {
    run<decltype(registers)::value, P>(t, w0, tail, first, blocks, out + w0);
  });
}

}  // namespace

void rank1_lattice_blocks_avx2(const rank1_lattice_block_tables& t, std::uint64_t first,
                               std::uint64_t blocks, double* out) noexcept {
  if (t.periodization == lattice_periodization::baker) {
    run_all<lattice_periodization::baker>(t, first, blocks, out);
  } else {
    run_all<lattice_periodization::none>(t, first, blocks, out);
  }
}

}  // namespace quadmc::detail
#endif
