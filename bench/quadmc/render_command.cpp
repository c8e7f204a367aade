// `quadmc render`: see render_command.hpp. Every image is cut into blocks of rows that any thread
// may compute; each pixel depends only on its own stream, and every statistic is summed in pixel
// order once all images are done, so the numbers do not depend on the thread count.
#include "render_command.hpp"

#include "quadmc/analysis/image_error.hpp"
#include "quadmc/analysis/power_law_fit.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/estimators/irradiance_image.hpp"
#include "quadmc/report/csv.hpp"
#include "quadmc/report/interruption.hpp"
#include "quadmc/report/provenance.hpp"
#include "quadmc/report/results_folder.hpp"
#include "quadmc/report/staged_output.hpp"
#include "quadmc/report/table_leaders.hpp"
#include "quadmc/scene/render_scene.hpp"

#include "build_provenance.hpp"
#include "cli_validators.hpp"
#include "plot_script.hpp"
#include "progress_bar.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace quadmc_cli {

namespace fs = std::filesystem;
namespace interruption = quadmc::interruption;
using quadmc::parse_render_scene_file;
using quadmc::render_scene;

namespace {

// Rows per work item: small enough that 2 threads stay balanced on a 256-row image, large enough
// that a work item is ~10⁴ samples or more.
constexpr std::size_t rows_per_block = 8;
// The binary copy of the images that render.py reads; removed once the PNGs are drawn.
constexpr std::string_view pixels_file = "pixels.f64";
constexpr std::string_view index_file = "images.csv";
constexpr std::array<std::string_view, 13> fixed_files{
    "README.md",          "meta.csv",           "rmse.csv",  "slopes.csv",     "light_sampling.csv",
    "lowpass.csv",        "error_spectrum.csv", "exact.png", "comparison.png", "rmse.png",
    "error_spectrum.png", "light_sampling.png", "images.csv"};
// The standard deviations (pixels) of the Gaussian low-pass filters of lowpass.csv; 0: none.
constexpr std::array<double, 5> lowpass_sigmas{0.0, 0.5, 1.0, 2.0, 4.0};
// The frequencies (cycles per pixel) the page's "low-frequency power" averages over.
constexpr double low_frequency = 1.0 / 16.0;
constexpr std::array<quadmc::light_sample_correlation, 2> correlations{
    quadmc::light_sample_correlation::correlated, quadmc::light_sample_correlation::decorrelated};

// A name as a stream-id part: the streams of a (estimator, set) pair do not move when the scene
// lists other estimators or sets, or lists them in another order (FNV-1a, 64 bits).
std::uint64_t name_key(std::string_view name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

// FNV-1a over the images' bit patterns: a fingerprint to compare images by, not a checksum
// against tampering.
std::string fingerprint(std::span<const double> x) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const double v : x) {
    std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    for (int b = 0; b < 8; ++b) {
      h ^= bits & 0xff;
      h *= 0x100000001b3ULL;
      bits >>= 8;
    }
  }
  return fmt::format("{:016x}", h);
}

enum class image_kind { exact, exact_mean, estimate, light_sampling };

struct image {
  image_kind kind = image_kind::estimate;
  quadmc::irradiance_sampling technique = quadmc::irradiance_sampling::light_area;
  const quadmc::point_set_entry* set = nullptr;
  std::uint64_t spp = 0;
  std::uint64_t pixel_samples = 0;  // light_sampling: P × L
  std::uint64_t light_samples = 0;
  quadmc::light_sample_correlation correlation = quadmc::light_sample_correlation::decorrelated;
  std::uint64_t stream = 0;
  std::vector<double> pixels{};
  std::string name() const {
    switch (kind) {
      case image_kind::exact:
        return "exact";
      case image_kind::exact_mean:
        return "exact_mean";
      case image_kind::estimate:
        return fmt::format("{}/{}/{}", to_string(technique), set->name, spp);
      case image_kind::light_sampling:
        return fmt::format("light_sampling/{}x{}/{}", pixel_samples, light_samples,
                           quadmc::to_string(correlation));
    }
    return "?";
  }
};

struct error_stats {
  double rmse = 0.0;
  std::array<double, 3> rmse_by_visibility{};  // full, penumbra, umbra (NaN without pixels)
  double mean_error = 0.0;
  double max_abs_error = 0.0;
  double neighbour_correlation = 0.0;  // Σ e(c, r)·e(c+1, r) / Σ e² over the same pairs
  // Estimates only (analysis/image_error.hpp): the RMSE after each low-pass of lowpass_sigmas,
  // and the relative power spectrum of the error.
  std::array<double, lowpass_sigmas.size()> lowpass_rmse{};
  std::vector<quadmc::spectrum_ring> spectrum{};
};

// The error image's low-pass RMSEs and spectrum into `s`.
void measure_frequencies(std::span<const double> x, std::span<const double> exact,
                         std::size_t width, std::size_t height, error_stats& s) {
  std::vector<double> e(x.size());
  for (std::size_t p = 0; p < x.size(); ++p) e[p] = x[p] - exact[p];
  for (std::size_t i = 0; i < lowpass_sigmas.size(); ++i) {
    s.lowpass_rmse[i] = quadmc::lowpass_rmse(e, width, height, lowpass_sigmas[i]);
  }
  s.spectrum = quadmc::error_spectrum(e, width, height);
}

// The share of its RMSE an error image keeps after the widest low-pass; NaN for an exact image.
double lowpass_share(const error_stats& s) {
  return s.lowpass_rmse[0] > 0.0 ? s.lowpass_rmse.back() / s.lowpass_rmse[0]
                                 : std::numeric_limits<double>::quiet_NaN();
}

// What the widest low-pass leaves of errors independent from pixel to pixel: the filter's
// Σ w² per axis, ≈ 1/(2σ√π) (docs/theory.md#error-spectrum).
double white_noise_share() {
  return 1.0 / (2.0 * lowpass_sigmas.back() * std::sqrt(std::numbers::pi));
}

// The mean relative power over the rings up to low_frequency (weighted by their frequencies).
double low_frequency_power(const error_stats& s) {
  double power = 0.0;
  std::uint64_t count = 0;
  for (const quadmc::spectrum_ring& ring : s.spectrum) {
    if (ring.frequency > low_frequency || ring.frequencies == 0) continue;
    power += ring.relative_power * static_cast<double>(ring.frequencies);
    count += ring.frequencies;
  }
  return count == 0 ? std::numeric_limits<double>::quiet_NaN() : power / static_cast<double>(count);
}

