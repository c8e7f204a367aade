#include "quadmc/sampling/random_permutation.hpp"

#include "quadmc/core/simd_level.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/chi_squared.hpp>

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace {

using quadmc::random_permutation;

// A permutation of [0, n): every value hit exactly once.
void expect_bijection(std::uint64_t n, std::uint64_t key) {
  const random_permutation p(n, key);
  std::vector<char> seen(n, 0);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t v = p(i);
    ASSERT_LT(v, n) << "n = " << n << ", key = " << key << ", i = " << i;
    ASSERT_EQ(seen[v], 0) << "value " << v << " hit twice, n = " << n << ", key = " << key;
    seen[v] = 1;
  }
}

TEST(RandomPermutation, IsABijectionForEverySmallSize) {
  for (std::uint64_t n = 1; n <= 300; ++n) expect_bijection(n, n * 7919);
}

TEST(RandomPermutation, IsABijectionForLargeAndPowerOfTwoSizes) {
  for (std::uint64_t n : {1024ULL, 1025ULL, 65535ULL, 1000003ULL}) expect_bijection(n, 42);
}

// apply() runs a vector kernel chosen at run time (AVX-512DQ, AVX2 with an emulated 64-bit
// multiply, or scalar): at every level this CPU has, each element must equal operator()'s, for
// sizes that walk (n just above a power of two), that never walk (powers of two), n = 1, the
// largest n, and runs whose length is not a multiple of the lane count.
TEST(RandomPermutation, ApplyEqualsElementByElementAtEverySimdLevel) {
  const quadmc::simd_level saved = quadmc::active_simd_level();
  constexpr std::uint64_t largest = std::uint64_t{1} << 62;
  for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
    quadmc::set_simd_level(level);
    for (const std::uint64_t n : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3},
                                  std::uint64_t{1000}, std::uint64_t{1025}, std::uint64_t{65536},
                                  std::uint64_t{1000003}, (std::uint64_t{1} << 40) + 1, largest}) {
      const random_permutation p(n, n ^ 0x5bd1e995);
      for (const std::uint64_t first : {std::uint64_t{0}, n / 3, n > 70 ? n - 70 : 0}) {
        std::vector<std::uint64_t> out(static_cast<std::size_t>(std::min<std::uint64_t>(
            67, n - first)));  // 67 = 8·8 + 3: full registers of 4 and 8 lanes and a tail
        p.apply(first, out);
        for (std::size_t k = 0; k < out.size(); ++k) {
          ASSERT_EQ(out[k], p(first + k))
              << "level " << quadmc::to_string(level) << ", n = " << n << ", element " << first + k;
        }
      }
    }
  }
  quadmc::set_simd_level(saved);
}

// Over many keys, element i of a permutation of [0, 8) lands on each j equally often: a chi-square
// test of the 8 × 8 table of (i, π(i)) counts, (8−1)² = 49 degrees of freedom (row and column
// sums are fixed). False-alarm probability α = 1e-4.
TEST(RandomPermutation, ElementsAreUniformOverKeys) {
  constexpr std::uint64_t n = 8;
  constexpr std::uint64_t keys = 16000;
  std::vector<double> counts(n * n, 0.0);
  for (std::uint64_t key = 0; key < keys; ++key) {
    const random_permutation p(n, key);
    for (std::uint64_t i = 0; i < n; ++i) counts[i * n + p(i)] += 1.0;
  }
  const double expected = static_cast<double>(keys) / static_cast<double>(n);
  double statistic = 0.0;
  for (double c : counts) statistic += (c - expected) * (c - expected) / expected;
  const double critical = boost::math::quantile(
      boost::math::complement(boost::math::chi_squared(double((n - 1) * (n - 1))), 1e-4));
  EXPECT_LT(statistic, critical);
}

TEST(RandomPermutation, DifferentKeysGiveDifferentPermutations) {
  const random_permutation a(1000, 1), b(1000, 2);
  int same = 0;
  for (std::uint64_t i = 0; i < 1000; ++i) same += a(i) == b(i);
  // Two independent random permutations agree in Poisson(1) places; P(≥ 10) < 1.2e-7.
  EXPECT_LT(same, 10);
}

TEST(RandomPermutation, RejectsAnEmptyDomain) {
  EXPECT_THROW(random_permutation(0, 1), quadmc::invalid_argument);
}

}  // namespace
