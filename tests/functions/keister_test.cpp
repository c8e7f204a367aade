// Keister's integrand: the radial-quadrature reference against the closed form ½Γ(s/2)·₁F₁(s/2;
// ½; −¼) (series summed here) and against a 2D nested integration over ℝ².
#include "quadmc/functions/keister.hpp"

#include "reference_quadrature.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <cstdio>

namespace quadmc {
namespace {

using test::at;
using test::relative_error;

// I_s = |S^{s−1}|·½Γ(s/2)·₁F₁(s/2; ½; −¼) = π^{s/2}·₁F₁(s/2; ½; −¼): Kummer series with terms
// (s/2)_k/(½)_k·(−¼)^k/k!, summed in long double until the terms vanish.
double keister_series(std::size_t s) {
  const long double a = 0.5L * s;
  long double term = 1.0L, sum = 1.0L;
  for (int k = 0; k < 200; ++k) {
    term *= (a + k) / (0.5L + k) * (-0.25L) / (k + 1);
    sum += term;
  }
  return static_cast<double>(std::pow(std::numbers::pi_v<long double>, a) * sum);
}

TEST(Keister, ReferenceMatchesKummerSeriesUpToDimensionTwenty) {
  double worst = 0.0;
  for (std::size_t s = 1; s <= keister::max_dimension; ++s) {
    const double err = relative_error(keister(s).info().exact, keister_series(s));
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-12) << "s = " << s;
  }
  std::printf("keister relative error vs independent series, s = 1..20: worst %.2e\n", worst);
  // s = 1: ∫_ℝ cos|t| e^{−t²} dt = √π e^{−1/4}.
  EXPECT_NEAR(keister(1).info().exact, std::sqrt(std::numbers::pi) * std::exp(-0.25), 1e-15);
}

TEST(Keister, TwoDimensionalIntegralOverThePlane) {
  using gk = boost::math::quadrature::gauss_kronrod<double, 61>;
  const double inf = std::numeric_limits<double>::infinity();
  const double v = gk::integrate(
      [&](double x) {
        return gk::integrate(
            [&](double y) {
              const double r = std::hypot(x, y);
              return std::cos(r) * std::exp(-r * r);
            },
            -inf, inf, 10, 1e-13);
      },
      -inf, inf, 10, 1e-13);
  const double err = relative_error(v, keister(2).info().exact);
  std::printf("keister relative error vs independent integration: s = 2 %.2e\n", err);
  EXPECT_LT(err, 1e-10);
}

TEST(Keister, UnitCubeFormAndFaces) {
  const keister f(2);
  // x = (½, ½) maps to z = 0: f = π·cos 0.
  EXPECT_NEAR(at(f, {0.5, 0.5}), std::numbers::pi, 1e-15);
  // On a face Φ⁻¹ is infinite: defined as 0 (a null set), never NaN.
  EXPECT_EQ(at(f, {0.0, 0.3}), 0.0);
  EXPECT_EQ(at(f, {0.3, 1.0}), 0.0);
  EXPECT_TRUE(std::isnan(at(f, {1.5, 0.3})));
  // Φ(1) ≈ 0.8413447460685429: z = (1, 0) gives π·cos(1/√2).
  EXPECT_NEAR(at(f, {0.8413447460685429, 0.5}), std::numbers::pi * std::cos(1.0 / std::sqrt(2.0)),
              1e-13);
  EXPECT_EQ(f.info().regularity, smoothness::singular);
}

TEST(Keister, BadDimensionIsNamed) {
  for (std::size_t s : {std::size_t{0}, std::size_t{21}}) {
    try {
      keister f(s);
      FAIL();
    } catch (const invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("invalid dimension = " + std::to_string(s)),
                std::string::npos);
    }
  }
}

}  // namespace
}  // namespace quadmc