error_stats compare(std::span<const double> x, std::span<const double> exact,
                    std::span<const quadmc::light_visibility> vis, std::size_t width) {
  quadmc::neumaier_sum sq, sum, lag, lag_sq;
  std::array<quadmc::neumaier_sum, 3> sq_by;
  std::array<std::size_t, 3> count_by{};
  error_stats s;
  for (std::size_t p = 0; p < x.size(); ++p) {
    const double e = x[p] - exact[p];
    // No page is written with a non-finite figure: a NaN here made every rmse NaN and the README
    // say "mean nan" with exit status 0.
    if (!std::isfinite(e)) {
      throw std::runtime_error(fmt::format(
          "pixel {} (column {}, row {}): estimate {} against exact {} gives a non-finite error; "
          "nothing written",
          p, p % width, p / width, x[p], exact[p]));
    }
    sq += e * e;
    sum += e;
    const auto v = static_cast<std::size_t>(vis[p]);
    sq_by[v] += e * e;
    ++count_by[v];
    s.max_abs_error = std::max(s.max_abs_error, std::abs(e));
    if ((p + 1) % width != 0) {
      const double next = x[p + 1] - exact[p + 1];
      lag += e * next;
      lag_sq += 0.5 * (e * e + next * next);
    }
  }
  const auto n = static_cast<double>(x.size());
  s.rmse = std::sqrt(sq.value() / n);
  s.mean_error = sum.value() / n;
  for (std::size_t v = 0; v < 3; ++v) {
    s.rmse_by_visibility[v] = count_by[v] == 0
                                  ? std::numeric_limits<double>::quiet_NaN()
                                  : std::sqrt(sq_by[v].value() / static_cast<double>(count_by[v]));
  }
  s.neighbour_correlation = lag_sq.value() > 0.0 ? lag.value() / lag_sq.value()
                                                 : std::numeric_limits<double>::quiet_NaN();
  return s;
}

class render_progress {
 public:
  explicit render_progress(std::uint64_t total, std::size_t images)
      : total_(total), images_(images) {}
  void add(std::uint64_t samples, bool image_finished) {
    const std::lock_guard lock(mutex_);
    done_ += samples;
    if (image_finished) ++images_done_;
    const auto held = interruption::hold();
    bar_.update({images_done_, images_, done_, total_});
  }
  void finish() {
    const std::lock_guard lock(mutex_);
    const auto held = interruption::hold();
    bar_.finish();
  }

 private:
  std::mutex mutex_;
  progress_bar bar_;
  std::uint64_t total_;
  std::size_t images_;
  std::uint64_t done_ = 0;
  std::size_t images_done_ = 0;
};

// Samples an image costs (for the progress bar): polygon evaluations count as one.
std::uint64_t cost_per_pixel(const image& im) {
  switch (im.kind) {
    case image_kind::exact:
      return 1;
    case image_kind::exact_mean:
      return 16;
    case image_kind::estimate:
      return im.spp;
    case image_kind::light_sampling:
      return im.pixel_samples * im.light_samples;
  }
  return 1;
}

void compute_block(const quadmc::irradiance_plane& plane, std::uint64_t seed, image& im,
                   std::size_t first_row) {
  const std::size_t rows = std::min(rows_per_block, plane.height - first_row);
  const std::size_t first = first_row * plane.width;
  const std::span<double> out(im.pixels.data() + first, rows * plane.width);
  switch (im.kind) {
    case image_kind::exact:
      quadmc::exact_irradiance_pixels(plane, first, out);
      break;
    case image_kind::exact_mean:
      quadmc::exact_irradiance_pixel_means(plane, first, out);
      break;
    case image_kind::estimate:
      quadmc::estimate_irradiance_pixels(plane, im.technique, *im.set, im.spp, seed, im.stream,
                                         first, out);
      break;
    case image_kind::light_sampling:
      quadmc::light_sampling_pixels(plane, *im.set, im.pixel_samples, im.light_samples,
                                    im.correlation, seed, im.stream, first, out);
      break;
  }
}

void write_file(const fs::path& file, std::string_view text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
}

std::string line(std::initializer_list<std::string> fields) {
  const std::vector<std::string> v(fields);
  return quadmc::csv_line(v);
}

std::string number(double x) {
  return fmt::format("{}", x);
}

std::string fixed(double x, int digits = 4) {
  if (std::isnan(x)) return "–";
  return fmt::format("{:.{}g}", x, digits);
}

std::vector<std::string> output_files(const render_scene& sc) {
  std::vector<std::string> files(fixed_files.begin(), fixed_files.end());
  files.emplace_back(pixels_file);
  for (const auto t : sc.estimators) files.push_back(fmt::format("errors_{}.png", to_string(t)));
  return files;
}

struct fit_row {
  quadmc::irradiance_sampling technique{};
  const quadmc::point_set_entry* set = nullptr;
  quadmc::power_law_fit fit;
};

// ---------------------------------------------------------------------------------------------
// Computing: the images, block by block over the threads, then their statistics and fits.

// The images of a render and what was measured on them: everything the report writes.
struct render_result {
  std::vector<image> images;  // in the order of the CSV files: exact, [exact_mean], estimates, …
  unsigned threads = 1;
  double seconds = 0.0;
  std::vector<quadmc::light_visibility> visibility;  // per pixel
  std::array<std::size_t, 3> visibility_count{};     // full, penumbra, umbra
  std::vector<error_stats> stats;                    // per image; zero for the exact ones
  double exact_max = 0.0;
  double exact_average = 0.0;
  double centre_vs_mean = 0.0;  // largest |centre − pixel mean|; 0 without [light_sampling]
  std::vector<fit_row> fits;    // per (estimator, point set), in the scene's order
};

// The images, in the order of the CSV files, each with its pixels allocated.
std::vector<image> render_images(const render_scene& sc, std::size_t pixels) {
  std::vector<image> images;
  images.push_back({.kind = image_kind::exact});
  if (sc.light_sampling) images.push_back({.kind = image_kind::exact_mean});
  for (const auto t : sc.estimators) {
    for (const auto* set : sc.point_sets) {
      for (const std::uint64_t spp : sc.spp) {
        images.push_back(
            {.kind = image_kind::estimate,
             .technique = t,
             .set = set,
             .spp = spp,
             .stream = quadmc::stream_id({1, name_key(to_string(t)), name_key(set->name), spp})});
      }
    }
  }
  if (sc.light_sampling) {
    const std::uint64_t L = sc.light_samples;
    for (const auto& [p, l] : {std::pair<std::uint64_t, std::uint64_t>{1, L}, {L, 1}}) {
      for (const auto c : correlations) {
        images.push_back({.kind = image_kind::light_sampling,
                          .set = sc.light_sampling_set,
                          .pixel_samples = p,
                          .light_samples = l,
                          .correlation = c,
                          .stream = quadmc::stream_id({2, p, l, static_cast<std::uint64_t>(c),
                                                       name_key(sc.light_sampling_set->name)})});
      }
    }
  }
  for (image& im : images) im.pixels.resize(pixels);
  return images;
}

