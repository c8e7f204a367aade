// detail::weighted_pairwise_sum (rules/weighted_sum.hpp): at every SIMD level this CPU offers,
// bitwise pairwise_sum (core/summation.hpp) of the rounded products w_i·y_i, for sizes around
// every boundary of its leaves (8 accumulators, leaves of 128, the split of a batch of 256).
#include "quadmc/core/simd_level.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/rules/weighted_sum.hpp"
#include "support/simd_level_guard.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

using quadmc::test_support::simd_level_guard;

// Values of both signs over ten binades with full 53-bit mantissas, from a fixed 64-bit LCG
// (Knuth's MMIX constants): their products are inexact, so a fused multiply-add or a changed
// order would change the last bits of the sum.
std::vector<double> mixed_values(std::size_t n, std::uint64_t seed) {
  std::vector<double> v(n);
  std::uint64_t state = seed;
  for (double& x : v) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double unit = static_cast<double>(state >> 11) * 0x1.0p-53;
    const double sign = (state >> 10 & 1U) != 0 ? -1.0 : 1.0;
    x = sign * std::ldexp(1.0 + unit, static_cast<int>(state >> 4 & 7U) - 3);
  }
  return v;
}

TEST(WeightedRowSum, EveryLevelEqualsPairwiseSumOfTheProducts) {
  const simd_level_guard guard;
  const std::size_t sizes[] = {0,   1,   3,   7,   8,   9,   15,  16,  17,
                               100, 127, 128, 129, 200, 255, 256, 257, 1000};
  for (const std::size_t n : sizes) {
    const std::vector<double> w = mixed_values(n, 2 * n + 1);
    const std::vector<double> y = mixed_values(n, 3 * n + 7);
    std::vector<double> products(n);
    for (std::size_t i = 0; i < n; ++i) products[i] = w[i] * y[i];
    const double expected = pairwise_sum(products);
    for (const simd_level level : available_simd_levels()) {
      set_simd_level(level);
      const double got = detail::weighted_pairwise_sum(w, y);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(expected))
          << "n " << n << ", level " << to_string(level) << ": " << got << " vs " << expected;
    }
  }
}

}  // namespace
