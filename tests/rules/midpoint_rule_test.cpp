#include "quadmc/rules/midpoint_rule.hpp"

#include "jump_integrand.hpp"
#include "log_log_slope.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "reference_integrands.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using quadmc::test_support::eps;

// Exact for linear f: the midpoint of each panel is its centroid. f = 3x − 2 on [−1, 2]:
// ∫ = [1.5x² − 2x] = (6 − 4) − (1.5 + 2) = −1.5. Bound: 4·n ulp of (b − a)·max|f| = 3·5.
TEST(MidpointRule, ExactForLinearFunctions) {
  const auto f = [](double x) { return 3.0 * x - 2.0; };
  for (std::uint64_t n : {1U, 2U, 7U, 64U, 1000U}) {
    const auto r = quadmc::integrate(f, -1.0, 2.0, quadmc::midpoint_rule{}, n);
    EXPECT_NEAR(r.value, -1.5, 4.0 * static_cast<double>(n) * eps * 15.0) << "n = " << n;
    EXPECT_EQ(r.evaluations, n);
  }
}

// Slope of log|error| on log n for eˣ on [0, 1], n = 4 … 2^14: the error (e − 1)h²/24 + O(h⁴)
// stays above 2e-10, six orders above rounding, so the fit sees the h² term only.
TEST(MidpointRule, SecondOrderOnSmoothIntegrand) {
  std::vector<double> ns;
  std::vector<double> errors;
  for (std::uint64_t n = 4; n <= (1U << 14); n *= 2) {
    const auto r = quadmc::integrate([](double x) { return std::exp(x); }, 0.0, 1.0,
                                     quadmc::midpoint_rule{}, n);
    ns.push_back(static_cast<double>(n));
    errors.push_back(r.value - std::expm1(1.0));
    // I − M = +(b − a)h²f″(ξ)/24 > 0 for f″ > 0: the midpoint rule under-estimates a convex f.
    EXPECT_LT(r.value, std::expm1(1.0)) << "n = " << n;
  }
  EXPECT_NEAR(quadmc::testing::log_log_slope(ns, errors), -2.0, 0.05);
}

// Opposite signs, the trapezoid error about twice as large (docs/theory.md#opposite-signs): for eˣ
// the ratio (T − I)/(I − M) → 2 as h → 0; at n = 64 the O(h²) correction to the ratio is below
// 1e-3.
TEST(MidpointRule, ErrorIsMinusHalfTheTrapezoidError) {
  const auto f = [](double x) { return std::exp(x); };
  const double exact = std::expm1(1.0);
  const double m = quadmc::integrate(f, 0.0, 1.0, quadmc::midpoint_rule{}, 64).value - exact;
  const double t = quadmc::integrate(f, 0.0, 1.0, quadmc::trapezoid_rule{}, 64).value - exact;
  EXPECT_NEAR(t / m, -2.0, 1e-3);
}

// Tolerance ±0.1 explained in jump_integrand.hpp. The midpoint error is at most one panel.
TEST(MidpointRule, FirstOrderAcrossAJump) {
  EXPECT_NEAR(quadmc::testing::jump_slope(quadmc::midpoint_rule{}, false, 1.0), -1.0, 0.1);
}

TEST(MidpointRule, RejectsZeroPanels) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::midpoint_rule{}.nodes(0); }, "invalid n = 0: expected at least 1 panel"));
}

}  // namespace
