// The floating-point stress integrands: reference values against an independent quadrature,
// the naive cosc's cancellation against the stable one, the float twins' rounding, the
// singular members' convention at 0, and the bad inputs of the functions layer (one test each).
#include "quadmc/functions/stability_1d.hpp"

#include "quadmc/functions/catalogue.hpp"
#include "reference_quadrature.hpp"
#include "support/floating_point.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace quadmc {
namespace {

using quadmc::test_support::eps;
constexpr double eps_float = std::numeric_limits<float>::epsilon();

template <class F>
double at(const F& f, double x) {
  double y = 0.0;
  f.evaluate(std::span<const double>(&x, 1), std::span<double>(&y, 1));
  return y;
}

// (1 − cos x)/x² = 1/2 − x²/24 + x⁴/720 − … (Taylor): for x ≤ 1e-3 the next term, x⁶/40320,
// is below 3e-23, so the three terms are the function to double precision.
double cosc_taylor(double x) {
  const double x2 = x * x;
  return 0.5 - x2 / 24.0 + x2 * x2 / 720.0;
}

TEST(Stability1d, CoscReferenceMatchesGaussKronrod) {
  const cosc_stable_1d f;
  // Si(1) = 0.946083070367183 (Abramowitz & Stegun Table 5.1), so ∫ = Si(1) − (1 − cos 1).
  EXPECT_NEAR(f.info().exact, 0.946083070367183 - (1.0 - std::cos(1.0)), 1e-15);
  const double gk = test::gauss_kronrod([&](double x) { return at(f, x); }, 0.0, 1.0);
  EXPECT_NEAR(f.info().exact, gk, 4 * eps) << "Gauss–Kronrod " << gk;
  EXPECT_EQ(cosc_naive_1d{}.info().exact, f.info().exact);
}

// The stable form keeps a few ε relative accuracy near 0; the naive one loses 1 − cos x to
// cancellation: absolute error ≈ ε/2 in 1 − cos x ≈ x²/2, i.e. relative ε/x² in f. At x = 1e-5
// that is ~1e-6, and below x ≈ 1e-8 the naive value is 0 (cos x rounds to 1).
TEST(Stability1d, NaiveCoscLosesToCancellationStableDoesNot) {
  const cosc_naive_1d naive;
  const cosc_stable_1d stable;
  // The naive error at one x depends on how cos x happens to round, so the claim is about the
  // worst of 100 points in [1e-5, 1e-4]: there the scaled error |δf|/f·x²/ε reaches ≈ 1.
  double worst_scaled = 0.0;
  for (int k = 1; k <= 100; ++k) {
    const double x = 1e-6 * (10 + 0.9 * k);
    const double truth = cosc_taylor(x);
    EXPECT_NEAR(at(stable, x), truth, 4 * eps * truth) << "stable at x = " << x;
    worst_scaled = std::max(worst_scaled, std::abs(at(naive, x) - truth) / truth * x * x / eps);
  }
  EXPECT_GT(worst_scaled, 0.1) << "naive cosc should lose ≈ ε/x² relative to cancellation";
  EXPECT_LT(worst_scaled, 4.0) << "and not more than the cancellation bound";
  EXPECT_EQ(at(naive, 1e-9), 0.0) << "cos(1e-9) rounds to 1";
  EXPECT_EQ(at(naive, 0.0), 0.5);
  EXPECT_EQ(at(stable, 0.0), 0.5);
  // Away from 0 both are the same function to a few ε.
  EXPECT_NEAR(at(naive, 0.7), at(stable, 0.7), 8 * eps);
}

TEST(Stability1d, SingularMembersAreZeroAtTheSingularityAndExactElsewhere) {
  const inverse_sqrt_1d inv;
  const log_1d lg;
  EXPECT_EQ(at(inv, 0.0), 0.0);
  EXPECT_EQ(at(lg, 0.0), 0.0);
  EXPECT_EQ(at(inv, 0.25), 2.0);
  EXPECT_EQ(at(lg, 1.0), 0.0);
  EXPECT_EQ(inv.info().exact, 2.0);
  EXPECT_EQ(lg.info().exact, -1.0);
  EXPECT_EQ(inv.info().regularity, smoothness::singular);
  // ∫_ε^1 by Gauss–Kronrod + the closed-form ∫_0^ε (2√ε, ε log ε − ε) checks the exact values.
  // Breakpoints at every decade keep each piece's integrand within a factor 10 of smooth.
  const double e0 = 1e-6;
  const std::vector<double> decades{1e-5, 1e-4, 1e-3, 1e-2, 1e-1};
  EXPECT_NEAR(test::gauss_kronrod([&](double x) { return at(inv, x); }, e0, 1.0, decades) +
                  2 * std::sqrt(e0),
              2.0, 1e-12);
  EXPECT_NEAR(test::gauss_kronrod([&](double x) { return at(lg, x); }, e0, 1.0, decades) +
                  (e0 * std::log(e0) - e0),
              -1.0, 1e-12);
}

TEST(Stability1d, ShiftedExpHasTheSameIntegralOnEveryBox) {
  for (const auto& [lo, hi] : {std::pair{0.0, 1.0}, std::pair{1e8, 1e8 + 1.0},
                               std::pair{0.0, 1e-100}, std::pair{-1e100, 1e100}}) {
    const shifted_exp_1d f(lo, hi);
    EXPECT_EQ(f.info().exact, std::expm1(1.0));
    // f(lower) = 1/w and f(upper) = e/w, to the rounding of (x − a)/w and the exp.
    const double w = hi - lo;
    EXPECT_NEAR(at(f, lo) * w, 1.0, 2 * eps) << lo;
    EXPECT_NEAR(at(f, hi) * w, std::numbers::e, 4 * eps) << lo;
  }
  // Derivative bounds overflow for w = 1e-100 from k = 3 (e·10^400): left empty, not inf.
  const auto info = shifted_exp_1d(0.0, 1e-100).info();
  EXPECT_TRUE(info.derivative_bound[0].has_value());
  EXPECT_FALSE(info.derivative_bound[4].has_value());
}

// The float twins are the float functions: |f_float − f| ≤ a few ε_float·|f| (x rounded to float
// moves eˣ by ≤ ε_f/2·x·eˣ, expf and the division add ≤ 1 ulp each).
TEST(Stability1d, FloatTwinsRoundToSinglePrecision) {
  const exp_float_1d ef;
  const inverse_quadratic_float_1d qf;
  for (double x : {0.1, 0.333333333333, 0.77, 0.999}) {
    EXPECT_NEAR(at(ef, x), std::exp(x), 3 * eps_float * std::exp(x)) << x;
    EXPECT_EQ(at(ef, x), static_cast<double>(std::exp(static_cast<float>(x)))) << x;
    const double q = 1.0 / (1.0 + x * x);
    EXPECT_NEAR(at(qf, x), q, 3 * eps_float * q) << x;
  }
  // 1/3 is not a float: the float twin differs from the double function there.
  EXPECT_NE(at(ef, 1.0 / 3.0), std::exp(1.0 / 3.0));
  EXPECT_EQ(ef.info().exact, std::numbers::e - 1.0);
  EXPECT_EQ(qf.info().exact, std::numbers::pi / 4);
}

using test_support::message_of;

TEST(Stability1d, ShiftedExpRejectsBadBoxes) {
  EXPECT_EQ(message_of([] { shifted_exp_1d(std::nan(""), 1.0); }),
            "invalid lower = nan: expected a finite number");
  EXPECT_EQ(message_of([] { shifted_exp_1d(0.0, std::numeric_limits<double>::infinity()); }),
            "invalid upper = inf: expected a finite number");
  EXPECT_NE(message_of([] { shifted_exp_1d(1.0, 0.0); })
                .find("invalid upper = 0: expected "
                      "upper > lower = 1"),
            std::string::npos);
  EXPECT_NE(message_of([] { shifted_exp_1d(-1e308, 1e308); }).find("a finite width"),
            std::string::npos);
}

// --- Bad input of the functions layer through the catalogue (what a scene reaches) ---------------

TEST(BadInput, ParameterVectorOfTheWrongLength) {
  integrand_params p;
  p.dimension = 3;
  p.vectors["a"] = {1.0, 2.0};
  EXPECT_EQ(message_of([&] { make_integrand("genz_gaussian", p); }),
            "invalid a = [1, 2]: expected a vector of length dimension = 3");
}

TEST(BadInput, ShiftOutsideTheUnitInterval) {
  integrand_params p;
  p.dimension = 2;
  p.vectors["u"] = {0.5, 1.25};
  EXPECT_EQ(message_of([&] { make_integrand("genz_gaussian", p); }),
            "invalid u = 1.25: expected uᵢ in [0, 1]");
}

// f = e^t/w reaches e/w at x = upper: a subnormal width made that inf (with a finite exact e − 1),
// and exp_float overflowed float above 88.72 with a finite double reference.
TEST(Stability1d, WidthsAndBoundsWhoseValuesOverflowAreRefused) {
  EXPECT_NE(message_of([] { shifted_exp_1d(0.0, 1e-310); }).find("a width of at least"),
            std::string::npos);
  const shifted_exp_1d narrow(0.0, std::numeric_limits<double>::min());
  double y = 0.0;
  const double x = std::numeric_limits<double>::min();
  narrow.evaluate(std::span<const double>(&x, 1), std::span<double>(&y, 1));
  EXPECT_TRUE(std::isfinite(y)) << y;
  EXPECT_NE(message_of([] { exp_float_1d(80.0, 89.0); }).find("invalid upper = 89"),
            std::string::npos);
  const auto info = exp_float_1d(80.0, 88.0).info();
  EXPECT_EQ(info.derivative_bound[0], std::exp(88.0f)) << "f's largest value, in float";
}

}  // namespace
}  // namespace quadmc
