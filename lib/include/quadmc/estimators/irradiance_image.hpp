// Irradiance images: a diffuse plane z = 0 (normal +z) under the rectangular area light of
// functions/irradiance.hpp, seen straight from above, one irradiance integral per pixel
// (docs/theory.md#irradiance-images).
//
// Use it to see an estimator's error the way a renderer's user does, pixel by pixel against the
// exact image (Lambert's polygon formula with the occluder's shadow clipped to the light). Not a
// renderer: no camera, no bounce, no reconstruction filter beyond the box of one pixel.
//
// Pixel (c, r) of a W × H image covers [x₀ + c·Δx, x₀ + (c+1)·Δx] × [y₁ − (r+1)·Δy, y₁ − r·Δy]
// (row 0 at the top, y growing upwards as seen from above), Δx = (x₁ − x₀)/W, Δy = (y₁ − y₀)/H;
// images are row-major, pixel index r·W + c.
//
// Randomness is counter-based: pixel p of an image takes the points of the set with
// sample_stream{seed, stream_id({image_stream, p})}, so every pixel is a pure function of
// (plane, seed, image_stream, p) and rows may be computed on any thread in any order with
// bitwise the same image. The point set is asked for its spp points once per pixel (one batch,
// one call through the catalogue's function pointer); the samples themselves are evaluated
// inline, without allocation.
#pragma once

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/functions/irradiance.hpp"
#include "quadmc/functions/orthonormal_basis.hpp"
#include "quadmc/functions/vec3.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

struct irradiance_plane {
  rectangle light;
  double radiance = 1.0;
  std::optional<rectangle> occluder;
  std::array<double, 4> region{};  // x₀, y₀, x₁, y₁ of the imaged part of z = 0
  std::size_t width = 0;
  std::size_t height = 0;

  std::size_t pixels() const noexcept { return width * height; }
  // The point of z = 0 at fractional pixel coordinates (column, row); (c + ½, r + ½) is the
  // centre of pixel (c, r).
  vec3 point(double column, double row) const noexcept {
    const double dx = (region[2] - region[0]) / static_cast<double>(width);
    const double dy = (region[3] - region[1]) / static_cast<double>(height);
    return {region[0] + column * dx, region[3] - row * dy, 0.0};
  }
  vec3 centre(std::size_t pixel) const noexcept {
    return point(static_cast<double>(pixel % width) + 0.5,
                 static_cast<double>(pixel / width) + 0.5);
  }
  irradiance_setup setup_at(vec3 x) const {
    return {
        .x = x, .n = {0.0, 0.0, 1.0}, .light = light, .radiance = radiance, .occluder = occluder};
  }
};

// Throws quadmc::invalid_argument when the region is empty or not finite, W or H is 0 or above
// 2^15, or the setup of some point of the region fails functions/irradiance.hpp's validate: every
// condition of validate is linear in x (the light facing x, the occluder between x and the
// light's plane) or independent of it, so checking the four corners of the region checks every
// pixel.
void validate(const irradiance_plane& plane);

// The catalogue's light and radiance (default_irradiance_setup) with its occluder (the 0.3 × 0.25
// rectangle at height 0.5) moved to `occluder_height` (no occluder when empty), over `region`.
irradiance_plane catalogue_irradiance_plane(std::optional<double> occluder_height,
                                            std::array<double, 4> region, std::size_t width,
                                            std::size_t height);

// How much of the light a point sees: all of it, part of it (penumbra), none of it (umbra).
enum class light_visibility { full, penumbra, umbra };
light_visibility visibility_at(const irradiance_plane& plane, vec3 x);

// The exact irradiance at the centres of pixels [first, first + out.size()).
void exact_irradiance_pixels(const irradiance_plane& plane, std::size_t first,
                             std::span<double> out);

// The exact mean irradiance over each pixel's square (the box-filtered image a pixel whose
// samples spread over it converges to), by the 4 × 4 Gauss–Legendre product rule of each
// pixel. E is continuous and piecewise smooth, so the rule's error is O(Δ²·|E″|) where a kink
// crosses the pixel and far smaller elsewhere (docs/theory.md#irradiance-images).
void exact_irradiance_pixel_means(const irradiance_plane& plane, std::size_t first,
                                  std::span<double> out);

// Samples of the three irradiance estimators (estimators/irradiance_estimators.hpp) at any point
// of the plane, with the light's and occluder's ray-test frames built once. value(x, u) is the
// estimator's Y for the uniform pair u: the same formulas as irradiance_uniform_hemisphere,
// irradiance_cosine_hemisphere and irradiance_light_area (tests compare them).
class irradiance_plane_sampler {
 public:
  explicit irradiance_plane_sampler(const irradiance_plane& plane)
      : frame_(vec3{0.0, 0.0, 1.0}),
        light_(plane.light),
        occluder_(plane.occluder ? detail::rectangle_frame(*plane.occluder)
                                 : detail::rectangle_frame()),
        occluded_(plane.occluder.has_value()),
        light_rect_(plane.light),
        light_normal_(plane.light.normal()),
        radiance_(plane.radiance),
        area_scale_(plane.radiance * plane.light.area()) {}

