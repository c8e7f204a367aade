// The one table of methods: every method a scene may name, by family, in listing order.
//
// Use find_method to look a scene's `name` up (then descriptor->create reads its options), and
// method_registry to list them (`quadmc list`, the README's table). Adding a method is one class
// and one descriptor in its family's file under lib/src/methods/; adding a family is one file
// there and one line in registry.cpp. Nothing outside this layer names a method.
#pragma once

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/methods/method.hpp"
#include "quadmc/methods/option_map.hpp"

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

std::span<const method_descriptor* const> method_registry();
const method_descriptor* find_method(std::string_view name) noexcept;  // nullptr when unknown
std::string method_names();  // comma-separated, for "expected one of …" messages

// The warps importance's `warp` key names, in listing order: the name a scene writes, the
// density on [0, 1] it samples by inversion (sampling/inversion_warps.hpp), and its one parameter
// with the default. `exponential` is the truncated exponential λe^(λx)/(e^λ − 1) on [0, 1]
// (truncated_exponential_warp), not exponential_warp on [0, ∞): every catalogue integrand that
// importance takes lives on a finite interval.
struct warp_descriptor {
  std::string_view name;
  std::string_view description;
  unit_warp_kind kind;
  std::string_view parameter;
  double default_value;
};
std::span<const warp_descriptor> importance_warps() noexcept;

// The one `point_set` of importance and the irradiance methods that is not a catalogue set
// (estimators/point_set_catalogue.hpp): the u are the rows of the user's files, read with the keys
// and checks of the external_points method (`path`, `points`). Its one line in `quadmc list`.
inline constexpr std::string_view external_point_set = "external_points";
inline constexpr std::string_view external_point_set_description =
    "the rows of the user's files (keys path, points as for the external_points method): 1 "
    "column for importance, 2 for the irradiance methods; error bars from replicates";

// The plugin point for methods the library must not depend on: the peers of bench/peers/ (GSL,
// cubature: GPL libraries, so an MIT build of quadmc cannot contain them). A build of the command
// that links them adds their family from a static initialiser, before main, so every later lookup
// and listing sees them. Throws logic_error when a name is already taken. Not for methods of the
// library itself (those are one line in registry.cpp) and not thread-safe: call it before any
// lookup.
void add_methods(std::span<const method_descriptor> family);

// The peers of bench/peers/ a scene may name, and the library each comes from: the one place
// their names are written. Their descriptors take the names from here
// (bench/peers/peer_scene_methods.cpp), and a build without them says where each is built
// (unavailable_method) instead of "unknown method".
struct known_peer {
  std::string_view name;
  std::string_view library;
};
namespace peers {
inline constexpr known_peer hcubature{"peer_hcubature", "cubature's hcubature, libcubature-dev"};
inline constexpr known_peer pcubature{"peer_pcubature", "cubature's pcubature, libcubature-dev"};
inline constexpr known_peer gsl_plain{"peer_gsl_plain", "GSL's gsl_monte_plain, libgsl-dev"};
inline constexpr known_peer gsl_miser{"peer_gsl_miser", "GSL's gsl_monte_miser, libgsl-dev"};
inline constexpr known_peer gsl_vegas{"peer_gsl_vegas", "GSL's gsl_monte_vegas, libgsl-dev"};
inline constexpr known_peer boost_tanh_sinh{"peer_boost_tanh_sinh", "Boost.Math's tanh_sinh"};
inline constexpr known_peer boost_gauss_kronrod{"peer_boost_gauss_kronrod",
                                                "Boost.Math's gauss_kronrod<double, 15>"};
inline constexpr known_peer scipy_qmc_quad{"peer_scipy_qmc_quad",
                                           "scipy's qmc_quad, python3-scipy"};
// In listing order.
inline constexpr std::array<known_peer, 8> known{
    hcubature, pcubature,       gsl_plain,           gsl_miser,
    gsl_vegas, boost_tanh_sinh, boost_gauss_kronrod, scipy_qmc_quad};
}  // namespace peers

// Why a scene cannot name `name` in this build although the suite knows it (a peer whose command
// was not built), and how to get it, one line; nullopt for a name that is present or unknown.
std::optional<std::string> unavailable_method(std::string_view name);

// The method `name` configured by `options` (the same checks as a scene's [[method]] table;
// unknown keys are refused). Throws invalid_argument for an unknown name or a bad option.
std::unique_ptr<const method> make_method(std::string_view name, const option_table& options = {});

}  // namespace quadmc
