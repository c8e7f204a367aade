#include "quadmc/sampling/hemisphere_warps.hpp"

#include "histogram_chi_square.hpp"
#include "quadmc/core/ulp_distance.hpp"
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

// Direction of (z, φ): dω = dz dφ, so the density in (z, φ) is the solid-angle pdf itself.
double pdf_at(const auto& w, double z, double phi) {
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double d[3] = {r * std::cos(phi), r * std::sin(phi), z};
  return w.pdf(std::span<const double>(d, 3));
}

template <class W>
double pdf_integral(const W& w) {
  using gk = boost::math::quadrature::gauss_kronrod<double, 21>;
  return gk::integrate(
      [&](double z) { return gk::integrate([&](double p) { return pdf_at(w, z, p); }, 0, 2 * pi); },
      0.0, 1.0);
}

template <class W>
test_support::chi_square_result histogram_test(const W& w, std::uint64_t seed) {
  constexpr std::size_t nz = 20, np = 20;
  std::vector<double> u(2 * warp_samples);
  independent_points(2, warp_samples, seed, 3).generate(0, u);
  std::vector<double> counts(nz * np, 0.0);
  double d[3];
  double worst_norm_error = 0.0;
  for (std::uint64_t i = 0; i < warp_samples; ++i) {
    w.sample(std::span<const double>(&u[2 * i], 2), d);
    worst_norm_error =
        std::max(worst_norm_error, std::abs(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - 1.0));
    double phi = std::atan2(d[1], d[0]);
    if (phi < 0) phi += 2 * pi;
    const auto iz = std::min<std::size_t>(nz - 1, std::size_t(d[2] * nz));
    const auto ip = std::min<std::size_t>(np - 1, std::size_t(phi / (2 * pi) * np));
    counts[iz * np + ip] += 1.0;
  }
  // Unit length to a few ulps (sin² + cos² and the square roots each round once).
  EXPECT_LE(worst_norm_error, 8 * std::numeric_limits<double>::epsilon());
  return test_support::chi_square_test(
      counts, nz, np, 0.0, 1.0, 0.0, 2 * pi, [&](double z, double p) { return pdf_at(w, z, p); },
      warp_samples, warp_alpha);
}

TEST(UniformHemisphereWarp, PdfIntegratesToOneAndSamplesFollowIt) {
  EXPECT_NEAR(pdf_integral(uniform_hemisphere_warp{}), 1.0, 1e-12);
  const auto r = histogram_test(uniform_hemisphere_warp{}, 1);
  EXPECT_TRUE(r.passes()) << "χ² = " << r.statistic << " > " << r.critical;
}

TEST(CosineHemisphereWarp, PdfIntegratesToOneAndSamplesFollowIt) {
  EXPECT_NEAR(pdf_integral(cosine_hemisphere_warp{}), 1.0, 1e-12);
  const auto r = histogram_test(cosine_hemisphere_warp{}, 2);
  EXPECT_TRUE(r.passes()) << "χ² = " << r.statistic << " > " << r.critical;
}

// The densities pointwise, against their formulas: 1/(2π) and cos θ/π on the upper hemisphere,
// 0 below it (a density that leaks below the horizon, or has the right integral but the wrong
// shape, passes ∫pdf = 1 over the upper hemisphere). Directions (sin θ cos φ, sin θ sin φ, cos θ)
// with cos θ exact in binary; the references 1/(2π) and cos θ/π are each one correctly rounded
// division (of fl(2π) or fl(π)), the library's products with fl(1/π) round once more, so 2 ulp.
// A wrong normalisation (1/π for uniform, cos θ/(2π)) is a factor 2, i.e. 2^52 ulp away.
TEST(HemisphereWarps, PdfsEqualTheirFormulasAtEveryDirection) {
  constexpr std::uint64_t ulps = 2;
  const double uniform_density = 1.0 / (2.0 * pi);
  for (double z : {1.0, 0.875, 0.5, 0.25, 0x1p-10, 0.0}) {
    for (double phi : {0.0, 1.0, 0.5 * pi, 3.0, 5.5}) {
      const double r = std::sqrt(1.0 - z * z);
      const double d[3] = {r * std::cos(phi), r * std::sin(phi), z};
      const std::span<const double> w(d, 3);
      EXPECT_LE(ulp_distance(uniform_hemisphere_warp{}.pdf(w), uniform_density), ulps)
          << "uniform, z = " << z << ", φ = " << phi;
      EXPECT_LE(ulp_distance(cosine_hemisphere_warp{}.pdf(w), z / pi), ulps)
          << "cosine, z = " << z << ", φ = " << phi;
      const double below[3] = {d[0], d[1], -z};
      if (z > 0.0) {
        EXPECT_EQ(uniform_hemisphere_warp{}.pdf(std::span<const double>(below, 3)), 0.0)
            << "below the horizon, z = " << -z;
        EXPECT_EQ(cosine_hemisphere_warp{}.pdf(std::span<const double>(below, 3)), 0.0)
            << "below the horizon, z = " << -z;
      }
    }
  }
}

// Uniform directions are not cosine-distributed: the cosine test must reject them.
TEST(CosineHemisphereWarp, TheTestRejectsTheWrongDensity) {
  struct uniform_claiming_cosine : uniform_hemisphere_warp {
    double pdf(std::span<const double> w) const noexcept { return w[2] / pi; }
  };
  const auto r = histogram_test(uniform_claiming_cosine{}, 3);
  EXPECT_FALSE(r.passes());
}

}  // namespace
