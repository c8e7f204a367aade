// Tests of periodizing_transforms.hpp (docs/theory.md#lattice-periodizations): each transform
// leaves the integral as it was on smooth families of the catalogue, maps [0, 1] onto itself
// increasingly with φ' its derivative, matches the textbook formulas, keeps φ relatively accurate
// near 0, and makes the weighted integrand vanish to exactly the claimed order at both ends.
#include "quadmc/sampling/periodizing_transforms.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace quadmc {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double pi = std::numbers::pi;

static_assert(periodizing_transform<c0_transform>);
static_assert(periodizing_transform<c1_transform>);
static_assert(periodizing_transform<c1sin_transform>);
static_assert(periodizing_transform<c2sin_transform>);
static_assert(periodizing_transform<c3sin_transform>);

// The formulas as QMCPy's periodization_transform options and the papers write them (φ, φ'),
// evaluated as written: the reference the stable forms must agree with. c3sin's φ' is the
// derivative of its φ, (12π − 16π cos 2πx + 4π cos 4πx)/(12π) ([Sidi 1993]).
struct textbook {
  double (*phi)(double);
  double (*jacobian)(double);
};
textbook textbook_of(std::string_view name) {
  if (name == "c0") {
    return {[](double x) { return 3 * x * x - 2 * x * x * x; },
            [](double x) { return 6 * x * (1 - x); }};
  }
  if (name == "c1") {
    return {[](double x) { return x * x * x * (10 - 15 * x + 6 * x * x); },
            [](double x) { return 30 * x * x * (1 - x) * (1 - x); }};
  }
  if (name == "c1sin") {
    return {[](double x) { return x - std::sin(2 * pi * x) / (2 * pi); },
            [](double x) { return 1 - std::cos(2 * pi * x); }};
  }
  if (name == "c2sin") {
    return {
        [](double x) { return (8 - 9 * std::cos(pi * x) + std::cos(3 * pi * x)) / 16; },
        [](double x) { return (9 * pi * std::sin(pi * x) - 3 * pi * std::sin(3 * pi * x)) / 16; }};
  }
  return {[](double x) {
            return (12 * pi * x - 8 * std::sin(2 * pi * x) + std::sin(4 * pi * x)) / (12 * pi);
          },
          [](double x) {
            return (12 * pi - 16 * pi * std::cos(2 * pi * x) + 4 * pi * std::cos(4 * pi * x)) /
                   (12 * pi);
          }};
}

// lim φ'(x)/x^m at 0 (m = jacobian_zero_order): 6, 30, 2π², (3π/4)π³, (8/3)π⁴; and φ(x)/x^(m+1)
// = that over m + 1.
double jacobian_leading(std::string_view name) {
  if (name == "c0") return 6.0;
  if (name == "c1") return 30.0;
  if (name == "c1sin") return 2.0 * pi * pi;
  if (name == "c2sin") return 0.75 * pi * pi * pi * pi;
  return 8.0 / 3.0 * pi * pi * pi * pi;
}

// max |φ'''| on [0, 1], from the formulas above: 12, 60, 4π², (9 + 27)π³/16, 32π²/3.
double third_derivative_bound(std::string_view name) {
  if (name == "c0") return 12.0;
  if (name == "c1") return 60.0;
  if (name == "c1sin") return 4.0 * pi * pi;
  if (name == "c2sin") return 36.0 * pi * pi * pi / 16.0;
  return 32.0 * pi * pi / 3.0;
}

template <class T>
class PeriodizingTransform : public ::testing::Test {};
using transforms =
    ::testing::Types<c0_transform, c1_transform, c1sin_transform, c2sin_transform, c3sin_transform>;
TYPED_TEST_SUITE(PeriodizingTransform, transforms);

