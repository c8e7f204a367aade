#include "quadmc/sampling/inversion_warps.hpp"

#include "histogram_chi_square.hpp"
#include "quadmc/sampling/independent_points.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <vector>

namespace {

using namespace quadmc;

constexpr std::uint64_t samples = 1000000;
// False-alarm probability of every chi-square test in this file.
constexpr double alpha = 1e-4;

std::vector<double> uniforms(std::uint64_t seed) {
  std::vector<double> u(samples);
  independent_points(1, samples, seed, 1).generate(0, u);
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
      counts, bins, 1, 0.0, upper, 0.0, 1.0, [&](double x, double) { return w.pdf(x); }, samples,
      alpha, tail, 1.0 - w.cdf(upper));
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

// The last line of [Ramamoorthi 2009, §3.1.2], X = −U′/a, drops the logarithm
// (docs/theory.md#inversion): it returns values in (−1/a, 0],
// outside the support. The correct inverse −ln(1 − U)/a maps U = 1 − e^(−a x) back to x.
TEST(ExponentialWarp, KeepsTheLogarithm) {
  const exponential_warp w(2.0);
  for (double x : {0.0, 0.1, 1.0, 5.0}) {
    const double u = 1.0 - std::exp(-2.0 * x);
    // u carries a rounding of ε; dx/du = 1/(a(1 − u)) amplifies it (and the log's own ε·x).
    const double tol = 4 * 2.3e-16 * (1.0 / (2.0 * (1.0 - u)) + x);
    EXPECT_NEAR(w.sample(u), x, tol) << "x = " << x;
  }
  const double dropped_logarithm = -(1.0 - 0.5) / 2.0;  // −U′/a at U = 0.5
  EXPECT_LT(dropped_logarithm, 0.0);
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

}  // namespace
