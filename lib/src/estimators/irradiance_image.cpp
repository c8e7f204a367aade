// The plane under the area light, pixel by pixel (irradiance_image.hpp).
#include "quadmc/estimators/irradiance_image.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/random_permutation.hpp"
#include "quadmc/sampling/zsobol_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace quadmc {

namespace {

constexpr std::size_t max_side = std::size_t{1} << 15;
constexpr std::uint64_t max_pattern = 4096;

// 4-point Gauss–Legendre on [0, 1]: nodes (1 + ξ)/2, weights w/2.
constexpr std::array<double, 4> gl_nodes{
    0.5 * (1.0 - 0.8611363115940526), 0.5 * (1.0 - 0.3399810435848563),
    0.5 * (1.0 + 0.3399810435848563), 0.5 * (1.0 + 0.8611363115940526)};
constexpr std::array<double, 4> gl_weights{0.5 * 0.3478548451374538, 0.5 * 0.6521451548625461,
                                           0.5 * 0.6521451548625461, 0.5 * 0.3478548451374538};

void require_pixels(const irradiance_plane& plane, std::size_t first, std::size_t count) {
  require(first <= plane.pixels() && count <= plane.pixels() - first, "first pixel", first,
          "pixels inside the image");
}

void require_size(const point_set_entry& set, std::uint64_t n, std::string_view what) {
  const std::string problem = size_problem(set, 2, n);
  if (!problem.empty()) {
    throw invalid_argument(what, std::to_string(n),
                           fmt::format("a count the {} points hold in 2D: {}", set.name, problem));
  }
}

}  // namespace

std::string pixel_samples_problem(const point_set_entry& set, std::size_t width, std::size_t height,
                                  std::uint64_t spp) {
  std::string problem = size_problem(set, 2, spp);
  if (problem.empty() && &set == &zsobol_render_set()) {
    try {
      const zsobol_points z(width, height, spp, 0, 0);
    } catch (const invalid_argument& e) {
      problem = e.what();
    }
  }
  return problem;
}

void validate(const irradiance_plane& plane) {
  const auto& g = plane.region;
  const bool finite = std::all_of(g.begin(), g.end(), [](double v) { return std::isfinite(v); });
  require(finite && g[0] < g[2] && g[1] < g[3], "region",
          fmt::format("[{}, {}, {}, {}]", g[0], g[1], g[2], g[3]),
          "finite [x_min, y_min, x_max, y_max] with x_min < x_max and y_min < y_max");
  // The irradiance formulas square distances to the light: at |x| ≈ 1e155 they overflow and every
  // figure of the render became NaN. 1e100 leaves squares and products of them finite.
  const bool bounded =
      std::all_of(g.begin(), g.end(), [](double v) { return std::abs(v) <= 1e100; });
  require(bounded, "region", fmt::format("[{}, {}, {}, {}]", g[0], g[1], g[2], g[3]),
          "coordinates with |x| ≤ 1e100 (the squared distances to the light must stay finite)");
  require(plane.width >= 1 && plane.width <= max_side, "width", plane.width, "1 ≤ W ≤ 32768");
  require(plane.height >= 1 && plane.height <= max_side, "height", plane.height, "1 ≤ H ≤ 32768");
  for (const double x : {g[0], g[2]}) {
    for (const double y : {g[1], g[3]}) validate(plane.setup_at({x, y, 0.0}));
  }
}

irradiance_plane catalogue_irradiance_plane(std::optional<double> occluder_height,
                                            std::array<double, 4> region, std::size_t width,
                                            std::size_t height) {
  const irradiance_setup s = default_irradiance_setup(occluder_height.has_value());
  irradiance_plane plane{.light = s.light,
                         .radiance = s.radiance,
                         .occluder = s.occluder,
                         .region = region,
                         .width = width,
                         .height = height};
  if (occluder_height) {
    require(std::isfinite(*occluder_height) && *occluder_height > 0.0, "occluder height",
            *occluder_height, "a finite height > 0 below the light");
    plane.occluder->corner.z = *occluder_height;  // its edges are horizontal
  }
  return plane;
}

light_visibility visibility_at(const irradiance_plane& plane, vec3 x) {
  const auto shadow = occluder_shadow_st(plane.setup_at(x));
  if (shadow.empty()) return light_visibility::full;
  // The shadow in the light's (s, t) square: all of it hidden when its area is the square's.
  double twice_area = 0.0;
  for (std::size_t i = 0; i < shadow.size(); ++i) {
    const auto& a = shadow[i];
    const auto& b = shadow[(i + 1) % shadow.size()];
    twice_area += a[0] * b[1] - a[1] * b[0];
  }
  return std::abs(twice_area) >= 2.0 * (1.0 - 1e-12) ? light_visibility::umbra
                                                     : light_visibility::penumbra;
}

void exact_irradiance_pixels(const irradiance_plane& plane, std::size_t first,
                             std::span<double> out) {
  require_pixels(plane, first, out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k] = irradiance_exact(plane.setup_at(plane.centre(first + k)));
  }
}

