// Tests of the Euler–Maclaurin expansion of the composite rules (rules/euler_maclaurin.hpp): the
// coefficients against the textbook values and against polynomials the rules do not integrate
// exactly, Simpson's superconvergence on 1/(1 + x²), and a periodic integrand on which every
// end-point term vanishes.
#include "quadmc/rules/euler_maclaurin.hpp"

#include "quadmc/functions/classic_1d.hpp"
#include "quadmc/functions/endpoint_derivatives.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>
#include <boost/math/differentiation/autodiff.hpp>
#include <boost/math/special_functions/bessel.hpp>

#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <string>

namespace quadmc {
namespace {

using quadmc::test_support::eps;

// The coefficients c_j of ∫f − Q(f) = Σ c_j·H^j·[f⁽ʲ⁻¹⁾(1) − f⁽ʲ⁻¹⁾(0)] in the convention of
// docs/theory.md#euler-maclaurin-expansion (H the width of the rule's panel: a pair for Simpson)
// [Stoer & Bulirsch, §3.3]. Computed from the rule's nodes and weights
// in double, so 1e-13 relative.
TEST(EulerMaclaurin, CoefficientsAreTheTextbookOnes) {
  const auto trapezoid = euler_maclaurin_rule::of(trapezoid_rule{}, 1);
  EXPECT_NEAR(static_cast<double>(trapezoid.coefficient(2)), -1.0 / 12.0, 1e-13 / 12.0);
  EXPECT_NEAR(static_cast<double>(trapezoid.coefficient(4)), 1.0 / 720.0, 1e-13 / 720.0);
  EXPECT_EQ(trapezoid.coefficient(3), 0.0L);
  EXPECT_EQ(trapezoid.order(), 2);

  const auto midpoint = euler_maclaurin_rule::of(midpoint_rule{}, 1);
  EXPECT_NEAR(static_cast<double>(midpoint.coefficient(2)), 1.0 / 24.0, 1e-13 / 24.0);
  EXPECT_NEAR(static_cast<double>(midpoint.coefficient(4)), -7.0 / 5760.0, 1e-13 * 7.0 / 5760.0);
  EXPECT_EQ(midpoint.coefficient(3), 0.0L);
  EXPECT_EQ(midpoint.order(), 2);

  const auto simpson = euler_maclaurin_rule::of(simpson_rule{}, 2);
  EXPECT_EQ(simpson.coefficient(2), 0.0L) << "Simpson is exact for cubics";
  EXPECT_NEAR(static_cast<double>(simpson.coefficient(4)), -1.0 / 2880.0, 1e-13 / 2880.0);
  EXPECT_NEAR(static_cast<double>(simpson.coefficient(6)), 1.0 / 96768.0, 1e-13 / 96768.0);
  EXPECT_EQ(simpson.order(), 4);

  // Two-point Gauss–Legendre: c₄ = (m!)⁴/((2m + 1)((2m)!)³) = 16/(5·24³) = 1/4320 and nothing
  // below order 2m = 4 [Davis & Rabinowitz, §2.7].
  const auto gauss = euler_maclaurin_rule::of(gauss_legendre_rule{2}, 1);
  EXPECT_EQ(gauss.order(), 4);
  EXPECT_NEAR(static_cast<double>(gauss.coefficient(4)), 1.0 / 4320.0, 1e-12 / 4320.0);
}

// On a polynomial the expansion terminates and is exact: for x^d on [0, 1] with n panels,
// ∫ − Q = Σ_{j ≤ d} c_j·H^j·[p⁽ʲ⁻¹⁾(1) − p⁽ʲ⁻¹⁾(0)], p⁽ᵏ⁾(1) − p⁽ᵏ⁾(0) = d!/(d − k)! for k < d.
// The degree is two above what the rule integrates exactly, so both of its first coefficients
// matter: a wrong c_r or c_(r+2) moves the sum by ≥ 1e-4 of the error, far above the rounding
// (n + 1 terms ≤ 1 summed pairwise: ~n·ε).
template <class R>
void expect_exact_on_monomial(const R& rule, std::uint64_t unit, int degree) {
  const auto em = euler_maclaurin_rule::of(rule, unit);
  for (std::uint64_t n : {unit, 2 * unit, 3 * unit, 8 * unit}) {
    const double q =
        integrate([degree](double x) { return std::pow(x, degree); }, 0.0, 1.0, rule, n).value;
    const double measured = 1.0 / (degree + 1.0) - q;
    const long double h = static_cast<long double>(unit) / static_cast<long double>(n);
    long double predicted = 0.0L;
    for (int j = 1; j <= degree; ++j) {
      long double delta = 1.0L;  // d!/(d − j + 1)!
      for (int k = 0; k < j - 1; ++k) delta *= static_cast<long double>(degree - k);
      predicted += em.coefficient(j) * std::pow(h, static_cast<long double>(j)) * delta;
    }
    EXPECT_NEAR(measured, static_cast<double>(predicted), 64.0 * eps)
        << rule.name() << ", x^" << degree << ", n = " << n;
    EXPECT_GT(std::abs(measured), 1e-6) << "the rule must not be exact on this polynomial";
  }
}

TEST(EulerMaclaurin, ExpansionIsExactOnPolynomialsTheRuleMisses) {
  expect_exact_on_monomial(trapezoid_rule{}, 1, 4);
  expect_exact_on_monomial(midpoint_rule{}, 1, 4);
  expect_exact_on_monomial(simpson_rule{}, 2, 6);
  expect_exact_on_monomial(gauss_legendre_rule{2}, 1, 6);
}

// Simpson on 1/(1 + x²): f‴(0) = f‴(1) = 0, so the H⁴ term vanishes and the error is
// (1/96768)·H⁶·[f⁽⁵⁾(1) − f⁽⁵⁾(0)] + O(H⁸) with f⁽⁵⁾(1) − f⁽⁵⁾(0) = 15. At n = 8 … 64 the
// error (≥ 2e-13) is ≥ 200 times the pairwise rounding of 65 terms (~6ε·π/4), so 1% is the
// expansion's own accuracy.
TEST(EulerMaclaurin, SimpsonOnInverseQuadraticIsSixthOrder) {
  const integrand_info info = inverse_quadratic_1d{}.info();
  const auto prediction =
      euler_maclaurin_prediction::make(euler_maclaurin_rule::of(simpson_rule{}, 2), info);
  ASSERT_TRUE(prediction.has_value());
  EXPECT_EQ(prediction->rule_order(), 4);
  EXPECT_EQ(prediction->leading_order(), 6);
  EXPECT_NE(prediction->vanished().find("f⁽³⁾(1) − f⁽³⁾(0) = 0"), std::string::npos)
      << prediction->vanished();
  for (std::uint64_t n : {8U, 16U, 32U, 64U}) {
    const double q = integrate(inverse_quadratic_1d{}, simpson_rule{}, n).value;
    const double measured = q - std::numbers::pi / 4;
    const euler_maclaurin_value p = prediction->at(n);
    EXPECT_LE(p.next_change, 0.01) << "n = " << n;
    EXPECT_NEAR(measured / p.error, 1.0, 0.01)
        << "n = " << n << ": " << measured << " vs " << p.error;
  }
  // The leading term alone: I − Q ≈ (15/96768)·H⁶ (H = 2/n, the width of a pair), within the
  // H⁸ term's share at n = 16 (a few percent).
  const double h = 2.0 / 16.0;
  EXPECT_NEAR(-prediction->at(16).error / (15.0 / 96768.0 * std::pow(h, 6)), 1.0, 0.05);
}

// e^{sin 2πx} is periodic with every derivative: every end-point term vanishes, and the
// trapezoid rule converges exponentially [Trefethen & Weideman 2014, Thm 3.2]. The end-point
// derivatives come from Boost.Math's automatic differentiation, independent of the closed forms.
TEST(EulerMaclaurin, PeriodicIntegrandHasNoEndpointTerm) {
  using boost::math::differentiation::make_fvar;
  constexpr std::size_t K = endpoint_derivative_count - 1;
  const auto derivatives = [](double x) {
    const auto v = make_fvar<double, K>(x);
    const auto y = exp(sin(2.0 * std::numbers::pi * v));
    return [y](std::size_t k) { return static_cast<double>(y.derivative(k)); };
  };
  integrand_info info;
  info.domain = box{{0.0}, {1.0}};
  info.exact = boost::math::cyl_bessel_i(0, 1.0);  // ∫₀¹ e^{sin 2πx} dx = I₀(1)
  info.endpoint_derivatives = endpoint::product_of(
      1.0, {endpoint::factor_of(derivatives(0.0), derivatives(1.0), 0.0, 1.0, info.exact)});
  ASSERT_TRUE(info.endpoint_derivatives.has_value());
  const auto prediction =
      euler_maclaurin_prediction::make(euler_maclaurin_rule::of(trapezoid_rule{}, 1), info);
  ASSERT_TRUE(prediction.has_value());
  EXPECT_EQ(prediction->leading_order(), 0) << "no term through H^24 survives";
  // And the rule does converge faster than any power: n = 4 → 8 gains more than 2^6.
  const auto f = [](double x) { return std::exp(std::sin(2.0 * std::numbers::pi * x)); };
  const double e4 = std::abs(integrate(f, 0.0, 1.0, trapezoid_rule{}, 4).value - info.exact);
  const double e8 = std::abs(integrate(f, 0.0, 1.0, trapezoid_rule{}, 8).value - info.exact);
  EXPECT_LT(e8, e4 / 64.0);
}

// 1/(1 + (x/a)²) on [0, 1]: poles ±i·a above the end 0 (residues ∓i·a/2), at distance d = a,
// with its end-point data in closed form (g⁽ᵏ⁾(x) = a⁻ᵏ·r⁽ᵏ⁾(x/a), r(t) = 1/(1 + t²)).
integrand_info scaled_inverse_quadratic(double a) {
  integrand_info info;
  info.domain = box{{0.0}, {1.0}};
  info.exact = a * std::atan(1.0 / a);
  const auto at = [a](double x) {
    return [a, x](std::size_t k) {
      return std::pow(a, -static_cast<double>(k)) * endpoint::inverse_quadratic(k, x / a);
    };
  };
  auto factor = endpoint::factor_of(at(0.0), at(1.0), 0.0, 1.0, info.exact);
  if (factor) factor->poles = endpoint::inverse_quadratic_poles(1.0 / a, 0.0);
  info.endpoint_derivatives = endpoint::product_of(1.0, {std::move(factor)});
  return info;
}

// The coarse-grid term (docs/theory.md#coarse-grid-term) against the measured error of the
// trapezoid, midpoint and Simpson rules on 1/(1 + (x/a)²) for a = 1/4, 1/2, 1, on grids where the
// term is at least 10 times the tolerance, so that the end-point terms alone miss. Tolerance from
// the derivation: what the prediction leaves out is the end-point series past its second term;
// the third term is |P₃ − P₂| = next_change·|P₂| (no uncertain pole here: the poles sit exactly
// above the end 0, where ω = 1/2 is exact), and an asymptotic series errs by about its first
// omitted term, so 2·|P₃ − P₂| (factor 2 for the terms past the third), plus 64ε·|I| for the
// rule's own rounding.
TEST(EulerMaclaurin, CoarseGridTermOfPolesMatchesTheMeasuredError) {
  std::map<std::string, int> checked;
  std::map<double, int> checked_a;
  for (const double a : {0.25, 0.5, 1.0}) {
    const integrand_info info = scaled_inverse_quadratic(a);
    ASSERT_TRUE(info.endpoint_derivatives.has_value());
    const auto f = [a](double x) { return 1.0 / (1.0 + (x / a) * (x / a)); };
    const auto check = [&](const char* name, const auto& rule, std::uint64_t unit,
                           std::uint64_t n) {
      const auto prediction =
          euler_maclaurin_prediction::make(euler_maclaurin_rule::of(rule, unit), info);
      ASSERT_TRUE(prediction.has_value());
      const euler_maclaurin_value p = prediction->at(n);
      if (!(p.next_change <= 0.01)) return;  // the end-point series is not predictive yet
      const double measured = integrate(f, 0.0, 1.0, rule, n).value - info.exact;
      const double tolerance =
          2.0 * p.next_change * std::abs(p.error) + 64.0 * eps * std::abs(info.exact);
      if (std::abs(p.coarse_grid) < 10.0 * tolerance) return;  // too small to test the term
      ++checked[name];
      ++checked_a[a];
      EXPECT_NEAR(measured, p.error, tolerance)
          << name << " a = " << a << " n = " << n << ": coarse-grid part " << p.coarse_grid;
      // Without the term the prediction misses by more than the tolerance.
      EXPECT_GT(std::abs(measured - (p.error - p.coarse_grid)), tolerance) << name << " n = " << n;
    };
    for (const std::uint64_t n : {1U, 2U, 3U, 4U, 6U, 8U}) {
      check("trapezoid", trapezoid_rule{}, 1, n);
      check("midpoint", midpoint_rule{}, 1, n);
    }
    for (const std::uint64_t n : {2U, 4U, 6U, 8U, 12U, 16U}) check("simpson", simpson_rule{}, 2, n);
  }
  // The derivation is exercised on every rule and every a: a grid each at least.
  for (const char* name : {"trapezoid", "midpoint", "simpson"}) {
    EXPECT_GE(checked[name], 1) << name;
  }
  for (const double a : {0.25, 0.5, 1.0}) EXPECT_GE(checked_a[a], 1) << "a = " << a;
}

// Simpson's term is led by the coarse trapezoid sum on the pair width H: −(π/3)·a·e^(−2πa/H)
// for 1/(1 + (x/a)²) (two poles, weight 1/2 each, ŵ(1) = −1/3), the square root of the
// trapezoid's e^(−2πa/h) on the same nodes (h = H/2).
TEST(EulerMaclaurin, SimpsonsCoarseGridTermIsOnThePairWidth) {
  for (const double a : {0.5, 1.0}) {
    const integrand_info info = scaled_inverse_quadratic(a);
    const auto simpson =
        euler_maclaurin_prediction::make(euler_maclaurin_rule::of(simpson_rule{}, 2), info);
    const auto trapezoid =
        euler_maclaurin_prediction::make(euler_maclaurin_rule::of(trapezoid_rule{}, 1), info);
    ASSERT_TRUE(simpson && trapezoid);
    const std::uint64_t n = 4;  // H = 1/2, h = 1/4
    const double pair = 0.5;
    const double leading =
        -(std::numbers::pi / 3.0) * a * std::exp(-2.0 * std::numbers::pi * a / pair);
    // The next harmonics are e^(−2πa/H) smaller.
    EXPECT_NEAR(simpson->at(n).coarse_grid / leading, 1.0,
                4.0 * std::exp(-2.0 * std::numbers::pi * a / pair))
        << "a = " << a;
    const double trapezoid_term = std::numbers::pi * a * std::exp(-2.0 * std::numbers::pi * a * n);
    EXPECT_NEAR(trapezoid->at(n).coarse_grid / trapezoid_term, 1.0,
                4.0 * std::exp(-2.0 * std::numbers::pi * a * n))
        << "a = " << a;
  }
}

}  // namespace
}  // namespace quadmc
