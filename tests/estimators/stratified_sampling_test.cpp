#include "quadmc/estimators/stratified_sampling.hpp"

#include "quadmc/sampling/independent_points.hpp"
#include "test_integrands.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/chi_squared.hpp>

#include <cmath>
#include <iostream>
#include <vector>

namespace {

using namespace quadmc;

const auto square_on_unit_interval = test_support::make_integrand(
    "x^2", box::unit(1), 1.0 / 3.0, [](std::span<const double> x) { return x[0] * x[0]; });

// μᵢ and σᵢ² of f(x) = x² on the stratum [a, a + h), in closed form:
// μ = (b³ − a³)/(3h), E[f²] = (b⁵ − a⁵)/(5h), σ² = E[f²] − μ².
struct stratum_moments {
  double mean, variance;
};
stratum_moments moments(double a, double h) {
  const double b = a + h;
  const double mu = (b * b * b - a * a * a) / (3 * h);
  const double m2 = (std::pow(b, 5) - std::pow(a, 5)) / (5 * h);
  return {mu, m2 - mu * mu};
}

// Two-sided chi-square interval for a variance V from the sample variance of R values:
// (R−1)s²/V ~ χ²(R−1) for normal values. Each estimate is a mean of n = 32 values of a bounded f,
// whose excess kurtosis (≈ −1.2/32 for the random estimator) barely changes Var(s²).
bool variance_matches(double sample_variance, int runs, double v, double alpha) {
  const boost::math::chi_squared chi(runs - 1);
  const double lo = boost::math::quantile(chi, alpha / 2);
  const double hi = boost::math::quantile(boost::math::complement(chi, alpha / 2));
  const double statistic = (runs - 1) * sample_variance / v;
  return lo <= statistic && statistic <= hi;
}

// The theorem of docs/theory.md#stratified-vs-random ([Stratified vs random 2023]), measured.
// f = x² on [0,1), k equal strata (vᵢ = 1/k), m points per stratum, n = km:
//   V_strat  = (1/n) Σ vᵢσᵢ²,
//   V_random = (1/n) [Σ vᵢσᵢ² + Σ vᵢ(μᵢ − I)²]   (= Var(U²)/n = (1/5 − 1/9)/n, a check).
// Observed variances over R = 2000 runs each must lie in their chi-square intervals, two-sided
// at α = 1e-5 per interval (6 intervals), and the reported variance's mean within 4.5 standard
// errors (Student's t, 1999 degrees of freedom: 7.2e-6 each, 3 checks): 8.2e-5 for the whole
// test. The interval for (R − 1)s²/V spans ±4.6 of its standard deviations √(2(R − 1)), i.e.
// s² ∈ [0.87, 1.15]·V: a formula off by 25% either way fails with probability ≥ 0.996.
TEST(StratifiedSampling, MeasuredVariancesMatchTheBlogsFormulas) {
  constexpr int runs = 2000;
  for (const auto& [k, m] : {std::pair<std::uint64_t, std::uint64_t>{4, 8}, {2, 16}, {16, 2}}) {
    const double n = double(k * m);
    const double h = 1.0 / double(k);
    double within = 0, between = 0;
    for (std::uint64_t i = 0; i < k; ++i) {
      const auto [mu, var] = moments(double(i) * h, h);
      within += h * var;
      between += h * (mu - 1.0 / 3.0) * (mu - 1.0 / 3.0);
    }
    const double v_strat = within / n;
    const double v_random = (within + between) / n;
    ASSERT_NEAR(v_random, (1.0 / 5 - 1.0 / 9) / n, 1e-15);

    welford strat, random, reported;
    for (int r = 0; r < runs; ++r) {
      const estimate e = stratified_sampling(square_on_unit_interval, k, m, 7, r);
      strat.add(e.value);
      reported.add(e.std_error * e.std_error);
      random.add(monte_carlo(square_on_unit_interval, independent_points(1, k * m, 8, r)).value);
    }
    std::cout << "[ measured ] k = " << k << ", m = " << m
              << ": Var strat / Var random = " << strat.variance() / random.variance()
              << " (formula " << v_strat / v_random << "); Var strat = " << strat.variance()
              << " (formula " << v_strat << "), Var random = " << random.variance() << " (formula "
              << v_random << ")\n";
    EXPECT_TRUE(variance_matches(strat.variance(), runs, v_strat, 1e-5))
        << "k = " << k << ", m = " << m << ": observed " << strat.variance() << ", formula "
        << v_strat;
    EXPECT_TRUE(variance_matches(random.variance(), runs, v_random, 1e-5))
        << "k = " << k << ", m = " << m << ": observed " << random.variance() << ", formula "
        << v_random;
    EXPECT_LT(strat.variance(), random.variance());
    // The estimator's own Σ vᵢ²σ̂ᵢ²/nᵢ is unbiased for V_strat: its mean over the runs is within
    // 4.5 standard errors (see above).
    EXPECT_NEAR(reported.mean(), v_strat, 4.5 * reported.std_error()) << "k = " << k;
  }
}

TEST(StratifiedSampling, RejectsZeroPointsPerStratumAndOverflow) {
  EXPECT_THROW(stratified_sampling(square_on_unit_interval, 4, 0, 1, 1), invalid_argument);
  EXPECT_THROW(stratified_sampling(square_on_unit_interval, 0, 4, 1, 1), invalid_argument);
  EXPECT_THROW(stratified_sampling(square_on_unit_interval, 1ULL << 54, 1, 1, 1), invalid_argument);
}

}  // namespace
