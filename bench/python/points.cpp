// quadmc.points(set, n, s, seed=0, stream=0, randomization=None, rng="philox4x32_10",
// **options): the points of any set of the catalogue (estimators/point_set_catalogue.hpp) as an
// (n, s) float64 array, bitwise the numbers `quadmc points` writes for the same set, options,
// seed, stream and generator (--rng): both take them from the entry's own points(), which this
// writes straight into the array's buffer with the GIL released. `rng` is the generator of the
// set's random numbers, Philox4x32-10 or ARS-4x32-7 (docs/theory.md#counter-based-generators),
// as a scene's `rng` is its methods'. The set's options are Python keywords (randomization="owen",
// allow_any_n=True); a key the set lacks is refused, as `quadmc points` refuses its flag, even when
// its value is the default, so that a typo never passes for a choice.
#include "bindings.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/estimators/point_set_catalogue.hpp"

#include <pybind11/numpy.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace quadmc_python {

namespace {

// The largest s `quadmc points` takes (its --s range): beyond it no set has tables.
constexpr std::uint64_t max_dimension = std::uint64_t{1} << 20;

// A keyword's value as text: a choice as the string given (any other type as repr(), which no
// choice matches), a flag's True as "true" and False as empty (the default).
std::string text_of(const quadmc::point_set_entry& set, std::string_view key,
                    const py::handle& value) {
  const quadmc::point_set_option* option = set.option(key);
  // An integer choice (interlacing = 2) takes a Python int, as a scene takes a TOML integer; its
  // text is then checked against the choices.
  if (option != nullptr && option->integer &&
      (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))) {
    throw quadmc::invalid_argument(
        key, quoted(value), fmt::format("an integer, one of {}", fmt::join(option->choices, ", ")));
  }
  if (option == nullptr || !option->is_flag()) return quoted(value);
  if (!py::isinstance<py::bool_>(value)) {
    throw quadmc::invalid_argument(key, quoted(value), "True or False");
  }
  return value.cast<bool>() ? "true" : "";
}

// A keyword names its key as itself in errors.
std::string keyword_of(std::string_view key) {
  return std::string(key);
}

// The keywords as the set reads them, every key and choice checked (checked_options).
quadmc::point_set_options options_for(const quadmc::point_set_entry& set,
                                      const py::dict& keywords) {
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& [key, value] : keywords) {
    const std::string name = py::str(key);
    texts.emplace_back(name, text_of(set, name, value));
  }
  std::vector<quadmc::named_option> given;
  for (const auto& [key, text] : texts) given.push_back({key, text});
  return quadmc::checked_options(set, given, keyword_of);
}

const quadmc::point_set_entry& find_set(const std::string& name) {
  const quadmc::point_set_entry* set = quadmc::find_point_set(name);
  if (set == nullptr) {
    throw quadmc::invalid_argument("set", name,
                                   fmt::format("one of: {}", quadmc::point_set_names()));
  }
  return *set;
}

py::array_t<double> points(const std::string& set_name, const py::object& n_value,
                           const py::object& s_value, const py::object& seed_value,
                           const py::object& stream_value, const py::object& randomization,
                           const py::object& rng, const py::kwargs& keywords) {
  const quadmc::point_set_entry& set = find_set(set_name);
  const std::uint64_t n = to_count(n_value, "n", 1);
  const std::uint64_t s = to_count(s_value, "s", 1);
  const quadmc::sample_stream stream{to_count(seed_value, "seed", 0),
                                     to_count(stream_value, "stream", 0), to_rng(rng)};
  py::dict given(keywords);
  if (!randomization.is_none()) given["randomization"] = randomization;
  const quadmc::point_set_options options = options_for(set, given);
  // The dimension first, so that a set that cannot have s dimensions blames s, not n.
  if (s > max_dimension) {
    throw quadmc::invalid_argument("s", std::to_string(s), "s ≤ 2^20");
  }
  if (const std::string problem = quadmc::dimension_problem(set, s, options); !problem.empty()) {
    throw quadmc::invalid_argument("s", std::to_string(s), problem);
  }
  if (const std::string problem = quadmc::size_problem(set, s, n, options); !problem.empty()) {
    throw quadmc::invalid_argument("n", fmt::format("{} (s = {})", n, s), problem);
  }
  // numpy refuses a shape whose size overflows, and raises MemoryError when it cannot allocate.
  py::array_t<double> out({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(s)});
  double* data = out.mutable_data();
  {
    py::gil_scoped_release unlocked;
    set.points(
        s, n, stream,
        [&](std::uint64_t first, std::span<const double> x) {
          std::memcpy(data + first * s, x.data(), x.size_bytes());
        },
        options);
  }
  return out;
}

}  // namespace

void add_points(py::module_& m) {
  m.def("points", &points, py::arg("set"), py::arg("n"), py::arg("s"), py::arg("seed") = 0,
        py::arg("stream") = 0, py::arg("randomization") = py::none(),
        py::arg("rng") = "philox4x32_10",
        R"(The n points of a point set in s dimensions as an (n, s) float64 array.

Bitwise the numbers `quadmc points SET --n N --s S --seed SEED --stream STREAM --rng RNG` writes.
set: a name of quadmc.point_sets(); randomization and the set's other options (periodization,
allow_any_n=True, drop_first_point=True) as keywords, as quadmc.point_sets() lists them.
rng: the generator of the set's random numbers, "philox4x32_10" (Philox4x32-10, the default) or
"ars4x32_7" (ARS-4x32-7), as a scene's top-level rng; the two give different points for the same
seed (an unrandomized set, such as randomization="none", is the same under both).
Raises ValueError naming the parameter for an unknown set or key, a bad value (rng included), or
an n the set cannot hold (N = 2^m for a randomized net, k^s for a grid).)");
}

}  // namespace quadmc_python
