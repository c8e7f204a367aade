// The Ishigami function: its mean a/2 and the variance of docs/theory.md#the-ishigami-function,
// both checked by nested Gauss–Kronrod (Boost.Math), independent of the closed forms.
#include "quadmc/functions/ishigami.hpp"

#include "quadmc/core/errors.hpp"
#include "reference_quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace quadmc {
namespace {

using test::at;
using test::gauss_kronrod;

// ∫ g(f(x)) over [0,1]³, nested 61-point Gauss–Kronrod (f is analytic: no breakpoints).
template <class G>
double nested_integral(const ishigami& f, G g) {
  return gauss_kronrod(
      [&](double x) {
        return gauss_kronrod(
            [&](double y) {
              return gauss_kronrod([&](double z) { return g(at(f, {x, y, z})); }, 0.0, 1.0);
            },
            0.0, 1.0);
      },
      0.0, 1.0);
}

TEST(Ishigami, MeanAndVarianceAgreeWithNestedGaussKronrod) {
  constexpr double pi = std::numbers::pi;
  for (const auto& [a, b] : {std::pair{7.0, 0.1}, std::pair{7.0, 0.05}, std::pair{-2.0, 1.5}}) {
    const ishigami f(a, b);
    const double mean = f.info().exact;
    EXPECT_EQ(mean, a / 2.0);
    const double scale = 1.0 + std::abs(a) + std::abs(b) * std::pow(pi, 4);  // bounds |f|
    EXPECT_NEAR(nested_integral(f, [](double v) { return v; }), mean, 1e-13 * scale)
        << "a = " << a << ", b = " << b;
    const double variance =
        a * a / 8 + b * std::pow(pi, 4) / 5 + b * b * std::pow(pi, 8) / 18 + 0.5;
    EXPECT_NEAR(nested_integral(f, [mean](double v) { return (v - mean) * (v - mean); }), variance,
                1e-12 * scale * scale)
        << "a = " << a << ", b = " << b;
  }
}

TEST(Ishigami, ValuesAtKnownPointsAndBounds) {
  const ishigami f;  // a = 7, b = 0.1
  EXPECT_EQ(f.dimension(), 3u);
  // x = 3/4 ↦ X = π/2; x = 1 ↦ X = π: sin X₁ = 1, sin² X₂ = 1, X₃⁴ = π⁴.
  const double pi4 = std::pow(std::numbers::pi, 4);
  EXPECT_NEAR(at(f, {0.75, 0.75, 1.0}), 1.0 + 7.0 + 0.1 * pi4, 1e-13);
  // x = 1/2 ↦ X = 0: every term vanishes.
  EXPECT_EQ(at(f, {0.5, 0.5, 0.5}), 0.0);
  // The largest value is attained there (a, b ≥ 0). The steepest first derivative is along x₃:
  // 2π·b·4π³ = 0.8π⁴ ≈ 77.9 at x = (3/4, ·, 1), above x₁'s 2π(1 + bπ⁴) ≈ 67.5 and x₂'s 2π·a ≈ 44.
  const integrand_info info = f.info();
  EXPECT_NEAR(*info.derivative_bound[0], 1.0 + 7.0 + 0.1 * pi4, 1e-13);
  EXPECT_NEAR(*info.derivative_bound[1], 0.8 * pi4, 1e-12);
  EXPECT_EQ(info.regularity, smoothness::analytic);
  // With a negative parameter the sum of the terms' maxima is no longer the maximum: not given.
  EXPECT_FALSE(ishigami(-1.0, 0.1).info().derivative_bound[0].has_value());
}

TEST(Ishigami, BadParametersAreNamed) {
  try {
    ishigami f(NAN, 0.1);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.parameter(), "a");
    EXPECT_NE(std::string(e.what()).find("expected a finite number"), std::string::npos)
        << e.what();
  }
  try {
    ishigami f(7.0, 1e307);  // |b|·π⁴ ≈ 9.7e308 > DBL_MAX
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.parameter(), "b");
    EXPECT_NE(std::string(e.what()).find("1 + |a| + |b|·π⁴ finite"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace quadmc
