// The one table of methods (registry.hpp): the families of lib/src/methods/, in listing order.
#include "quadmc/methods/registry.hpp"

#include "families.hpp"

#include "quadmc/core/errors.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>
#include <vector>

// Each family's descriptors, in listing order, defined in its own file of lib/src/methods/.
namespace quadmc::methods {
std::span<const method_descriptor> tensor_rule_methods() noexcept;
std::span<const method_descriptor> romberg_methods() noexcept;
std::span<const method_descriptor> point_set_methods() noexcept;
std::span<const method_descriptor> importance_methods() noexcept;
std::span<const method_descriptor> irradiance_methods() noexcept;
std::span<const method_descriptor> sparse_grid_methods() noexcept;
std::span<const method_descriptor> adaptive_methods() noexcept;
std::span<const method_descriptor> vegas_methods() noexcept;
std::span<const method_descriptor> qmc_methods() noexcept;
std::span<const method_descriptor> external_methods() noexcept;
}  // namespace quadmc::methods

namespace quadmc {
namespace {

// One entry per family; a family lists its own methods in its file.
constexpr std::span<const method_descriptor> (*families[])() noexcept = {
    methods::tensor_rule_methods, methods::romberg_methods,    methods::point_set_methods,
    methods::importance_methods,  methods::irradiance_methods, methods::sparse_grid_methods,
    methods::adaptive_methods,    methods::vegas_methods,      methods::qmc_methods,
    methods::external_methods,
};

std::vector<const method_descriptor*>& all() {
  static std::vector<const method_descriptor*> table = [] {
    std::vector<const method_descriptor*> out;
    for (const auto family : families) {
      for (const method_descriptor& d : family()) out.push_back(&d);
    }
    return out;
  }();
  return table;
}

}  // namespace

void add_methods(std::span<const method_descriptor> family) {
  for (const method_descriptor& d : family) {
    if (find_method(d.name) != nullptr) {
      throw std::logic_error(fmt::format("add_methods: method '{}' is already registered", d.name));
    }
    all().push_back(&d);
  }
}

std::optional<std::string> unavailable_method(std::string_view name) {
  if (find_method(name) != nullptr) return std::nullopt;
  for (const known_peer& p : peers::known) {
    if (p.name == name) {
      return fmt::format(
          "method '{}' ({}) is a peer, not built into this quadmc (the peers are optional; "
          "GSL and cubature are GPL): run the scene with "
          "build/<preset>/bench/peers/quadmc_with_peers, which ./run.sh benchmarks (release "
          "preset) and ./run.sh test (test preset) build when libgsl-dev and libcubature-dev "
          "are installed; README command 1 builds only the plain command",
          name, p.library);
    }
  }
  return std::nullopt;
}

std::span<const method_descriptor* const> method_registry() {
  return all();
}

const method_descriptor* find_method(std::string_view name) noexcept {
  for (const method_descriptor* d : all()) {
    if (d->name == name) return d;
  }
  return nullptr;
}

std::string method_names() {
  std::vector<std::string_view> names;
  for (const method_descriptor* d : all()) names.push_back(d->name);
  return fmt::format("{}", fmt::join(names, ", "));
}

std::unique_ptr<const method> make_method(std::string_view name, const option_table& options) {
  const method_descriptor* d = find_method(name);
  if (d == nullptr) {
    if (auto why = unavailable_method(name)) {
      throw invalid_argument("method", std::string(name),
                             fmt::format("a method of this build: {}", *why));
    }
    throw invalid_argument("method", std::string(name), fmt::format("one of: {}", method_names()));
  }
  option_map reader(options, fmt::format("method '{}'", name));
  std::unique_ptr<const method> m = d->create(*d, reader);
  std::vector<std::string_view> accepted;
  for (const option_doc& o : d->options) accepted.push_back(o.key);
  reader.reject_unread(fmt::format("a '{}' method", name), accepted);
  return m;
}

}  // namespace quadmc
