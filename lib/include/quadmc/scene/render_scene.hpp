// The scene file of `quadmc render` (bench/scenes/render.toml): which image of the plane under
// the area light to compute, with which estimators, point sets and samples per pixel.
//
// Use it for `quadmc render`'s scene files; a convergence study's scene is parse.hpp's. Its own
// parser rather than parse.hpp's: a render scene has none of a convergence scene's tables
// ([[integrand]], [[method]], [budget]) and keys of its own (the image, the estimators, the spp
// ladder), and `quadmc run` must keep refusing these keys as typos. It reads the TOML with the
// scene layer's reader, so it follows the same rules: the file read within parse.hpp's limits
// (read_scene_file), the text through toml_text.hpp, unknown keys refused, and every error one
// line "file:line:column: key 'k': expected …, got …" (scene_error.hpp).
//
// Keys (all optional; the README's render key table lists them):
//   name = "render"        results/<name>/ unless --out; letters, digits, '_', '-', '.'
//                          (default: the file name without extension).
//   description = "…"      printed under the title of the folder's README.md.
//   seed = 2026            the key of every random stream (default 0).
//   threads = 0            0 = all cores, at most 4096 (default 0).
//   width = 256            W pixels, 1…4096 (default 256).
//   height = 256           H pixels, 1…4096 (default 256).
//   region = [x₀, y₀, x₁, y₁]   the imaged part of the plane z = 0
//                          (default [-0.55, -0.6, 0.15, 0.1]).
//   occluder = true        the catalogue's occluder (functions/irradiance.hpp) or none.
//   occluder_height = 0.5  its height, 0 < h below the light (default 0.5, the catalogue's).
//   estimators = [...]     uniform_hemisphere, cosine_hemisphere, light_area (default all three).
//   point_sets = [...]     names of the point-set catalogue, or zsobol (render only:
//                          sampling/zsobol_points.hpp) (default independent, jittered,
//                          padded_jittered, latin_hypercube, sobol).
//   spp = [1, 4, 16, 64]   samples per pixel, increasing, each 1…4096, at most 16 values; every
//                          set must hold each in 2D.
//   images = true          draw the PNGs (false: CSV and README only, no matplotlib needed).
//   [light_sampling]       the 1 × L against L × 1 experiment (optional; absent: not run):
//     samples = 16         light samples per pixel, 1…4096 (default 16)
//     point_set = "jittered"   the set of both the pixel and the light patterns.
// Bounds: (images) × W × H ≤ 2^25 doubles (256 MiB), checked at `width`.
#pragma once

#include "quadmc/estimators/irradiance_image.hpp"
#include "quadmc/estimators/point_set_catalogue.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

struct render_scene {
  std::string file;
  std::string name;
  std::string description;
  std::uint64_t seed = 0;
  unsigned threads = 0;
  std::size_t width = 256;
  std::size_t height = 256;
  std::array<double, 4> region{-0.55, -0.6, 0.15, 0.1};
  bool occluder = true;
  double occluder_height = 0.5;
  std::vector<irradiance_sampling> estimators;
  std::vector<const point_set_entry*> point_sets;
  std::vector<std::uint64_t> spp;
  bool images = true;
  bool light_sampling = false;
  std::uint64_t light_samples = 16;
  const point_set_entry* light_sampling_set = nullptr;

  irradiance_plane plane() const;
  // Images the render computes: estimated ones, the two exact ones, and 4 of the experiment.
  std::size_t image_count() const noexcept {
    return estimators.size() * point_sets.size() * spp.size() + 2 + (light_sampling ? 4 : 0);
  }
};

std::string_view to_string(irradiance_sampling technique) noexcept;

// The top-level keys and those of [light_sampling], as the parser accepts them.
std::span<const std::string_view> render_scene_keys() noexcept;
std::span<const std::string_view> light_sampling_keys() noexcept;

render_scene parse_render_scene(std::string_view toml_text, std::string_view file_name);
render_scene parse_render_scene_file(const std::filesystem::path& path);

}  // namespace quadmc
