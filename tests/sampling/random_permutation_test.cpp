#include "quadmc/sampling/random_permutation.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/chi_squared.hpp>

#include <cstdint>
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
