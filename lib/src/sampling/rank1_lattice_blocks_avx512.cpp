// The AVX-512 lattice kernel: 8 coordinates per register, up to 8 registers (64 coordinates) held
// across a run of blocks (sampling/rank1_lattice_blocks.hpp), the scalar loop's operations lane
// by lane. Compiled with -mavx512f -mavx512dq (lib/CMakeLists.txt) for vcvtqq2pd; called only
// when the CPU has both (rank1_lattice_blocks.cpp).
#if defined(__x86_64__)
#include "quadmc/sampling/point_set.hpp"
#include "rank1_lattice_kernels.hpp"

#include <immintrin.h>

#include <algorithm>

namespace quadmc::detail {
namespace {

template <int V, lattice_periodization P>
void run(const rank1_lattice_block_tables& t, std::size_t w0, __mmask8 tail, std::uint64_t first,
         std::uint64_t blocks, double* out) noexcept {
  __m512i k[V], step[V];
  __m512d shift[V];
  const __m512i mask = _mm512_set1_epi64(static_cast<long long>(t.mask));
  const __m512i index = _mm512_set1_epi64(static_cast<long long>(first));
  for (int v = 0; v < V; ++v) {
    const __mmask8 m = v + 1 == V ? tail : __mmask8{0xff};
    const std::size_t w = w0 + 8 * static_cast<std::size_t>(v);
    // k = (first + r)·z mod N: the low 64 bits of the product suffice (N divides 2^64).
    const __m512i point = _mm512_add_epi64(index, _mm512_maskz_loadu_epi64(m, t.point.data() + w));
    k[v] = _mm512_and_si512(_mm512_mullo_epi64(point, _mm512_maskz_loadu_epi64(m, t.z.data() + w)),
                            mask);
    step[v] = _mm512_maskz_loadu_epi64(m, t.step.data() + w);
    shift[v] = _mm512_maskz_loadu_pd(m, t.shift.data() + w);
  }
  const __m512d inv_n = _mm512_set1_pd(t.inv_n);
  const __m512d one = _mm512_set1_pd(1.0);
  const __m512d two = _mm512_set1_pd(2.0);
  const __m512d below_one = _mm512_set1_pd(largest_below_one);
  const __m512d sign = _mm512_set1_pd(-0.0);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    for (int v = 0; v < V; ++v) {
      __m512d x = _mm512_add_pd(_mm512_mul_pd(_mm512_cvtepi64_pd(k[v]), inv_n), shift[v]);
      x = _mm512_mask_sub_pd(x, _mm512_cmp_pd_mask(x, one, _CMP_GE_OQ), x, one);
      if constexpr (P == lattice_periodization::baker) {
        // min(1 − |2x − 1|, largest_below_one), as baker_transform computes it.
        const __m512d centred = _mm512_sub_pd(_mm512_mul_pd(two, x), one);
        x = _mm512_min_pd(_mm512_sub_pd(one, _mm512_andnot_pd(sign, centred)), below_one);
      }
      if (v + 1 == V) {
        _mm512_mask_storeu_pd(out + 8 * v, tail, x);
      } else {
        _mm512_storeu_pd(out + 8 * v, x);
      }
      k[v] = _mm512_and_si512(_mm512_add_epi64(k[v], step[v]), mask);
    }
    out += t.words;
  }
}

template <lattice_periodization P>
void run_lanes(const rank1_lattice_block_tables& t, std::size_t w0, std::size_t lanes,
               std::uint64_t first, std::uint64_t blocks, double* out) noexcept {
  const int registers = static_cast<int>((lanes + 7) / 8);
  const auto tail = static_cast<__mmask8>(0xffu >> (8 * registers - lanes));
  switch (registers) {
    case 1:
      return run<1, P>(t, w0, tail, first, blocks, out);
    case 2:
      return run<2, P>(t, w0, tail, first, blocks, out);
    case 3:
      return run<3, P>(t, w0, tail, first, blocks, out);
    case 4:
      return run<4, P>(t, w0, tail, first, blocks, out);
    case 5:
      return run<5, P>(t, w0, tail, first, blocks, out);
    case 6:
      return run<6, P>(t, w0, tail, first, blocks, out);
    case 7:
      return run<7, P>(t, w0, tail, first, blocks, out);
    default:
      return run<8, P>(t, w0, tail, first, blocks, out);
  }
}

template <lattice_periodization P>
void run_all(const rank1_lattice_block_tables& t, std::uint64_t first, std::uint64_t blocks,
             double* out) noexcept {
  for (std::size_t w0 = 0; w0 < t.words; w0 += 64) {
    run_lanes<P>(t, w0, std::min<std::size_t>(64, t.words - w0), first, blocks, out + w0);
  }
}

}  // namespace

void rank1_lattice_blocks_avx512(const rank1_lattice_block_tables& t, std::uint64_t first,
                                 std::uint64_t blocks, double* out) noexcept {
  if (t.periodization == lattice_periodization::baker) {
    run_all<lattice_periodization::baker>(t, first, blocks, out);
  } else {
    run_all<lattice_periodization::none>(t, first, blocks, out);
  }
}

}  // namespace quadmc::detail
#endif
