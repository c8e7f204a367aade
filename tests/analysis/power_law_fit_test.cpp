// Tests for power_law_fit.hpp: exact recovery, interval coverage, degenerate input.
#include "quadmc/analysis/power_law_fit.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace quadmc {
namespace {

// A standard normal by Box–Muller from uniforms 2i and 2i + 1 of a Philox stream; 1 − u lies in
// (0, 1], so the logarithm is finite.
double standard_normal(const philox_stream& stream, std::uint64_t i) {
  const double u1 = 1.0 - stream.uniform(2 * i);
  const double u2 = stream.uniform(2 * i + 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// error_k = C·N_k^slope·exp(σ·Z_k), N = 2^4 … 2^(3 + points): lognormal noise, the fit's model.
void synthetic_ladder(double c, double slope, double sigma, std::size_t points,
                      const philox_stream& stream, std::vector<double>& n,
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

TEST(PowerLawFit, NoisyLadderIntervalCoversTheTruth) {
  // Seed 20240611, stream 1: one ladder of 12 points with σ = 0.3 (RMSE of ~5 repetitions).
  // A random seed would fail with probability 0.05; this seed is fixed, not chosen by retrying.
  std::vector<double> n, error;
  synthetic_ladder(0.7, -0.5, 0.3, 12, philox_stream(20240611, 1), n, error);
  const power_law_fit fit = fit_power_law(n, error);
  ASSERT_TRUE(fit.ok());
  EXPECT_LE(fit.ci_low, -0.5) << "slope " << fit.slope << " ± " << fit.half_width();
  EXPECT_GE(fit.ci_high, -0.5) << "slope " << fit.slope << " ± " << fit.half_width();
  EXPECT_LT(fit.half_width(), 0.2) << "12 points over 11 doublings with σ = 0.3";
}

TEST(PowerLawFit, IntervalCoversInNinetyFivePercentOfLadders) {
  // M = 2000 independent ladders (seed 7, stream m), 8 points each, σ = 0.5: the Student-t
  // interval is exact for this model, so the number covering is Binomial(M, 0.95): mean 1900,
  // sd √(M·0.95·0.05) = 9.75. Accepting ±4 sd (±39) has a false-alarm probability ≈ 6e-5.
  constexpr std::size_t ladders = 2000;
  std::size_t covered = 0;
  std::vector<double> n, error;
  for (std::size_t m = 0; m < ladders; ++m) {
    synthetic_ladder(2.0, -1.25, 0.5, 8, philox_stream(7, m), n, error);
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
