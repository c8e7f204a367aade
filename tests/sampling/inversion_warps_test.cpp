#include "quadmc/sampling/inversion_warps.hpp"

#include "histogram_chi_square.hpp"
#include "quadmc/sampling/independent_points.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace quadmc;

using test_support::warp_alpha;
using test_support::warp_samples;

std::vector<double> uniforms(std::uint64_t seed) {
  std::vector<double> u(warp_samples);
  independent_points(1, warp_samples, seed, 1).generate(0, u);
  return u;
}

// Histogram of warp(U) on [0, upper) in `bins` cells plus the tail [upper, ∞).
template <class W>
test_support::chi_square_result histogram_test(const W& w, double upper, std::size_t bins,
                                               std::uint64_t seed) {
  std::vector<double> counts(bins, 0.0);
  double tail = 0.0;
  for (double u : uniforms(seed)) {
    const double x = w.sample(u);
    if (x >= upper) {
      tail += 1.0;
    } else {
      counts[std::size_t(x / upper * double(bins))] += 1.0;
    }
  }
  return test_support::chi_square_test(
      counts, bins, 1, 0.0, upper, 0.0, 1.0, [&](double x, double) { return w.pdf(x); },
      warp_samples, warp_alpha, tail, 1.0 - w.cdf(upper));
}

TEST(PowerWarp, PdfIntegratesToOne) {
  for (double n : {0.0, 1.0, 2.5, 10.0}) {
    const power_warp w(n);
    const double total = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
        [&](double x) { return w.pdf(x); }, 0.0, 1.0, 10, 1e-13);
    EXPECT_NEAR(total, 1.0, 1e-12) << "n = " << n;
  }
}

TEST(PowerWarp, SamplesFollowThePdf) {
  for (double n : {1.0, 4.0}) {
    const auto r = histogram_test(power_warp(n), 1.0, 100, 1);
    EXPECT_TRUE(r.passes()) << "n = " << n << ": χ² = " << r.statistic << " > " << r.critical
                            << " (dof " << r.dof << ")";
  }
}

TEST(ExponentialWarp, PdfIntegratesToOne) {
  const exponential_warp w(2.5);
  const double total = boost::math::quadrature::exp_sinh<double>().integrate(
      [&](double x) { return w.pdf(x); }, 0.0, std::numeric_limits<double>::infinity());
  EXPECT_NEAR(total, 1.0, 1e-12);
}

TEST(ExponentialWarp, SamplesFollowThePdf) {
  const exponential_warp w(2.5);
  const auto r = histogram_test(w, 3.0, 100, 2);
  EXPECT_TRUE(r.passes()) << "χ² = " << r.statistic << " > " << r.critical;
}

// X = −ln(1 − U)/a inverts P(x) = 1 − e^(−ax); the shortcut X = −U′/a (U′ = 1 − U) that drops the
// logarithm lands in (−1/a, 0], outside the support, and the plain −log(1 − U)/a returns 0 for
// U < ε/2 (1 − U rounds to 1). So: x = P⁻¹(u) on a grid of x, P(X(u)) = u across [0, 1) with
// X ≥ 0, and full relative accuracy X = U/a at tiny U (log1p).
TEST(ExponentialWarp, InvertsTheCdfOnTheWholeUnitInterval) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const exponential_warp w(2.0);
  for (double x : {0.0, 0.1, 1.0, 5.0}) {
    const double u = 1.0 - std::exp(-2.0 * x);
    // u carries a rounding of ε; dx/du = 1/(a(1 − u)) amplifies it (and the log's own ε·x).
    const double tol = 4 * 2.3e-16 * (1.0 / (2.0 * (1.0 - u)) + x);
    EXPECT_NEAR(w.sample(u), x, tol) << "x = " << x;
  }
  // P(X(u)) − u: X has a relative error of ~2ε (log1p, one division), which moves P by
  // p(X)·X·2ε = (1 − u)·(−ln(1 − u))·2ε ≤ 2ε/e; −expm1 adds ε/2·u. 4ε covers both.
  for (double u :
       {0x1p-60, 1e-9, 0.01, 0.25, 0.5, 0.75, 0.99, 1.0 - 0x1p-40, 0x1.fffffffffffffp-1}) {
    const double x = w.sample(u);
    EXPECT_GE(x, 0.0) << "u = " << u;
    EXPECT_NEAR(w.cdf(x), u, 4.0 * eps) << "u = " << u;
  }
  // −log1p(−u)/a = (u + u²/2 + …)/a: at u = 1e-20 the u² term is 5e-21 relative, far below ε.
  EXPECT_NEAR(w.sample(1e-20), 0.5e-20, 2.0 * eps * 0.5e-20);
  EXPECT_NEAR(w.sample(0.5), std::log(2.0) / 2.0, 1e-16);
  EXPECT_EQ(w.sample(0.0), 0.0);
  EXPECT_TRUE(std::isfinite(w.sample(0x1.fffffffffffffp-1)));
}

TEST(TruncatedExponentialWarp, PdfIntegratesToOneAndSamplesFollowIt) {
  for (double lambda : {1.0, -3.0}) {
    const truncated_exponential_warp w(lambda);
    const double total = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
        [&](double x) { return w.pdf(x); }, 0.0, 1.0, 10, 1e-13);
    EXPECT_NEAR(total, 1.0, 1e-13) << "λ = " << lambda;
    const auto r = histogram_test(w, 1.0, 100, 3);
    EXPECT_TRUE(r.passes()) << "λ = " << lambda << ": χ² = " << r.statistic << " > " << r.critical;
  }
}

TEST(InversionWarps, RejectParametersOutsideTheirDomain) {
  EXPECT_THROW(power_warp(-1.0), invalid_argument);
  EXPECT_THROW(exponential_warp(0.0), invalid_argument);
  EXPECT_THROW(exponential_warp(-1.0), invalid_argument);
  EXPECT_THROW(truncated_exponential_warp(0.0), invalid_argument);
}

// Exponents above 1e5: X = U^(1/(n+1)) rounds to the double grid below 1, which biases f(X)/p(X)
// by up to n·2^-52 relative (inversion_warps.hpp); at n = 1e308 every sample was X = 1 and an
// importance estimate of ∫eˣ came out e/1e308 ≈ 0. The bound and the rates' ±700 hold exactly.
TEST(InversionWarps, ExponentsAndRatesWithinTheirAccurateRange) {
  EXPECT_NO_THROW(power_warp{power_warp::max_exponent});
  EXPECT_THROW(power_warp(std::nextafter(power_warp::max_exponent, 1e6)), invalid_argument);
  EXPECT_THROW(power_warp(1e308), invalid_argument);
  const double rate = truncated_exponential_warp::max_abs_rate;
  EXPECT_NO_THROW(truncated_exponential_warp{rate});
  EXPECT_NO_THROW(truncated_exponential_warp(-rate));
  EXPECT_THROW(truncated_exponential_warp(std::nextafter(rate, 1e3)), invalid_argument);
  EXPECT_THROW(truncated_exponential_warp(-std::nextafter(rate, 1e3)), invalid_argument);
  // At the bound the density is finite and normal at both ends, and integrates to 1.
  for (const double lambda : {rate, -rate}) {
    const truncated_exponential_warp w(lambda);
    for (const double x : {0.0, 1.0}) {
      EXPECT_TRUE(std::isnormal(w.pdf(x))) << "λ = " << lambda << ", x = " << x;
    }
    EXPECT_TRUE(std::isfinite(w.sample(0.999999)));
  }
}

}  // namespace
