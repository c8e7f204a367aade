// Tests of halton_points.hpp: the radical inverse against hand-computed values, the 1D
// stratification each randomization keeps, uniformity and unbiasedness, the dimension range and
// bitwise reproducibility for any batch order.
#include "quadmc/sampling/halton_points.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <vector>

namespace quadmc {
namespace {

static_assert(point_set<halton_points<unrandomized_radical_inverse>>);
static_assert(point_set<halton_points<random_digit_permutation>>);
static_assert(point_set<halton_points<nested_digit_scramble>>);

TEST(HaltonBases, AreTheFirstTenThousandPrimes) {
  const auto b = halton_bases();
  ASSERT_EQ(b.size(), 10000u);
  EXPECT_EQ(b[0], 2u);
  EXPECT_EQ(b[1], 3u);
  EXPECT_EQ(b[9], 29u);
  EXPECT_EQ(b[999], 7919u);     // the 1000th prime
  EXPECT_EQ(b[9999], 104729u);  // the 10 000th prime
}

// φ_2(6) = 0.011₂ = 3/8, φ_3(5) = 0.21₃ = 7/9, φ_5(7) = 0.21₅ = 11/25; point 0 is the origin.
TEST(HaltonPoints, AreRadicalInversesInPrimeBases) {
  const halton_points<unrandomized_radical_inverse> p(3, 8, 0, 0);
  std::vector<double> x(8 * 3);
  p.generate(0, x);
  EXPECT_EQ(x[0], 0.0);
  EXPECT_EQ(x[1], 0.0);
  EXPECT_EQ(x[2], 0.0);
  EXPECT_EQ(x[6 * 3 + 0], 3.0 / 8.0);
  EXPECT_NEAR(x[5 * 3 + 1], 7.0 / 9.0, 1e-15);
  EXPECT_NEAR(x[7 * 3 + 2], 11.0 / 25.0, 1e-15);
}

template <class R>
class HaltonRandomized : public ::testing::Test {};
using all_halton =
    ::testing::Types<unrandomized_radical_inverse, random_digit_permutation, nested_digit_scramble>;
TYPED_TEST_SUITE(HaltonRandomized, all_halton);

// The first b^k points of dimension j hold exactly one point in each interval of width b^−k:
// the radical inverse puts the k last digits of i first, and a digit permutation (nested or
// not) is a bijection of each digit given the ones before it.
TYPED_TEST(HaltonRandomized, FirstBToTheKPointsStratifyEachAxis) {
  const std::size_t s = 5;  // bases 2, 3, 5, 7, 11
  const auto bases = halton_bases();
  for (std::uint64_t seed : {1u, 2u}) {
    const halton_points<TypeParam> p(s, 3000, seed, 4);
    std::vector<double> x(3000 * s);
    p.generate(0, x);
    for (std::size_t j = 0; j < s; ++j) {
      const std::uint64_t b = bases[j];
      std::uint64_t n = b;
      while (n * b <= 3000) n *= b;
      std::vector<int> count(n, 0);
      // Unrandomized points are the intervals' left ends k/n, which the rounded x·n can put a few
      // ulp below k: the nudge of 1e-9 (against an interval of width 1 in units of x·n) keeps
      // them in their own interval.
      for (std::uint64_t i = 0; i < n; ++i) {
        ++count[static_cast<std::size_t>(x[i * s + j] * static_cast<double>(n) + 1e-9)];
      }
      EXPECT_TRUE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }))
          << "base " << b << ", " << n << " points";
    }
  }
}

TYPED_TEST(HaltonRandomized, BatchOrderDoesNotChangeAnyBit) {
  const std::size_t s = 6;
  const std::uint64_t n = 999;
  const halton_points<TypeParam> p(s, n, 5, 6);
  std::vector<double> whole(n * s), pieces(n * s);
  p.generate(0, whole);
  for (std::uint64_t end = n; end > 0;) {
    const std::uint64_t size = std::min<std::uint64_t>(end, 1 + end % 29);
    p.generate(end - size, std::span<double>(pieces).subspan((end - size) * s, size * s));
    end -= size;
  }
  EXPECT_EQ(std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(double)), 0);
  for (double v : whole) {
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
  }
}

