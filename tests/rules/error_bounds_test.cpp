#include "quadmc/rules/error_bounds.hpp"

#include "reference_integrands.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <span>
#include <string>
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

// Why the bounds are attained. Every rule here has a Peano kernel of one sign on each panel
// (Davis & Rabinowitz, "Methods of Numerical Integration", 2nd ed., §4.3), so the mean-value
// theorem gives the error on panel i exactly as C·h^k·H·f⁽ᵏ⁾(ξ_i), ξ_i in the panel (h the node
// spacing, H the panel width: H = h except for Simpson, whose panel is a pair, H = 2h; C the
// rule's constant, e.g. 1/12 for the trapezoid), and the composite error is
//   E = C·h^k · Σ_i H·f⁽ᵏ⁾(ξ_i),
// while the library's bound is C·h^k·(b − a)·M_k. Hence bound/|E| = M_k / μ with
// μ = Σ_i H·f⁽ᵏ⁾(ξ_i)/(b − a), a mean of f⁽ᵏ⁾ over the panels. Two consequences are tested:
//  (1) f⁽ᵏ⁾ constant ⇒ μ = M_k ⇒ bound = |E| exactly: the constant is checked to rounding, so a
//      factor 2 (trapezoid ÷6 instead of ÷12) or 1.001 fails;
//  (2) f = eˣ on [0, 1], M_k = e: μ lies between the left and right Riemann sums of eˣ with
//      panel width H, L_H = (e − 1)·H/(e^H − 1) and L_H·e^H, so bound/|E| ∈ [e/(L_H·e^H), e/L_H]
//      (→ e/(e − 1) ≈ 1.58 as H → 0, width ≈ 1.58·H).
// The rounding allowance r (reference_integrands.hpp's model) enters as a relative tolerance
// r/|E| on the ratio; the cases are chosen so that it stays below 1e-4.

// One rule, one n, the derivative order k of its bound and its bound at a given M_k.
struct bound_case {
  std::string name;
  std::function<double(const std::function<double(double)>&, double, double, std::uint64_t)>
      integrate;
  std::function<double(double, double, std::uint64_t, double)> bound;
  unsigned k = 0;
  double panel_width_in_nodes = 1.0;  // H/h: 2 for Simpson (pairs of node intervals), else 1
  std::vector<std::uint64_t> n;
};

template <class R>
auto integrator(R rule) {
  return [rule](const std::function<double(double)>& f, double a, double b, std::uint64_t n) {
    return quadmc::integrate(f, a, b, rule, n).value;
  };
}

std::vector<bound_case> bound_cases() {
  using quadmc::gauss_legendre_error_bound;
  std::vector<bound_case> cases = {
      {"left_rectangle",
       integrator(quadmc::left_rectangle_rule{}),
       quadmc::rectangle_error_bound,
       1,
       1.0,
       {1, 2, 3, 7, 16}},
      {"right_rectangle",
       integrator(quadmc::right_rectangle_rule{}),
       quadmc::rectangle_error_bound,
       1,
       1.0,
       {1, 2, 3, 7, 16}},
      {"midpoint",
       integrator(quadmc::midpoint_rule{}),
       quadmc::midpoint_error_bound,
       2,
       1.0,
       {1, 2, 3, 7, 16}},
      {"trapezoid",
       integrator(quadmc::trapezoid_rule{}),
       quadmc::trapezoid_error_bound,
       2,
       1.0,
       {1, 2, 3, 7, 16}},
      {"simpson",
       integrator(quadmc::simpson_rule{}),
       quadmc::simpson_error_bound,
       4,
       2.0,
       {2, 4, 8, 16}},
  };
  for (unsigned m : {2U, 3U, 4U, 5U, 7U}) {  // m = 1 is the midpoint bound (below)
    cases.push_back(
        {"gauss_legendre_" + std::to_string(m), integrator(quadmc::gauss_legendre_rule(m)),
         [m](double a, double b, std::uint64_t n, double mk) {
           return gauss_legendre_error_bound(a, b, n, m, mk);
         },
         2 * m, 1.0, m <= 3 ? std::vector<std::uint64_t>{1, 2, 3} : std::vector<std::uint64_t>{1}});
  }
  return cases;
}

