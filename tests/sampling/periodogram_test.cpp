// Tests of periodogram.hpp: the bin counts against a brute-force count over the whole plane, the
// exact spectrum of a shifted grid (spikes at the multiples of k, nothing elsewhere), and the
// expected spectra of independent points (flat at 1) and of jittered points (1 − sinc⁴-type dip
// at the origin) within the stated standard errors.
#include "quadmc/sampling/periodogram.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

namespace quadmc {
namespace {

// Every frequency f ∈ Z² \ {0} with round(|f|) = r (rounded in floating point, |f| never lies
// on a half-integer since |f|² is an integer), halved: P(−f) = P(f) is one frequency.
std::uint64_t brute_force_count(std::size_t r) {
  const auto R = static_cast<int>(r) + 1;
  std::uint64_t count = 0;
  for (int a = -R; a <= R; ++a) {
    for (int b = -R; b <= R; ++b) {
      if (a == 0 && b == 0) continue;
      if (std::lround(std::hypot(a, b)) == static_cast<long>(r)) ++count;
    }
  }
  return count / 2;
}

TEST(Periodogram, HalfPlaneFrequencyCountsMatchABruteForceCount) {
  EXPECT_EQ(half_plane_frequencies(1), 4u);  // (1,0), (0,1), (1,1), (1,−1)
  for (std::size_t r = 1; r <= 80; ++r) EXPECT_EQ(half_plane_frequencies(r), brute_force_count(r));
}

// A k × k grid of centres shifted by (a, b): Σ_j exp(−2πi f·x_j) is a product of two geometric
// sums, N·exp(−2πi f·(shift + ½/k)) when k divides f₁ and f₂ and 0 otherwise. So P(f) = N on
// the multiples of k and 0 elsewhere, and bin r's mean is N·(multiples of k in the bin)/(its
// frequencies), exactly up to rounding (the sums are O(N) with terms of size 1: error ≲ N²·1e-13).
TEST(Periodogram, ShiftedGridHasSpikesAtTheMultiplesOfK) {
  constexpr std::size_t k = 8;
  constexpr std::size_t n = k * k;
  constexpr std::size_t max_radius = 30;
  std::vector<double> x(2 * n);
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      x[2 * (i * k + j)] = std::fmod((static_cast<double>(i) + 0.5) / k + 0.123, 1.0);
      x[2 * (i * k + j) + 1] = std::fmod((static_cast<double>(j) + 0.5) / k + 0.456, 1.0);
    }
  }
  radial_periodogram p(max_radius);
  p.add(x);
  const auto bins = p.bins();
  ASSERT_EQ(bins.size(), max_radius);
  for (const radial_power_bin& bin : bins) {
    std::uint64_t multiples = 0;
    const int r = static_cast<int>(bin.radius);
    for (int a = 0; a <= r + 1; ++a) {
      for (int b = -r - 1; b <= r + 1; ++b) {
        if ((a == 0 && b <= 0) || a % static_cast<int>(k) != 0 || b % static_cast<int>(k) != 0) {
          continue;
        }
        if (std::lround(std::hypot(a, b)) == r) ++multiples;
      }
    }
    const double expected = static_cast<double>(n) * static_cast<double>(multiples) /
                            static_cast<double>(bin.frequencies);
    EXPECT_NEAR(bin.mean_power, expected, 1e-9) << "r = " << bin.radius;
  }
  EXPECT_EQ(p.realizations(), 1u);
  EXPECT_TRUE(std::isnan(bins[0].standard_error));  // one realization has no spread
}

