#include "quadmc/rules/error_bounds.hpp"

#include "reference_integrands.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

namespace {

using quadmc::testing::smooth_case;

// |Q_n − I| ≤ bound + rounding allowance (reference_integrands.hpp) for every rule with a bound,
// all six integrands and n = 2, 4, …, 2^14. The allowance matters only where the bound falls
// below ~1e-15 (Simpson and Gauss past n ≈ 2^9).
TEST(ErrorBounds, HoldForEveryRuleIntegrandAndN) {
  for (const smooth_case& c : quadmc::testing::smooth_cases()) {
    const double slack = quadmc::testing::rounding_allowance(c);
    for (std::uint64_t n = 2; n <= (1U << 14); n *= 2) {
      const auto error = [&](const auto& rule) {
        return std::abs(quadmc::integrate(c.f, c.a, c.b, rule, n).value - c.exact);
      };
      EXPECT_LE(error(quadmc::midpoint_rule{}),
                quadmc::midpoint_error_bound(c.a, c.b, n, c.m2) + slack)
          << c.name << " midpoint n = " << n;
      EXPECT_LE(error(quadmc::trapezoid_rule{}),
                quadmc::trapezoid_error_bound(c.a, c.b, n, c.m2) + slack)
          << c.name << " trapezoid n = " << n;
      EXPECT_LE(error(quadmc::simpson_rule{}),
                quadmc::simpson_error_bound(c.a, c.b, n, c.m4) + slack)
          << c.name << " simpson n = " << n;
      EXPECT_LE(error(quadmc::left_rectangle_rule{}),
                quadmc::rectangle_error_bound(c.a, c.b, n, c.m1) + slack)
          << c.name << " left rectangle n = " << n;
      EXPECT_LE(error(quadmc::right_rectangle_rule{}),
                quadmc::rectangle_error_bound(c.a, c.b, n, c.m1) + slack)
          << c.name << " right rectangle n = " << n;
      EXPECT_LE(error(quadmc::gauss_legendre_rule(2)),
                quadmc::gauss_legendre_error_bound(c.a, c.b, n, 2, c.m4) + slack)
          << c.name << " gauss_legendre_2 n = " << n;
    }
  }
}

// Tight: for eˣ on [0, 1] every derivative is eˣ ∈ [1, e], so the error is (mean of f⁽ᵏ⁾ = e − 1)
// times the bound's constant and bound/error → e/(e − 1) ≈ 1.58 (rectangles: f(b) − f(a) = e − 1
// against M₁ = e, same ratio). n = 16 keeps every error far above rounding (Gauss 2: 1e-9).
TEST(ErrorBounds, AreWithinAFactorTenOfTheErrorForExp) {
  const smooth_case c = quadmc::testing::smooth_cases().front();
  ASSERT_EQ(c.name, "exp");
  const std::uint64_t n = 16;
  const auto ratio = [&](const auto& rule, double bound) {
    return bound / std::abs(quadmc::integrate(c.f, c.a, c.b, rule, n).value - c.exact);
  };
  const double ratios[] = {
      ratio(quadmc::midpoint_rule{}, quadmc::midpoint_error_bound(c.a, c.b, n, c.m2)),
      ratio(quadmc::trapezoid_rule{}, quadmc::trapezoid_error_bound(c.a, c.b, n, c.m2)),
      ratio(quadmc::simpson_rule{}, quadmc::simpson_error_bound(c.a, c.b, n, c.m4)),
      ratio(quadmc::left_rectangle_rule{}, quadmc::rectangle_error_bound(c.a, c.b, n, c.m1)),
      ratio(quadmc::right_rectangle_rule{}, quadmc::rectangle_error_bound(c.a, c.b, n, c.m1)),
      ratio(quadmc::gauss_legendre_rule(2),
            quadmc::gauss_legendre_error_bound(c.a, c.b, n, 2, c.m4)),
  };
  const char* names[] = {"midpoint", "trapezoid", "simpson", "left", "right", "gauss_2"};
  for (int i = 0; i < 6; ++i) {
    EXPECT_GE(ratios[i], 1.0) << names[i];
    EXPECT_LE(ratios[i], 10.0) << names[i];
  }
}

// Gauss with m = 1 would be the midpoint rule: the general constant must reduce to 1/24.
TEST(ErrorBounds, GaussConstantReducesToMidpoint) {
  EXPECT_DOUBLE_EQ(quadmc::gauss_legendre_error_bound(0.0, 2.0, 5, 1, 3.0),
                   quadmc::midpoint_error_bound(0.0, 2.0, 5, 3.0));
}

// exp(x₁ + … + x_s) on [0, 1]^s: ∂ᵏ/∂x_jᵏ f = f ≤ e^s on the box, so M_k = e^s on every axis.
struct exp_of_sum {
  std::size_t s;
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < s; ++j) sum += x[i * s + j];
      y[i] = std::exp(sum);
    }
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info i;
    i.name = "exp_of_sum";
    i.domain = quadmc::box::unit(s);
    i.exact = std::pow(std::expm1(1.0), static_cast<double>(s));
    const double m = std::exp(static_cast<double>(s));
    i.derivative_bound = {m, m, m, m, m};
    return i;
  }
};