// φ(0) = 0, φ(1) = 1 up to the [0, 1) clamp, increasing on a grid with every dyadic scale down to
// 2^−53 at both ends, φ' ≥ 0.
TYPED_TEST(PeriodizingTransform, MapsTheUnitIntervalOntoItselfIncreasingly) {
  using T = TypeParam;
  EXPECT_EQ(periodize<T>(0.0).value, 0.0);
  EXPECT_EQ(periodize<T>(0.0).jacobian, 0.0);
  EXPECT_EQ(periodize<T>(1.0).value, largest_below_one) << "φ(1) = 1, clamped into [0, 1)";
  std::vector<double> x{0.0};
  for (int k = 53; k >= 2; --k) x.push_back(std::ldexp(1.0, -k));
  for (int i = 1; i < 4096; ++i) x.push_back(0.25 + 0.5 * i / 4096.0);
  for (int k = 2; k <= 53; ++k) x.push_back(1.0 - std::ldexp(1.0, -k));
  double last = -1.0;
  for (const double xi : x) {
    const periodized_coordinate c = periodize<T>(xi);
    EXPECT_GE(c.jacobian, 0.0) << T::name << " x = " << xi;
    EXPECT_GE(c.value, 0.0) << T::name << " x = " << xi;
    EXPECT_LT(c.value, 1.0) << T::name << " x = " << xi;
    EXPECT_GE(c.value, last) << T::name << " x = " << xi;
    if (xi > 0.0 && xi <= 0.5) {
      EXPECT_GT(c.value, 0.0) << T::name << " x = " << xi;
    }
    last = c.value;
  }
}

// The stable forms against the formulas as written, on a grid of [0, 1]: both are a few roundings
// of O(1) terms (the largest, c3sin's 12πx, over 12π), so they agree to a few ε absolute; 16ε
// leaves room for the libm's sin and cos (≤ 1 ulp each) in every term.
TYPED_TEST(PeriodizingTransform, AgreesWithTheTextbookFormulas) {
  using T = TypeParam;
  const textbook ref = textbook_of(T::name);
  for (int i = 0; i <= 1000; ++i) {
    const double x = i / 1000.0;
    const periodized_coordinate c = periodize<T>(std::min(x, largest_below_one));
    EXPECT_NEAR(c.value, std::min(ref.phi(x), largest_below_one), 16 * eps) << T::name << " " << x;
    EXPECT_NEAR(c.jacobian, ref.jacobian(x), 16 * eps * 4.0) << T::name << " " << x;
  }
}

// φ' is the derivative of φ: the central difference (φ(x + h) − φ(x − h))/(2h) errs by at most
// h²·max|φ'''|/6 (Taylor) plus 2·(4ε)/(2h) from φ's own rounding (≤ 4ε absolute, as above).
// h = 2^−18 balances the two (≈ 3e-10 each); the tolerance is their sum, not a fitted figure.
TYPED_TEST(PeriodizingTransform, JacobianIsTheDerivative) {
  using T = TypeParam;
  const double h = std::ldexp(1.0, -18);
  const double tolerance = h * h * third_derivative_bound(T::name) / 6.0 + 4.0 * eps / h;
  for (int i = 1; i < 1000; ++i) {
    const double x = i / 1000.0;
    const double difference = (periodize<T>(x + h).value - periodize<T>(x - h).value) / (2 * h);
    EXPECT_NEAR(periodize<T>(x).jacobian, difference, tolerance) << T::name << " x = " << x;
  }
}

