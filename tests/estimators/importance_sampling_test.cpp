#include "quadmc/estimators/importance_sampling.hpp"

#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/inversion_warps.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/unjittered_points.hpp"
#include "test_integrands.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>

namespace {

using namespace quadmc;
using test_support::make_integrand;
constexpr double e_minus_1 = std::numbers::e - 1.0;

const auto exp_on_unit = make_integrand("e^x", box::unit(1), e_minus_1,
                                        [](std::span<const double> x) { return std::exp(x[0]); });

// A deliberately bad density for e^x: p(x) = 3/2 − x, largest where f is smallest.
// P(x) = 3x/2 − x²/2 = u  →  x = (3 − √(9 − 8u))/2.
struct decreasing_linear_warp {
  std::size_t input_dimension() const { return 1; }
  std::size_t output_dimension() const { return 1; }
  void sample(std::span<const double> u, std::span<double> x) const {
    x[0] = (3.0 - std::sqrt(9.0 - 8.0 * u[0])) / 2.0;
  }
  double pdf(std::span<const double> x) const { return 1.5 - x[0]; }
};

// docs/theory.md#zero-variance: p ∝ f gives Y = f/p = e − 1 for every sample. To rounding: e^x and
// the pdf e^x/(e−1) each carry a few ulps, so |Y − (e − 1)| ≤ 8ε(e − 1) and the variance ≤ that
// squared.
TEST(ImportanceSampling, DensityProportionalToFHasZeroVariance) {
  const truncated_exponential_warp w(1.0);
  const estimate e = importance_sampling(exp_on_unit, w, independent_points(1, 100000, 1, 1));
  const double tol = 8 * std::numeric_limits<double>::epsilon() * e_minus_1;
  EXPECT_NEAR(e.value, e_minus_1, tol);
  EXPECT_LE(e.variance, tol * tol);
  EXPECT_EQ(e.evaluations, 100000u);
}

// The bad density's per-sample variance ∫f²/p − I² exceeds uniform sampling's
// (e² − 1)/2 − (e − 1)² ≈ 0.242. Both sample variances (N = 10⁵) are checked against the exact
// values within 5%: the relative SD of a sample variance is √((κ + 2)/N) < 1% here (κ the
// excess kurtosis of Y, below 5 for these bounded Y), so 5% is over 5 SDs (false alarm < 1e-6).
TEST(ImportanceSampling, ABadDensityIncreasesTheVariance) {
  const double v_uniform = (std::exp(2.0) - 1) / 2 - e_minus_1 * e_minus_1;
  const double v_bad = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
                           [](double x) { return std::exp(2 * x) / (1.5 - x); }, 0.0, 1.0) -
                       e_minus_1 * e_minus_1;
  const estimate bad = importance_sampling(exp_on_unit, decreasing_linear_warp{},
                                           independent_points(1, 100000, 2, 2));
  const estimate uniform = monte_carlo(exp_on_unit, independent_points(1, 100000, 3, 3));
  std::cout << "[ measured ] per-sample variance: uniform " << uniform.variance << " (exact "
            << v_uniform << "), bad p = 3/2 − x " << bad.variance << " (exact " << v_bad << ")\n";
  EXPECT_NEAR(uniform.variance, v_uniform, 0.05 * v_uniform);
  EXPECT_NEAR(bad.variance, v_bad, 0.05 * v_bad);
  EXPECT_GT(bad.variance, 1.5 * uniform.variance);
  EXPECT_NEAR(bad.value, e_minus_1, 5 * bad.std_error);
}

// Unbiasedness over R = 400 runs with three warps on three integrands (mean within 4 standard
// errors of the mean: false alarm 7.5e-5 each, Student's t with 399 degrees of freedom).
TEST(ImportanceSampling, IsUnbiased) {
  // ∫₀¹ x³ dx = 1/4 with p = 2x (power n = 1).
  const auto cube = make_integrand("x^3", box::unit(1), 0.25,
                                   [](std::span<const double> x) { return x[0] * x[0] * x[0]; });
  // ∫₀^∞ x e^(−x) dx = 1 with p = e^(−x/2)/2 (exponential a = 1/2).
  const auto gamma2 =
      make_integrand("x e^-x", box{{0.0}, {INFINITY}}, 1.0,
                     [](std::span<const double> x) { return x[0] * std::exp(-x[0]); });
  welford a, b, c;
  for (int r = 0; r < 400; ++r) {
    a.add(importance_sampling(cube, power_warp(1.0), independent_points(1, 64, 1, r)).value);
    b.add(
        importance_sampling(gamma2, exponential_warp(0.5), independent_points(1, 64, 2, r)).value);
    c.add(importance_sampling(exp_on_unit, decreasing_linear_warp{}, jittered_points(1, 64, 3, r))
              .value);
  }
  EXPECT_NEAR(a.mean(), 0.25, 4 * a.std_error());
  EXPECT_NEAR(b.mean(), 1.0, 4 * b.std_error());
  EXPECT_NEAR(c.mean(), e_minus_1, 4 * c.std_error());
}

// A pdf that is 0 where f ≠ 0 biases the estimate: refused, naming the point.
TEST(ImportanceSampling, PdfZeroWhereFIsNonZeroIsAnErrorNamingThePoint) {
  struct half_support_warp {
    std::size_t input_dimension() const { return 1; }
    std::size_t output_dimension() const { return 1; }
    void sample(std::span<const double> u, std::span<double> x) const { x[0] = u[0]; }
    double pdf(std::span<const double> x) const { return x[0] < 0.5 ? 2.0 : 0.0; }
  };
  try {
    importance_sampling(exp_on_unit, half_support_warp{}, unjittered_points(1, 4));
    FAIL();
  } catch (const invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("importance sampling of e^x: pdf = 0 at x = (0.625) where f = 1.86"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("expected pdf > 0 wherever f ≠ 0"), std::string::npos) << m;
  }
}

TEST(ImportanceSampling, RejectsMismatchedDimensions) {
  EXPECT_THROW(importance_sampling(exp_on_unit, power_warp(1.0), independent_points(2, 4, 1, 1)),
               invalid_argument);
}

}  // namespace
