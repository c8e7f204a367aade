// `quadmc render SCENE.toml [--out DIR] [--seed K] [--threads T]`: the plane under the area light
// of the irradiance catalogue seen from above (estimators/irradiance_image.hpp), one irradiance
// integral per pixel, estimated by each estimator with each point set at each spp of the scene
// (scene/render_scene.hpp) and set beside the exact image, written to results/<scene name>/ (or
// DIR).
//
// Use it to see what an estimator's error looks like in a picture and how fast the image RMSE
// falls with the samples per pixel; with [light_sampling], why a renderer decorrelates the light
// samples of neighbouring pixels. Not a convergence study of one integral (that is `quadmc run`).
//
// What it writes (this command computes and writes the CSV and README; bench/render.py draws the
// PNGs from a binary copy of the images that is removed once they are drawn):
//  - rmse.csv: per (estimator, point set, spp) the image RMSE against the exact image at the
//    pixel centres, over all pixels and over the full-light, penumbra and umbra pixels, the mean
//    and largest error, and a fingerprint of the image's bits (equal fingerprints: equal images);
//  - slopes.csv: per (estimator, point set) the fitted slope of RMSE against spp
//    (analysis/power_law_fit.hpp) with its 95% interval;
//  - light_sampling.csv: the P × L experiment's RMSE against the exact pixel means, the
//    correlation of horizontally neighbouring errors, and fingerprints;
//  - README.md, meta.csv, and with images = true exact.png, comparison.png, rmse.png,
//    errors_<estimator>.png and light_sampling.png.
// Same (scene, seed) → the same bits for any thread count: each pixel is a pure function of its
// stream and the statistics are summed in pixel order after all images are done. The folder is
// replaced by the rules of report/results_staging.hpp. Errors are one line.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace quadmc_cli {

struct render_request {
  std::string scene_file;
  std::string out;                    // empty: results/<scene name>
  std::optional<std::uint64_t> seed;  // empty: the scene's
  std::optional<unsigned> threads;    // empty: the scene's; 0 = all cores
};

// Adds the `render` subcommand to `app`, filling `request` when it is parsed.
CLI::App* add_render_subcommand(CLI::App& app, render_request& request);

// Whether `name` is a file a render writes (report/results_staging.hpp's predicate).
bool is_render_file_name(std::string_view name);

// Parses the scene, prints the plan, computes with a progress bar on a terminal, writes the
// folder and prints where. `print` writes to stdout. Throws with a one-line message on failure.
void run_render(const render_request& request, const std::function<void(std::string_view)>& print);

}  // namespace quadmc_cli
