#include "quadmc/rules/simpson_rule.hpp"

#include "jump_integrand.hpp"
#include "log_log_slope.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace {

using quadmc::test_support::eps;

// Exact for cubics (the x³ error term integrates to zero over each symmetric panel pair).
// f = x³ − 2x² + x − 5 on [−1, 2]: ∫ = [x⁴/4 − 2x³/3 + x²/2 − 5x] = (4 − 16/3 + 2 − 10) −
// (1/4 + 2/3 + 1/2 + 5) = −15.75. Bound: 4·n ulp of (b − a)·max|f| = 3·9 (|f(−1)| = 9).
TEST(SimpsonRule, ExactForCubics) {
  const auto f = [](double x) { return ((x - 2.0) * x + 1.0) * x - 5.0; };
  for (std::uint64_t n : {2U, 4U, 10U, 64U, 1000U}) {
    const auto r = quadmc::integrate(f, -1.0, 2.0, quadmc::simpson_rule{}, n);
    EXPECT_NEAR(r.value, -15.75, 4.0 * static_cast<double>(n) * eps * 27.0) << "n = " << n;
    EXPECT_EQ(r.evaluations, n + 1);
  }
}

// eˣ on [0, 1], n = 4 … 256: error (e − 1)h⁴/180 ≥ 2e-12 at n = 256, four orders above the
// rounding level ~1e-16; beyond n ≈ 2^10 rounding takes over and the slope flattens.
TEST(SimpsonRule, FourthOrderOnSmoothIntegrand) {
  std::vector<double> ns;
  std::vector<double> errors;
  for (std::uint64_t n = 4; n <= 256; n *= 2) {
    const auto r = quadmc::integrate([](double x) { return std::exp(x); }, 0.0, 1.0,
                                     quadmc::simpson_rule{}, n);
    ns.push_back(static_cast<double>(n));
    errors.push_back(r.value - std::expm1(1.0));
  }
  EXPECT_NEAR(quadmc::testing::log_log_slope(ns, errors), -4.0, 0.1);
}

// S on 2n panels (spacing h) = (2·M + T)/3 with M, T on n panels of width 2h
// (docs/theory.md#opposite-signs). Both sides are rounded sums of ~2n terms of size ≤ e/n, so they
// agree to a few ε·e.
TEST(SimpsonRule, IsTheWeightedMeanOfMidpointAndTrapezoid) {
  const auto f = [](double x) { return std::exp(x); };
  for (std::uint64_t n : {1U, 3U, 16U, 100U}) {
    const double s = quadmc::integrate(f, 0.0, 1.0, quadmc::simpson_rule{}, 2 * n).value;
    const double m = quadmc::integrate(f, 0.0, 1.0, quadmc::midpoint_rule{}, n).value;
    const double t = quadmc::integrate(f, 0.0, 1.0, quadmc::trapezoid_rule{}, n).value;
    EXPECT_NEAR(s, (2.0 * m + t) / 3.0, 16.0 * eps * std::numbers::e) << "n = " << n;
  }
}

TEST(SimpsonRule, FirstOrderAcrossAJump) {
  // Tolerance ±0.1 explained in jump_integrand.hpp. The weights 4h/3, 2h/3 alternate, so the
  // error can reach 4/3 of a node spacing (plus the jump's own share): allow 2/n.
  EXPECT_NEAR(quadmc::testing::jump_slope(quadmc::simpson_rule{}, true, 2.0), -1.0, 0.1);
}

TEST(SimpsonRule, RejectsOddOrZeroPanelsInsteadOfRounding) {
  using quadmc::testing::throws_with;
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>([] { (void)quadmc::simpson_rule{}.nodes(7); },
                                                    "invalid n = 7: expected an even number"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>([] { (void)quadmc::simpson_rule{}.nodes(0); },
                                                    "invalid n = 0: expected an even number"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] {
        (void)quadmc::integrate([](double x) { return x; }, 0.0, 1.0, quadmc::simpson_rule{}, 3);
      },
      "invalid n = 3"));
}

}  // namespace
