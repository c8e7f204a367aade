// The per-instruction-set leaves of detail::weighted_pairwise_sum (rules/weighted_sum.hpp).
// Private to lib/src/rules. Each kernel file calls no inline function of a shared header (the ODR
// hazard of per-file -m flags, core/philox_lanes.hpp).
#pragma once

#include <cstddef>

namespace quadmc::detail {

// Σ w_i·y_i over i < n ≤ weighted_sum_leaf, as pairwise_sum's leaf (core/summation.hpp) sums
// x_i = w_i·y_i: eight accumulators acc[i mod 8] in index order, then ((a0 + a1) + (a2 + a3)) +
// ((a4 + a5) + (a6 + a7)).
inline constexpr std::size_t weighted_sum_leaf = 128;
double weighted_leaf_sum_scalar(const double* w, const double* y, std::size_t n) noexcept;
#if defined(__x86_64__)
double weighted_leaf_sum_avx2(const double* w, const double* y, std::size_t n) noexcept;
#endif

}  // namespace quadmc::detail
