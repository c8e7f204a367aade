// The render scene's parser (render_scene.hpp): toml++ document → render_scene, read with the
// scene layer's TOML reader (toml_reader.hpp), so every error is a one-line scene_error at the key.
#include "quadmc/scene/render_scene.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/scene_error.hpp"

#include "toml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace quadmc {

namespace {

using scene_toml::entry;
using scene_toml::reader;

constexpr std::array<std::string_view, 14> top_keys{
    "name",     "description",     "seed",       "threads",    "width", "height", "region",
    "occluder", "occluder_height", "estimators", "point_sets", "spp",   "images", "light_sampling"};
constexpr std::array<std::string_view, 2> experiment_keys{"samples", "point_set"};
constexpr std::array<irradiance_sampling, 3> all_estimators{irradiance_sampling::uniform_hemisphere,
                                                            irradiance_sampling::cosine_hemisphere,
                                                            irradiance_sampling::light_area};
constexpr std::array<std::string_view, 5> default_sets{"independent", "jittered", "padded_jittered",
                                                       "latin_hypercube", "sobol"};
constexpr std::size_t max_side = 4096;
constexpr std::uint64_t max_spp = 4096;
constexpr std::size_t max_spp_values = 16;
constexpr std::uint64_t max_doubles = std::uint64_t{1} << 25;

// A non-empty array of at most `most` values.
const toml::array& bounded_array(const reader& r, const entry& e, std::size_t most,
                                 std::string_view what) {
  const toml::array& a = r.array(e, what);
  if (a.size() > most) r.fail(e, fmt::format("{} values; at most {}", a.size(), most));
  return a;
}

// A set of the catalogue, or (for the images of point_sets, not [light_sampling], whose light
// pattern is one integral's) the render-only zsobol.
const point_set_entry& set_named(const reader& r, const entry& e, bool render_only_too) {
  const std::string what =
      fmt::format("a point set, one of: {}{}", point_set_names(),
                  render_only_too ? fmt::format(", {}", zsobol_render_set().name) : "");
  const std::string name = r.string(e, what);
  const point_set_entry* set = find_point_set(name);
  if (render_only_too && name == zsobol_render_set().name) set = &zsobol_render_set();
  if (set == nullptr) r.expected(e, what);
  return *set;
}

void read_region(const reader& r, const entry& e, render_scene& sc) {
  const std::string_view what =
      "[x_min, y_min, x_max, y_max], four finite numbers with x_min < x_max, y_min < y_max";
  const auto* a = e.value->as_array();
  if (a == nullptr || a->size() != 4) r.expected(e, what);
  for (std::size_t i = 0; i < 4; ++i) {
    sc.region[i] = r.number(reader::element(e, i), "a finite number");
  }
  if (!(sc.region[0] < sc.region[2] && sc.region[1] < sc.region[3])) {
    r.fail(e, fmt::format("expected {}, got [{}, {}, {}, {}]", what, sc.region[0], sc.region[1],
                          sc.region[2], sc.region[3]));
  }
}

void read_estimators(const reader& r, const entry& e, render_scene& sc) {
  // A vector, not std::views::transform: clang 14 (the sanitize build) cannot compile
  // libstdc++ 12's views.
  std::vector<std::string> names;
  for (const auto t : all_estimators) names.emplace_back(to_string(t));
  const std::string what = fmt::format("estimator names, each one of: {}", fmt::join(names, ", "));
  const toml::array& a = bounded_array(r, e, all_estimators.size(), what);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const entry element = reader::element(e, i);
    const std::string name = r.string(element, what);
    const auto it = std::find_if(all_estimators.begin(), all_estimators.end(),
                                 [&](auto t) { return to_string(t) == name; });
    if (it == all_estimators.end()) r.expected(element, what);
    if (std::find(sc.estimators.begin(), sc.estimators.end(), *it) != sc.estimators.end()) {
      r.fail(element, fmt::format("'{}' is listed twice", name));
    }
    sc.estimators.push_back(*it);
  }
}

void read_point_sets(const reader& r, const entry& e, render_scene& sc) {
  const toml::array& a =
      bounded_array(r, e, point_set_catalogue().size() + 1, "a non-empty array of point-set names");
  for (std::size_t i = 0; i < a.size(); ++i) {
    const entry element = reader::element(e, i);
    const point_set_entry& set = set_named(r, element, true);
    if (std::find(sc.point_sets.begin(), sc.point_sets.end(), &set) != sc.point_sets.end()) {
      r.fail(element, fmt::format("'{}' is listed twice", set.name));
    }
    sc.point_sets.push_back(&set);
  }
}

void read_spp(const reader& r, const entry& e, render_scene& sc) {
  const toml::array& a =
      bounded_array(r, e, max_spp_values, "a non-empty, increasing array of samples per pixel");
  for (std::size_t i = 0; i < a.size(); ++i) {
    const entry element = reader::element(e, i);
    const std::uint64_t n = r.integer(element, 1, max_spp, "samples per pixel between 1 and 4096");
    if (!sc.spp.empty() && n <= sc.spp.back()) {
      r.fail(element, fmt::format("spp must increase, got {} after {}", n, sc.spp.back()));
    }
    sc.spp.push_back(n);
  }
}

