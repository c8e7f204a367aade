// random_permutation::apply's kernel: the scalar reference and the run-time choice among the
// vector kernels (permutation_kernels.hpp). Every kernel computes the same integer function, so
// the choice changes only the speed (tests/sampling/random_permutation_test.cpp checks each
// level against operator()). Also the run-time choice of Latin hypercube's fused kernel
// (tests/sampling/latin_hypercube_points_test.cpp checks each level against the per-axis loop).
#include "permutation_kernels.hpp"

#include "quadmc/core/simd_level.hpp"

namespace quadmc::detail {

void permutation_blocks_scalar(const permutation_schedule& schedule, std::uint64_t first,
                               std::size_t count, std::uint64_t* out) noexcept {
  // A copy: out and the keys are both uint64_t, so without it every store to out would force the
  // keys to be reloaded. The bijection over the whole run first (independent iterations without a
  // branch, which the CPU overlaps), then the cycle walk for the values in [n, 2^w).
  const permutation_schedule p = schedule;
#pragma GCC unroll 4
  for (std::size_t k = 0; k < count; ++k) out[k] = p.bijection(first + k);
  for (std::size_t k = 0; k < count; ++k) {
    while (out[k] >= p.n) out[k] = p.bijection(out[k]);
  }
}

void permutation_blocks(const permutation_schedule& p, std::uint64_t first, std::size_t count,
                        std::uint64_t* out) noexcept {
#if defined(__x86_64__)
  // vpmullq is AVX-512DQ, which the avx512 level (AVX512F) does not imply: checked once here.
  static const bool has_avx512dq = __builtin_cpu_supports("avx512dq");
  switch (active_simd_level()) {
    case simd_level::avx512:
      if (has_avx512dq) return permutation_blocks_avx512(p, first, count, out);
      return permutation_blocks_avx2(p, first, count, out);
    case simd_level::avx2:
      return permutation_blocks_avx2(p, first, count, out);
    default:
      break;
  }
#endif
  permutation_blocks_scalar(p, first, count, out);
}

bool latin_hypercube_place(const latin_hypercube_lanes& lanes, std::uint64_t first,
                           std::size_t count, double* x) noexcept {
#if defined(__x86_64__)
  static const bool has_avx512dq = __builtin_cpu_supports("avx512dq");
  const bool narrow = lanes.n <= (std::uint64_t{1} << 31);
  switch (active_simd_level()) {
    case simd_level::avx512:
      if (has_avx512dq) {
        latin_hypercube_place_avx512(lanes, first, count, x);
        return true;
      }
      if (!narrow) return false;
      latin_hypercube_place_avx2(lanes, first, count, x);
      return true;
    case simd_level::avx2:
      if (!narrow) return false;
      latin_hypercube_place_avx2(lanes, first, count, x);
      return true;
    default:
      break;
  }
#endif
  (void)lanes;
  (void)first;
  (void)count;
  (void)x;
  return false;
}

}  // namespace quadmc::detail