double integer_power(double x, unsigned k) {
  double p = 1.0;
  for (unsigned i = 0; i < k; ++i) p *= x;
  return p;
}

double factorial(unsigned k) {
  double p = 1.0;
  for (unsigned i = 2; i <= k; ++i) p *= i;
  return p;
}

// (1): f = (x − a)^k on [a, b] = [0.5, 2] (b − a ≠ 1 and a ≠ 0, so every power of b − a and h in
// the bound matters), f⁽ᵏ⁾ = k! everywhere, ∫ = (b − a)^{k+1}/(k + 1).
TEST(ErrorBounds, AreAttainedWhenTheDerivativeIsConstant) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double a = 0.5, b = 2.0, length = b - a;
  for (const bound_case& c : bound_cases()) {
    const unsigned k = c.k;
    const std::function<double(double)> f = [&](double x) { return integer_power(x - a, k); };
    const double exact = integer_power(length, k + 1) / (k + 1);
    // r = 16ε(b − a)(M₀ + M₁·max(|a|, |b|)), M₀ = (b − a)^k, M₁ = k(b − a)^{k−1}; the bound
    // itself rounds a few times (Gauss: factorials and pow, "a few ulp"): 64ε relative.
    const double allowance =
        16.0 * eps * length *
        (integer_power(length, k) + k * integer_power(length, k - 1) * std::max(a, b));
    for (std::uint64_t n : c.n) {
      const double error = std::abs(c.integrate(f, a, b, n) - exact);
      const double ratio = c.bound(a, b, n, factorial(k)) / error;
      const double tolerance = allowance / error + 64.0 * eps;
      ASSERT_LT(tolerance, 1e-4) << c.name << " n = " << n << ": the case cannot resolve 1e-4";
      EXPECT_NEAR(ratio, 1.0, tolerance) << c.name << " n = " << n << ", error " << error;
    }
  }
}

// (2): eˣ on [0, 1]: bound/|E| ∈ [e/(L_H·e^H), e/L_H] with L_H = (e − 1)·H/(e^H − 1).
TEST(ErrorBounds, OverErrorForExpLieBetweenTheRiemannSumsOfTheDerivative) {
  const smooth_case c = quadmc::testing::smooth_cases().front();
  ASSERT_EQ(c.name, "exp");
  const double e = std::numbers::e;
  const double slack = quadmc::testing::rounding_allowance(c);
  const std::function<double(double)> f = c.f;
  for (const bound_case& r : bound_cases()) {
    // Gauss m ≥ 5 on eˣ: |E| ≈ 1e-12 already at n = 1, too close to rounding to resolve 1e-4.
    if (r.k > 8) continue;
    for (std::uint64_t n : r.n) {
      const double panel = r.panel_width_in_nodes / static_cast<double>(n);
      const double left_sum = std::expm1(1.0) * panel / std::expm1(panel);
      const double error = std::abs(r.integrate(f, c.a, c.b, n) - c.exact);
      const double ratio = r.bound(c.a, c.b, n, e) / error;
      const double tolerance = slack / error;
      ASSERT_LT(tolerance, 1e-4) << r.name << " n = " << n;
      EXPECT_GE(ratio, e / (left_sum * std::exp(panel)) * (1.0 - tolerance))
          << r.name << " n = " << n;
      EXPECT_LE(ratio, e / left_sum * (1.0 + tolerance)) << r.name << " n = " << n;
    }
  }
}

// Gauss with m = 1 would be the midpoint rule: the general constant must reduce to 1/24.
TEST(ErrorBounds, GaussConstantReducesToMidpoint) {
  EXPECT_DOUBLE_EQ(quadmc::gauss_legendre_error_bound(0.0, 2.0, 5, 1, 3.0),
                   quadmc::midpoint_error_bound(0.0, 2.0, 5, 3.0));
}

