#include "quadmc/sampling/disk_warps.hpp"

#include "histogram_chi_square.hpp"
#include "quadmc/sampling/independent_points.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using namespace quadmc;
using std::numbers::pi;

using test_support::warp_alpha;
using test_support::warp_samples;

// Histogram in polar cells (r, θ) ∈ [0,1] × [0, 2π), 20 × 20; expected probability of a cell =
// ∫∫ pdf(r cos θ, r sin θ)·r dr dθ (Jacobian r).
template <class W>
test_support::chi_square_result polar_histogram_test(const W& w, std::uint64_t seed) {
  constexpr std::size_t nr = 20, nt = 20;
  std::vector<double> u(2 * warp_samples);
  independent_points(2, warp_samples, seed, 2).generate(0, u);
  std::vector<double> counts(nr * nt, 0.0);
  double x[2];
  for (std::uint64_t i = 0; i < warp_samples; ++i) {
    w.sample(std::span<const double>(&u[2 * i], 2), x);
    const double r = std::hypot(x[0], x[1]);
    double theta = std::atan2(x[1], x[0]);
    if (theta < 0) theta += 2 * pi;
    const auto ir = std::min<std::size_t>(nr - 1, std::size_t(r * nr));
    const auto it = std::min<std::size_t>(nt - 1, std::size_t(theta / (2 * pi) * nt));
    counts[ir * nt + it] += 1.0;
  }
  return test_support::chi_square_test(
      counts, nr, nt, 0.0, 1.0, 0.0, 2 * pi,
      [&](double r, double t) {
        const double p[2] = {r * std::cos(t), r * std::sin(t)};
        return w.pdf(std::span<const double>(p, 2)) * r;
      },
      warp_samples, warp_alpha);
}

TEST(UniformDiskWarp, PdfIntegratesToOne) {
  const uniform_disk_warp w;
  using gk = boost::math::quadrature::gauss_kronrod<double, 21>;
  const double total = gk::integrate(
      [&](double r) {
        return gk::integrate(
            [&](double t) {
              const double p[2] = {r * std::cos(t), r * std::sin(t)};
              return w.pdf(std::span<const double>(p, 2)) * r;
            },
            0.0, 2 * pi);
      },
      0.0, 1.0);
  EXPECT_NEAR(total, 1.0, 1e-12);
}

TEST(UniformDiskWarp, SamplesAreUniformInTheDisk) {
  const auto r = polar_histogram_test(uniform_disk_warp{}, 1);
  EXPECT_TRUE(r.passes()) << "χ² = " << r.statistic << " > " << r.critical << " (dof " << r.dof
                          << ")";
}

// r = U₁ clumps at the centre: its true density is 1/(2πr), not the claimed 1/π, and the same
// test must reject it (by a huge margin: the inner ring gets 5% of the samples instead of 0.25%).
TEST(NaiveDiskWarp, FailsTheSameTest) {
  const auto r = polar_histogram_test(naive_disk_warp{}, 1);
  EXPECT_FALSE(r.passes()) << "χ² = " << r.statistic << " ≤ " << r.critical;
  EXPECT_GT(r.statistic, 100 * r.critical);
}

}  // namespace
