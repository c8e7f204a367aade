// The render scene's parser (render_scene.hpp): toml++ document → render_scene, every error a
// one-line scene_error at the key.
#include "render_scene.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/scene_error.hpp"
#include "quadmc/scene/toml_text.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace quadmc_cli {

namespace {

constexpr std::array<std::string_view, 14> top_keys{
    "name",     "description",     "seed",       "threads",    "width", "height", "region",
    "occluder", "occluder_height", "estimators", "point_sets", "spp",   "images", "light_sampling"};
constexpr std::array<std::string_view, 2> experiment_keys{"samples", "point_set"};
constexpr std::array<quadmc::irradiance_sampling, 3> all_estimators{
    quadmc::irradiance_sampling::uniform_hemisphere, quadmc::irradiance_sampling::cosine_hemisphere,
    quadmc::irradiance_sampling::light_area};
constexpr std::array<std::string_view, 5> default_sets{"independent", "jittered", "padded_jittered",
                                                       "latin_hypercube", "sobol"};
constexpr std::size_t max_side = 4096;
constexpr std::uint64_t max_spp = 4096;
constexpr std::size_t max_spp_values = 16;
constexpr std::uint64_t max_doubles = std::uint64_t{1} << 25;

std::string describe(const toml::node& n) {
  if (const auto* v = n.as_integer()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_floating_point()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_string()) return fmt::format("\"{}\"", v->get());
  if (const auto* v = n.as_boolean()) return v->get() ? "true" : "false";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date/time";
}

class reader {
 public:
  explicit reader(std::string file) : file_(std::move(file)) {}

  quadmc::source_location at(const toml::source_region& s) const {
    return {file_, s.begin.line, s.begin.column};
  }
  [[noreturn]] void fail(const quadmc::source_location& where, std::string_view key,
                         std::string_view message) const {
    throw quadmc::scene_error(where, quadmc::toml_original_text(key),
                              quadmc::toml_original_text(message));
  }
  [[noreturn]] void expected(const toml::key& key, std::string_view path, const toml::node& v,
                             std::string_view what) const {
    fail(at(key.source()), path, fmt::format("expected {}, got {}", what, describe(v)));
  }

  std::uint64_t count(const toml::key& k, std::string_view path, const toml::node& v,
                      std::uint64_t lo, std::uint64_t hi, std::string_view what) const {
    if (const auto* i = v.as_integer()) {
      if (i->get() >= 0 && static_cast<std::uint64_t>(i->get()) >= lo &&
          static_cast<std::uint64_t>(i->get()) <= hi) {
        return static_cast<std::uint64_t>(i->get());
      }
    }
    expected(k, path, v, what);
  }
  double number(const toml::key& k, std::string_view path, const toml::node& v,
                std::string_view what) const {
    if (const auto* i = v.as_integer()) return static_cast<double>(i->get());
    if (const auto* f = v.as_floating_point(); f != nullptr && std::isfinite(f->get())) {
      return f->get();
    }
    expected(k, path, v, what);
  }
  std::string string(const toml::key& k, std::string_view path, const toml::node& v,
                     std::string_view what) const {
    if (const auto* s = v.as_string()) return quadmc::toml_original_text(s->get());
    expected(k, path, v, what);
  }
  bool boolean(const toml::key& k, std::string_view path, const toml::node& v) const {
    if (const auto* b = v.as_boolean()) return b->get();
    expected(k, path, v, "true or false");
  }
  const toml::array& array(const toml::key& k, std::string_view path, const toml::node& v,
                           std::size_t most, std::string_view what) const {
    const auto* a = v.as_array();
    if (a == nullptr || a->empty()) expected(k, path, v, what);
    if (a->size() > most) {
      fail(at(k.source()), path, fmt::format("{} values; at most {}", a->size(), most));
    }
    return *a;
  }
  void check_keys(const toml::table& t, std::span<const std::string_view> allowed,
                  std::string_view prefix, std::string_view what) const {
    for (auto&& [key, value] : t) {
      if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
      const std::string path =
          prefix.empty() ? std::string(key.str()) : fmt::format("{}.{}", prefix, key.str());
      fail(at(key.source()), path,
           fmt::format("unknown key in {}; expected one of: {}", what, fmt::join(allowed, ", ")));
    }
  }
  const std::string& file() const noexcept { return file_; }

