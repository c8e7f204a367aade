// Tests of analysis/image_error.hpp: the low-pass against a direct 2D sum with mirrored borders,
// its limits (σ = 0, a constant image), white noise's spectrum flat at 1 within its Gamma
// bounds, a single cosine's power all in its ring, and the refusals.
#include "quadmc/analysis/image_error.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/gamma.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace quadmc {
namespace {

std::vector<double> noise(std::size_t pixels, std::uint64_t stream) {
  const random_stream rng(17, stream);
  std::vector<double> e(pixels);
  for (std::size_t p = 0; p < pixels; ++p) {
    // Box–Muller from two uniforms in (0, 1]: standard normal errors.
    const double u1 = 1.0 - rng.uniform(2 * p);
    const double u2 = rng.uniform(2 * p + 1);
    e[p] = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  return e;
}

double rms(const std::vector<double>& e) {
  double s = 0.0;
  for (const double x : e) s += x * x;
  return std::sqrt(s / static_cast<double>(e.size()));
}

// The filter written out as one 2D sum over the (4σ)-square with the borders mirrored
// (… b a | a b … y z | z y …): an independent form of the separable passes.
double direct_lowpass_rmse(const std::vector<double>& e, std::size_t w, std::size_t h,
                           double sigma) {
  const auto radius = static_cast<long>(std::ceil(4.0 * sigma));
  auto mirror = [](long i, long n) {
    while (i < 0 || i >= n) i = i < 0 ? -i - 1 : 2 * n - 1 - i;
    return static_cast<std::size_t>(i);
  };
  double norm = 0.0;
  for (long d = -radius; d <= radius; ++d) norm += std::exp(-0.5 * d * d / (sigma * sigma));
  double sq = 0.0;
  for (long r = 0; r < static_cast<long>(h); ++r) {
    for (long c = 0; c < static_cast<long>(w); ++c) {
      double v = 0.0;
      for (long dr = -radius; dr <= radius; ++dr) {
        for (long dc = -radius; dc <= radius; ++dc) {
          const double weight = std::exp(-0.5 * (dr * dr + dc * dc) / (sigma * sigma));
          v += weight *
               e[mirror(r + dr, static_cast<long>(h)) * w + mirror(c + dc, static_cast<long>(w))];
        }
      }
      v /= norm * norm;
      sq += v * v;
    }
  }
  return std::sqrt(sq / static_cast<double>(e.size()));
}

TEST(ImageError, LowpassEqualsTheDirectSumWithMirroredBorders) {
  // 13 × 9 pixels: σ = 4 reaches 16 pixels out, past both sides, so the mirror repeats.
  const std::vector<double> e = noise(13 * 9, 1);
  for (const double sigma : {0.5, 1.0, 2.0, 4.0}) {
    const double direct = direct_lowpass_rmse(e, 13, 9, sigma);
    EXPECT_NEAR(lowpass_rmse(e, 13, 9, sigma), direct, 1e-13 * direct) << "σ = " << sigma;
  }
}

TEST(ImageError, SigmaZeroIsTheRmseAndAConstantStaysConstant) {
  const std::vector<double> e = noise(32 * 16, 2);
  EXPECT_DOUBLE_EQ(lowpass_rmse(e, 32, 16, 0.0), rms(e));
  const std::vector<double> constant(24 * 10, -0.75);
  for (const double sigma : {0.5, 2.0, 16.0}) {
    EXPECT_NEAR(lowpass_rmse(constant, 24, 10, sigma), 0.75, 1e-14) << "σ = " << sigma;
  }
}

// Standard normal white noise on 256 × 256 pixels: each P(f)/σ² is exponential with mean 1, and
// P(f) = P(−f), so a ring of n frequencies averages n/2 independent exponentials: Gamma(n/2,
// 2/n). Dividing by the image's own mean square instead of σ² = 1 moves every ring by at most
// 6·√(2/N) = 0.033 relative (χ²_N/N, 6 standard deviations: a false alarm of 2e-9). Each ring's
// bounds are the Gamma quantiles at 1e-4/64 on either side: a false alarm of at most 1e-4 for all
// 32 rings (seed fixed).
TEST(ImageError, WhiteNoiseHasAFlatSpectrumAtOne) {
  constexpr std::size_t side = 256;
  const std::vector<double> e = noise(side * side, 3);
  const std::vector<spectrum_ring> rings = error_spectrum(e, side, side);
  ASSERT_EQ(rings.size(), spectrum_rings);
  const double drift = 6.0 * std::sqrt(2.0 / (side * side));
  std::uint64_t total = 0;
  for (std::size_t b = 0; b < rings.size(); ++b) {
    EXPECT_DOUBLE_EQ(rings[b].frequency, static_cast<double>(b + 1) / 64.0);
    ASSERT_GT(rings[b].frequencies, 0u) << "ring " << b;
    total += rings[b].frequencies;
    const double half = static_cast<double>(rings[b].frequencies) / 2.0;
    const boost::math::gamma_distribution<double> mean_of(half, 1.0 / half);
    const double low = quantile(mean_of, 1e-4 / 64) * (1.0 - drift);
    const double high = quantile(complement(mean_of, 1e-4 / 64)) * (1.0 + drift);
    EXPECT_GT(rings[b].relative_power, low) << "ring " << b;
    EXPECT_LT(rings[b].relative_power, high) << "ring " << b;
  }
  // Every frequency of the disk |f| ≤ ½ but f = 0: about π/4 of the 256² (lattice points of the
  // disk of radius 128, Gauss's circle problem: within 2·128·π of π·128²).
  EXPECT_NEAR(static_cast<double>(total), std::numbers::pi * 128.0 * 128.0,
              2.0 * std::numbers::pi * 128.0);
}

// e = cos(2π(a·c/W + b·r/H)) has all its power at ±(a/W, b/H): P = (W·H/2)²/(W·H) at each, over a
// mean square of ½, so its ring holds relative power W·H/n (n the ring's frequencies) and every
// other ring none (to rounding).
TEST(ImageError, ACosineHasItsPowerInItsRingOnly) {
  constexpr std::size_t w = 128, h = 96;
  for (const auto& [a, b] : {std::pair<int, int>{5, 3}, {0, 20}, {40, -30}}) {
    std::vector<double> e(w * h);
    for (std::size_t r = 0; r < h; ++r) {
      for (std::size_t c = 0; c < w; ++c) {
        e[r * w + c] = std::cos(2.0 * std::numbers::pi *
                                (a * static_cast<double>(c) / w + b * static_cast<double>(r) / h));
      }
    }
    const double f = std::hypot(a / static_cast<double>(w), b / static_cast<double>(h));
    const auto ring = static_cast<std::size_t>(std::ceil(f * 64.0)) - 1;
    const std::vector<spectrum_ring> rings = error_spectrum(e, w, h);
    for (std::size_t k = 0; k < rings.size(); ++k) {
      const double expected =
          k == ring ? static_cast<double>(w * h) / static_cast<double>(rings[k].frequencies) : 0.0;
      EXPECT_NEAR(rings[k].relative_power, expected, 1e-9 * static_cast<double>(w * h))
          << "(" << a << ", " << b << "), ring " << k;
    }
  }
}

// Independent standard normal pixels: the filtered pixel y_p = Σ_q W_pq·e_q has E[y_p²] = Σ_q
// W_pq², W the product of the two axes' weight matrices with the mirrored borders folded in, so
// E[mean y²] = (mean over columns of Σ_i M_W[c][i]²)·(mean over rows of Σ_i M_H[r][i]²). Its
// relative standard deviation is √(2A/N), A = Σ_δ ρ(δ)² the area over which filtered pixels are
// correlated (ρ the filter's autocorrelation, computed here per axis, A its square). Pixels
// within 2r of a border (r = ⌈4σ⌉; a fraction at most 8r/side of the image) also share mirrored
// pixels, which at most doubles their ρ: bounding their ρ² by 4 times the interior's, A grows by
// at most a factor 1 + 3·8r/side. The RMSE's relative
// standard deviation is half that of its square; 5 of them on either side (the mean of N/A ≥ 300
// effectively independent squares is near normal): a false alarm below 1e-5 for each σ.
TEST(ImageError, WhiteNoiseKeepsTheFiltersNormOfItsRmse) {
  constexpr std::size_t side = 256;
  const std::vector<double> e = noise(side * side, 4);
  for (const double sigma : {1.0, 2.0, 4.0}) {
    const auto radius = static_cast<long>(std::ceil(4.0 * sigma));
    std::vector<double> w(2 * radius + 1);
    double total = 0.0;
    for (long d = -radius; d <= radius; ++d) {
      total += w[d + radius] = std::exp(-0.5 * d * d / (sigma * sigma));
    }
    for (double& v : w) v /= total;
    // Σ_i M[j][i]² averaged over j, the mirror folding the weights that fall outside.
    double axis = 0.0;
    for (long j = 0; j < static_cast<long>(side); ++j) {
      std::vector<double> row(side, 0.0);
      for (long d = -radius; d <= radius; ++d) {
        long i = j + d;
        while (i < 0 || i >= static_cast<long>(side)) {
          i = i < 0 ? -i - 1 : 2 * static_cast<long>(side) - 1 - i;
        }
        row[static_cast<std::size_t>(i)] += w[d + radius];
      }
      for (const double v : row) axis += v * v;
    }
    axis /= side;
    const double expected = std::sqrt(axis * axis);
    double rho_sq = 0.0;  // Σ_δ ρ(δ)² per axis, ρ(δ) = Σ_d w_d·w_(d+δ) / Σ_d w_d²
    double norm = 0.0;
    for (const double v : w) norm += v * v;
    for (long delta = -2 * radius; delta <= 2 * radius; ++delta) {
      double rho = 0.0;
      for (long d = -radius; d <= radius; ++d) {
        if (d + delta >= -radius && d + delta <= radius)
          rho += w[d + radius] * w[d + delta + radius];
      }
      rho_sq += (rho / norm) * (rho / norm);
    }
    const double edges = 1.0 + 3.0 * 8.0 * static_cast<double>(radius) / side;
    const double area = rho_sq * rho_sq * edges;
    const double sd = 0.5 * std::sqrt(2.0 * area / (side * side));
    EXPECT_NEAR(lowpass_rmse(e, side, side, sigma), expected, 5.0 * sd * expected)
        << "σ = " << sigma;
  }
}

TEST(ImageError, RefusesBadImagesAndWidths) {
  const std::vector<double> e(12, 0.5);
  EXPECT_THROW(lowpass_rmse(e, 4, 4, 1.0), invalid_argument);   // 12 ≠ 16
  EXPECT_THROW(lowpass_rmse(e, 4, 3, -1.0), invalid_argument);  // σ < 0
  EXPECT_THROW(lowpass_rmse(e, 4, 3, std::numeric_limits<double>::quiet_NaN()), invalid_argument);
  EXPECT_THROW(lowpass_rmse(e, 4, 3, 65.0), invalid_argument);
  EXPECT_THROW(error_spectrum(e, 0, 12), invalid_argument);
  std::vector<double> bad = e;
  bad[7] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(error_spectrum(bad, 4, 3), invalid_argument);
  EXPECT_THROW(lowpass_rmse(bad, 4, 3, 1.0), invalid_argument);
  // A zero image has no relative power: NaN, not 0/0 passed off as a number.
  const std::vector<spectrum_ring> zero = error_spectrum(std::vector<double>(64, 0.0), 8, 8);
  EXPECT_TRUE(std::isnan(zero[0].relative_power));
}

}  // namespace
}  // namespace quadmc