// The tensor bound Σ_j E_j·Π_{i≠j}(b_i − a_i) holds and, for this f, is within
// (e/(e − 1))^s ≤ 4 of the error (s ≤ 3): tight enough to plot beside the measurement.
TEST(ErrorBounds, TensorProductBoundHoldsAndIsTight) {
  for (std::size_t s : {2U, 3U}) {
    const exp_of_sum f{s};
    const auto info = f.info();
    for (std::uint64_t n : {4U, 8U, 16U}) {
      const auto check = [&](const auto& rule) {
        const double error = std::abs(quadmc::integrate(f, rule, n).value - info.exact);
        const double bound = quadmc::tensor_product_error_bound(rule, info, n);
        EXPECT_LE(error, bound) << rule.name() << " s = " << s << " n = " << n;
        EXPECT_LE(bound, 10.0 * error) << rule.name() << " s = " << s << " n = " << n;
      };
      check(quadmc::midpoint_rule{});
      check(quadmc::trapezoid_rule{});
      check(quadmc::simpson_rule{});
      check(quadmc::left_rectangle_rule{});
    }
  }
  // Per-axis M_k and unequal sides: [0, 1] × [0, 2], M₂ along x₂ is e³, along x₁ also e³.
  const quadmc::box b{{0.0, 0.0}, {1.0, 2.0}};
  const double m = std::exp(3.0);
  const std::vector<double> per_axis = {m, m};
  EXPECT_DOUBLE_EQ(quadmc::tensor_product_error_bound(quadmc::midpoint_rule{}, b, 8, per_axis),
                   quadmc::midpoint_error_bound(0.0, 1.0, 8, m) * 2.0 +
                       quadmc::midpoint_error_bound(0.0, 2.0, 8, m) * 1.0);
}

// The autodiff grid estimate recovers every exact M_k of the reference integrands (the comments
// in reference_integrands.hpp derive them). A grid maximum can only fall short of the true one
// (by O(spacing²) at an interior maximum: ~1e-8 relative here), never exceed it beyond rounding.
TEST(ErrorBounds, AutodiffGridEstimateMatchesExactDerivativeBounds) {
  const auto cases = quadmc::testing::smooth_cases();
  const auto expect_close = [](double estimate, double exact, const std::string& what) {
    EXPECT_LE(estimate, exact * (1.0 + 1e-12)) << what;
    EXPECT_GE(estimate, exact * (1.0 - 1e-6)) << what;
  };
  const auto check = [&](const smooth_case& c, const auto& g) {
    expect_close(quadmc::max_abs_derivative<1>(g, c.a, c.b), c.m1, c.name + " M1");
    expect_close(quadmc::max_abs_derivative<2>(g, c.a, c.b), c.m2, c.name + " M2");
    expect_close(quadmc::max_abs_derivative<4>(g, c.a, c.b), c.m4, c.name + " M4");
  };
  using std::cos;
  using std::exp;
  using std::log;
  using std::sin;
  check(cases[0], [](auto x) { return exp(x); });
  check(cases[1], [](auto x) { return sin(x); });
  check(cases[2], [](auto x) { return 1.0 / (1.0 + x * x); });
  check(cases[3], [](auto x) { return cos(3.0 * x); });
  check(cases[4], [](auto x) { return x * x * x * x * x; });
  check(cases[5], [](auto x) { return log(1.0 + x); });
}

TEST(ErrorBounds, RejectBadInput) {
  using quadmc::invalid_argument;
  using quadmc::testing::throws_with;
  EXPECT_TRUE(
      throws_with<invalid_argument>([] { (void)quadmc::midpoint_error_bound(0.0, 1.0, 0, 1.0); },
                                    "invalid n = 0: expected at least 1 panel"));
  EXPECT_TRUE(
      throws_with<invalid_argument>([] { (void)quadmc::trapezoid_error_bound(1.0, 0.0, 4, 1.0); },
                                    "invalid b = 0: expected ≥ a = 1"));
  EXPECT_TRUE(
      throws_with<invalid_argument>([] { (void)quadmc::rectangle_error_bound(0.0, 1.0, 4, -1.0); },
                                    "invalid M1 = -1: expected a finite bound ≥ 0"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] { (void)quadmc::midpoint_error_bound(0.0, 1.0, 4, std::nan("")); }, "invalid M2 = nan"));
  EXPECT_TRUE(
      throws_with<invalid_argument>([] { (void)quadmc::simpson_error_bound(0.0, 1.0, 5, 1.0); },
                                    "invalid n = 5: expected an even number"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] { (void)quadmc::gauss_legendre_error_bound(0.0, 1.0, 4, 31, 1.0); },
      "invalid m = 31: expected between 1 and 30"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] {
        (void)quadmc::midpoint_error_bound(0.0, std::numeric_limits<double>::infinity(), 4, 1.0);
      },
      "invalid b = inf: expected a finite number"));
  // M_k not recorded in the metadata.
  quadmc::integrand_info info = exp_of_sum{2}.info();
  info.derivative_bound[4].reset();
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { (void)quadmc::tensor_product_error_bound(quadmc::simpson_rule{}, info, 4); },
      "invalid exp_of_sum: derivative_bound[4] = unknown: expected a known M_4"));
  // Gauss m = 3 needs M_6, which integrand_info cannot hold.
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { (void)quadmc::tensor_product_error_bound(quadmc::gauss_legendre_rule(3), info, 4); },
      "derivative_bound[6] = unknown"));
  const std::vector<double> one = {1.0};
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] {
        (void)quadmc::tensor_product_error_bound(quadmc::midpoint_rule{}, quadmc::box::unit(2), 4,
                                                 one);
      },
      "invalid derivative bounds per axis = 1: expected one per dimension, 2"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] { (void)quadmc::max_abs_derivative<2>([](auto x) { return x * x; }, 0.0, 1.0, 1); },
      "invalid grid_points = 1: expected at least 2"));
}

}  // namespace
