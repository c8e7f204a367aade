// detail::weighted_pairwise_sum (rules/weighted_sum.hpp): pairwise_sum's recursion over leaves of
// 128 products, the portable leaf (the reference the vector leaf is tested against) and the
// run-time choice of leaf (core/simd_level.hpp).
#include "weighted_row_sum_kernels.hpp"

#include "quadmc/core/simd_level.hpp"
#include "quadmc/rules/weighted_sum.hpp"

namespace quadmc::detail {

double weighted_leaf_sum_scalar(const double* w, const double* y, std::size_t n) noexcept {
  double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    for (std::size_t k = 0; k < 8; ++k) acc[k] += w[i + k] * y[i + k];
  }
  for (std::size_t k = 0; k < n % 8; ++k) acc[k] += w[i + k] * y[i + k];
  return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

namespace {

using leaf_sum = double (*)(const double*, const double*, std::size_t) noexcept;

// The split of pairwise_sum: halves on a multiple of the leaf, so every leaf but the last is full.
double pairwise(leaf_sum leaf, const double* w, const double* y, std::size_t n) noexcept {
  if (n <= weighted_sum_leaf) return leaf(w, y, n);
  const std::size_t half =
      ((n / 2 + weighted_sum_leaf - 1) / weighted_sum_leaf) * weighted_sum_leaf;
  return pairwise(leaf, w, y, half) + pairwise(leaf, w + half, y + half, n - half);
}

}  // namespace

double weighted_pairwise_sum(std::span<const double> w, std::span<const double> y) noexcept {
  leaf_sum leaf = weighted_leaf_sum_scalar;
#if defined(__x86_64__)
  switch (active_simd_level()) {
    case simd_level::avx512:
    case simd_level::avx2:
      leaf = weighted_leaf_sum_avx2;
      break;
    default:
      break;
  }
#endif
  return pairwise(leaf, w.data(), y.data(), w.size());
}

}  // namespace quadmc::detail
