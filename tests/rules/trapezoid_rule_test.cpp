#include "quadmc/rules/trapezoid_rule.hpp"

#include "jump_integrand.hpp"
#include "log_log_slope.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using quadmc::test_support::eps;

// Exact for linear f (the chord is the function). f = 3x − 2 on [−1, 2], ∫ = −1.5 (see the
// midpoint test). Bound: 4·n ulp of (b − a)·max|f| = 3·5.
TEST(TrapezoidRule, ExactForLinearFunctions) {
  const auto f = [](double x) { return 3.0 * x - 2.0; };
  for (std::uint64_t n : {1U, 2U, 7U, 64U, 1000U}) {
    const auto r = quadmc::integrate(f, -1.0, 2.0, quadmc::trapezoid_rule{}, n);
    EXPECT_NEAR(r.value, -1.5, 4.0 * static_cast<double>(n) * eps * 15.0) << "n = " << n;
    EXPECT_EQ(r.evaluations, n + 1);
  }
}

// eˣ on [0, 1], n = 4 … 2^14: error (e − 1)h²/12 ≥ 5e-10 stays far above rounding.
TEST(TrapezoidRule, SecondOrderOnSmoothIntegrand) {
  std::vector<double> ns;
  std::vector<double> errors;
  for (std::uint64_t n = 4; n <= (1U << 14); n *= 2) {
    const auto r = quadmc::integrate([](double x) { return std::exp(x); }, 0.0, 1.0,
                                     quadmc::trapezoid_rule{}, n);
    ns.push_back(static_cast<double>(n));
    errors.push_back(r.value - std::expm1(1.0));
    EXPECT_GT(r.value, std::expm1(1.0)) << "n = " << n;  // I − T = −(b−a)h²f″/12 < 0, f convex
  }
  EXPECT_NEAR(quadmc::testing::log_log_slope(ns, errors), -2.0, 0.05);
}

// exp(sin 2πx) over one period: ∫₀¹ = I₀(1) (modified Bessel function, Abramowitz & Stegun
// 9.6.19: I₀(z) = (1/π)∫₀^π e^{z cos θ}dθ). The error decays like e^{−2πa·n}·… for every strip
// half-width a (Trefethen & Weideman 2014, Thm 3.2); here it is I_n-sized, ~1e-33 by n = 32, so
// what remains is rounding: 1e-15 relative is ~4.5 ulp.
TEST(TrapezoidRule, ExponentialConvergenceOnPeriodicIntegrand) {
  const auto f = [](double x) { return std::exp(std::sin(2.0 * std::numbers::pi * x)); };
  const double exact = std::cyl_bessel_i(0.0, 1.0);
  const auto r = quadmc::integrate(f, 0.0, 1.0, quadmc::trapezoid_rule{}, 32);
  EXPECT_LE(std::abs(r.value - exact), 1e-15 * exact) << "value " << r.value;
  // Far from algebraic: at n = 8 the error is the aliased 8th Fourier mode, ±2·I₈(1) ≈ 1.9e-7
  // (I₈(1) ≈ 2⁻⁸/8!), where an h² rate with this f″ would leave ~1e-2.
  const auto coarse = quadmc::integrate(f, 0.0, 1.0, quadmc::trapezoid_rule{}, 8);
  EXPECT_LE(std::abs(coarse.value - exact), 2.5 * std::cyl_bessel_i(8.0, 1.0)) << coarse.value;
  EXPECT_GE(std::abs(coarse.value - exact), 1.5 * std::cyl_bessel_i(8.0, 1.0)) << coarse.value;
}

TEST(TrapezoidRule, FirstOrderAcrossAJump) {
  // Tolerance ±0.1 explained in jump_integrand.hpp; the error is at most one panel.
  EXPECT_NEAR(quadmc::testing::jump_slope(quadmc::trapezoid_rule{}, false, 1.0), -1.0, 0.1);
}

TEST(TrapezoidRule, RejectsBadPanelCounts) {
  using quadmc::testing::throws_with;
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>([] { (void)quadmc::trapezoid_rule{}.nodes(0); },
                                                    "invalid n = 0: expected at least 1"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::trapezoid_rule{}.nodes(std::numeric_limits<std::uint64_t>::max()); },
      "n + 1 nodes must be countable in 64 bits"));
}

}  // namespace
