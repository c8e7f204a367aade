// Tests for core/welford.hpp: the mergeable running mean/variance behind every Monte Carlo
// estimator.
//
// References are exact: either closed forms for data built to have them, or a two-pass
// mean/variance in cpp_bin_float_50 (50 digits) over the very doubles fed to the accumulator.
//
// Why the merge test does not demand "merged equals one pass to 4 ulp": one-pass Welford is not
// correctly rounded; its running mean and M2 drift by O(√n) roundings. For the data below
// (n = 3000, x = 3 + 2v², v uniform) one pass is off by up to 32 ulp in mean and 30 ulp in
// variance over 200 seeds, chunked-and-merged by at most 9 ulp, so the two can differ by 34 ulp.
// Both are therefore held to the exact values, with the tolerance of the probabilistic rounding
// model of Higham & Mary ("A new approach to probabilistic rounding error analysis", SIAM J. Sci.
// Comput. 41(5), 2019, Thm 2.4): relative error ≤ λ·√n·u, which fails with probability at most
// 2n·exp(−λ²(1−u)²/2); λ = 7 and n = 3000 give ≤ 1.4e-7. That is ≈ 4.3e-14 relative (~350 ulp
// at 3.6): loose next to the measured 32 ulp, but a wrong merge weight errs by O(1) and a single
// precision slip by 1e-7.
#include "quadmc/core/welford.hpp"

#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "quadmc/core/rng.hpp"
#include "support/floating_point.hpp"