// Averages R realizations of the points `make(stream)` and checks every bin against `expected`:
// the bin mean over R independent realizations has the stated standard error, so
// (mean − expected)/standard_error is Student-t with R − 1 degrees of freedom under the CLT
// (R = 1000; the least averaged bin, r = 1, holds 4 frequencies, whose per-realization mean is
// about Gamma(4)/4 with skewness 1, so the R-mean's skewness is 1/√1000 ≈ 0.03 and the Edgeworth
// correction to the tail at t ≈ 4.8 is ≈ 0.03·(t² − 1)/6 ≈ 11 % of it). Two-sided, Bonferroni
// over the B = 32 bins: false-alarm probability ≤ 1e-4 per test, 1e-4/32 per bin.
void expect_spectrum(const std::function<std::vector<double>(std::uint64_t)>& make,
                     const std::function<double(int, int)>& expected_power) {
  constexpr std::size_t max_radius = 32;
  constexpr std::uint64_t realizations = 1000;
  radial_periodogram p(max_radius);
  for (std::uint64_t r = 0; r < realizations; ++r) p.add(make(r));
  const double t = boost::math::quantile(boost::math::students_t(realizations - 1),
                                         1.0 - 1e-4 / (2.0 * max_radius));
  for (const radial_power_bin& bin : p.bins()) {
    // The bin's expectation: the mean of E[P(f)] over its frequencies.
    double sum = 0.0;
    std::uint64_t count = 0;
    const int r = static_cast<int>(bin.radius);
    for (int a = 0; a <= r + 1; ++a) {
      for (int b = -r - 1; b <= r + 1; ++b) {
        if (a == 0 && b <= 0) continue;
        if (std::lround(std::hypot(a, b)) != r) continue;
        sum += expected_power(a, b);
        ++count;
      }
    }
    ASSERT_EQ(count, bin.frequencies);
    const double expected = sum / static_cast<double>(count);
    EXPECT_LE(std::abs(bin.mean_power - expected), t * bin.standard_error)
        << "r = " << bin.radius << ": " << bin.mean_power << " ± " << bin.standard_error
        << " against " << expected;
  }
}

// Independent uniform points: E[P(f)] = 1 at every f ≠ 0 (white noise: the cross terms of
// |Σ_j e_j|² have mean |E e_j|² = 0 for an integer f ≠ 0).
TEST(Periodogram, IndependentPointsAreFlatAwayFromTheOrigin) {
  expect_spectrum(
      [](std::uint64_t stream) {
        const independent_points points(2, 256, 2026, stream);
        std::vector<double> x(2 * points.size());
        points.generate(0, x);
        return x;
      },
      [](int, int) { return 1.0; });
}

// Jittered points, one per cell of a k × k grid: the cross terms of distinct cells leave
// E[P(f)] = 1 − |g(f)|², g(f) = Π_i sin(πf_i/k)/(πf_i/k) the characteristic function of the
// jitter within a cell ([Pilleboue et al. 2015]; the grid's sum Σ_c exp(−2πi f·c/k) vanishes
// unless k | f, and there g = 0): low power near the origin, the blue noise of stratification.
TEST(Periodogram, JitteredPointsFollowTheirExpectedSpectrum) {
  constexpr int k = 16;
  expect_spectrum(
      [](std::uint64_t stream) {
        const jittered_points points(2, k * k, 2026, stream);
        std::vector<double> x(2 * points.size());
        points.generate(0, x);
        return x;
      },
      [](int a, int b) {
        auto sinc2 = [](int m) {
          if (m == 0) return 1.0;
          const double z = std::numbers::pi * m / k;
          return std::sin(z) * std::sin(z) / (z * z);
        };
        return 1.0 - sinc2(a) * sinc2(b);
      });
}

TEST(Periodogram, RejectsBadInput) {
  EXPECT_THROW(radial_periodogram(0), invalid_argument);
  EXPECT_THROW(radial_periodogram(5000), invalid_argument);
  radial_periodogram p(4);
  EXPECT_THROW(p.add(std::vector<double>{0.5}), invalid_argument);
  EXPECT_THROW(p.add(std::vector<double>{}), invalid_argument);
  EXPECT_THROW(p.add(std::vector<double>{0.5, NAN}), invalid_argument);
  EXPECT_EQ(p.realizations(), 0u);
}

}  // namespace
}  // namespace quadmc