std::size_t blocks_per_image(const quadmc::irradiance_plane& plane) {
  return (plane.height + rows_per_block - 1) / rows_per_block;
}

// The scene's thread count, no more than there are blocks to share.
unsigned render_threads(const render_scene& sc, const quadmc::irradiance_plane& plane,
                        std::size_t images) {
  const unsigned cores = quadmc::resolve_threads(sc.threads);
  const std::size_t work_items = blocks_per_image(plane) * images;
  return std::max(1u, static_cast<unsigned>(std::min<std::size_t>(cores, work_items)));
}

// What the render will do, printed before it starts.
std::string plan_text(const render_scene& sc, const quadmc::irradiance_plane& plane,
                      unsigned threads, const fs::path& folder) {
  std::string spp_list;
  for (const auto n : sc.spp) spp_list += fmt::format("{}{}", spp_list.empty() ? "" : ", ", n);
  const double light_low =
      std::min(plane.light.corner.z, (plane.light.corner + plane.light.edge_v).z);
  const double light_high =
      std::max(plane.light.corner.z, (plane.light.corner + plane.light.edge_v).z);
  std::string plan = fmt::format(
      "render: {} × {} pixels of the plane z = 0 over [{}, {}] × [{}, {}] (seed {}), {} threads "
      "→ {}\n"
      "  light: the catalogue's {:.3g} × {:.3g} rectangle at height {:.3g} … {:.3g}, radiance {}; "
      "{}\n",
      plane.width, plane.height, plane.region[0], plane.region[2], plane.region[1], plane.region[3],
      sc.seed, threads, folder.string(), quadmc::length(plane.light.edge_u),
      quadmc::length(plane.light.edge_v), light_low, light_high, plane.radiance,
      sc.occluder ? fmt::format("occluder: the catalogue's 0.25 × 0.3 rectangle at height {}",
                                sc.occluder_height)
                  : std::string("no occluder"));
  plan += fmt::format("  exact image: Lambert's polygon formula at each pixel centre\n");
  plan += fmt::format("  {} estimators × {} point sets × spp {} = {} images, {} samples\n",
                      sc.estimators.size(), sc.point_sets.size(), spp_list,
                      sc.estimators.size() * sc.point_sets.size() * sc.spp.size(), [&] {
                        std::uint64_t n = 0;
                        for (const auto s : sc.spp) n += s;
                        return n * sc.estimators.size() * sc.point_sets.size() * plane.pixels();
                      }());
  for (const auto t : sc.estimators) plan += fmt::format("    estimator {}\n", to_string(t));
  for (const auto* s : sc.point_sets) plan += fmt::format("    point set {}\n", s->name);
  if (sc.light_sampling) {
    plan += fmt::format(
        "  light sampling: 1 × {0} and {0} × 1 (pixel × light samples, light_area, {1} points), "
        "correlated and decorrelated, against the exact pixel means (4 × 4 Gauss–Legendre)\n",
        sc.light_samples, sc.light_sampling_set->name);
  }
  plan +=
      fmt::format("  images: {}\n", sc.images ? "PNG (bench/render.py)" : "off (images = false)");
  return plan;
}

