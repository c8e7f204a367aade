#include "quadmc/rules/romberg.hpp"

#include "reference_integrands.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>

namespace {

using quadmc::test_support::eps;

// Converges to near machine precision on every smooth reference integrand, within the default
// budget, and says so.
TEST(Romberg, ConvergesOnSmoothIntegrands) {
  for (const auto& c : quadmc::testing::smooth_cases()) {
    const auto r = quadmc::romberg(c.f, c.a, c.b, {.relative_tolerance = 1e-13});
    EXPECT_TRUE(r.converged) << c.name << " levels " << r.levels;
    EXPECT_LE(std::abs(r.value - c.exact), 1e-13 * (c.b - c.a) * c.m0 + 16.0 * eps)
        << c.name << " levels " << r.levels;
    EXPECT_EQ(r.evaluations, (std::uint64_t{1} << r.levels) + 1) << c.name;
    EXPECT_LE(r.levels, 12U) << c.name;  // 4097 points: Romberg's point is to need few
  }
}

// The estimate |R(k,k) − R(k−1,k−1)| (floored at 8ε·L1) bounds the true error at every level,
// from the crude k = 1 to the rounding floor, for all six smooth cases.
TEST(Romberg, ErrorEstimateIsHonestOnSmoothIntegrands) {
  for (const auto& c : quadmc::testing::smooth_cases()) {
    for (unsigned levels = 1; levels <= 16; ++levels) {
      const auto r = quadmc::romberg(
          c.f, c.a, c.b, {.relative_tolerance = 0.0, .min_levels = 0, .max_levels = levels});
      EXPECT_EQ(r.levels, levels);
      EXPECT_LE(std::abs(r.value - c.exact), r.error_estimate)
          << c.name << " levels " << levels << " value " << r.value;
    }
  }
}

// A budget too small for the tolerance is reported, not passed off as success.
TEST(Romberg, ReportsAnExhaustedBudget) {
  const auto r = quadmc::romberg([](double x) { return std::exp(x); }, 0.0, 1.0,
                                 {.relative_tolerance = 1e-14, .min_levels = 1, .max_levels = 2});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.levels, 2U);
  EXPECT_EQ(r.evaluations, 5U);
  EXPECT_GT(r.error_estimate, 1e-14);
}

// min_levels guards against a false early stop: sin²(4πx)·… vanishes at 0, ½, ¼, ¾ (levels ≤ 2)
// so R = 0 and the estimate would be 0 at the first levels. ∫₀¹ sin²(4πx) = ½.
TEST(Romberg, MinimumLevelsPreventAFalseStop) {
  const auto f = [](double x) {
    const double s = std::sin(4.0 * std::numbers::pi * x);
    return s * s;
  };
  const auto r = quadmc::romberg(f, 0.0, 1.0);
  EXPECT_NEAR(r.value, 0.5, 1e-12);
  EXPECT_GE(r.levels, 4U);
}

// The batch integrand path: a 1D integrand object with its own domain.
struct exp_on_interval {
  std::size_t dimension() const { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::exp(x[i]);
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info i;
    i.name = "exp_on_interval";
    i.domain = quadmc::box{{-1.0}, {2.0}};
    return i;
  }
};

TEST(Romberg, BatchIntegrandPath) {
  const auto r = quadmc::romberg(exp_on_interval{});
  const double exact = std::exp(2.0) - std::exp(-1.0);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(std::abs(r.value - exact), r.error_estimate);
  EXPECT_LE(std::abs(r.value - exact), 1e-11 * exact);
}

TEST(Romberg, NonFiniteValueNamesThePoint) {
  // 1/(x − ½) blows up at the level-1 node x = 0.5.
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::non_finite_value>(
      [] { (void)quadmc::romberg([](double x) { return 1.0 / (x - 0.5); }, 0.0, 1.0); },
      "returned inf at x = (0.5)"));
}

TEST(Romberg, RejectsBadInput) {
  using quadmc::testing::throws_with;
  const auto f = [](double x) { return x; };
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [&] { (void)quadmc::romberg(f, 0.0, 1.0, {.max_levels = 0}); },
      "invalid max_levels = 0: expected between 1 and 40"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [&] { (void)quadmc::romberg(f, 0.0, 1.0, {.max_levels = 41}); }, "max_levels = 41"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [&] { (void)quadmc::romberg(f, 0.0, 1.0, {.min_levels = 9, .max_levels = 8}); },
      "invalid min_levels = 9: expected ≤ max_levels = 8"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [&] { (void)quadmc::romberg(f, 0.0, 1.0, {.relative_tolerance = -1.0}); },
      "invalid relative_tolerance = -1: expected a finite number ≥ 0"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>([&] { (void)quadmc::romberg(f, 1.0, 0.0); },
                                                    "invalid b = 0: expected ≥ a = 1"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [&] { (void)quadmc::romberg(f, 0.0, std::numeric_limits<double>::infinity()); },
      "invalid b = inf: expected a finite number"));
}

}  // namespace
