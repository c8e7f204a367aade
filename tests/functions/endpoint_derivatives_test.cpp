// Tests of the closed-form derivatives of functions/endpoint_derivatives.hpp against Boost.Math's
// automatic differentiation (an independent computation: Taylor arithmetic on the formula as
// written), and the exact zeros the Euler–Maclaurin terms rely on.
#include "quadmc/functions/endpoint_derivatives.hpp"

#include "quadmc/functions/classic_1d.hpp"

#include <gtest/gtest.h>
#include <boost/math/differentiation/autodiff.hpp>

#include <cmath>
#include <cstddef>

namespace quadmc {
namespace {

using boost::math::differentiation::make_fvar;
constexpr std::size_t K = endpoint_derivative_count - 1;

double factorial(std::size_t k) {
  double f = 1.0;
  for (std::size_t j = 2; j <= k; ++j) f *= static_cast<double>(j);
  return f;
}

// |dᵏ/dtᵏ 1/(1 + t²)| ≤ k!/(1 + t²)^((k+1)/2) (the modulus of k!·(t − i)^−(k+1)): the scale of
// the comparison, so that a structural zero is compared with the size of its neighbours.
TEST(EndpointDerivatives, InverseQuadraticMatchesAutodiff) {
  for (const double t : {0.0, 0.3, 1.0, 2.5}) {
    const auto x = make_fvar<double, K>(t);
    const auto y = 1.0 / (1.0 + x * x);
    for (std::size_t k = 0; k <= K; ++k) {
      const double scale = factorial(k) / std::pow(1.0 + t * t, (k + 1.0) / 2.0);
      EXPECT_NEAR(endpoint::inverse_quadratic(k, t), static_cast<double>(y.derivative(k)),
                  1e-11 * scale)
          << "k = " << k << ", t = " << t;
    }
  }
  // The zeros Simpson's superconvergence on 1/(1 + x²) rests on are exact, not merely small.
  for (std::size_t k = 1; k <= K; k += 2) EXPECT_EQ(endpoint::inverse_quadratic(k, 0.0), 0.0);
  for (std::size_t k = 3; k <= K; k += 4) EXPECT_EQ(endpoint::inverse_quadratic(k, 1.0), 0.0);
  EXPECT_EQ(endpoint::inverse_quadratic(5, 1.0) - endpoint::inverse_quadratic(5, 0.0), 15.0);
}

// |H_k(t)|·e^{−t²/2} ≤ 1.0865·√(2ᵏk!) (Cramér's inequality, [Abramowitz & Stegun], 22.14.17):
// the scale of the comparison.
TEST(EndpointDerivatives, GaussianMatchesAutodiff) {
  for (const double t : {0.0, 0.4, 1.0, 3.0}) {
    const auto x = make_fvar<double, K>(t);
    const auto y = exp(-x * x);
    for (std::size_t k = 0; k <= K; ++k) {
      const double scale =
          std::sqrt(std::ldexp(factorial(k), static_cast<int>(k))) * std::exp(-t * t / 2.0);
      EXPECT_NEAR(endpoint::gaussian(k, t), static_cast<double>(y.derivative(k)), 1e-11 * scale)
          << "k = " << k << ", t = " << t;
    }
  }
}

// (1 − cos x)/x²: autodiff of the formula as written at x = 1 (away from 0, where it is 0/0 for
// autodiff) for k ≤ 8 — beyond that its Taylor arithmetic on 1 − cos x loses digits (1.4e-9 off at
// k = 10, measured against the exact rational series) — and for every k the identity that
// x²·g = 1 − cos x implies by Leibniz's rule: x²g⁽ᵏ⁾ + 2kx·g⁽ᵏ⁻¹⁾ + k(k − 1)·g⁽ᵏ⁻²⁾ = −cos⁽ᵏ⁾x,
// to 1e-12 of the terms' size, at 0, 1/2 and 1.
TEST(EndpointDerivatives, CoscMatchesAutodiffAndItsDifferentialIdentity) {
  const auto x = make_fvar<double, 8>(1.0);
  const auto y = (1.0 - cos(x)) / (x * x);
  for (std::size_t k = 0; k <= 8; ++k) {
    EXPECT_NEAR(endpoint::cosc(k, 1.0), static_cast<double>(y.derivative(k)), 1e-9) << "k = " << k;
  }
  for (const double t : {0.0, 0.5, 1.0}) {
    const double cycle[4] = {std::cos(t), -std::sin(t), -std::cos(t), std::sin(t)};
    for (std::size_t k = 2; k <= K; ++k) {
      const double kk = static_cast<double>(k);
      const double a = t * t * endpoint::cosc(k, t), b = 2.0 * kk * t * endpoint::cosc(k - 1, t),
                   c = kk * (kk - 1.0) * endpoint::cosc(k - 2, t);
      const double size = std::abs(a) + std::abs(b) + std::abs(c) + 1.0;
      EXPECT_NEAR(a + b + c, -cycle[k % 4], 1e-12 * size) << "k = " << k << ", x = " << t;
    }
  }
  EXPECT_EQ(endpoint::cosc(0, 0.0), 0.5);
  EXPECT_EQ(endpoint::cosc(1, 0.0), 0.0);
}

// factor_of writes G⁽ᵏ⁾ = wᵏ·g⁽ᵏ⁾ in the unit variable and refuses what overflows.
TEST(EndpointDerivatives, FactorInTheUnitVariable) {
  const auto f = endpoint::exponential(1.0, 2.0, 5.0, std::exp(5.0) - std::exp(2.0));
  ASSERT_TRUE(f.has_value());
  EXPECT_DOUBLE_EQ(f->at_lower[3].real(), 27.0 * std::exp(2.0));  // w = 3: 3³·e²
  EXPECT_DOUBLE_EQ(f->at_upper[0].real(), std::exp(5.0));
  EXPECT_FALSE(endpoint::exponential(1.0, 0.0, 1e300, 1.0).has_value()) << "e^(10³⁰⁰) overflows";
  EXPECT_TRUE(inverse_quadratic_1d{}.info().endpoint_derivatives.has_value());
}

}  // namespace
}  // namespace quadmc