// exp(x₁ + … + x_s) on [0, 1]^s: ∂ᵏ/∂x_jᵏ f = f ≤ e^s on the box, so M_k = e^s on every axis.
struct exp_of_sum_on_unit_cube {
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

// Σ_j c_j·(x_j − a_j)^k over a box with unequal sides L_j: ∂ᵏf/∂x_jᵏ = c_j·k! on axis j. The
// rules integrate constants exactly (positive weights summing to L_i), so the tensor error is
// exactly Σ_j c_j·E_j·Π_{i≠j} L_i with E_j the 1D error of (x − a_j)^k on axis j, all of one sign
// (c_j > 0); each E_j attains its 1D bound (test (1) above), hence the tensor bound equals the
// error to rounding. A wrong side product Π_{i≠j} L_i, a missing axis, the wrong axis's M_k or a
// wrong 1D constant all fail.
struct sum_of_powers {
  quadmc::box domain;
  std::vector<double> c;  // per-axis coefficients, powers of 2 (exact products)
  unsigned k;
  std::size_t dimension() const { return domain.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = dimension();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < s; ++j) {
        sum += c[j] * integer_power(x[i * s + j] - domain.lower[j], k);
      }
      y[i] = sum;
    }
  }
  double volume() const {
    double v = 1.0;
    for (std::size_t j = 0; j < dimension(); ++j) v *= domain.upper[j] - domain.lower[j];
    return v;
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info i;
    i.name = "sum_of_powers";
    i.domain = domain;
    i.exact = 0.0;
    for (std::size_t j = 0; j < dimension(); ++j) {
      const double side = domain.upper[j] - domain.lower[j];
      // c_j·L_j^{k+1}/(k + 1)·Π_{i≠j} L_i
      i.exact += c[j] * integer_power(side, k) / (k + 1) * volume();
    }
    const bool same_on_every_axis =
        std::all_of(c.begin(), c.end(), [&](double v) { return v == c.front(); });
    if (k <= 4 && same_on_every_axis) i.derivative_bound[k] = c.front() * factorial(k);
    return i;
  }
};

TEST(ErrorBounds, TensorBoundIsAttainedForASumOfOneDimensionalPowers) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const quadmc::box boxes[] = {{{0.5, -1.0}, {2.0, 0.0}},             // sides 1.5, 1
                               {{0.5, -1.0, 0.0}, {2.0, 0.0, 3.0}}};  // sides 1.5, 1, 3
  for (const quadmc::box& domain : boxes) {
    const std::size_t s = domain.dimension();
    const std::vector<double> ones(s, 1.0);
    const std::vector<double> unequal =
        s == 2 ? std::vector<double>{2.0, 0.5} : std::vector<double>{2.0, 0.5, 1.0};
    const auto check = [&](const auto& rule, unsigned k, std::uint64_t n) {
      for (const std::vector<double>& c : {ones, unequal}) {
        const sum_of_powers f{domain, c, k};
        const auto info = f.info();
        const double error = std::abs(quadmc::integrate(f, rule, n).value - info.exact);
        std::vector<double> per_axis;
        for (double cj : c) per_axis.push_back(cj * factorial(k));
        const double bound = quadmc::tensor_product_error_bound(rule, domain, n, per_axis);
        // Rounding: reference_integrands.hpp's 16ε·volume·(M₀ + M₁·max|x|), with M₀ = max f ≤
        // 2s·3^k and M₁ = 2k·3^{k−1} (c_j ≤ 2, sides and coordinates ≤ 3), per axis term.
        const double allowance =
            16.0 * eps * f.volume() * s *
            (2.0 * s * integer_power(3.0, k) + 2.0 * k * integer_power(3.0, k - 1) * 3.0);
        const double tolerance = allowance / error + 64.0 * eps;
        const std::string what = std::string(rule.name()) + " s = " + std::to_string(s) +
                                 " n = " + std::to_string(n) + " c₀ = " + std::to_string(c[0]);
        ASSERT_LT(tolerance, 1e-4) << what;
        EXPECT_NEAR(bound / error, 1.0, tolerance) << what;
        if (k <= 4 && info.derivative_bound[k].has_value()) {
          // The metadata overload: one M_k for every axis.
          EXPECT_NEAR(quadmc::tensor_product_error_bound(rule, info, n) / error, 1.0, tolerance)
              << what;
        }
      }
    };
    for (std::uint64_t n : {2U, 4U, 8U}) {
      check(quadmc::left_rectangle_rule{}, 1, n);
      check(quadmc::right_rectangle_rule{}, 1, n);
      check(quadmc::midpoint_rule{}, 2, n);
      check(quadmc::trapezoid_rule{}, 2, n);
      check(quadmc::simpson_rule{}, 4, n);
      check(quadmc::gauss_legendre_rule(2), 4, n);
    }
    check(quadmc::gauss_legendre_rule(3), 6, 1);
    check(quadmc::gauss_legendre_rule(3), 6, 2);
  }
}

