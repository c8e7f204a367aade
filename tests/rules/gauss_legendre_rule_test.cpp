#include "quadmc/rules/gauss_legendre_rule.hpp"

#include "jump_integrand.hpp"
#include "log_log_slope.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace {

using quadmc::test_support::eps;

// m nodes integrate degree 2m − 1 exactly: xᵈ + x^(d−1) on [0, 1] with d = 2m − 1, ∫ = 1/(d + 1)
// + 1/d. Bound: 4·n ulp of (b − a)·max|f| = 2 (the node tables themselves are correctly rounded
// or, for m ≤ 5, computed by Boost to ~1 ulp).
TEST(GaussLegendreRule, ExactForDegreeTwoMMinusOne) {
  for (unsigned m : quadmc::gauss_legendre_rule::supported_points) {
    const int d = 2 * static_cast<int>(m) - 1;
    const auto f = [d](double x) { return std::pow(x, d) + std::pow(x, d - 1); };
    const double exact = 1.0 / (d + 1) + 1.0 / d;
    for (std::uint64_t n : {1U, 3U, 8U}) {
      const auto r = quadmc::integrate(f, 0.0, 1.0, quadmc::gauss_legendre_rule(m), n);
      EXPECT_NEAR(r.value, exact, 4.0 * static_cast<double>(n) * eps * 2.0)
          << "m = " << m << " n = " << n;
      EXPECT_EQ(r.evaluations, m * n);
    }
  }
}

// …and not degree 2m: x^(2m) on one panel [−1, 1] errs by 2^(2m+1)(m!)⁴/((2m + 1)((2m)!)³)·(2m)!
// (Davis & Rabinowitz eq. 2.7.12 with f^(2m) = (2m)!): 8/45 for m = 2 (2/9 against 2/5), 2.9e-3
// for m = 5, so 1e-4 separates "not exact" from rounding for m ≤ 5.
TEST(GaussLegendreRule, NotExactForDegreeTwoM) {
  for (unsigned m : {2U, 3U, 4U, 5U}) {
    const int d = 2 * static_cast<int>(m);
    const auto r = quadmc::integrate([d](double x) { return std::pow(x, d); }, -1.0, 1.0,
                                     quadmc::gauss_legendre_rule(m), 1);
    EXPECT_GT(std::abs(r.value - 2.0 / (d + 1)), 1e-4) << "m = " << m;
  }
}

// One panel on [−1, 1] is Boost's own gauss<double, M>::integrate; the unfolding of the
// half-tables into ascending nodes must not change it beyond the summation order (a few ε).
TEST(GaussLegendreRule, OnePanelMatchesBoost) {
  const auto f = [](double x) { return std::exp(x) * std::cos(3.0 * x); };
  const auto check = [&](auto boost_value, unsigned m) {
    const auto r = quadmc::integrate(f, -1.0, 1.0, quadmc::gauss_legendre_rule(m), 1);
    EXPECT_NEAR(r.value, boost_value, 8.0 * eps * 2.0 * std::exp(1.0)) << "m = " << m;
  };
  check(boost::math::quadrature::gauss<double, 3>::integrate(f, -1.0, 1.0), 3);
  check(boost::math::quadrature::gauss<double, 4>::integrate(f, -1.0, 1.0), 4);
  check(boost::math::quadrature::gauss<double, 7>::integrate(f, -1.0, 1.0), 7);
  check(boost::math::quadrature::gauss<double, 20>::integrate(f, -1.0, 1.0), 20);
}

// Order 2m: eˣ on [0, 1]. m = 2, n = 2 … 128: error ≈ (e − 1)H⁴/4320 ≥ 1e-12, above rounding.
// m = 3, n = 1 … 16: error ≈ (e − 1)H⁶/2016000 ≥ 5e-14.
TEST(GaussLegendreRule, OrderTwoMOnSmoothIntegrand) {
  const auto slope = [](unsigned m, std::uint64_t n_max) {
    std::vector<double> ns;
    std::vector<double> errors;
    for (std::uint64_t n = m == 2 ? 2 : 1; n <= n_max; n *= 2) {
      const auto r = quadmc::integrate([](double x) { return std::exp(x); }, 0.0, 1.0,
                                       quadmc::gauss_legendre_rule(m), n);
      ns.push_back(static_cast<double>(n));
      errors.push_back(r.value - std::expm1(1.0));
    }
    return quadmc::testing::log_log_slope(ns, errors);
  };
  EXPECT_NEAR(slope(2, 128), -4.0, 0.1);
  EXPECT_NEAR(slope(3, 16), -6.0, 0.15);
}

TEST(GaussLegendreRule, FirstOrderAcrossAJump) {
  // Tolerance ±0.1 explained in jump_integrand.hpp; the error is at most one panel.
  EXPECT_NEAR(quadmc::testing::jump_slope(quadmc::gauss_legendre_rule(3), false, 1.0), -1.0, 0.1);
}

TEST(GaussLegendreRule, RejectsUnsupportedPointCountsAndOverflow) {
  using quadmc::testing::throws_with;
  for (unsigned m : {0U, 1U, 6U, 31U}) {
    EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
        [m] { (void)quadmc::gauss_legendre_rule(m); },
        "m (Gauss–Legendre points per panel) = " + std::to_string(m) +
            ": expected one of 2, 3, 4, 5, 7, 10, 15, 20, 25, 30"))
        << "m = " << m;
  }
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::gauss_legendre_rule(3).nodes(0); }, "invalid n = 0"));
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] {
        (void)quadmc::gauss_legendre_rule(3).nodes(std::numeric_limits<std::uint64_t>::max() / 2);
      },
      "m·n nodes must be countable in 64 bits"));
  // The largest n whose m·n still fits is accepted (no floating-point estimate of the limit).
  EXPECT_EQ(
      quadmc::gauss_legendre_rule(3).nodes(std::numeric_limits<std::uint64_t>::max() / 3).size(),
      std::numeric_limits<std::uint64_t>::max() / 3 * 3);
}

}  // namespace
