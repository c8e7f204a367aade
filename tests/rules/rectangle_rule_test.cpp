#include "quadmc/rules/rectangle_rule.hpp"

#include "jump_integrand.hpp"
#include "log_log_slope.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using quadmc::test_support::eps;

// Exact for constants only (first order). f = 2.5 on [−1, 2]: ∫ = 7.5, within 4·n ulp of 7.5.
TEST(RectangleRule, ExactForConstants) {
  const auto f = [](double) { return 2.5; };
  for (std::uint64_t n : {1U, 3U, 64U, 1000U}) {
    const auto left = quadmc::integrate(f, -1.0, 2.0, quadmc::left_rectangle_rule{}, n);
    const auto right = quadmc::integrate(f, -1.0, 2.0, quadmc::right_rectangle_rule{}, n);
    EXPECT_NEAR(left.value, 7.5, 4.0 * static_cast<double>(n) * eps * 7.5) << "n = " << n;
    EXPECT_NEAR(right.value, 7.5, 4.0 * static_cast<double>(n) * eps * 7.5) << "n = " << n;
    EXPECT_EQ(left.evaluations, n);
  }
}

// Right − left = h·(f(b) − f(a)): the sums share every interior node. For x² on [0, 1] that is
// 1/n; both sums are rounded to a few ε, so 8ε.
TEST(RectangleRule, RightMinusLeftIsOnePanelOfTheRise) {
  const auto f = [](double x) { return x * x; };
  for (std::uint64_t n : {1U, 5U, 64U}) {
    const double l = quadmc::integrate(f, 0.0, 1.0, quadmc::left_rectangle_rule{}, n).value;
    const double r = quadmc::integrate(f, 0.0, 1.0, quadmc::right_rectangle_rule{}, n).value;
    EXPECT_NEAR(r - l, 1.0 / static_cast<double>(n), 8.0 * eps) << "n = " << n;
  }
}

// eˣ on [0, 1], n = 8 … 2^14: error ∓(e − 1)h/2 + O(h²); the O(h²) term bends the fit by
// ~h·(e − 1)/6 relative, negligible from n = 8.
template <class R>
double smooth_slope(const R& rule) {
  std::vector<double> ns;
  std::vector<double> errors;
  for (std::uint64_t n = 8; n <= (1U << 14); n *= 2) {
    const auto r = quadmc::integrate([](double x) { return std::exp(x); }, 0.0, 1.0, rule, n);
    ns.push_back(static_cast<double>(n));
    errors.push_back(r.value - std::expm1(1.0));
  }
  return quadmc::testing::log_log_slope(ns, errors);
}

TEST(RectangleRule, FirstOrderOnSmoothIntegrand) {
  EXPECT_NEAR(smooth_slope(quadmc::left_rectangle_rule{}), -1.0, 0.05);
  EXPECT_NEAR(smooth_slope(quadmc::right_rectangle_rule{}), -1.0, 0.05);
}

TEST(RectangleRule, FirstOrderAcrossAJump) {
  // Tolerance ±0.1 explained in jump_integrand.hpp; the error is at most one panel.
  EXPECT_NEAR(quadmc::testing::jump_slope(quadmc::left_rectangle_rule{}, false, 1.0), -1.0, 0.1);
  EXPECT_NEAR(quadmc::testing::jump_slope(quadmc::right_rectangle_rule{}, false, 1.0), -1.0, 0.1);
}

TEST(RectangleRule, RejectsZeroPanels) {
  using quadmc::testing::throws_with;
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::left_rectangle_rule{}.nodes(0); }, "invalid n = 0"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::right_rectangle_rule{}.nodes(0); }, "at least 1 panel"));
}

}  // namespace
