// Tests of rank1_lattice_points.hpp: the generating vector's validity and quality (the worst-case
// error of the Korobov space falls at the proven rate), the lattice structure, the shift's
// uniformity, the baker's transform, and the sizes it refuses.
#include "quadmc/sampling/rank1_lattice_points.hpp"

#include "quadmc/core/simd_level.hpp"
#include "quadmc/core/summation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <numeric>
#include <vector>

namespace quadmc {
namespace {

static_assert(point_set<rank1_lattice_points<no_periodization>>);
static_assert(point_set<rank1_lattice_points<baker_transform>>);

// Every component odd (a unit modulo 2^m, so every 1D projection of the lattice is the whole
// grid k/N) and z_1 = 1.
TEST(LatticeGeneratingVector, HasThirtySixHundredOddComponents) {
  const auto z = lattice_generating_vector();
  ASSERT_EQ(z.size(), 3600u);
  EXPECT_EQ(z[0], 1u);
  for (std::size_t j = 0; j < z.size(); ++j) {
    ASSERT_EQ(z[j] % 2, 1u) << j;
    ASSERT_LT(z[j], 1u << 20) << j;
  }
}

// The squared worst-case error of the rank-1 lattice rule (N, z) in the Korobov space of
// smoothness α with product weights γ_j = j^−2 ([Dick, Kuo & Sloan 2013, §5]):
//   e² = (1/N) Σ_k [Π_j (1 + γ_j ω_α({k z_j / N})) − 1],
// ω_1(x) = 2π² B_2(x), ω_2(x) = −(2π⁴/3) B_4(x), B_2 = x² − x + 1/6, B_4 = x⁴ − 2x³ + x² − 1/30.
// Summed in long double with compensation (e² ~ 1e-19 at the largest N is a difference of O(1)
// terms).
double worst_case_error(std::size_t s, std::uint64_t n, int alpha) {
  const auto z = lattice_generating_vector();
  long double sum = 0.0L, c = 0.0L;
  const long double pi2 = std::numbers::pi_v<long double> * std::numbers::pi_v<long double>;
  for (std::uint64_t k = 0; k < n; ++k) {
    long double product = 1.0L;
    for (std::size_t j = 0; j < s; ++j) {
      const long double x = static_cast<long double>((k * z[j]) % n) / static_cast<long double>(n);
      const long double w = alpha == 1
                                ? 2.0L * pi2 * (x * x - x + 1.0L / 6.0L)
                                : -(2.0L * pi2 * pi2 / 3.0L) *
                                      (x * x * x * x - 2.0L * x * x * x + x * x - 1.0L / 30.0L);
      product *= 1.0L + w / static_cast<long double>((j + 1) * (j + 1));
    }
    const long double y = (product - 1.0L) - c;
    const long double t = sum + y;
    c = (t - sum) - y;
    sum = t;
  }
  return static_cast<double>(std::sqrt(std::max(0.0L, sum / static_cast<long double>(n))));
}

// The proven rate is e = O(N^(−α+δ)) for every δ > 0 ([Dick, Kuo & Sloan 2013, §5], CBC
// vectors; no rule beats N^−α, [Dick, Kuo & Sloan 2013, §5]); on a finite ladder the bound's
// (log N)^(αs) factor flattens the fitted slope by about αs/ln N̄ (d ln (ln N)^(αs) / d ln N at
// the ladder's geometric middle N̄ = 2^13). So the slope of log e over N = 2^6 … 2^20 must lie in
// [−α − 0.2, −α + αs/ln N̄]. Deterministic: no false alarm.
TEST(LatticeGeneratingVector, WorstCaseErrorFallsAtTheProvenRate) {
  for (const int alpha : {1, 2}) {
    for (const std::size_t s : {2u, 4u}) {
      std::vector<double> lx, ly;
      for (unsigned m = 6; m <= 20; m += 2) {
        lx.push_back(std::log(std::ldexp(1.0, static_cast<int>(m))));
        ly.push_back(std::log(worst_case_error(s, std::uint64_t{1} << m, alpha)));
      }
      const double mx = std::accumulate(lx.begin(), lx.end(), 0.0) / static_cast<double>(lx.size());
      const double my = std::accumulate(ly.begin(), ly.end(), 0.0) / static_cast<double>(ly.size());
      double sxy = 0.0, sxx = 0.0;
      for (std::size_t k = 0; k < lx.size(); ++k) {
        sxy += (lx[k] - mx) * (ly[k] - my);
        sxx += (lx[k] - mx) * (lx[k] - mx);
      }
      const double slope = sxy / sxx;
      const double flattening = alpha * static_cast<double>(s) / std::log(std::ldexp(1.0, 13));
      EXPECT_LE(slope, -alpha + flattening) << "alpha " << alpha << ", s " << s;
      EXPECT_GE(slope, -alpha - 0.2) << "alpha " << alpha << ", s " << s;
    }
  }
}

TEST(RankOneLatticePoints, UnshiftedPointsAreTheLatticeAndStartAtTheOrigin) {
  const rank1_lattice_points<no_periodization> p(3, 64, 1, 2, false);
  std::vector<double> x(64 * 3);
  p.generate(0, x);
  const auto z = lattice_generating_vector();
  for (std::uint64_t i = 0; i < 64; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      ASSERT_EQ(x[i * 3 + j], static_cast<double>((i * z[j]) % 64) / 64.0);
    }
  }
}

// With a shift, every point is uniform: over 4096 shifts, point 7's coordinate 2 falls into each
// of 16 bins within 4.9 binomial standard deviations (a false alarm of 1.6e-5 for the 16); the
// baker's transform keeps it uniform (φ maps the uniform law to itself).
TEST(RankOneLatticePoints, ShiftedPointsAreUniformWithAndWithoutTheBaker) {
  std::vector<int> plain(16, 0), baker(16, 0);
  std::vector<double> x(3), y(3);
  for (std::uint64_t r = 0; r < 4096; ++r) {
    rank1_lattice_points<no_periodization>(3, 32, 4, r).generate(7, x);
    rank1_lattice_points<baker_transform>(3, 32, 4, r).generate(7, y);
    ++plain[static_cast<std::size_t>(x[2] * 16)];
    ++baker[static_cast<std::size_t>(y[2] * 16)];
    ASSERT_EQ(y[2], std::min(1.0 - std::abs(2.0 * x[2] - 1.0), largest_below_one));
  }
  const double sd = std::sqrt(4096.0 * (1.0 / 16) * (15.0 / 16));
  for (int b = 0; b < 16; ++b) {
    EXPECT_NEAR(plain[b], 256.0, 4.9 * sd) << b;
    EXPECT_NEAR(baker[b], 256.0, 4.9 * sd) << b;
  }
}

// The vector kernel (sampling/rank1_lattice_blocks.hpp) against the scalar loop kept as
// generate_reference: bitwise equal with and without shift and baker's transform, dimensions on
// both sides of the block sizes (s ≤ 8: 8/gcd(s, 8) points per block; above: 64-lane slices, 16
// with AVX2, with a masked tail), N = 2^4 … 2^16 and 2^20 once per transform, batches cut at sizes
// and starts that split blocks anywhere; at every simd level this CPU offers.
template <class P>
void expect_lattice_kernel_equals_reference(std::size_t s, std::uint64_t n, bool shifted) {
  const rank1_lattice_points<P> points(s, n, 2026, 18, shifted);
  std::vector<double> reference(n * s);
  points.generate_reference(0, reference);
  for (const simd_level level : available_simd_levels()) {
    set_simd_level(level);
    std::vector<double> whole(n * s);
    points.generate(0, whole);
    ASSERT_EQ(std::memcmp(whole.data(), reference.data(), whole.size() * sizeof(double)), 0)
        << "one batch, s = " << s << ", N = " << n << ", level " << to_string(level);
    std::vector<double> split(n * s, -1.0);
    const std::uint64_t sizes[] = {1, 7, 256, 1000, 3};
    for (std::uint64_t p = 0, k = 0; p < n; ++k) {
      const std::uint64_t c = std::min(sizes[k % 5], n - p);
      points.generate(p, std::span<double>(split.data() + p * s, c * s));
      p += c;
    }
    ASSERT_EQ(std::memcmp(split.data(), reference.data(), split.size() * sizeof(double)), 0)
        << "split batches, s = " << s << ", N = " << n << ", level " << to_string(level);
  }
}

TEST(RankOneLatticePoints, VectorKernelEqualsTheScalarLoopBitwise) {
  const simd_level saved = active_simd_level();
  for (const std::size_t s : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u, 9u, 13u, 64u, 65u, 130u}) {
    for (const std::uint64_t n : {std::uint64_t{1} << 4, std::uint64_t{1} << 12,
                                  s <= 2   ? std::uint64_t{1} << 16
                                  : s <= 8 ? std::uint64_t{1} << 14
                                           : std::uint64_t{1} << 13}) {
      for (const bool shifted : {false, true}) {
        expect_lattice_kernel_equals_reference<no_periodization>(s, n, shifted);
        expect_lattice_kernel_equals_reference<baker_transform>(s, n, shifted);
      }
    }
  }
  // The largest N, 2^20 (products i·z_j up to 2^40), once per transform.
  expect_lattice_kernel_equals_reference<no_periodization>(1, std::uint64_t{1} << 20, true);
  expect_lattice_kernel_equals_reference<baker_transform>(2, std::uint64_t{1} << 20, true);
  expect_lattice_kernel_equals_reference<baker_transform>(3600, 64, true);
  set_simd_level(saved);
}

TEST(RankOneLatticePoints, RefusesSizesTheVectorWasNotBuiltFor) {
  EXPECT_THROW(rank1_lattice_points<no_periodization>(2, 1000, 0, 0), invalid_argument);
  EXPECT_THROW(rank1_lattice_points<no_periodization>(2, std::uint64_t{1} << 21, 0, 0),
               invalid_argument);
  EXPECT_THROW(rank1_lattice_points<no_periodization>(3601, 1024, 0, 0), invalid_argument);
  EXPECT_NO_THROW(rank1_lattice_points<no_periodization>(3600, 1024, 0, 0));
}

}  // namespace
}  // namespace quadmc