void read_light_sampling(const reader& r, const entry& e, render_scene& sc) {
  const toml::table& t = r.table(e, "a [light_sampling] table");
  r.check_keys(t, experiment_keys, "light_sampling", "[light_sampling]");
  sc.light_sampling = true;
  sc.light_sampling_set = find_point_set("jittered");
  for (auto&& [key, value] : t) {
    const entry inner = reader::of(key, value, "light_sampling");
    if (key.str() == "samples") {
      sc.light_samples = r.integer(inner, 1, max_spp, "light samples between 1 and 4096");
    } else {
      sc.light_sampling_set = &set_named(r, inner, false);
    }
  }
  for (const std::uint64_t n : {std::uint64_t{1}, sc.light_samples}) {
    const std::string problem = size_problem(*sc.light_sampling_set, 2, n);
    if (!problem.empty()) {
      r.fail(r.at(e), "light_sampling.samples",
             fmt::format("the {} points cannot hold {} samples in 2D: {}",
                         sc.light_sampling_set->name, n, problem));
    }
  }
}

// One top-level key (check_keys has refused the others).
void read_key(const reader& r, const entry& e, render_scene& sc) {
  const std::string_view k = e.key->str();
  if (k == "name") {
    sc.name = r.display_name(e, false);
  } else if (k == "description") {
    sc.description = r.string(e, "a string");
  } else if (k == "seed") {
    sc.seed = r.integer(e, 0, static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()),
                        "an integer ≥ 0");
  } else if (k == "threads") {
    sc.threads = static_cast<unsigned>(
        r.integer(e, 0, 4096, "a thread count between 0 (all cores) and 4096"));
  } else if (k == "width") {
    sc.width = r.integer(e, 1, max_side, "a width between 1 and 4096 pixels");
  } else if (k == "height") {
    sc.height = r.integer(e, 1, max_side, "a height between 1 and 4096 pixels");
  } else if (k == "region") {
    read_region(r, e, sc);
  } else if (k == "occluder") {
    sc.occluder = r.boolean(e);
  } else if (k == "occluder_height") {
    const std::string_view what = "a height > 0 between the plane and the light";
    sc.occluder_height = r.number(e, what);
    if (!(sc.occluder_height > 0.0)) r.expected(e, what);
  } else if (k == "estimators") {
    read_estimators(r, e, sc);
  } else if (k == "point_sets") {
    read_point_sets(r, e, sc);
  } else if (k == "spp") {
    read_spp(r, e, sc);
  } else if (k == "images") {
    sc.images = r.boolean(e);
  } else if (k == "light_sampling") {
    read_light_sampling(r, e, sc);
  }
}

// What no single key decides: every set holds every spp, the images fit in memory, and the
// plane is one the catalogue accepts.
void check_scene(const reader& r, const toml::table& root, const render_scene& sc) {
  const source_location file_start{r.file(), 1, 1};
  const auto spp = r.find(root, "spp", "");
  for (const auto* set : sc.point_sets) {
    for (const std::uint64_t n : sc.spp) {
      const std::string problem = pixel_samples_problem(*set, sc.width, sc.height, n);
      if (problem.empty()) continue;
      r.fail(spp ? r.at(*spp) : file_start, "spp",
             fmt::format("the {} points cannot hold {} samples per pixel in 2D: {}", set->name, n,
                         problem));
    }
  }
  const std::uint64_t doubles = static_cast<std::uint64_t>(sc.image_count()) * sc.width * sc.height;
  if (doubles > max_doubles) {
    const auto width = r.find(root, "width", "");
    r.fail(width ? r.at(*width) : file_start, "width",
           fmt::format("{} images of {} × {} pixels need {} MiB; at most {} MiB (reduce width, "
                       "height, spp, estimators or point_sets)",
                       sc.image_count(), sc.width, sc.height, doubles * 8 >> 20,
                       max_doubles * 8 >> 20));
  }
  try {
    validate(sc.plane());
  } catch (const invalid_argument& e) {
    // At the value, not the key: the plane's own message is about the value.
    const bool occluder = std::string_view(e.what()).find("occluder") != std::string_view::npos;
    const auto* where = occluder ? root.get("occluder_height") : root.get("region");
    r.fail(where ? r.at(where->source()) : file_start, occluder ? "occluder_height" : "region",
           e.what());
  }
}

render_scene parse_root(const reader& r, const toml::table& root) {
  r.check_keys(root, render_scene_keys(), "", "a render scene");
  render_scene sc;
  sc.file = r.file();
  sc.name = scene_name_from_file(r.file(), "render");
  for (auto&& [key, value] : root) read_key(r, reader::of(key, value, ""), sc);
  if (sc.estimators.empty()) sc.estimators.assign(all_estimators.begin(), all_estimators.end());
  if (sc.point_sets.empty()) {
    for (const std::string_view name : default_sets) sc.point_sets.push_back(find_point_set(name));
  }
  if (sc.spp.empty()) sc.spp = {1, 4, 16, 64};
  check_scene(r, root, sc);
  return sc;
}

}  // namespace

std::string_view to_string(irradiance_sampling technique) noexcept {
  switch (technique) {
    case irradiance_sampling::uniform_hemisphere:
      return "uniform_hemisphere";
    case irradiance_sampling::cosine_hemisphere:
      return "cosine_hemisphere";
    case irradiance_sampling::light_area:
      return "light_area";
  }
  return "?";
}

irradiance_plane render_scene::plane() const {
  return catalogue_irradiance_plane(
      occluder ? std::optional<double>(occluder_height) : std::nullopt, region, width, height);
}

std::span<const std::string_view> render_scene_keys() noexcept {
  return top_keys;
}

std::span<const std::string_view> light_sampling_keys() noexcept {
  return experiment_keys;
}

render_scene parse_render_scene(std::string_view toml_text, std::string_view file_name) {
  const reader r{std::string(file_name)};
  return parse_root(r, r.parse(toml_text));
}

render_scene parse_render_scene_file(const std::filesystem::path& path) {
  return parse_render_scene(read_scene_file(path), path.string());
}

}  // namespace quadmc