// Near 0, φ(x) = C·x^(m+1)(1 + δ) with C = lim φ'/x^m/(m + 1) and |δ| ≤ (2πx)² for the sin forms,
// 2x for the polynomials (the next Taylor term over the first). The stable forms keep that
// relative accuracy where x − sin(2πx)/(2π) and c3sin's sum would have cancelled to nothing
// (x = 2^−30: φ ≈ 1e-27 … 1e-45, below the formulas' rounding of x itself); 64ε covers the
// roundings of the series and of the powers.
TYPED_TEST(PeriodizingTransform, StaysRelativelyAccurateNearZero) {
  using T = TypeParam;
  const int m = T::jacobian_zero_order;
  const double leading = jacobian_leading(T::name);
  for (const int k : {20, 30, 40, 53}) {
    const double x = std::ldexp(1.0, -k);
    const double bound = std::max(2.0 * x, 4.0 * pi * pi * x * x) + 64 * eps;
    const periodized_coordinate c = periodize<T>(x);
    const double phi_expected = leading / (m + 1) * std::pow(x, m + 1);
    EXPECT_NEAR(c.value / phi_expected, 1.0, bound) << T::name << " x = 2^-" << k;
    EXPECT_NEAR(c.jacobian / (leading * std::pow(x, m)), 1.0, bound) << T::name << " x = 2^-" << k;
  }
}

// g = f(φ(x))φ'(x) with f smooth and f(0) ≠ ±f(1): g(x)/x^m → f(0)·C and g(1 − x)/x^m → f(1)·C
// as x → 0 (C = lim φ'/x^m; φ' is even about 1/2). So g and its first m − 1 derivatives vanish at
// both ends — g is periodic through order m − 1, the order docs/theory.md#lattice-periodizations
// claims — while g^(m) is m!·f(0)·C at 0 and (−1)^m·m!·f(1)·C at 1, which differ. The relative
// deviation at x is φ'(x)/(C·x^m) − 1 (≤ 2x, from (1 − x)^k and (sin πx/πx)^k) plus
// f(φ(x))/f(0) − 1 (≤ |f'/f|·φ(x) ≤ x here): 3x with 64ε for the roundings.
TYPED_TEST(PeriodizingTransform, WeightedIntegrandIsPeriodicThroughOrderMMinusOne) {
  using T = TypeParam;
  const int m = T::jacobian_zero_order;
  const auto f = [](double x) { return std::exp(0.5 * x); };  // f(0) = 1, f(1) = e^½
  const double c = jacobian_leading(T::name);
  for (const int k : {10, 14, 18}) {
    const double x = std::ldexp(1.0, -k);
    const double bound = 3.0 * x + 64 * eps;
    const periodized_coordinate at0 = periodize<T>(x);
    const periodized_coordinate at1 = periodize<T>(1.0 - x);
    const double g0 = f(at0.value) * at0.jacobian;
    const double g1 = f(at1.value) * at1.jacobian;
    EXPECT_NEAR(g0 / std::pow(x, m) / (f(0.0) * c), 1.0, bound) << T::name << " x = 2^-" << k;
    EXPECT_NEAR(g1 / std::pow(x, m) / (f(1.0) * c), 1.0, bound) << T::name << " x = 1 - 2^-" << k;
  }
}