 private:
  std::string file_;
};

const quadmc::point_set_entry& set_named(const reader& r, const toml::key& k, std::string_view path,
                                         const toml::node& v) {
  const std::string what = fmt::format("a point set, one of: {}", quadmc::point_set_names());
  const std::string name = r.string(k, path, v, what);
  const quadmc::point_set_entry* set = quadmc::find_point_set(name);
  if (set == nullptr) r.expected(k, path, v, what);
  return *set;
}

render_scene parse_root(const reader& r, const toml::table& root) {
  r.check_keys(root, render_scene_keys(), "", "a render scene");
  render_scene sc;
  sc.file = r.file();
  sc.name = quadmc::scene_name_from_file(r.file(), "render");
  std::optional<std::pair<const toml::key*, const toml::node*>> spp_entry, width_entry,
      region_entry, height_entry;
  for (auto&& [key, value] : root) {
    const std::string_view k = key.str();
    const std::string path(k);
    if (k == "name") {
      const std::string_view what =
          "a name of letters, digits, '_', '-', '.', other than '.' and '..'";
      sc.name = r.string(key, path, value, what);
      if (!quadmc::is_portable_name(sc.name)) r.expected(key, path, value, what);
    } else if (k == "description") {
      sc.description = r.string(key, path, value, "a string");
    } else if (k == "seed") {
      sc.seed = r.count(key, path, value, 0,
                        static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()),
                        "an integer ≥ 0");
    } else if (k == "threads") {
      sc.threads = static_cast<unsigned>(
          r.count(key, path, value, 0, 4096, "a thread count between 0 (all cores) and 4096"));
    } else if (k == "width") {
      sc.width = r.count(key, path, value, 1, max_side, "a width between 1 and 4096 pixels");
      width_entry.emplace(&key, &value);
    } else if (k == "height") {
      sc.height = r.count(key, path, value, 1, max_side, "a height between 1 and 4096 pixels");
      height_entry.emplace(&key, &value);
    } else if (k == "region") {
      const std::string_view what =
          "[x_min, y_min, x_max, y_max], four finite numbers with x_min < x_max, y_min < y_max";
      const auto* a = value.as_array();
      if (a == nullptr || a->size() != 4) r.expected(key, path, value, what);
      for (std::size_t i = 0; i < 4; ++i) {
        sc.region[i] =
            r.number(key, fmt::format("region[{}]", i + 1), *a->get(i), "a finite number");
      }
      if (!(sc.region[0] < sc.region[2] && sc.region[1] < sc.region[3])) {
        r.fail(r.at(key.source()), path,
               fmt::format("expected {}, got [{}, {}, {}, {}]", what, sc.region[0], sc.region[1],
                           sc.region[2], sc.region[3]));
      }
      region_entry.emplace(&key, &value);
    } else if (k == "occluder") {
      sc.occluder = r.boolean(key, path, value);
    } else if (k == "occluder_height") {
      const std::string_view what = "a height > 0 between the plane and the light";
      sc.occluder_height = r.number(key, path, value, what);
      if (!(sc.occluder_height > 0.0)) r.expected(key, path, value, what);
    } else if (k == "estimators") {
      // A vector, not std::views::transform: clang 14 (the sanitize build) cannot compile
      // libstdc++ 12's views.
      std::vector<std::string> names;
      for (const auto e : all_estimators) names.emplace_back(to_string(e));
      const std::string what =
          fmt::format("estimator names, each one of: {}", fmt::join(names, ", "));
      const toml::array& a = r.array(key, path, value, all_estimators.size(), what);
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string element_path = fmt::format("estimators[{}]", i + 1);
        const std::string name = r.string(key, element_path, *a.get(i), what);
        const auto it = std::find_if(all_estimators.begin(), all_estimators.end(),
                                     [&](auto e) { return to_string(e) == name; });
        if (it == all_estimators.end()) r.expected(key, element_path, *a.get(i), what);
        if (std::find(sc.estimators.begin(), sc.estimators.end(), *it) != sc.estimators.end()) {
          r.fail(r.at(key.source()), element_path, fmt::format("'{}' is listed twice", name));
        }
        sc.estimators.push_back(*it);
      }
    } else if (k == "point_sets") {
      const toml::array& a = r.array(key, path, value, quadmc::point_set_catalogue().size(),
                                     "a non-empty array of point-set names");
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string element_path = fmt::format("point_sets[{}]", i + 1);
        const quadmc::point_set_entry& set = set_named(r, key, element_path, *a.get(i));
        if (std::find(sc.point_sets.begin(), sc.point_sets.end(), &set) != sc.point_sets.end()) {
          r.fail(r.at(key.source()), element_path, fmt::format("'{}' is listed twice", set.name));
        }
        sc.point_sets.push_back(&set);
      }
    } else if (k == "spp") {
      const toml::array& a = r.array(key, path, value, max_spp_values,
                                     "a non-empty, increasing array of samples per pixel");
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string element_path = fmt::format("spp[{}]", i + 1);
        const std::uint64_t n = r.count(key, element_path, *a.get(i), 1, max_spp,
                                        "samples per pixel between 1 and 4096");
        if (!sc.spp.empty() && n <= sc.spp.back()) {
          r.fail(r.at(key.source()), element_path,
                 fmt::format("spp must increase, got {} after {}", n, sc.spp.back()));
        }
        sc.spp.push_back(n);
      }
      spp_entry.emplace(&key, &value);
    } else if (k == "images") {
      sc.images = r.boolean(key, path, value);
    } else if (k == "light_sampling") {
      const auto* t = value.as_table();
      if (t == nullptr) r.expected(key, path, value, "a [light_sampling] table");
      r.check_keys(*t, experiment_keys, "light_sampling", "[light_sampling]");
      sc.light_sampling = true;
      sc.light_sampling_set = quadmc::find_point_set("jittered");
      for (auto&& [ek, ev] : *t) {
        const std::string epath = fmt::format("light_sampling.{}", ek.str());
        if (ek.str() == "samples") {
          sc.light_samples = r.count(ek, epath, ev, 1, max_spp, "light samples between 1 and 4096");
        } else {
          sc.light_sampling_set = &set_named(r, ek, epath, ev);
        }
      }
      for (const std::uint64_t n : {std::uint64_t{1}, sc.light_samples}) {
        const std::string problem = quadmc::size_problem(*sc.light_sampling_set, 2, n);
        if (!problem.empty()) {
          r.fail(r.at(key.source()), "light_sampling.samples",
                 fmt::format("the {} points cannot hold {} samples in 2D: {}",
                             sc.light_sampling_set->name, n, problem));
        }
      }
    }
  }
  if (sc.estimators.empty()) sc.estimators.assign(all_estimators.begin(), all_estimators.end());
  if (sc.point_sets.empty()) {
    for (const std::string_view name : default_sets) {
      sc.point_sets.push_back(quadmc::find_point_set(name));
    }
  }
  if (sc.spp.empty()) sc.spp = {1, 4, 16, 64};
  const quadmc::source_location file_start{r.file(), 1, 1};
  for (const auto* set : sc.point_sets) {
    for (const std::uint64_t n : sc.spp) {
      const std::string problem = quadmc::size_problem(*set, 2, n);
      if (problem.empty()) continue;
      r.fail(spp_entry ? r.at(spp_entry->first->source()) : file_start, "spp",
             fmt::format("the {} points cannot hold {} samples per pixel in 2D: {}", set->name, n,
                         problem));
    }
  }
  const std::uint64_t doubles = static_cast<std::uint64_t>(sc.image_count()) * sc.width * sc.height;
  if (doubles > max_doubles) {
    r.fail(width_entry ? r.at(width_entry->first->source()) : file_start, "width",
           fmt::format("{} images of {} × {} pixels need {} MiB; at most {} MiB (reduce width, "
                       "height, spp, estimators or point_sets)",
                       sc.image_count(), sc.width, sc.height, doubles * 8 >> 20,
                       max_doubles * 8 >> 20));
  }
  try {
    quadmc::validate(sc.plane());
  } catch (const quadmc::invalid_argument& e) {
    const bool occluder = std::string_view(e.what()).find("occluder") != std::string_view::npos;
    const auto* where = occluder ? root.get("occluder_height") : root.get("region");
    r.fail(where ? quadmc::source_location{r.file(), where->source().begin.line,
                                           where->source().begin.column}
                 : file_start,
           occluder ? "occluder_height" : "region", e.what());
  }
  return sc;
}

}  // namespace

std::string_view to_string(quadmc::irradiance_sampling technique) noexcept {
  switch (technique) {
    case quadmc::irradiance_sampling::uniform_hemisphere:
      return "uniform_hemisphere";
    case quadmc::irradiance_sampling::cosine_hemisphere:
      return "cosine_hemisphere";
    case quadmc::irradiance_sampling::light_area:
      return "light_area";
  }
  return "?";
}

quadmc::irradiance_plane render_scene::plane() const {
  return quadmc::catalogue_irradiance_plane(
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
  const std::string safe = quadmc::toml_safe_text(toml_text, file_name);
  toml::table root;
  try {
    root = toml::parse(safe, file_name);
  } catch (const toml::parse_error& e) {
    throw quadmc::scene_error(r.at(e.source()), "", quadmc::toml_original_text(e.description()));
  }
  return parse_root(r, root);
}

render_scene parse_render_scene_file(const std::filesystem::path& path) {
  return parse_render_scene(quadmc::read_scene_file(path), path.string());
}

}  // namespace quadmc_cli
