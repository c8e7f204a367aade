// Tests of estimators/replicate_estimator.hpp: the order-statistic coverage against the binomial
// sum itself, the rank chosen for the one-σ probability, the mean's and the median's values and
// error bars, the refusals, and the median's claim covering at its stated probability on a
// continuous law.
#include "quadmc/estimators/replicate_estimator.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace quadmc {
namespace {

// 1 − 2·Σ_{i<l} C(k, i)/2^k by Pascal's triangle, exact in doubles for k ≤ 50.
double coverage_by_pascal(std::size_t k, std::size_t l) {
  std::vector<double> row{1.0};
  for (std::size_t n = 1; n <= k; ++n) {
    std::vector<double> next(n + 1, 1.0);
    for (std::size_t i = 1; i < n; ++i) next[i] = row[i - 1] + row[i];
    row = std::move(next);
  }
  double tail = 0.0;
  for (std::size_t i = 0; i < l; ++i) tail += row[i];
  return 1.0 - 2.0 * std::ldexp(tail, -static_cast<int>(k));
}

TEST(ReplicateEstimator, OrderStatisticCoverageIsTheBinomialSum) {
  for (std::size_t k = 1; k <= 50; ++k) {
    for (std::size_t l = 1; 2 * l <= k + 1; ++l) {
      EXPECT_NEAR(median_interval_coverage(k, l), coverage_by_pascal(k, l), 1e-14)
          << "k = " << k << ", l = " << l;
    }
  }
  EXPECT_THROW(median_interval_coverage(11, 0), invalid_argument);
  EXPECT_THROW(median_interval_coverage(11, 7), invalid_argument);
}

TEST(ReplicateEstimator, RankIsTheNarrowestIntervalOfOneSigmaProbability) {
  const double one_sigma = std::erf(1.0 / std::sqrt(2.0));
  for (std::size_t k = 3; k <= 101; k += 2) {
    const std::size_t l = median_interval_rank(k, one_sigma);
    EXPECT_GE(median_interval_coverage(k, l), one_sigma) << "k = " << k;
    if (2 * (l + 1) <= k + 1) {
      EXPECT_LT(median_interval_coverage(k, l + 1), one_sigma) << "k = " << k;
    }
  }
  // k = 11: l = 4 covers 1 − 2·(1 + 11 + 55 + 165)/2048 = 0.773, l = 5 only 0.451.
  EXPECT_EQ(median_interval_rank(11, one_sigma), 4u);
  EXPECT_THROW(median_interval_rank(1, one_sigma), invalid_argument);
}

TEST(ReplicateEstimator, MeanAndMedianWithTheirErrorBars) {
  const std::vector<double> four{1.0, 2.0, 3.0, 4.0};
  const combined_replicates mean = combine_replicates(four, replicate_estimator::mean);
  EXPECT_DOUBLE_EQ(mean.value, 2.5);
  // s² = (2.25 + 0.25 + 0.25 + 2.25)/3 = 5/3, std_error = s/√4.
  EXPECT_DOUBLE_EQ(mean.std_error, std::sqrt(5.0 / 3.0) / 2.0);
  EXPECT_DOUBLE_EQ(mean.error_estimate, mean.std_error);

  // k = 11, sorted 0 … 10 shuffled, one value far out: the median is 5, the interval
  // x_(4) … x_(8) = 3 … 7 (0-based ranks 3 and 7), half-width 2; the outlier moves neither.
  const std::vector<double> eleven{7.0, 0.0, 9.0, 3.0, 5.0, 1e9, 2.0, 6.0, 4.0, 1.0, 8.0};
  const combined_replicates median = combine_replicates(eleven, replicate_estimator::median);
  EXPECT_EQ(median.value, 5.0);
  EXPECT_EQ(median.error_estimate, 2.0);
  EXPECT_TRUE(std::isnan(median.std_error));
  // An asymmetric interval: the larger of the two distances.
  const std::vector<double> skewed{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 3.0, 3.0, 3.0};
  EXPECT_EQ(combine_replicates(skewed, replicate_estimator::median).error_estimate, 1.0);
}

TEST(ReplicateEstimator, RefusesCountsItCannotCombine) {
  const std::vector<double> one{1.0}, two{1.0, 2.0};
  EXPECT_THROW(combine_replicates(one, replicate_estimator::mean), invalid_argument);
  try {
    combine_replicates(two, replicate_estimator::median);
    FAIL() << "a median of two values";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("replicate_count"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("odd k ≥ 3"), std::string::npos) << e.what();
  }
  const std::vector<double> four{1.0, 2.0, 3.0, 4.0};
  EXPECT_THROW(combine_replicates(four, replicate_estimator::median), invalid_argument);
}

TEST(ReplicateEstimator, MedianClaimCoversAtItsStatedProbabilityOnAContinuousLaw) {
  // Normal draws (median 0): the interval x_(4) … x_(8) of k = 11 covers 0 with probability
  // exactly 0.7734 (a continuous law), the claim max-distance interval at least that. Over
  // T = 20000 fixed-seed trials the covering fraction has a standard deviation of at most
  // √(0.7734·0.2266/T) = 0.00296; requiring ≥ 0.7734 − 4.5·0.00296 = 0.760 fails by chance with
  // probability Φ(−4.5) = 3.4e-6 (false alarm).
  const boost::math::normal_distribution<double> normal;
  constexpr int trials = 20000;
  std::vector<double> u(11 * trials);
  random_stream(2026, 38).fill_uniform(0, u);
  int covered = 0;
  std::vector<double> x(11);
  for (int t = 0; t < trials; ++t) {
    // Uniforms in [0, 1): 0 has no normal quantile, so it moves to 2^−60.
    for (int i = 0; i < 11; ++i) {
      x[i] = boost::math::quantile(normal, std::max(u[11 * t + i], 0x1p-60));
    }
    const combined_replicates c = combine_replicates(x, replicate_estimator::median);
    covered += std::abs(c.value) <= c.error_estimate ? 1 : 0;
  }
  EXPECT_GE(static_cast<double>(covered) / trials, 0.7734 - 4.5 * 0.00296);
}

}  // namespace
}  // namespace quadmc
