// Tests of discrepancy.hpp against closed forms: one point, the centred 1D grid, and the
// expectations over independent uniform points; invariances; the input checks.
#include "quadmc/sampling/discrepancy.hpp"

#include "quadmc/sampling/independent_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace quadmc {
namespace {

// One point x in 1D, from the definitions by integration:
//   D*² = ∫₀¹ (1[x < t] − t)² dt = 1/3 − (1 − x²) + (1 − x) = x² − x + 1/3,
//   CD² = 13/12 − 2(1 + a/2 − a²/2) + (1 + a),  a = |x − ½|,
//   WD² = −4/3 + 3/2 = 1/6 (shift invariant: the same for every x).
TEST(Discrepancy, OfOnePointMatchesTheDefinition) {
  for (const double x : {0.0, 0.1, 0.5, 0.9}) {
    const std::vector<double> p{x};
    const double a = std::abs(x - 0.5);
    EXPECT_NEAR(l2_star_discrepancy(p, 1), std::sqrt(x * x - x + 1.0 / 3.0), 1e-15);
    EXPECT_NEAR(centered_discrepancy(p, 1),
                std::sqrt(13.0 / 12 - 2 * (1 + a / 2 - a * a / 2) + 1 + a), 1e-15);
    EXPECT_NEAR(wraparound_discrepancy(p, 1), std::sqrt(1.0 / 6.0), 1e-15);
  }
}

// The centred grid (2i + 1)/(2N) has D*² = 1/(12N²), by direct integration: the local
// discrepancy (#points below t)/N − t is a sawtooth of height 1/(2N) on each cell, whose mean
// square is 1/(12N²).
TEST(Discrepancy, OfTheCentredGridIsOneOverTwelveNSquared) {
  for (const std::size_t n : {1u, 7u, 100u, 4096u}) {
    std::vector<double> p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = (2.0 * static_cast<double>(i) + 1.0) / (2.0 * n);
    const double expected = 1.0 / (std::sqrt(12.0) * static_cast<double>(n));
    // D² is a difference of O(1) compensated sums (1/3 − … + …), each within a few ulp: its
    // absolute error is ≲ 4ε, so D's (D = √D², dD = dD²/(2D)) is ≲ 4ε/(2D).
    const double eps = std::numeric_limits<double>::epsilon();
    EXPECT_NEAR(l2_star_discrepancy(p, 1), expected, 4.0 * eps / (2.0 * expected)) << n;
  }
}

// For N independent uniform points: E[D*²] = (2^−s − 3^−s)/N, E[CD²] = ((5/4)^s − (13/12)^s)/N,
// E[WD²] = ((3/2)^s − (4/3)^s)/N (docs/theory.md#discrepancy). The mean of D² over K = 400
// independent sets of N = 64 points is within 4.4 standard errors (the sample sd of the 400 D²
// over √400) of the expectation: a false alarm of 1e-5 per check under the CLT, 1e-4 for the 9.
TEST(Discrepancy, ExpectationOverIndependentPointsMatchesTheClosedForm) {
  constexpr int K = 400;
  constexpr std::uint64_t n = 64;
  for (const std::size_t s : {1u, 2u, 5u}) {
    const double sd_ = static_cast<double>(s);
    const double expected[3] = {(std::pow(2.0, -sd_) - std::pow(3.0, -sd_)) / n,
                                (std::pow(1.25, sd_) - std::pow(13.0 / 12.0, sd_)) / n,
                                (std::pow(1.5, sd_) - std::pow(4.0 / 3.0, sd_)) / n};
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    for (int k = 0; k < K; ++k) {
      const l2_discrepancies d =
          discrepancies_of(independent_points(s, n, 2024, static_cast<std::uint64_t>(k)));
      const double sq[3] = {d.l2_star * d.l2_star, d.centered * d.centered,
                            d.wraparound * d.wraparound};
      for (int m = 0; m < 3; ++m) {
        sum[m] += sq[m];
        sum2[m] += sq[m] * sq[m];
      }
    }
    for (int m = 0; m < 3; ++m) {
      const double mean = sum[m] / K;
      const double se = std::sqrt((sum2[m] / K - mean * mean) / (K - 1));
      EXPECT_NEAR(mean, expected[m], 4.4 * se) << "s = " << s << ", measure " << m;
    }
  }
}

// Wrap-around: invariant under a shift modulo 1; centered: invariant under x ↦ 1 − x.
TEST(Discrepancy, WrapAroundIsShiftInvariantAndCenteredReflectionInvariant) {
  std::vector<double> p(50 * 3), shifted(50 * 3), reflected(50 * 3);
  independent_points(3, 50, 1, 2).generate(0, p);
  for (std::size_t k = 0; k < p.size(); ++k) {
    shifted[k] = std::fmod(p[k] + 0.375 + 0.125 * static_cast<double>(k % 3), 1.0);
    reflected[k] = 1.0 - p[k];
  }
  EXPECT_NEAR(wraparound_discrepancy(shifted, 3), wraparound_discrepancy(p, 3), 1e-13);
  EXPECT_NEAR(centered_discrepancy(reflected, 3), centered_discrepancy(p, 3), 1e-13);
}

TEST(Discrepancy, RefusesWhatItCannotMeasure) {
  EXPECT_THROW(discrepancies(std::vector<double>{}, 1), invalid_argument);
  EXPECT_THROW(discrepancies(std::vector<double>{0.5, 0.5, 0.5}, 2), invalid_argument);
  EXPECT_THROW(discrepancies(std::vector<double>{1.5}, 1), invalid_argument);
  EXPECT_THROW(discrepancies(std::vector<double>(16385, 0.5), 1), invalid_argument);
  EXPECT_THROW(discrepancies(std::vector<double>{0.5}, 0), invalid_argument);
}

}  // namespace
}  // namespace quadmc