void exact_irradiance_pixel_means(const irradiance_plane& plane, std::size_t first,
                                  std::span<double> out) {
  require_pixels(plane, first, out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t p = first + k;
    const auto c = static_cast<double>(p % plane.width);
    const auto r = static_cast<double>(p / plane.width);
    double sum = 0.0;
    for (std::size_t i = 0; i < gl_nodes.size(); ++i) {
      for (std::size_t j = 0; j < gl_nodes.size(); ++j) {
        const vec3 x = plane.point(c + gl_nodes[i], r + gl_nodes[j]);
        sum += gl_weights[i] * gl_weights[j] * irradiance_exact(plane.setup_at(x));
      }
    }
    out[k] = sum;
  }
}

void estimate_irradiance_pixels(const irradiance_plane& plane, irradiance_sampling technique,
                                const point_set_entry& set, std::uint64_t spp, std::uint64_t seed,
                                std::uint64_t image_stream, std::size_t first,
                                std::span<double> out) {
  require_pixels(plane, first, out.size());
  require_size(set, spp, "samples per pixel");
  const irradiance_plane_sampler sampler(plane);
  vec3 x{};
  double sum = 0.0;
  // One batch per pixel (spp ≤ 256) or a few: the sink is called per batch, never per sample.
  const point_batch_sink sink = [&](std::uint64_t, std::span<const double> u) {
    for (std::size_t i = 0; i + 1 < u.size(); i += 2) {
      sum += sampler.value(technique, x, u[i], u[i + 1]);
    }
  };
  const double inv = 1.0 / static_cast<double>(spp);
  // zsobol: one sequence for the whole image (one stream), each pixel its Morton block of it,
  // into a buffer sized once per call, not per pixel.
  std::optional<zsobol_points> z;
  std::vector<double> u;
  if (&set == &zsobol_render_set()) {
    z.emplace(plane.width, plane.height, spp, seed, stream_id({image_stream}));
    u.resize(2 * spp);
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t p = first + k;
    x = plane.centre(p);
    sum = 0.0;
    if (z) {
      z->generate(p % plane.width, p / plane.width, u);
      sink(0, u);
    } else {
      set.points(2, spp, {seed, stream_id({image_stream, p})}, sink);
    }
    out[k] = sum * inv;
  }
}

std::string_view to_string(light_sample_correlation c) noexcept {
  return c == light_sample_correlation::correlated ? "correlated" : "decorrelated";
}

void light_sampling_pixels(const irradiance_plane& plane, const point_set_entry& set,
                           std::uint64_t pixel_samples, std::uint64_t light_samples,
                           light_sample_correlation correlation, std::uint64_t seed,
                           std::uint64_t image_stream, std::size_t first, std::span<double> out) {
  require_pixels(plane, first, out.size());
  require(pixel_samples >= 1 && light_samples >= 1 && pixel_samples <= max_pattern / light_samples,
          "pixel samples × light samples", pixel_samples * light_samples, "1 … 4096");
  const std::uint64_t n_light = pixel_samples * light_samples;
  require_size(set, pixel_samples, "pixel samples");
  require_size(set, n_light, "pixel samples × light samples");
  const irradiance_plane_sampler sampler(plane);
  // Buffers sized once per call: no allocation per pixel or per sample.
  std::vector<double> pixel_u(2 * pixel_samples);
  std::vector<double> light_u(2 * n_light);
  auto into = [](std::vector<double>& buffer) {
    return point_batch_sink([&buffer](std::uint64_t first_point, std::span<const double> u) {
      std::copy(u.begin(), u.end(), buffer.begin() + static_cast<std::ptrdiff_t>(2 * first_point));
    });
  };
  const point_batch_sink to_pixel = into(pixel_u);
  const point_batch_sink to_light = into(light_u);
  const bool shared = correlation == light_sample_correlation::correlated;
  if (shared) set.points(2, n_light, {seed, stream_id({image_stream, 1})}, to_light);
  const double inv = 1.0 / static_cast<double>(n_light);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t p = first + k;
    const auto c = static_cast<double>(p % plane.width);
    const auto r = static_cast<double>(p / plane.width);
    set.points(2, pixel_samples, {seed, stream_id({image_stream, p, 0})}, to_pixel);
    if (!shared) set.points(2, n_light, {seed, stream_id({image_stream, p, 1})}, to_light);
    const random_permutation shuffle(n_light, stream_id({image_stream, p, 2}));
    double sum = 0.0;
    for (std::uint64_t i = 0; i < pixel_samples; ++i) {
      const vec3 x = plane.point(c + pixel_u[2 * i], r + pixel_u[2 * i + 1]);
      for (std::uint64_t l = 0; l < light_samples; ++l) {
        const std::uint64_t j = shared ? i * light_samples + l : shuffle(i * light_samples + l);
        sum +=
            sampler.value(irradiance_sampling::light_area, x, light_u[2 * j], light_u[2 * j + 1]);
      }
    }
    out[k] = sum * inv;
  }
}

}  // namespace quadmc
