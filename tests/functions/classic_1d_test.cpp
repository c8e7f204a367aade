// Classic 1D integrands: exact integrals against Gauss–Kronrod / tanh–sinh, and the exact
// derivative maxima against Boost autodiff on a dense grid.
#include "quadmc/functions/classic_1d.hpp"

#include "jump_metadata.hpp"
#include "reference_quadrature.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>
#include <boost/math/differentiation/autodiff.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace quadmc {
namespace {

using test::at;
using test::gauss_kronrod;
using test::relative_error;
using test_support::message_of;

template <class F>
double integral_by_gauss_kronrod(const F& f, std::vector<double> breaks = {}) {
  const auto d = f.info().domain;
  return gauss_kronrod([&](double x) { return at(f, {x}); }, d.lower[0], d.upper[0], breaks);
}

template <class F>
void expect_exact(const F& f, double numeric) {
  const double err = relative_error(numeric, f.info().exact);
  std::printf("%-18s relative error vs independent integration %.2e\n", f.info().name.c_str(), err);
  EXPECT_LT(err, 1e-13) << f.info().name;
}

TEST(Classic1d, ExactIntegralsMatchGaussKronrod) {
  expect_exact(poly_1d(), integral_by_gauss_kronrod(poly_1d()));
  expect_exact(poly_1d(-2.0, 1.5), integral_by_gauss_kronrod(poly_1d(-2.0, 1.5)));
  expect_exact(exp_1d(), integral_by_gauss_kronrod(exp_1d()));
  expect_exact(exp_1d(-1.0, 3.0), integral_by_gauss_kronrod(exp_1d(-1.0, 3.0)));
  expect_exact(sin_1d(), integral_by_gauss_kronrod(sin_1d()));
  expect_exact(sin_1d(0.3, 5.0), integral_by_gauss_kronrod(sin_1d(0.3, 5.0)));
  expect_exact(inverse_quadratic_1d(), integral_by_gauss_kronrod(inverse_quadratic_1d()));
  // Kink and jump at c: split there so both pieces are smooth.
  for (double c : {0.3, 0.5, 0.0, 1.0}) {
    expect_exact(abs_kink_1d(c), integral_by_gauss_kronrod(abs_kink_1d(c), {c}));
    if (c < 1.0) expect_exact(step_1d(c), integral_by_gauss_kronrod(step_1d(c), {c}));
  }
  // √x: tanh–sinh handles the endpoint singularity of f'.
  const sqrt_1d root;
  expect_exact(root, boost::math::quadrature::tanh_sinh<double>().integrate(
                         [&](double x) { return at(root, {x}); }, 0.0, 1.0));
}

// max over a 100001-point grid of |f⁽ᵏ⁾| by forward-mode autodiff (an independent derivation of
// the derivatives); the grid includes both ends and the stated interior maximisers come within
// h/2 = 5e-6 of a node, so the sampled max is within ~M_{k+2}·h²/8 relative ~1e-9 of M_k.
template <class G>
std::array<double, 5> sampled_maxima(G&& g, double lo, double hi) {
  using namespace boost::math::differentiation;
  std::array<double, 5> m{};
  const int n = 100000;
  for (int i = 0; i <= n; ++i) {
    const auto x = make_fvar<double, 4>(lo + (hi - lo) * i / n);
    const auto y = g(x);
    for (int k = 0; k <= 4; ++k)
      m[k] = std::max(m[k], std::abs(static_cast<double>(y.derivative(k))));
  }
  return m;
}

template <class F, class G>
void expect_bounds(const F& f, G&& g, std::vector<int> orders) {
  const auto info = f.info();
  const auto m = sampled_maxima(g, info.domain.lower[0], info.domain.upper[0]);
  for (int k : orders) {
    ASSERT_TRUE(info.derivative_bound[k].has_value()) << info.name << " k = " << k;
    const double bound = *info.derivative_bound[k];
    EXPECT_LE(m[k], bound * (1 + 1e-14)) << info.name << " k = " << k;
    EXPECT_GE(m[k], bound * (1 - 1e-8)) << info.name << " k = " << k << ": bound not attained";
  }
}

TEST(Classic1d, DerivativeBoundsAreExactMaxima) {
  using std::exp, std::sin, std::sqrt, std::abs;
  expect_bounds(poly_1d(), [](auto x) { return x * x * x * x * x; }, {0, 1, 2, 3, 4});
  expect_bounds(poly_1d(-2.0, 1.5), [](auto x) { return x * x * x * x * x; }, {0, 1, 2, 3, 4});
  expect_bounds(exp_1d(-1.0, 3.0), [](auto x) { return exp(x); }, {0, 1, 2, 3, 4});
  expect_bounds(sin_1d(), [](auto x) { return sin(x); }, {0, 1, 2, 3, 4});
  expect_bounds(sin_1d(0.3, 1.2), [](auto x) { return sin(x); }, {0, 1, 2, 3, 4});
  expect_bounds(inverse_quadratic_1d(), [](auto x) { return 1.0 / (1.0 + x * x); },
                {0, 1, 2, 3, 4});
  expect_bounds(abs_kink_1d(0.3), [](auto x) { return abs(x - 0.3); }, {0, 1});
  // √x: only M₀; the derivative bounds from k = 1 on are absent (unbounded at 0).
  EXPECT_FALSE(sqrt_1d().info().derivative_bound[1].has_value());
  EXPECT_EQ(sqrt_1d().info().regularity, smoothness::singular);
  EXPECT_EQ(abs_kink_1d().info().regularity, smoothness::c0);
  EXPECT_EQ(step_1d().info().regularity, smoothness::discontinuous);
}

TEST(Classic1d, StepCarriesItsJumpAndFlatPieces) {
  // An interior jump of size 1 at c, f(c) = 1 = f(c+); the pieces are constant (M₁…M₄ = 0).
  for (double c : {0.3, 1.0 / std::sqrt(2.0), 0.93750095367431640625}) {
    const step_1d f(c);
    const integrand_info info = f.info();
    ASSERT_EQ(info.separable_factors.size(), 1u);
    const piecewise_smooth_factor& g = info.separable_factors[0];
    ASSERT_EQ(g.jumps.size(), 1u);
    EXPECT_EQ(g.jumps[0].location, c);
    EXPECT_EQ(g.jumps[0].size, 1.0);
    for (std::size_t k = 1; k < g.derivative_bound.size(); ++k) {
      EXPECT_EQ(g.derivative_bound[k], 0.0) << "k = " << k;
    }
    test::expect_factors_describe(f, {0.0}, {1.0});
  }
  // c = 1: only the point value f(1) = 1 differs from the limit 0: an end-point jump.
  test::expect_factors_describe(step_1d(1.0), {0.0}, {1.0});
  EXPECT_EQ(step_1d(1.0).info().separable_factors[0].jumps.size(), 1u);
  // c = 0: f ≡ 1 on [0, 1], no jump at all.
  EXPECT_TRUE(step_1d(0.0).info().separable_factors[0].jumps.empty());
  test::expect_factors_describe(step_1d(0.0), {0.0}, {1.0});
  // Smooth families carry no factors: their series keep the slope verdict.
  EXPECT_TRUE(exp_1d().info().separable_factors.empty());
  EXPECT_TRUE(abs_kink_1d().info().separable_factors.empty());
}

TEST(Classic1d, BadParametersAreNamed) {
  EXPECT_NE(message_of([] { poly_1d(1.0, 1.0); }).find("invalid upper = 1"), std::string::npos);
  EXPECT_NE(message_of([] { exp_1d(NAN, 1.0); }).find("invalid lower"), std::string::npos);
  EXPECT_NE(message_of([] { abs_kink_1d(1.5); }).find("invalid c = 1.5"), std::string::npos);
  EXPECT_NE(message_of([] { step_1d(-0.1); }).find("invalid c = -0.1"), std::string::npos);
}

// exp on [0, 1000] had exact = inf and poly on [−1e100, 1e100] exact = NaN, and both planned:
// the run then failed at the first value. The bounds that keep the closed forms finite are
// checked when the integrand is built.
TEST(Classic1d, BoundsWhoseIntegralOverflowsAreRefused) {
  std::string m = message_of([] { exp_1d(0.0, 1000.0); });
  EXPECT_NE(m.find("invalid upper = 1000: expected upper ≤ 709.78"), std::string::npos) << m;
  const double at_limit = exp_1d(709.0, 709.78).info().exact;
  EXPECT_TRUE(std::isfinite(at_limit));
  EXPECT_NEAR(at_limit, std::exp(709.78) - std::exp(709.0), 1e-15 * at_limit);
  m = message_of([] { poly_1d(-1e100, 1e100); });
  EXPECT_NE(m.find("invalid lower = -1e+100: expected |lower| ≤ 1e51"), std::string::npos) << m;
  m = message_of([] { poly_1d(0.0, 2e51); });
  EXPECT_NE(m.find("invalid upper = 2e+51"), std::string::npos) << m;
  // (1e51)⁶/6 = 1.7e305: finite.
  EXPECT_NEAR(poly_1d(0.0, 1e51).info().exact, 1e306 / 6.0, 1e-14 * 1e306 / 6.0);
  // A width beyond double: every node lower + (upper − lower)·t would be NaN.
  m = message_of([] { sin_1d(-1e308, 1e308); });
  EXPECT_NE(m.find("a finite width upper − lower"), std::string::npos) << m;
  EXPECT_TRUE(std::isfinite(sin_1d(-1e307, 1e307).info().exact));
}

// Regression: the closed forms subtracted two nearly equal values. On narrow intervals e^hi − e^lo
// was off by 7.5e-7 relative on [700, 700 + 1e-10] (so a Simpson estimate right to 1e-16 showed
// |error| 7.6e287), (hi⁶ − lo⁶)/6 by 2e-7 on [1e10, 1e10 + 1] and cos lo − cos hi by 1.5e-7 on
// [0.3, 0.3 + 1e-10]. The reference is the same difference in 50 significant digits of the same
// double endpoints (Boost.Multiprecision), where the cancellation leaves over 35 digits.
TEST(Classic1d, ClosedFormsKeepTheirDigitsOnNarrowIntervals) {
  using big = boost::multiprecision::cpp_bin_float_50;
  const auto relative = [](double value, const big& exact) {
    return static_cast<double>(abs((big(value) - exact) / exact));
  };
  const double e_lo = 700.0;
  const double e_hi = 700.0000000001;
  EXPECT_LT(relative(exp_1d(e_lo, e_hi).info().exact, exp(big(e_hi)) - exp(big(e_lo))), 1e-14);
  const double p_lo = 1e10;
  const double p_hi = 1e10 + 1.0;
  EXPECT_LT(relative(poly_1d(p_lo, p_hi).info().exact, (pow(big(p_hi), 6) - pow(big(p_lo), 6)) / 6),
            1e-14);
  // Across 0, where x⁵ is odd: ∫ over [−1, 1 + 1e-9] is the sliver [1, 1 + 1e-9].
  const double q_hi = 1.0 + 1e-9;
  EXPECT_LT(relative(poly_1d(-1.0, q_hi).info().exact, (pow(big(q_hi), 6) - 1) / 6), 1e-14);
  EXPECT_EQ(poly_1d(-2.0, 2.0).info().exact, 0.0) << "an odd function over a symmetric interval";
  const double s_lo = 0.3;
  const double s_hi = 0.3 + 1e-10;
  EXPECT_LT(relative(sin_1d(s_lo, s_hi).info().exact, cos(big(s_lo)) - cos(big(s_hi))), 1e-14);
  // Wide intervals keep the direct forms, still to 1e-14.
  EXPECT_LT(relative(sin_1d(0.3, 1e10).info().exact, cos(big(0.3)) - cos(big(1e10))), 1e-14);
  EXPECT_LT(relative(exp_1d(-1000.0, 1.0).info().exact, exp(big(1.0)) - exp(big(-1000.0))), 1e-14);
}

// Regression: e^x on [−745, −744.9] and x⁵ on [0, 1e-60] had the exact value 0 (the integral
// underflows), which the README says is refused; and what no form carries to 12 digits is refused
// too, naming the interval.
TEST(Classic1d, IntegralsThatUnderflowOrCannotBeCarriedAreRefused) {
  for (const std::string& m :
       {message_of([] { exp_1d(-745.0, -744.9); }), message_of([] { poly_1d(0.0, 1e-60); }),
        message_of([] { sin_1d(1e10, 1e10 + 1e-6); })}) {
    EXPECT_NE(m.find("invalid upper = "), std::string::npos) << m;
    EXPECT_NE(m.find("accurate to 1e-12"), std::string::npos) << m;
  }
  // A whole period: the integral is 0 to within the rounding of its values, which is what a rule
  // resolves too (error is judged against (upper − lower)·max|f|).
  EXPECT_LT(std::abs(sin_1d(0.0, 2.0 * std::numbers::pi).info().exact), 1e-15);
}

}  // namespace
}  // namespace quadmc
