// Tests for power_law_fit.hpp: exact recovery, interval coverage, degenerate input.
#include "quadmc/analysis/power_law_fit.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace quadmc {
namespace {

// A standard normal by Box–Muller from uniforms 2i and 2i + 1 of a Philox stream; 1 − u lies in
// (0, 1], so the logarithm is finite.
double standard_normal(const random_stream& stream, std::uint64_t i) {
  const double u1 = 1.0 - stream.uniform(2 * i);
  const double u2 = stream.uniform(2 * i + 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// error_k = C·N_k^slope·exp(σ·Z_k), N = 2^4 … 2^(3 + points): lognormal noise, the fit's model.
void synthetic_ladder(double c, double slope, double sigma, std::size_t points,
                      const random_stream& stream, std::vector<double>& n,
                      std::vector<double>& error) {
  n.clear();
  error.clear();
  for (std::size_t k = 0; k < points; ++k) {
    const double nk = std::ldexp(1.0, static_cast<int>(k) + 4);
    n.push_back(nk);
    error.push_back(c * std::pow(nk, slope) * std::exp(sigma * standard_normal(stream, k)));
  }
}

TEST(PowerLawFit, RecoversAnExactPowerLaw) {
  std::vector<double> n, error;
  for (int k = 4; k <= 24; ++k) {
    n.push_back(std::ldexp(1.0, k));
    error.push_back(3.0 * std::pow(n.back(), -1.5));
  }
  const power_law_fit fit = fit_power_law(n, error);
  ASSERT_TRUE(fit.ok()) << to_string(fit.status);
  // ln e is exact to ~ε·|ln e| ≈ 1e-14 per point; over a ln N span of 14 the slope keeps ~1e-15.
  EXPECT_NEAR(fit.slope, -1.5, 1e-12);
  EXPECT_NEAR(fit.intercept, std::log(3.0), 1e-11);
  EXPECT_LT(fit.half_width(), 1e-12);
  EXPECT_LE(fit.ci_low, fit.slope);
  EXPECT_GE(fit.ci_high, fit.slope);
  EXPECT_EQ(fit.points, n.size());
  EXPECT_NEAR(fit.predict(1024.0), 3.0 * std::pow(1024.0, -1.5), 1e-12 * 3.0 / 32768.0);
}

// One ladder of 12 points with σ = 0.3 (RMSE of ~5 repetitions), seed 20240611, stream 1. σ is
// known here, so both outputs have exact distributions under the fit's own model (Draper & Smith,
// "Applied Regression Analysis", 3rd ed., §1.4): b̂ − b ~ N(0, σ²/Sxx), and, independent of it,
// (n − 2)·se²·Sxx/σ² ~ χ²(n − 2) with se = slope_std_error; the interval is b̂ ± t_{n−2,0.975}·se.
// Each of the two checks is two-sided at α = 4e-5 (8e-5 for the test; a simulation of 4·10⁶
// streams with α = 5e-5 each failed at 1.04e-4, as designed). Sxx = ln²2·143 here, so
// sd(b̂) = 0.036 and the slope band is ±4.11·0.036 = ±0.149: a slope biased by 0.2 fails with
// probability ≥ 0.92. The se band is [0.251σ, 1.990σ]/√Sxx, wide for one ladder of 10 degrees of
// freedom: an se off by a factor 8 or more either way (a forgotten square root, Sxx² for Sxx)
// fails with probability ≥ 0.9999, a factor 3 too large with 0.93; subtler errors are the
// coverage test's job below.
TEST(PowerLawFit, NoisyLadderSlopeAndStandardErrorFollowTheirDistributions) {
  constexpr double sigma = 0.3, alpha = 4e-5;
  constexpr std::size_t points = 12;
  std::vector<double> n, error;
  synthetic_ladder(0.7, -0.5, sigma, points, random_stream(20240611, 1), n, error);
  const power_law_fit fit = fit_power_law(n, error);
  ASSERT_TRUE(fit.ok());
  double mean = 0.0, sxx = 0.0;
  for (double v : n) mean += std::log(v) / static_cast<double>(points);
  for (double v : n) sxx += (std::log(v) - mean) * (std::log(v) - mean);
  const double z = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2));
  EXPECT_NEAR(fit.slope, -0.5, z * sigma / std::sqrt(sxx)) << "slope " << fit.slope;
  const boost::math::chi_squared chi(static_cast<double>(points - 2));
  const double dof = static_cast<double>(points - 2);
  const double se_low = sigma * std::sqrt(boost::math::quantile(chi, alpha / 2) / dof / sxx);
  const double se_high =
      sigma * std::sqrt(boost::math::quantile(boost::math::complement(chi, alpha / 2)) / dof / sxx);
  EXPECT_GE(fit.slope_std_error, se_low);
  EXPECT_LE(fit.slope_std_error, se_high);
  const double t =
      boost::math::quantile(boost::math::complement(boost::math::students_t(dof), 0.025));
  EXPECT_NEAR(fit.half_width(), t * fit.slope_std_error, 1e-12) << "the 95% interval is t·se";
}

TEST(PowerLawFit, IntervalCoversInNinetyFivePercentOfLadders) {
  // M = 2000 independent ladders (seed 7, stream m), 8 points each, σ = 0.5: the Student-t
  // interval is exact for this model, so the number covering is Binomial(M, 0.95): mean 1900,
  // sd √(M·0.95·0.05) = 9.75. Accepting ±4 sd (±39): the exact binomial tails give a
  // false-alarm probability of 5.9e-5 (below 1861) + 7.0e-6 (above 1939) = 6.6e-5.
  constexpr std::size_t ladders = 2000;
  std::size_t covered = 0;
  std::vector<double> n, error;
  for (std::size_t m = 0; m < ladders; ++m) {
    synthetic_ladder(2.0, -1.25, 0.5, 8, random_stream(7, m), n, error);
    const power_law_fit fit = fit_power_law(n, error);
    ASSERT_TRUE(fit.ok()) << "ladder " << m;
    if (fit.ci_low <= -1.25 && -1.25 <= fit.ci_high) ++covered;
  }
  const double sd = std::sqrt(ladders * 0.95 * 0.05);
  EXPECT_NEAR(static_cast<double>(covered), 0.95 * ladders, 4.0 * sd);
}

TEST(PowerLawFit, ThreePointsUseTheOneDegreeOfFreedomQuantile) {
  // ln N = 0, 1, 2 (N = 1, e, e²) and ln error = 0, −1, −3: slope −1.5, intercept 1/6,
  // residuals (−1, 2, −1)/6, SSR = 1/6, Sxx = 2, se = √(SSR/(1·Sxx)) = √(1/12). With one degree
  // of freedom Student's t is Cauchy: t_{1,0.975} = tan(π·0.475) = 12.7062047.
  const std::vector<double> n = {1.0, std::exp(1.0), std::exp(2.0)};
  const std::vector<double> error = {1.0, std::exp(-1.0), std::exp(-3.0)};
  const power_law_fit fit = fit_power_law(n, error);
  ASSERT_TRUE(fit.ok());
  EXPECT_NEAR(fit.slope, -1.5, 1e-14);
  EXPECT_NEAR(fit.slope_std_error, std::sqrt(1.0 / 12.0), 1e-14);
  const double t = std::tan(std::numbers::pi * 0.475);
  EXPECT_NEAR(fit.half_width(), t * std::sqrt(1.0 / 12.0), 1e-12);
}

TEST(PowerLawFit, TooFewPointsIsAStatusNotACrash) {
  const std::vector<double> n = {10.0, 100.0}, error = {1e-2, 1e-4};
  const power_law_fit fit = fit_power_law(n, error);
  EXPECT_EQ(fit.status, fit_status::too_few_points);
  EXPECT_FALSE(fit.ok());
  EXPECT_TRUE(std::isnan(fit.slope));
  EXPECT_EQ(fit_power_law({}, {}).status, fit_status::too_few_points);
}

TEST(PowerLawFit, EqualNIsDegenerate) {
  const std::vector<double> n = {10.0, 10.0, 10.0}, error = {1e-2, 2e-2, 3e-2};
  EXPECT_EQ(fit_power_law(n, error).status, fit_status::degenerate_abscissa);
}

TEST(PowerLawFit, RejectsNonPositiveValues) {
  const std::vector<double> n = {10.0, 100.0, 1000.0};
  EXPECT_THROW(fit_power_law(n, std::vector<double>{1e-2, 0.0, 1e-6}), invalid_argument);
  EXPECT_THROW(fit_power_law(n, std::vector<double>{1e-2, 1e-4}), invalid_argument);
  EXPECT_THROW(
      fit_power_law(std::vector<double>{10.0, -1.0, 1000.0}, std::vector<double>{1e-2, 1e-4, 1e-6}),
      invalid_argument);
  EXPECT_THROW(fit_power_law(n, std::vector<double>{1e-2, 1e-4, 1e-6}, 1.0), invalid_argument);
}

}  // namespace
}  // namespace quadmc