// ∫ g = ∫ f for g(u) = (b − a)^s·f(a + (b − a)φ(u))∏φ'(u_j) over [0, 1]^s, by the composite
// Gauss–Legendre rule of rules/ with 30 nodes on each of P panels per axis, as a tensor product.
// Its error on a panel of width H is H^60(30!)⁴/(61·(60!)³)·|g^(60)| ([Davis & Rabinowitz,
// §2.7]); g is analytic within a distance δ of [0, 1], so |g^(60)| ≲ 60!·M/δ^60 (Cauchy) and the
// error is about M·(H/(4δ))^60·πm/(2m + 1) ≈ 1.5·M·(H/(4δ))^60. The nearest singularities are the
// product peak's poles at u ± i/a (1/a = 1/3 here) and the corner peak's at −1/a (a ≤ 0.8);
// through φ (|φ'| ≤ 8/3) they lie at δ ≥ (1/3)/(8/3) = 1/8 in u, and the sin forms' growth
// e^(π|Im u|) ≤ e^(π/8) adds under a factor 2 per axis. P = 16 (H = 1/16) puts H/(4δ) ≤ 1/8:
// the rule's error is below 1e-50, far under 1e-14, and the comparison checks the transform alone.
// The sums run in long double, so that 230 000 roundings of the terms stay below 1e-16·|I|.
template <class T>
double transformed_integral(const any_integrand& f, std::size_t panels) {
  const std::size_t s = f.dimension();
  const gauss_legendre_rule rule(30);
  const gauss_legendre_rule::node_set nodes(rule, panels);
  const std::uint64_t per_axis = nodes.size();
  const box& domain = f.info().domain;
  std::uint64_t total = 1;
  for (std::size_t j = 0; j < s; ++j) total *= per_axis;
  long double sum = 0.0L;
  std::vector<double> x(batch_points * s), w(batch_points), y(batch_points);
  std::vector<double> rule_weight(batch_points);
  for (std::uint64_t first = 0; first < total; first += batch_points) {
    const std::size_t count =
        static_cast<std::size_t>(std::min<std::uint64_t>(batch_points, total - first));
    for (std::size_t i = 0; i < count; ++i) {
      std::uint64_t k = first + i;
      rule_weight[i] = 1.0;
      for (std::size_t j = 0; j < s; ++j) {
        x[i * s + j] = nodes.node(k % per_axis);
        rule_weight[i] *= nodes.weight(k % per_axis);
        k /= per_axis;
      }
    }
    const std::span<double> batch(x.data(), count * s);
    periodize_points<T>(batch, s, std::span<double>(w.data(), count));
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t j = 0; j < s; ++j) {
        const double width = domain.upper[j] - domain.lower[j];
        x[i * s + j] = domain.lower[j] + width * x[i * s + j];
      }
    }
    f.evaluate(std::span<const double>(batch), std::span<double>(y.data(), count));
    for (std::size_t i = 0; i < count; ++i) {
      sum += static_cast<long double>(rule_weight[i]) * w[i] * y[i];
    }
  }
  return static_cast<double>(sum) * domain.volume();
}

struct family {
  std::string name;
  integrand_params params;
};

// Smooth families with closed-form integrals, a and u given (not drawn) so the analyticity
// radius above holds: the four analytic Genz families in s = 1 and 2, and three 1D classics.
std::vector<family> smooth_families() {
  std::vector<family> out;
  for (const std::size_t s : {1u, 2u}) {
    for (const char* name :
         {"genz_oscillatory", "genz_product_peak", "genz_corner_peak", "genz_gaussian"}) {
      integrand_params p;
      p.dimension = s;
      const bool corner = std::string_view(name) == "genz_corner_peak";
      p.vectors["a"] = s == 1 ? std::vector<double>{corner ? 0.8 : 3.0}
                              : std::vector<double>{corner ? 0.6 : 2.5, corner ? 0.4 : 3.0};
      p.vectors["u"] = s == 1 ? std::vector<double>{0.3} : std::vector<double>{0.3, 0.65};
      out.push_back({name, p});
    }
  }
  for (const char* name : {"poly", "exp", "inverse_quadratic"}) {
    integrand_params p;
    p.dimension = 1;
    out.push_back({name, p});
  }
  return out;
}

// The required check: a transform changes the error, never the value — every periodization's
// weighted integrand integrates to the family's exact integral, to 1e-14 relative to
// max(1, |I|) (the rule's own error is far below that, as derived above).
TYPED_TEST(PeriodizingTransform, LeavesTheIntegralAsItWas) {
  using T = TypeParam;
  for (const family& fam : smooth_families()) {
    const any_integrand f = make_integrand(fam.name, fam.params);
    const double exact = f.info().exact;
    ASSERT_TRUE(std::isfinite(exact)) << fam.name;
    const double q = transformed_integral<T>(f, 16);
    EXPECT_NEAR(q, exact, 1e-14 * std::max(1.0, std::abs(exact)))
        << T::name << " on " << fam.name << " in s = " << f.dimension();
  }
}

}  // namespace
}  // namespace quadmc