// Every block of every image, taken in turn by `threads` workers, with a progress bar; the
// first failure stops the others and is rethrown. Returns the seconds it took.
double compute_blocks(const quadmc::irradiance_plane& plane, std::uint64_t seed,
                      std::vector<image>& images, unsigned threads) {
  const std::size_t per_image = blocks_per_image(plane);
  const std::size_t work_items = per_image * images.size();
  std::uint64_t total_samples = 0;
  for (const image& im : images) total_samples += cost_per_pixel(im) * plane.pixels();

  const auto start = std::chrono::steady_clock::now();
  render_progress progress(total_samples, images.size());
  std::vector<std::atomic<std::size_t>> blocks_left(images.size());
  for (auto& b : blocks_left) b = per_image;
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(threads);
  {
    std::vector<std::jthread> workers;
    for (unsigned w = 0; w < threads; ++w) {
      workers.emplace_back([&, w] {
        try {
          for (std::size_t i = next++; i < work_items; i = next++) {
            const std::size_t k = i / per_image;
            const std::size_t row = (i % per_image) * rows_per_block;
            compute_block(plane, seed, images[k], row);
            const std::size_t rows = std::min(rows_per_block, plane.height - row);
            progress.add(cost_per_pixel(images[k]) * rows * plane.width, --blocks_left[k] == 0);
          }
        } catch (...) {
          errors[w] = std::current_exception();
          next = work_items;
        }
      });
    }
  }
  progress.finish();
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The statistics of the computed images, in pixel order (so independent of the thread count),
// and the fit of RMSE against spp per (estimator, point set).
void measure(const render_scene& sc, const quadmc::irradiance_plane& plane, render_result& r) {
  r.visibility.resize(plane.pixels());
  for (std::size_t p = 0; p < plane.pixels(); ++p) {
    r.visibility[p] = quadmc::visibility_at(plane, plane.centre(p));
    ++r.visibility_count[static_cast<std::size_t>(r.visibility[p])];
  }
  const std::vector<double>& exact = r.images[0].pixels;
  const std::vector<double>* exact_mean = sc.light_sampling ? &r.images[1].pixels : nullptr;
  r.stats.resize(r.images.size());
  for (std::size_t k = 0; k < r.images.size(); ++k) {
    const image& im = r.images[k];
    if (im.kind == image_kind::estimate) {
      r.stats[k] = compare(im.pixels, exact, r.visibility, plane.width);
      measure_frequencies(im.pixels, exact, plane.width, plane.height, r.stats[k]);
    }
    if (im.kind == image_kind::light_sampling) {
      r.stats[k] = compare(im.pixels, *exact_mean, r.visibility, plane.width);
    }
  }
  quadmc::neumaier_sum exact_sum;
  for (const double e : exact) {
    exact_sum += e;
    r.exact_max = std::max(r.exact_max, e);
  }
  r.exact_average = exact_sum.value() / static_cast<double>(plane.pixels());
  if (exact_mean != nullptr) {
    for (std::size_t p = 0; p < plane.pixels(); ++p) {
      r.centre_vs_mean = std::max(r.centre_vs_mean, std::abs(exact[p] - (*exact_mean)[p]));
    }
  }
  for (const auto t : sc.estimators) {
    for (const auto* set : sc.point_sets) {
      std::vector<double> n, err;
      for (std::size_t k = 0; k < r.images.size(); ++k) {
        const image& im = r.images[k];
        if (im.kind != image_kind::estimate || im.technique != t || im.set != set) continue;
        if (r.stats[k].rmse > 0.0) {
          n.push_back(static_cast<double>(im.spp));
          err.push_back(r.stats[k].rmse);
        }
      }
      r.fits.push_back({t, set, quadmc::fit_power_law(n, err)});
    }
  }
}

render_result compute_render(const render_scene& sc, const quadmc::irradiance_plane& plane,
                             std::vector<image> images, unsigned threads) {
  render_result r;
  r.images = std::move(images);
  r.threads = threads;
  r.seconds = compute_blocks(plane, sc.seed, r.images, threads);
  measure(sc, plane, r);
  return r;
}

// ---------------------------------------------------------------------------------------------
// Reporting: the CSV files, the README and the images' binary copy for render.py.

std::string rmse_csv(const render_scene& sc, const render_result& r) {
  std::string csv =
      line({"estimator", "point_set", "spp", "rmse", "rmse_full_light", "rmse_penumbra",
            "rmse_umbra", "mean_error", "max_abs_error", "fingerprint"});
  for (const auto t : sc.estimators) {
    for (const auto* set : sc.point_sets) {
      for (std::size_t k = 0; k < r.images.size(); ++k) {
        const image& im = r.images[k];
        if (im.kind != image_kind::estimate || im.technique != t || im.set != set) continue;
        const error_stats& s = r.stats[k];
        csv += line({std::string(to_string(t)), std::string(set->name), std::to_string(im.spp),
                     number(s.rmse), number(s.rmse_by_visibility[0]),
                     number(s.rmse_by_visibility[1]), number(s.rmse_by_visibility[2]),
                     number(s.mean_error), number(s.max_abs_error), fingerprint(im.pixels)});
      }
    }
  }
  return csv;
}

std::string slopes_csv(const render_result& r) {
  std::string csv =
      line({"estimator", "point_set", "points", "slope", "ci_low", "ci_high", "status"});
  for (const fit_row& f : r.fits) {
    csv += line({std::string(to_string(f.technique)), std::string(f.set->name),
                 std::to_string(f.fit.points), number(f.fit.slope), number(f.fit.ci_low),
                 number(f.fit.ci_high), quadmc::to_string(f.fit.status)});
  }
  return csv;
}

std::string lowpass_csv(const render_result& r) {
  std::string csv = line({"estimator", "point_set", "spp", "sigma", "rmse"});
  for (std::size_t k = 0; k < r.images.size(); ++k) {
    const image& im = r.images[k];
    if (im.kind != image_kind::estimate) continue;
    for (std::size_t i = 0; i < lowpass_sigmas.size(); ++i) {
      csv += line({std::string(to_string(im.technique)), std::string(im.set->name),
                   std::to_string(im.spp), number(lowpass_sigmas[i]),
                   number(r.stats[k].lowpass_rmse[i])});
    }
  }
  return csv;
}

std::string error_spectrum_csv(const render_result& r) {
  std::string csv =
      line({"estimator", "point_set", "spp", "frequency", "frequencies", "relative_power"});
  for (std::size_t k = 0; k < r.images.size(); ++k) {
    const image& im = r.images[k];
    if (im.kind != image_kind::estimate) continue;
    for (const quadmc::spectrum_ring& ring : r.stats[k].spectrum) {
      csv += line({std::string(to_string(im.technique)), std::string(im.set->name),
                   std::to_string(im.spp), number(ring.frequency), std::to_string(ring.frequencies),
                   number(ring.relative_power)});
    }
  }
  return csv;
}

std::string light_sampling_csv(const render_result& r) {
  std::string csv =
      line({"point_set", "pixel_samples", "light_samples", "correlation", "rmse", "rmse_penumbra",
            "mean_error", "max_abs_error", "neighbour_correlation", "fingerprint"});
  for (std::size_t k = 0; k < r.images.size(); ++k) {
    const image& im = r.images[k];
    if (im.kind != image_kind::light_sampling) continue;
    const error_stats& s = r.stats[k];
    csv += line({std::string(im.set->name), std::to_string(im.pixel_samples),
                 std::to_string(im.light_samples), std::string(quadmc::to_string(im.correlation)),
                 number(s.rmse), number(s.rmse_by_visibility[1]), number(s.mean_error),
                 number(s.max_abs_error), number(s.neighbour_correlation), fingerprint(im.pixels)});
  }
  return csv;
}

// The statistics of the estimated image of (technique, set, spp); nullptr if it was not rendered.
const error_stats* stats_of(const render_result& r, quadmc::irradiance_sampling technique,
                            const quadmc::point_set_entry* set, std::uint64_t spp) {
  for (std::size_t k = 0; k < r.images.size(); ++k) {
    const image& im = r.images[k];
    if (im.kind == image_kind::estimate && im.technique == technique && im.set == set &&
        im.spp == spp) {
      return &r.stats[k];
    }
  }
  return nullptr;
}

// The RMSE of the image of (technique, set, spp) over all pixels (visibility nullopt) or over one
// visibility class; nullopt where that class has no pixel (its RMSE is NaN).
std::optional<double> rmse_of(const render_result& r, quadmc::irradiance_sampling technique,
                              const quadmc::point_set_entry* set, std::uint64_t spp,
                              std::optional<std::size_t> visibility) {
  const error_stats* s = stats_of(r, technique, set, spp);
  if (s == nullptr) return std::nullopt;
  const double e = visibility ? s->rmse_by_visibility[*visibility] : s->rmse;
  return std::isnan(e) ? std::nullopt : std::optional<double>(e);
}

// Per estimator, its point sets' RMSE at each spp: the table the page shows, as one
// report/table_leaders.hpp table per estimator.
std::string best_set_per_estimator(const render_scene& sc, const render_result& r,
                                   std::optional<std::size_t> visibility) {
  std::vector<std::string> parts;
  for (const auto tech : sc.estimators) {
    quadmc::scored_table t{"spp", sc.spp, {}, {}};
    for (const auto* set : sc.point_sets) {
      t.rows.emplace_back(set->name);
      std::vector<std::optional<double>> values;
      for (const std::uint64_t spp : sc.spp)
        values.push_back(rmse_of(r, tech, set, spp, visibility));
      t.values.push_back(std::move(values));
    }
    parts.push_back(
        fmt::format("`{}`: {}", to_string(tech), quadmc::leaders_phrase(t, "independent")));
  }
  return fmt::format("{}", fmt::join(parts, "; "));
}

// The answer at the top of the page, read from its tables: the lowest RMSE at the largest spp,
// the best point set of each estimator over all pixels and in the penumbra, the range of the fitted
// slopes, and the light-sampling layouts from lowest RMSE to highest.
std::vector<std::string> answer_lines(const render_scene& sc, const render_result& r) {
  std::vector<std::string> lines;
  const std::uint64_t top = sc.spp.back();
  struct entry {
    double rmse;
    std::string what;
    std::optional<double> independent;  // the same estimator with independent points
  };
  std::vector<entry> at_top;
  const auto found = std::find_if(sc.point_sets.begin(), sc.point_sets.end(),
                                  [](const auto* set) { return set->name == "independent"; });
  const quadmc::point_set_entry* independent = found == sc.point_sets.end() ? nullptr : *found;
  for (const auto tech : sc.estimators) {
    for (const auto* set : sc.point_sets) {
      if (const auto e = rmse_of(r, tech, set, top, std::nullopt)) {
        at_top.push_back({*e, fmt::format("`{}` with `{}`", to_string(tech), set->name),
                          independent != nullptr && independent != set
                              ? rmse_of(r, tech, independent, top, std::nullopt)
                              : std::nullopt});
      }
    }
  }
  if (!at_top.empty()) {
    const auto [low, high] =
        std::minmax_element(at_top.begin(), at_top.end(),
                            [](const entry& a, const entry& b) { return a.rmse < b.rmse; });
    std::string line =
        fmt::format("**Lowest image RMSE at spp = {}:** {} ({:.4g}", top, low->what, low->rmse);
    if (low->independent && *low->independent > low->rmse) {
      line += fmt::format(", {:.3g}× below the same estimator with `independent` points",
                          *low->independent / low->rmse);
    }
    lines.push_back(line + fmt::format("); highest {} ({:.4g}).", high->what, high->rmse));
  }
  // After the widest low-pass at the largest spp: the lowest RMSE left, and the smallest share of
  // its own RMSE an image keeps (white noise keeps ≈ 1/(2σ√π); blue noise less).
  const double widest = lowpass_sigmas.back();
  std::optional<std::pair<double, std::string>> lowest_left, smallest_share;
  for (std::size_t k = 0; k < r.images.size(); ++k) {
    const image& im = r.images[k];
    const double share = lowpass_share(r.stats[k]);
    if (im.kind != image_kind::estimate || im.spp != top || std::isnan(share)) continue;
    const std::string what = fmt::format("`{}` with `{}`", to_string(im.technique), im.set->name);
    const double left = r.stats[k].lowpass_rmse.back();
    if (!lowest_left || left < lowest_left->first) lowest_left = {left, what};
    if (!smallest_share || share < smallest_share->first) smallest_share = {share, what};
  }
  if (lowest_left) {
    lines.push_back(fmt::format(
        "**After a Gaussian low-pass of σ = {} pixels** (spp {}): lowest RMSE {} ({:.4g}); the "
        "smallest share of its own RMSE kept, {} ({:.3g}; errors independent from pixel to pixel "
        "keep ≈ {:.3g}).",
        widest, top, lowest_left->second, lowest_left->first, smallest_share->second,
        smallest_share->first, white_noise_share()));
  }
  lines.push_back("**Best point set per estimator, all pixels:** " +
                  best_set_per_estimator(sc, r, std::nullopt) + ".");
  lines.push_back("**In the penumbra** (where the occluder hides part of the light): " +
                  best_set_per_estimator(sc, r, 1) + ".");
  const fit_row* steep = nullptr;
  const fit_row* shallow = nullptr;
  for (const fit_row& f : r.fits) {
    if (!f.fit.ok()) continue;
    if (steep == nullptr || f.fit.slope < steep->fit.slope) steep = &f;
    if (shallow == nullptr || f.fit.slope > shallow->fit.slope) shallow = &f;
  }
  if (steep != nullptr) {
    const auto described = [](const fit_row& f) {
      return fmt::format("`{}` with `{}` {:.3f} [{:.3f}, {:.3f}]", to_string(f.technique),
                         f.set->name, f.fit.slope, f.fit.ci_low, f.fit.ci_high);
    };
    lines.push_back(fmt::format(
        "**Slopes of log RMSE on log spp** (independent samples: −1/2): steepest {}, shallowest "
        "{}.",
        described(*steep), described(*shallow)));
  }
  if (sc.light_sampling) {
    std::vector<std::pair<double, std::string>> layouts;
    for (std::size_t k = 0; k < r.images.size(); ++k) {
      const image& im = r.images[k];
      if (im.kind != image_kind::light_sampling) continue;
      layouts.emplace_back(
          r.stats[k].rmse,
          fmt::format("{} × {} {} {:.4g} (neighbour correlation {:.3f})", im.pixel_samples,
                      im.light_samples, quadmc::to_string(im.correlation), r.stats[k].rmse,
                      r.stats[k].neighbour_correlation));
    }
    std::stable_sort(layouts.begin(), layouts.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> listed;
    for (const auto& l : layouts) listed.push_back(l.second);
    lines.push_back(fmt::format("**{} light samples per pixel**, lowest RMSE first: {}.",
                                sc.light_samples, fmt::join(listed, ", ")));
  }
  return lines;
}

// The README's title, what was rendered and how, and the exact image.
std::string readme_intro(const render_scene& sc, const quadmc::irradiance_plane& plane,
                         const quadmc::provenance& build, const render_result& r) {
  const double pixels = static_cast<double>(plane.pixels());
  std::string t;
  t += fmt::format("# {}\n\n", sc.name);
  if (!sc.description.empty()) t += sc.description + "\n\n";
  // The answer first, from the tables further down; a quotation, as on the run pages.
  for (const std::string& line : answer_lines(sc, r)) t += fmt::format("> - {}\n", line);
  t += "\n";
  t += fmt::format(
      "The plane z = 0 under the area light of the irradiance catalogue, seen from above: {} × {} "
      "pixels over [{}, {}] × [{}, {}], one irradiance integral E(x) = ∫ L·V·cosθ dω per pixel "
      "centre. Made by `quadmc render {}` (seed {}) in {:.1f} s on {} threads; quadmc {} (commit "
      "{}, {}).\n\n",
      plane.width, plane.height, plane.region[0], plane.region[2], plane.region[1], plane.region[3],
      sc.file, sc.seed, r.seconds, r.threads, build.version, build.commit, build.compiler);
  t += fmt::format(
      "Exact image: Lambert's polygon formula minus the occluder's shadow clipped to the light "
      "(functions/irradiance.hpp); E ranges up to {:.4g}, mean {:.4g}. Pixels in full light {:.1f} "
      "%, penumbra {:.1f} %, umbra {:.1f} %.\n\n",
      r.exact_max, r.exact_average, 100.0 * static_cast<double>(r.visibility_count[0]) / pixels,
      100.0 * static_cast<double>(r.visibility_count[1]) / pixels,
      100.0 * static_cast<double>(r.visibility_count[2]) / pixels);
  if (sc.images) {
    t += "![Exact irradiance and where the light is fully visible, partly hidden, "
         "hidden](exact.png)\n\n";
    t += "![Estimates and signed errors of the three estimators](comparison.png)\n\n";
  }
  return t;
}

// The RMSE tables: over all pixels with the fitted slopes, then over the penumbra.
std::string readme_rmse(const render_scene& sc, const render_result& r) {
  std::string t;
  t += "## Image RMSE against samples per pixel\n\n";
  t += "RMSE over all pixels of (estimate − exact); slope of log RMSE on log spp with its 95% "
       "interval (Student t, analysis/power_law_fit.hpp).\n\n";
  t += "| estimator | point set |";
  for (const auto n : sc.spp) t += fmt::format(" spp {} |", n);
  t += " slope [95% interval] |\n|---|---|";
  for (std::size_t i = 0; i < sc.spp.size(); ++i) t += "---|";
  t += "---|\n";
  std::size_t f = 0;
  for (const auto tech : sc.estimators) {
    for (const auto* set : sc.point_sets) {
      t += fmt::format("| {} | {} |", to_string(tech), set->name);
      for (std::size_t k = 0; k < r.images.size(); ++k) {
        const image& im = r.images[k];
        if (im.kind == image_kind::estimate && im.technique == tech && im.set == set) {
          t += fmt::format(" {} |", fixed(r.stats[k].rmse));
        }
      }
      const auto& fit = r.fits[f++].fit;
      t += fit.ok()
               ? fmt::format(" {:.3f} [{:.3f}, {:.3f}] |\n", fit.slope, fit.ci_low, fit.ci_high)
               : fmt::format(" {} |\n", quadmc::to_string(fit.status));
    }
  }
  t += "\nThe same in the penumbra only (where the occluder hides part of the light):\n\n";
  t += "| estimator | point set |";
  for (const auto n : sc.spp) t += fmt::format(" spp {} |", n);
  t += "\n|---|---|";
  for (std::size_t i = 0; i < sc.spp.size(); ++i) t += "---|";
  t += "\n";
  for (const auto tech : sc.estimators) {
    for (const auto* set : sc.point_sets) {
      t += fmt::format("| {} | {} |", to_string(tech), set->name);
      for (std::size_t k = 0; k < r.images.size(); ++k) {
        const image& im = r.images[k];
        if (im.kind == image_kind::estimate && im.technique == tech && im.set == set) {
          t += fmt::format(" {} |", fixed(r.stats[k].rmse_by_visibility[1]));
        }
      }
      t += "\n";
    }
  }
  if (sc.images) {
    t += "\n![Image RMSE against spp, log-log, with fitted slopes](rmse.png)\n";
    for (const auto tech : sc.estimators) {
      t += fmt::format("\n![Signed error of {0}, every point set and spp](errors_{0}.png)\n",
                       to_string(tech));
    }
  }
  return t;
}

// The low-pass table: per estimator and point set at the largest spp, the RMSE after each
// Gaussian low-pass, how much of it the widest leaves, and the error's power at low frequencies.
std::string readme_lowpass(const render_scene& sc, const render_result& r) {
  const std::uint64_t top = sc.spp.back();
  const double widest = lowpass_sigmas.back();
  std::string t;
  t += fmt::format("\n## Error after a low-pass filter, and its spectrum (spp {})\n\n", top);
  t += fmt::format(
      "The RMSE of the error image after a Gaussian low-pass of σ pixels (normalized, mirrored "
      "at the borders; σ = 0 is the RMSE above), as the eye sees an image from further away; and "
      "the error's power at frequencies up to {} cycle per pixel relative to its mean square "
      "(white noise: 1; analysis/image_error.hpp). Errors independent from pixel to pixel keep "
      "a fraction ≈ 1/(2σ√π) of their RMSE after the filter ({:.3g} at σ = {}); errors that "
      "cancel between neighbouring pixels (blue noise) keep less, and have low-frequency power "
      "below 1 (docs/theory.md#error-spectrum). Every spp: `lowpass.csv`; every ring of the "
      "spectrum: `error_spectrum.csv`.\n\n",
      low_frequency, white_noise_share(), widest);
  t += "| estimator | point set |";
  for (const double s : lowpass_sigmas) t += fmt::format(" σ = {} |", s);
  t += fmt::format(" σ = {} / σ = 0 | power at f ≤ {} |\n|---|---|", widest, low_frequency);
  for (std::size_t i = 0; i < lowpass_sigmas.size() + 2; ++i) t += "---|";
  t += "\n";
  for (const auto tech : sc.estimators) {
    for (const auto* set : sc.point_sets) {
      const error_stats* s = stats_of(r, tech, set, top);
      if (s == nullptr) continue;
      t += fmt::format("| {} | {} |", to_string(tech), set->name);
      for (const double v : s->lowpass_rmse) t += fmt::format(" {} |", fixed(v));
      t += fmt::format(" {} | {} |\n", fixed(lowpass_share(*s), 3),
                       fixed(low_frequency_power(*s), 3));
    }
  }
  if (sc.images) {
    t += "\n![Error power by frequency and RMSE after each low-pass, at the largest "
         "spp](error_spectrum.png)\n";
  }
  return t;
}

std::string readme_how_to_read() {
  return "\n## How to read it\n\n"
         "- **Exact image**: irradiance at each pixel centre. Under the occluder the light is "
         "fully hidden (umbra), around it partly (penumbra); elsewhere the whole light is seen and "
         "E falls off with the distance and angle to the light.\n"
         "- **Signed error** (estimate − exact) in a diverging colour map centred on 0: blue "
         "below, red above the exact value; each column of `errors_<estimator>.png` shares one "
         "symmetric scale (stated above it) so the point sets are compared at equal spp.\n"
         "- **uniform_hemisphere** samples directions uniformly (Y = 2π·L·V·cosθ), "
         "**cosine_hemisphere** by cosθ/π (Y = π·L·V), **light_area** points on the light "
         "(Y = A·L·V·cosθ·cosθ′/r²): every light_area sample hits the light, so its error comes "
         "only from the occluder's outline and the smooth cosθ·cosθ′/r², and vanishes in full "
         "light for a stratified set (docs/theory.md#irradiance-images).\n"
         "- **Slopes**: independent points give −1/2 exactly in expectation (each pixel is a mean "
         "of spp independent samples); stratified sets are steeper where the integrand is smooth "
         "(light_area in full light: −1 for jittered points) and −3/4 across a visibility edge in "
         "2D; an image mixes these regions, and its ladder starts at 1 spp where every set is one "
         "random point, so its fitted slope lies between them "
         "(docs/theory.md#irradiance-images).\n";
}

// The [light_sampling] experiment's section; empty without it.
std::string readme_light_sampling(const render_scene& sc, const render_result& r) {
  if (!sc.light_sampling) return {};
  std::string t;
  t += fmt::format("\n## Light sampling: 1 × {0} against {0} × 1\n\n", sc.light_samples);
  t += fmt::format(
      "light_area with {1} points, {0} light samples per pixel in both layouts: one pixel "
      "sample (a random point of the pixel's square) with {0} light samples, or {0} pixel "
      "samples (a {1} pattern over the pixel) with one light sample each. **Correlated**: every "
      "pixel reuses one realization of the light pattern, paired with its pixel samples in "
      "order. **Decorrelated**: each pixel draws its own light pattern and (with {0} pixel "
      "samples) shuffles it against the pixel samples by a random permutation (padding). "
      "Reference: the exact mean over each pixel's square (4 × 4 Gauss–Legendre; it differs "
      "from the centre value by at most {2:.2g} here). *Neighbour correlation* is "
      "Σ e(c, r)·e(c+1, r) / Σ ½(e(c, r)² + e(c+1, r)²): 1 when horizontally neighbouring "
      "errors are equal, 0 when they are independent.\n\n",
      sc.light_samples, sc.light_sampling_set->name, r.centre_vs_mean);
  t += "| pixel × light samples | light samples of neighbouring pixels | RMSE | RMSE in the "
       "penumbra | mean error | neighbour correlation |\n|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < r.images.size(); ++k) {
    const image& im = r.images[k];
    if (im.kind != image_kind::light_sampling) continue;
    const error_stats& s = r.stats[k];
    t += fmt::format("| {} × {} | {} | {} | {} | {} | {:.3f} |\n", im.pixel_samples,
                     im.light_samples, quadmc::to_string(im.correlation), fixed(s.rmse),
                     fixed(s.rmse_by_visibility[1]), fixed(s.mean_error, 2),
                     s.neighbour_correlation);
  }
  t += "\nCorrelated or not, the RMSE is of the same order; what changes is its structure. With "
       "one light pattern for every pixel the error is one smooth function of the position: "
       "the penumbra shows the pattern's copies of the occluder's outline as bands, neighbouring "
       "errors are nearly equal, and the pattern's own error is a mean error shared by the "
       "whole image that no averaging over pixels removes. Decorrelated, the error is noise "
       "(neighbour correlation ≈ 0, mean ≈ 0). That is why a sampler shuffles: the error is "
       "not smaller, but it has no structure for the eye to find "
       "([Pharr et al. 2016, §7.3]; docs/theory.md#irradiance-images).\n";
  if (sc.images) {
    t += "\n![Light sampling: correlated against decorrelated, 1 × L against L × "
         "1](light_sampling.png)\n";
  }
  return t;
}

std::string readme_files(const render_scene& sc) {
  return "\n## Files\n\n"
         "`rmse.csv` (estimator, point_set, spp, rmse, rmse_full_light, rmse_penumbra, "
         "rmse_umbra, mean_error, max_abs_error, fingerprint: FNV-1a of the image's bits), "
         "`slopes.csv` (estimator, point_set, points, slope, ci_low, ci_high, status), "
         "`light_sampling.csv` (point_set, pixel_samples, light_samples, correlation, rmse, "
         "rmse_penumbra, mean_error, max_abs_error, neighbour_correlation, fingerprint), "
         "`lowpass.csv` (estimator, point_set, spp, sigma, rmse: after a Gaussian low-pass of "
         "sigma pixels), `error_spectrum.csv` (estimator, point_set, spp, frequency: the ring's "
         "outer radius in cycles per pixel, frequencies in it, relative_power: their mean power "
         "over the error's mean square), "
         "`meta.csv` (what built the command). Per-pixel randomness is counter-based: pixel p of "
         "an image uses the Philox stream stream_id({image, p}), the image named by (estimator, "
         "point set, spp), and `zsobol` one stream stream_id({image}) for its whole image, so "
         "the files are the same bits for any thread count. Regenerate with "
         "`build/release/bench/quadmc render " +
         sc.file + "`.\n";
}

std::string readme_text(const render_scene& sc, const quadmc::irradiance_plane& plane,
                        const quadmc::provenance& build, const render_result& r) {
  return readme_intro(sc, plane, build, r) + readme_rmse(sc, r) + readme_lowpass(sc, r) +
         readme_how_to_read() + readme_light_sampling(sc, r) + readme_files(sc);
}

// The images for render.py: float64 little-endian, one after the other, described by
// images.csv; the visibility map first.
void write_pixels(const fs::path& dir, const quadmc::irradiance_plane& plane,
                  const render_result& r) {
  std::string index =
      line({"name", "kind", "estimator", "point_set", "spp", "pixel_samples", "light_samples",
            "correlation", "offset", "width", "height", "x_min", "y_min", "x_max", "y_max"});
  const std::string x_min = number(plane.region[0]), y_min = number(plane.region[1]),
                    x_max = number(plane.region[2]), y_max = number(plane.region[3]);
  // Written image by image (never a second copy of every image in memory).
  std::uint64_t offset = 0;
  index +=
      line({"visibility", "visibility", "", "", "", "", "", "", "0", std::to_string(plane.width),
            std::to_string(plane.height), x_min, y_min, x_max, y_max});
  std::vector<double> visibility(r.visibility.size());
  std::transform(r.visibility.begin(), r.visibility.end(), visibility.begin(),
                 [](quadmc::light_visibility v) { return static_cast<double>(v); });
  offset += visibility.size();
  for (const image& im : r.images) {
    const std::string kind = im.kind == image_kind::exact        ? "exact"
                             : im.kind == image_kind::exact_mean ? "exact_mean"
                             : im.kind == image_kind::estimate   ? "estimate"
                                                                 : "light_sampling";
    index +=
        line({im.name(), kind,
              im.kind == image_kind::estimate ? std::string(to_string(im.technique)) : "",
              im.set ? std::string(im.set->name) : "",
              im.kind == image_kind::estimate ? std::to_string(im.spp) : "",
              std::to_string(im.pixel_samples), std::to_string(im.light_samples),
              im.kind == image_kind::light_sampling ? std::string(quadmc::to_string(im.correlation))
                                                    : "",
              std::to_string(offset), std::to_string(plane.width), std::to_string(plane.height),
              x_min, y_min, x_max, y_max});
    offset += im.pixels.size();
  }
  static_assert(std::endian::native == std::endian::little, "render.py reads little-endian");
  write_file(dir / std::string(index_file), index);
  const fs::path file = dir / std::string(pixels_file);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  auto put = [&out](const std::vector<double>& x) {
    out.write(reinterpret_cast<const char*>(x.data()),
              static_cast<std::streamsize>(x.size() * sizeof(double)));
  };
  put(visibility);
  for (const image& im : r.images) put(im.pixels);
  out.close();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
}

// Every file of the report into `dir`, and with images = true the binary copy render.py draws
// the PNGs from. Called as one staged_output::write step, which a signal does not cut in half.
void write_report(const fs::path& dir, const render_scene& sc,
                  const quadmc::irradiance_plane& plane, const quadmc::provenance& build,
                  const render_result& r) {
  write_file(dir / "rmse.csv", rmse_csv(sc, r));
  write_file(dir / "slopes.csv", slopes_csv(r));
  write_file(dir / "lowpass.csv", lowpass_csv(r));
  write_file(dir / "error_spectrum.csv", error_spectrum_csv(r));
  if (sc.light_sampling) write_file(dir / "light_sampling.csv", light_sampling_csv(r));
  write_file(dir / std::string(quadmc::meta_csv_file), quadmc::meta_csv_text(build));
  write_file(dir / "README.md", readme_text(sc, plane, build, r));
  if (sc.images) write_pixels(dir, plane, r);
}

// The fitted slopes, printed once the folder is written.
std::string summary_text(const render_result& r) {
  std::string summary;
  for (const fit_row& fr : r.fits) {
    if (fr.fit.ok()) {
      summary +=
          fmt::format("  {:<19} {:<16} slope {:.3f} [{:.3f}, {:.3f}]\n", to_string(fr.technique),
                      fr.set->name, fr.fit.slope, fr.fit.ci_low, fr.fit.ci_high);
    }
  }
  return summary;
}

}  // namespace