namespace {

using mp = boost::multiprecision::cpp_bin_float_50;

using quadmc::test_support::unit_roundoff;  // u = 2^-53

struct exact_moments {
  double mean;
  double variance;
};

// Two-pass mean and unbiased variance in 50 digits, rounded once to double.
exact_moments two_pass(const std::vector<double>& x) {
  mp sum = 0;
  for (const double v : x) sum += v;
  const mp mean = sum / x.size();
  mp m2 = 0;
  for (const double v : x) m2 += (mp(v) - mean) * (mp(v) - mean);
  return {static_cast<double>(mean), static_cast<double>(m2 / (x.size() - 1))};
}

double relative_error(double value, double exact) {
  return std::abs(value - exact) / exact;
}

TEST(Welford, MergedUnevenChunksMatchOnePassAndTheExactMoments) {
  constexpr std::uint64_t seed = 20240611;
  const quadmc::random_stream rng(seed, quadmc::stream_id({1}));
  std::vector<double> x(3000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double v = rng.uniform(i);
    x[i] = 3 + 2 * v * v;  // skewed, mean ≈ 3.67, so mean and variance both carry rounding
  }
  const exact_moments exact = two_pass(x);

  quadmc::welford one_pass;
  for (const double v : x) one_pass.add(v);

  // Uneven chunks, one of them empty, merged in order; sizes sum to 3000.
  const std::size_t sizes[] = {1, 7, 500, 13, 0, 999, 2, 1000, 478};
  quadmc::welford merged;
  std::size_t begin = 0;
  for (const std::size_t size : sizes) {
    quadmc::welford chunk;
    for (std::size_t i = begin; i < begin + size; ++i) chunk.add(x[i]);
    merged.merge(chunk);
    begin += size;
  }
  ASSERT_EQ(begin, x.size());
  ASSERT_EQ(merged.count(), x.size());
  ASSERT_EQ(one_pass.count(), x.size());

  const double tolerance =
      7 * std::sqrt(static_cast<double>(x.size())) * unit_roundoff;  // see file comment
  EXPECT_LE(relative_error(one_pass.mean(), exact.mean), tolerance) << "one pass, seed " << seed;
  EXPECT_LE(relative_error(one_pass.variance(), exact.variance), tolerance)
      << "one pass, seed " << seed;
  EXPECT_LE(relative_error(merged.mean(), exact.mean), tolerance) << "merged, seed " << seed;
  EXPECT_LE(relative_error(merged.variance(), exact.variance), tolerance)
      << "merged, seed " << seed;
  EXPECT_LE(relative_error(merged.mean(), one_pass.mean()), 2 * tolerance) << "seed " << seed;
  EXPECT_LE(relative_error(merged.variance(), one_pass.variance()), 2 * tolerance)
      << "seed " << seed;
  EXPECT_DOUBLE_EQ(merged.m2(), merged.variance() * static_cast<double>(x.size() - 1));
}

TEST(Welford, MergeOfSmallIntegersIsExact) {
  // {1, 2, 3} ∪ {4, 5}: mean 3, M2 = 4+1+0+1+4 = 10, variance 10/4 = 2.5, all within 4 ulp
  // (the merge multiplies by n_b/n = 0.4 and n_a·n_b/n = 1.2, which are not exact doubles).
  quadmc::welford a;
  for (const double v : {1.0, 2.0, 3.0}) a.add(v);
  quadmc::welford b;
  for (const double v : {4.0, 5.0}) b.add(v);
  a.merge(b);
  EXPECT_EQ(a.count(), 5u);
  EXPECT_DOUBLE_EQ(a.mean(), 3.0);
  EXPECT_DOUBLE_EQ(a.m2(), 10.0);
  EXPECT_DOUBLE_EQ(a.variance(), 2.5);
  EXPECT_DOUBLE_EQ(a.std_error(), std::sqrt(2.5 / 5));
}

TEST(Welford, HugeMeanTinyVarianceDefeatsTheTextbookFormulaButNotWelford) {
  // x_i = 1e9 + h·((1531·i) mod n), h = 2^-10, n = 4096: a permutation of an arithmetic
  // progression, every value exact in double (1e9 < 2^30, so the spacing there is 2^-23 ≤ h).
  // Exact: mean = 1e9 + h(n−1)/2, unbiased variance = h²·n(n+1)/12 ≈ 1.33.
  constexpr std::uint64_t n = 4096;
  constexpr double h = 0x1p-10;
  std::vector<double> x(n);
  for (std::uint64_t i = 0; i < n; ++i) x[i] = 1e9 + h * static_cast<double>((1531 * i) % n);
  const double exact_mean = 1e9 + h * (n - 1) / 2;
  const double exact_variance = h * h * static_cast<double>(n) * (n + 1) / 12;

  quadmc::welford w;
  double sum = 0;
  double sum_of_squares = 0;
  for (const double v : x) {
    w.add(v);
    sum += v;
    sum_of_squares += v * v;
  }
  const double textbook = (sum_of_squares - sum * sum / n) / (n - 1);

  // Condition number of the variance κ ≈ |mean|/σ ≈ 8.7e8. The textbook formula subtracts two
  // numbers of size n·1e18 whose difference is n·σ², losing κ² ≈ 7.5e17 times u: relative error
  // O(100). Welford works on deviations; under the Higham–Mary model its relative error is of
  // order √n·κ·u ≈ 6e-6 (worst case n·κ·u ≈ 4e-4). Measured: 3e-10 against 1055 for the textbook.
  const double kappa = exact_mean / std::sqrt(exact_variance);
  EXPECT_GT(relative_error(textbook, exact_variance), 1.0) << "textbook variance " << textbook;
  EXPECT_LE(relative_error(w.variance(), exact_variance),
            std::sqrt(double{n}) * kappa * unit_roundoff)
      << "welford variance " << w.variance() << ", exact " << exact_variance;
  EXPECT_LE(relative_error(w.mean(), exact_mean), 7 * std::sqrt(double{n}) * unit_roundoff)
      << "welford mean " << w.mean() << ", exact " << exact_mean;
}

TEST(Welford, VarianceIsNanBelowTwoValues) {
  quadmc::welford w;
  EXPECT_EQ(w.count(), 0u);
  EXPECT_TRUE(std::isnan(w.variance()));
  EXPECT_TRUE(std::isnan(w.std_error()));
  w.add(4.0);
  EXPECT_EQ(w.mean(), 4.0);
  EXPECT_EQ(w.m2(), 0.0);
  EXPECT_TRUE(std::isnan(w.variance()));
  EXPECT_TRUE(std::isnan(w.std_error()));
  w.add(6.0);
  EXPECT_EQ(w.variance(), 2.0);
}

TEST(Welford, MergeWithEmptyAccumulatorsChangesNothing) {
  quadmc::welford a;
  for (const double v : {0.1, 0.7, 0.3, 1e-3}) a.add(v);
  const quadmc::welford before = a;

  a.merge(quadmc::welford{});  // empty on the right
  EXPECT_EQ(a.count(), before.count());
  EXPECT_EQ(a.mean(), before.mean());
  EXPECT_EQ(a.m2(), before.m2());

  quadmc::welford empty;  // empty on the left takes the other's moments bit for bit
  empty.merge(before);
  EXPECT_EQ(empty.count(), before.count());
  EXPECT_EQ(empty.mean(), before.mean());
  EXPECT_EQ(empty.m2(), before.m2());

  quadmc::welford both;  // two empties stay empty: no 0/0 in the merge weights
  both.merge(quadmc::welford{});
  EXPECT_EQ(both.count(), 0u);
  EXPECT_EQ(both.mean(), 0.0);
  EXPECT_EQ(both.m2(), 0.0);
  EXPECT_TRUE(std::isnan(both.variance()));
}

}  // namespace