template <class R>
class HaltonScrambled : public ::testing::Test {};
using scrambled_halton = ::testing::Types<random_digit_permutation, nested_digit_scramble>;
TYPED_TEST_SUITE(HaltonScrambled, scrambled_halton);

// Each randomized coordinate is uniform: over 4096 randomizations, point 11's coordinate in
// bases 2 and 7 falls into each of 16 bins within 4.9 binomial standard deviations of 256
// (a false alarm of 1e-6 per bin, 3.2e-5 for the 32).
TYPED_TEST(HaltonScrambled, EachRandomizedCoordinateIsUniform) {
  for (const std::size_t j : {0u, 3u}) {
    std::vector<int> bins(16, 0);
    std::vector<double> x(4);
    for (std::uint64_t r = 0; r < 4096; ++r) {
      const halton_points<TypeParam> p(4, 20, 8, r);
      p.generate(11, x);
      ++bins[static_cast<std::size_t>(x[j] * 16)];
    }
    const double sd = std::sqrt(4096.0 * (1.0 / 16) * (15.0 / 16));
    for (int b = 0; b < 16; ++b)
      EXPECT_NEAR(bins[b], 256.0, 4.9 * sd) << "dim " << j << " bin " << b;
  }
}

// The mean over R = 400 randomizations of a 100-point estimate of ∫ Π 3x_j² = 1 over [0,1]^3 is
// within t(1 − 5e-5, R − 1)·s_R/√R of 1 (a false alarm of 1e-4).
TYPED_TEST(HaltonScrambled, ReplicateMeanIsWithinItsStandardError) {
  constexpr int R = 400;
  std::vector<double> values, x(100 * 3);
  for (int r = 0; r < R; ++r) {
    const halton_points<TypeParam> p(3, 100, 21, static_cast<std::uint64_t>(r));
    p.generate(0, x);
    double sum = 0.0;
    for (int i = 0; i < 100; ++i) {
      sum += 27.0 * x[3 * i] * x[3 * i] * x[3 * i + 1] * x[3 * i + 1] * x[3 * i + 2] * x[3 * i + 2];
    }
    values.push_back(sum / 100.0);
  }
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / R;
  double m2 = 0.0;
  for (double v : values) m2 += (v - mean) * (v - mean);
  const double se = std::sqrt(m2 / (R - 1) / R);
  const double t = boost::math::quantile(boost::math::students_t(R - 1), 1.0 - 5e-5);
  EXPECT_LE(std::abs(mean - 1.0), t * se);
  EXPECT_GT(se, 0.0);
}

// The permutation randomizer walks only the digits of i and starts from a precomputed sum of the
// permuted zero digits above them: bitwise the full walk over every digit position (kept as
// reference()), for the first 2^14 points, indices with every digit count up to the largest N
// allows, and bases 2 … 547 (s = 100).
TEST(HaltonPoints, PermutationTailTableEqualsTheFullDigitWalkBitwise) {
  const std::size_t s = 100;
  const std::uint64_t n = (std::uint64_t{1} << 62) / s;
  const halton_points<random_digit_permutation> points(s, n, 2026, 18);
  std::vector<std::uint64_t> indices;
  for (std::uint64_t i = 0; i < (1u << 14); ++i) indices.push_back(i);
  for (std::uint64_t i = 1; i < n / 3; i = i * 3 + 1) indices.push_back(i);
  indices.push_back(n - 1);
  std::vector<double> x(s);
  for (const std::uint64_t i : indices) {
    points.generate(i, x);
    for (std::size_t j = 0; j < s; ++j) {
      const double expected =
          points.randomizer().reference(i, j, points.base(j), points.inverse_base(j));
      ASSERT_EQ(std::memcmp(&x[j], &expected, sizeof(double)), 0)
          << "point " << i << ", dimension " << j << ": " << x[j] << " vs " << expected;
    }
  }
}

TEST(HaltonPoints, CoverAThousandDimensionsAndNoMore) {
  const halton_points<nested_digit_scramble> p(1000, 16, 1, 1);
  std::vector<double> x(16 * 1000);
  p.generate(0, x);
  for (double v : x) {
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
  }
  EXPECT_NO_THROW(halton_points<unrandomized_radical_inverse>(10000, 2, 0, 0));
  EXPECT_THROW(halton_points<unrandomized_radical_inverse>(10001, 2, 0, 0), invalid_argument);
}

}  // namespace
}  // namespace quadmc