  double value(irradiance_sampling technique, vec3 x, double u1, double u2) const noexcept {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    switch (technique) {
      case irradiance_sampling::uniform_hemisphere: {
        const double z = u1;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = two_pi * u2;
        const vec3 w = frame_.to_world({r * std::cos(phi), r * std::sin(phi), z});
        return z != 0.0 && lit(x, w) ? radiance_ * z * two_pi : 0.0;
      }
      case irradiance_sampling::cosine_hemisphere: {
        const double r = std::sqrt(u1);
        const double phi = two_pi * u2;
        const double z = std::sqrt(1.0 - u1);
        const vec3 w = frame_.to_world({r * std::cos(phi), r * std::sin(phi), z});
        return z != 0.0 && lit(x, w) ? radiance_ * std::numbers::pi : 0.0;
      }
      case irradiance_sampling::light_area: {
        const vec3 on_light = light_rect_.point(u1, u2);
        const vec3 d = on_light - x;
        const double r2 = dot(d, d);
        const double v = area_scale_ * d.z * -dot(light_normal_, d) / (r2 * r2);
        return occluded_ && occluder_.hit(x, d, 1.0) ? 0.0 : v;
      }
    }
    return 0.0;
  }

 private:
  bool lit(vec3 x, vec3 w) const noexcept {
    constexpr double inf = std::numeric_limits<double>::infinity();
    bool hit = light_.hit(x, w, inf);
    if (occluded_) hit &= !occluder_.hit(x, w, inf);
    return hit;
  }

  orthonormal_basis frame_;
  detail::rectangle_frame light_, occluder_;
  bool occluded_;
  rectangle light_rect_;
  vec3 light_normal_;
  double radiance_;
  double area_scale_;
};

// Pixels [first, first + out.size()) of one estimated image: each the mean of the estimator's Y
// over the `spp` points of `set` (s = 2, the set's default options) at the pixel centre, stream
// stream_id({image_stream, pixel}); with zsobol_render_set() (point_set_catalogue.hpp) instead,
// one Z-ordered Sobol' sequence over the whole image, stream stream_id({image_stream}), pixel p
// taking its Morton block (sampling/zsobol_points.hpp). Throws invalid_argument when the set
// cannot hold spp points in 2D (padded and jittered sets need N = k², Sobol' N = 2^m; zsobol
// also 4^⌈log₂ max(W, H)⌉ × spp ≤ 2^32).
// Why `set` cannot draw a W × H image with spp samples per pixel (empty when it can): its 2D
// counts (size_problem), and for zsobol the Sobol' index range, 4^⌈log₂ max(W, H)⌉ × spp ≤ 2^32.
std::string pixel_samples_problem(const point_set_entry& set, std::size_t width, std::size_t height,
                                  std::uint64_t spp);

void estimate_irradiance_pixels(const irradiance_plane& plane, irradiance_sampling technique,
                                const point_set_entry& set, std::uint64_t spp, std::uint64_t seed,
                                std::uint64_t image_stream, std::size_t first,
                                std::span<double> out);

// How the light samples of neighbouring pixels relate in light_sampling_pixels.
enum class light_sample_correlation {
  // Every pixel reuses one realization of the light pattern, paired with its pixel samples in
  // the same order: the error of neighbouring pixels is one smooth function of x.
  correlated,
  // Each pixel its own realization, and (with several pixel samples) the pattern's points
  // shuffled against the pixel samples by a random permutation per pixel (padding).
  decorrelated,
};
std::string_view to_string(light_sample_correlation c) noexcept;

// Pixels of a light-area image with `pixel_samples` points of `set` spread over each pixel's
// square and `light_samples` light samples per pixel sample: the P·L points of one light
// pattern of `set` per pixel; pixel sample i takes points π(i·L) … π(i·L + L − 1), π the
// identity (correlated: one realization for the whole image, stream stream_id({image_stream,
// 1})) or a random permutation per pixel (decorrelated: stream stream_id({image_stream, p, 1})
// per pixel). Pixel positions use stream stream_id({image_stream, p, 0}). P·L ≤ 4096. The value is
// the mean over the P·L samples: compare it with exact_irradiance_pixel_means.
void light_sampling_pixels(const irradiance_plane& plane, const point_set_entry& set,
                           std::uint64_t pixel_samples, std::uint64_t light_samples,
                           light_sample_correlation correlation, std::uint64_t seed,
                           std::uint64_t image_stream, std::size_t first, std::span<double> out);

}  // namespace quadmc