CLI::App* add_render_subcommand(CLI::App& app, render_request& request) {
  auto* render = app.add_subcommand(
      "render",
      "Render the plane under the area light with every estimator, point set and spp of a render "
      "scene, against the exact image, into results/<scene name>/");
  render->add_option("scene", request.scene_file, "Render scene file (TOML)")->required();
  render->add_option("--out", request.out, "Output folder (default: results/<scene name>)")
      ->check(quadmc_cli::non_empty_path());
  render->add_option("--seed", request.seed, "Seed K ≥ 0 (default: the scene's `seed`)")
      ->check(non_negative_integer());
  render
      ->add_option("--threads", request.threads,
                   "Threads, 0 = all cores, at most 4096 (default: the scene's `threads`)")
      ->check(CLI::Range(0u, 4096u));
  return render;
}

bool is_render_file_name(std::string_view name) {
  if (std::find(fixed_files.begin(), fixed_files.end(), name) != fixed_files.end()) return true;
  if (name == pixels_file) return true;
  for (const std::string_view t : {"uniform_hemisphere", "cosine_hemisphere", "light_area"}) {
    if (name == fmt::format("errors_{}.png", t)) return true;
  }
  return false;
}

void run_render(const render_request& request, const std::function<void(std::string_view)>& print) {
  render_scene sc = parse_render_scene_file(request.scene_file);
  if (request.seed) sc.seed = *request.seed;
  if (request.threads) sc.threads = *request.threads;
  const quadmc::provenance build = quadmc::bench::build_provenance();
  const quadmc::irradiance_plane plane = sc.plane();
  const fs::path folder = quadmc::results_folder_path(request.out, sc.name);

  // The folder is staged before any work (a refusal costs nothing) and committed once the report
  // and the images are in it (report/staged_output.hpp).
  const bool given = !request.out.empty();
  quadmc::staged_output staged("render", given ? "--out" : "results folder",
                               given ? request.out : "results/" + sc.name, folder, output_files(sc),
                               &is_render_file_name);
  if (sc.images) check_plotting(render_script_path(), "to draw the images, or set images = false");

  std::vector<image> images = render_images(sc, plane.pixels());
  const unsigned threads = render_threads(sc, plane, images.size());
  print(plan_text(sc, plane, threads, folder));
  const render_result result = compute_render(sc, plane, std::move(images), threads);
  staged.write([&](const fs::path& dir) { write_report(dir, sc, plane, build, result); });
  if (sc.images) {
    staged.run_child(quadmc::plot_command_line(render_script_path(), staged.staging()));
    // The pixels were render.py's input only.
    staged.write([](const fs::path& dir) {
      fs::remove(dir / std::string(pixels_file));
      fs::remove(dir / std::string(index_file));
    });
  }
  const quadmc::staged_output::committed done = staged.commit();
  print(summary_text(result));
  print(fmt::format("render: {} images of {} × {} pixels in {:.1f} s on {} threads; {}\n",
                    result.images.size(), plane.width, plane.height, result.seconds, result.threads,
                    done.written));
  if (!done.warning.empty()) fmt::print(stderr, "quadmc: warning: {}\n", done.warning);
}

}  // namespace quadmc_cli
