// The irradiance images of `quadmc render` (estimators/irradiance_image.hpp): the exact image
// against 10⁷-sample estimates in full light, penumbra and umbra; the per-pixel kernel against
// the library's estimators; and the orderings and the slope of image RMSE the render pages
// report, each with its margin in standard errors derived from the pixels themselves.
#include "quadmc/estimators/irradiance_image.hpp"

#include "quadmc/core/normal_quantile.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/estimators/irradiance_estimators.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/zsobol_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <span>
#include <utility>
#include <vector>

namespace {

using namespace quadmc;

// The scene of bench/scenes/render.toml: the catalogue's occluder lowered to 0.15, where the
// region shows full light, penumbra and umbra.
irradiance_plane render_plane(std::size_t side) {
  return catalogue_irradiance_plane(0.15, {-0.55, -0.6, 0.15, 0.1}, side, side);
}

std::vector<double> exact_image(const irradiance_plane& plane) {
  std::vector<double> out(plane.pixels());
  exact_irradiance_pixels(plane, 0, out);
  return out;
}

std::vector<double> estimated(const irradiance_plane& plane, irradiance_sampling t,
                              std::string_view set, std::uint64_t spp, std::uint64_t stream) {
  std::vector<double> out(plane.pixels());
  estimate_irradiance_pixels(plane, t, *find_point_set(set), spp, 7, stream, 0, out);
  return out;
}

// The image's mean squared error and the standard error of that mean: pixels use distinct
// streams, so their squared errors are independent and the sample variance of e² over the P
// pixels gives se(MSE) = sd(e²)/√P.
struct mse_estimate {
  double mse = 0.0;
  double se = 0.0;
};
mse_estimate mse_of(const std::vector<double>& x, const std::vector<double>& exact) {
  double sum = 0.0, sum_sq = 0.0;
  for (std::size_t p = 0; p < x.size(); ++p) {
    const double e2 = (x[p] - exact[p]) * (x[p] - exact[p]);
    sum += e2;
    sum_sq += e2 * e2;
  }
  const auto n = static_cast<double>(x.size());
  const double mean = sum / n;
  const double var = (sum_sq - n * mean * mean) / (n - 1.0);
  return {mean, std::sqrt(std::max(var, 0.0) / n)};
}

// a's MSE below b's. The images are independent (distinct streams), so the difference has
// standard error √(se_a² + se_b²); the test asserts the observed ordering and that it holds by at
// least 3.72 standard errors, so the margin of this seed is large enough that the one-sided
// probability of the ordering flipping under another seed is at most 1e-4 (Φ(−3.72) = 1e-4;
// with a margin of z σ it is Φ(−z)).
void expect_smaller(const mse_estimate& a, const mse_estimate& b, const std::string& what) {
  const double z = (b.mse - a.mse) / std::hypot(a.se, b.se);
  EXPECT_GT(z, 3.72) << what << ": MSE " << a.mse << " ± " << a.se << " against " << b.mse << " ± "
                     << b.se;
  std::cout << "[ measured ] " << what << ": RMSE " << std::sqrt(a.mse) << " < " << std::sqrt(b.mse)
            << " by " << z << " standard errors\n";
}

TEST(IrradianceImage, PlaneShowsFullLightPenumbraAndUmbra) {
  const irradiance_plane plane = render_plane(32);
  int counts[3] = {0, 0, 0};
  for (std::size_t p = 0; p < plane.pixels(); ++p) {
    ++counts[static_cast<int>(visibility_at(plane, plane.centre(p)))];
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

// At two full-light, three penumbra and one umbra pixel: the light-area estimate with N = 10⁷
// independent points and its own standard error σ̂/√N. |estimate − exact| ≤ z·σ̂/√N with
// z = Φ⁻¹(1 − 10⁻⁴/10) ≈ 4.26: a two-sided false alarm of 10⁻⁵ per pixel, ≤ 10⁻⁴ over the five
// pixels with a random estimate (σ̂ from 10⁷ samples is within 0.1 % of σ; the mean of 10⁷
// bounded values is normal to far better than that tail needs). In the umbra every sample is
// occluded: the estimate is exactly 0, and the exact value must be 0 up to rounding of the two
// equal Lambert sums that cancel (1e-12 of the full light's).
TEST(IrradianceImage, ExactPixelsAgreeWithTenMillionSampleEstimates) {
  const irradiance_plane plane = render_plane(64);
  std::vector<std::size_t> full, penumbra, umbra;
  for (std::size_t p = 0; p < plane.pixels(); p += 7) {
    switch (visibility_at(plane, plane.centre(p))) {
      case light_visibility::full:
        full.push_back(p);
        break;
      case light_visibility::penumbra:
        penumbra.push_back(p);
        break;
      case light_visibility::umbra:
        umbra.push_back(p);
        break;
    }
  }
  ASSERT_GE(full.size(), 2u);
  ASSERT_GE(penumbra.size(), 3u);
  ASSERT_GE(umbra.size(), 1u);
  const std::vector<std::size_t> random_pixels{full.front(), full.back(), penumbra.front(),
                                               penumbra[penumbra.size() / 2], penumbra.back()};
  const double z = normal_quantile(1.0 - 1e-4 / 10.0);
  constexpr std::uint64_t n = 10'000'000;
  for (const std::size_t p : random_pixels) {
    const irradiance_setup setup = plane.setup_at(plane.centre(p));
    const double exact = irradiance_exact(setup);
    const estimate e = irradiance_light_area(setup, independent_points(2, n, 11, p), 2);
    EXPECT_NEAR(e.value, exact, z * e.std_error) << "pixel " << p;
    std::cout << "[ measured ] pixel " << p << ": exact " << exact << ", 10^7 samples " << e.value
              << " ± " << e.std_error << "\n";
  }
  const double full_light = irradiance_exact(plane.setup_at(plane.centre(full.front())));
  const irradiance_setup dark = plane.setup_at(plane.centre(umbra.front()));
  const estimate e = irradiance_light_area(dark, independent_points(2, n, 11, 1), 2);
  EXPECT_EQ(e.value, 0.0);
  EXPECT_LE(std::abs(irradiance_exact(dark)), 1e-12 * full_light);
}

// The per-pixel kernel computes the library estimators' Y: on the same 64 points, the same mean
// up to the rounding of the two ways of writing Y (2π·z·L against L·z/(1/2π): a few ulp).
TEST(IrradianceImage, PixelKernelMatchesTheLibraryEstimators) {
  const irradiance_plane plane = render_plane(16);
  const irradiance_plane_sampler sampler(plane);
  for (const std::size_t p :
       {std::size_t{0}, std::size_t{77}, std::size_t{130}, std::size_t{255}}) {
    const vec3 x = plane.centre(p);
    const irradiance_setup setup = plane.setup_at(x);
    const independent_points points(2, 64, 3, p);
    std::vector<double> u(128);
    points.generate(0, u);
    for (const auto t : {irradiance_sampling::uniform_hemisphere,
                         irradiance_sampling::cosine_hemisphere, irradiance_sampling::light_area}) {
      double sum = 0.0;
      for (std::size_t i = 0; i < 64; ++i) sum += sampler.value(t, x, u[2 * i], u[2 * i + 1]);
      const double library = t == irradiance_sampling::uniform_hemisphere
                                 ? irradiance_uniform_hemisphere(setup, points).value
                             : t == irradiance_sampling::cosine_hemisphere
                                 ? irradiance_cosine_hemisphere(setup, points).value
                                 : irradiance_light_area(setup, points).value;
      EXPECT_NEAR(sum / 64.0, library, 1e-14 * (1.0 + std::abs(library)))
          << "pixel " << p << ", technique " << static_cast<int>(t);
    }
  }
}

// zsobol draws the whole image from one sequence: a pixel is the mean over its Morton block of
// zsobol_points with the image's one stream, whatever block of rows the call computes.
TEST(IrradianceImage, ZsobolPixelsAreTheirMortonBlocksInAnySplit) {
  const irradiance_plane plane = catalogue_irradiance_plane(0.15, {-0.55, -0.6, 0.15, 0.1}, 12, 9);
  const irradiance_plane_sampler sampler(plane);
  const zsobol_points z(12, 9, 16, 7, stream_id({5}));
  std::vector<double> whole(plane.pixels());
  estimate_irradiance_pixels(plane, irradiance_sampling::cosine_hemisphere, zsobol_render_set(), 16,
                             7, 5, 0, whole);
  std::vector<double> u(32);
  for (std::size_t p = 0; p < plane.pixels(); ++p) {
    z.generate(p % 12, p / 12, u);
    double sum = 0.0;
    for (std::size_t i = 0; i < 16; ++i) {
      sum += sampler.value(irradiance_sampling::cosine_hemisphere, plane.centre(p), u[2 * i],
                           u[2 * i + 1]);
    }
    EXPECT_EQ(whole[p], sum / 16.0) << "pixel " << p;
  }
  std::vector<double> parts(plane.pixels());
  for (const auto& [first, count] :
       {std::pair<std::size_t, std::size_t>{0, 13}, {13, 50}, {63, 45}}) {
    estimate_irradiance_pixels(plane, irradiance_sampling::cosine_hemisphere, zsobol_render_set(),
                               16, 7, 5, first, std::span<double>(parts).subspan(first, count));
  }
  EXPECT_EQ(parts, whole);
  // Sizes it cannot index, and the estimators of one integral, are refused in one line.
  EXPECT_THROW(estimate_irradiance_pixels(plane, irradiance_sampling::light_area,
                                          zsobol_render_set(), 12, 7, 5, 0, whole),
               invalid_argument);
  EXPECT_FALSE(pixel_samples_problem(zsobol_render_set(), 4096, 4096, 512).empty());
  EXPECT_TRUE(pixel_samples_problem(zsobol_render_set(), 4096, 4096, 256).empty());
  EXPECT_THROW(zsobol_render_set().irradiance(irradiance_sampling::light_area, plane.setup_at({}),
                                              {1, 2}, 16, 1),
               invalid_argument);
}

TEST(IrradianceImage, CosineBeatsUniformHemisphereAtEqualSpp) {
  const irradiance_plane plane = render_plane(48);
  const auto exact = exact_image(plane);
  for (const std::uint64_t spp : {4u, 16u}) {
    expect_smaller(
        mse_of(estimated(plane, irradiance_sampling::cosine_hemisphere, "independent", spp, 1),
               exact),
        mse_of(estimated(plane, irradiance_sampling::uniform_hemisphere, "independent", spp, 2),
               exact),
        "cosine < uniform hemisphere, spp " + std::to_string(spp));
  }
}

// Far from the light (the region [2.5, 3.5]², about 3.5 away) the light covers a small solid
// angle: most hemisphere directions miss it, while every light-area sample hits it.
TEST(IrradianceImage, LightAreaBeatsCosineWhereTheLightIsSmall) {
  const irradiance_plane plane = catalogue_irradiance_plane(0.15, {2.5, 2.5, 3.5, 3.5}, 32, 32);
  validate(plane);
  const auto exact = exact_image(plane);
  expect_smaller(
      mse_of(estimated(plane, irradiance_sampling::light_area, "independent", 16, 1), exact),
      mse_of(estimated(plane, irradiance_sampling::cosine_hemisphere, "independent", 16, 2), exact),
      "light_area < cosine far from the light, spp 16");
}

TEST(IrradianceImage, JitteredBeatsIndependentWithLightAreaSampling) {
  const irradiance_plane plane = render_plane(48);
  const auto exact = exact_image(plane);
  expect_smaller(
      mse_of(estimated(plane, irradiance_sampling::light_area, "jittered", 16, 1), exact),
      mse_of(estimated(plane, irradiance_sampling::light_area, "independent", 16, 2), exact),
      "jittered < independent, light_area, spp 16");
}

// Image RMSE against spp with independent points: each pixel is a mean of spp i.i.d. samples,
// so E[MSE] = mean σ²/spp exactly and the slope of RMSE is −1/2. The fitted slope's noise comes
// from the MSE estimates: ln RMSE_k has standard error se_k ≈ ½·se(MSE_k)/MSE_k (delta method),
// the images are independent, and the least-squares slope Σ w_k ln RMSE_k (w_k = (x_k − x̄)/Sxx,
// x = ln spp) has standard error √(Σ w_k² se_k²). The test checks |slope + ½| ≤ 0.05 and that
// 0.05 is at least 3.9 of those standard errors (two-sided false alarm ≤ 1e-4), so the tolerance
// is not a guess that happens to pass for this seed. (E[ln RMSE] is biased by −se²/2 ≈ −1e-4, the
// same at every spp to first order: it moves the intercept, not the slope.)
TEST(IrradianceImage, IndependentPointsGiveSlopeMinusOneHalf) {
  const irradiance_plane plane = render_plane(48);
  const auto exact = exact_image(plane);
  for (const auto t : {irradiance_sampling::cosine_hemisphere, irradiance_sampling::light_area}) {
    std::vector<double> n, rmse, se_log;
    for (const std::uint64_t spp : {1u, 4u, 16u, 64u}) {
      const mse_estimate m = mse_of(estimated(plane, t, "independent", spp, spp), exact);
      n.push_back(static_cast<double>(spp));
      rmse.push_back(std::sqrt(m.mse));
      se_log.push_back(0.5 * m.se / m.mse);
    }
    // The least-squares slope of ln RMSE on ln spp, as analysis/power_law_fit.hpp fits it (that
    // layer is above this one).
    double x_mean = 0.0;
    for (const double v : n) x_mean += std::log(v) / 4.0;
    double sxx = 0.0;
    for (const double v : n) sxx += (std::log(v) - x_mean) * (std::log(v) - x_mean);
    double var = 0.0;
    double slope = 0.0;
    for (std::size_t k = 0; k < n.size(); ++k) {
      const double w = (std::log(n[k]) - x_mean) / sxx;
      slope += w * std::log(rmse[k]);
      var += w * w * se_log[k] * se_log[k];
    }
    const double se_slope = std::sqrt(var);
    EXPECT_NEAR(slope, -0.5, 0.05) << "technique " << static_cast<int>(t);
    EXPECT_LE(3.9 * se_slope, 0.05) << "the tolerance is under 3.9 standard errors";
    std::cout << "[ measured ] technique " << static_cast<int>(t) << ": slope " << slope << " ± "
              << se_slope << " (one standard error)\n";
  }
}

TEST(IrradianceImage, RefusesBadPlanesAndCounts) {
  EXPECT_THROW(validate(catalogue_irradiance_plane(0.15, {0.0, 0.0, 0.0, 1.0}, 8, 8)),
               invalid_argument);
  EXPECT_THROW(validate(catalogue_irradiance_plane(0.15, {-0.55, -0.6, 0.15, 0.1}, 0, 8)),
               invalid_argument);
  // The occluder at 1.5 is above the light: not between the plane and the light.
  EXPECT_THROW(validate(catalogue_irradiance_plane(1.5, {-0.55, -0.6, 0.15, 0.1}, 8, 8)),
               invalid_argument);
  const irradiance_plane plane = render_plane(4);
  std::vector<double> out(plane.pixels());
  EXPECT_THROW(estimate_irradiance_pixels(plane, irradiance_sampling::light_area,
                                          *find_point_set("jittered"), 5, 1, 1, 0, out),
               invalid_argument);
  EXPECT_THROW(estimate_irradiance_pixels(plane, irradiance_sampling::light_area,
                                          *find_point_set("independent"), 4, 1, 1, 10, out),
               invalid_argument);
}

}  // namespace