// exp(x₁ + … + x_s) on [0, 1]^s with M_k = e^s on every axis (a derivative that varies):
// Q⊗ = q^s with q the 1D rule on eˣ, so with ε = (e − 1) − q the tensor error is
//   |(e − 1)^s − q^s| = |ε|·Σ_{j<s} (e − 1)^{s−1−j} q^j,
// and the bound is s·C'h^k·e^s against the 1D |ε| = C'h^k·μ (test (2): μ ∈ [L_H, L_H·e^H]):
//   bound/error = s·e^{s−1} / Σ_{j<s} (e − 1)^{s−1−j} q^j · e/μ
// (→ (e/(e − 1))^s as h → 0). q is measured with the 1D rule: only the bound is under test.
TEST(ErrorBounds, TensorBoundOverErrorForExpOfSumLiesInTheDerivedInterval) {
  const double e = std::numbers::e;
  const double e1 = std::expm1(1.0);
  for (std::size_t s : {2U, 3U}) {
    const exp_of_sum_on_unit_cube f{s};
    const auto info = f.info();
    const auto check = [&](const auto& rule, double panel_width_in_nodes, std::uint64_t n) {
      const double q =
          quadmc::integrate([](double x) { return std::exp(x); }, 0.0, 1.0, rule, n).value;
      double sum = 0.0;
      for (std::size_t j = 0; j < s; ++j) {
        sum += std::pow(e1, static_cast<double>(s - 1 - j)) * std::pow(q, static_cast<double>(j));
      }
      const double factor = static_cast<double>(s) * std::pow(e, static_cast<double>(s - 1)) / sum;
      const double panel = panel_width_in_nodes / static_cast<double>(n);
      const double left_sum = e1 * panel / std::expm1(panel);
      const double error = std::abs(quadmc::integrate(f, rule, n).value - info.exact);
      const double ratio = quadmc::tensor_product_error_bound(rule, info, n) / error;
      // Rounding of the tensor sum and of the reference (e − 1)^s: 16ε·e^s·s per the 1D model.
      const double tolerance =
          16.0 * std::numeric_limits<double>::epsilon() * std::exp(double(s)) * s / error;
      ASSERT_LT(tolerance, 1e-4) << rule.name() << " s = " << s << " n = " << n;
      EXPECT_GE(ratio, factor * e / (left_sum * std::exp(panel)) * (1.0 - tolerance))
          << rule.name() << " s = " << s << " n = " << n;
      EXPECT_LE(ratio, factor * e / left_sum * (1.0 + tolerance))
          << rule.name() << " s = " << s << " n = " << n;
    };
    for (std::uint64_t n : {4U, 8U, 16U}) {
      check(quadmc::midpoint_rule{}, 1.0, n);
      check(quadmc::trapezoid_rule{}, 1.0, n);
      check(quadmc::simpson_rule{}, 2.0, n);
      check(quadmc::left_rectangle_rule{}, 1.0, n);
      check(quadmc::right_rectangle_rule{}, 1.0, n);
      check(quadmc::gauss_legendre_rule(2), 1.0, n);
    }
  }
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
  quadmc::integrand_info info = exp_of_sum_on_unit_cube{2}.info();
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
