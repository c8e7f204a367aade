// The catalogue of test integrands: every family of this layer by name, with the parameter keys
// it accepts, and make_integrand to build any of them from a flat parameter set. The scene parser
// maps a scene's TOML keys 1:1 onto integrand_params, so the keys documented here are the scene
// keys.
//
// Use it where the integrand is chosen at run time (scenes, `quadmc list`). Kernels that know the
// family at compile time construct the concrete type (genz.hpp, classic_1d.hpp, …) instead and
// skip the type erasure.
//
// Rules: unknown names, unknown keys, keys of the wrong kind (a vector given as a scalar, a
// number for a string key, …) and a string outside its key's choices are
// quadmc::invalid_argument naming them; a family's own validation reports bad values. Omitted
// Genz a/u are drawn from `seed` (genz_random_parameters, weights shaped by the string key
// `coefficient_decay`) and normalised.
#pragma once

#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/irradiance.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

struct integrand_params {
  // s; 0 = the family's default: 2 for the irradiance integrands, 1 for everything else. The 1D
  // classics accept only 1, the irradiance integrands only 2.
  std::size_t dimension = 0;
  std::map<std::string, std::vector<double>, std::less<>> vectors;
  std::map<std::string, double, std::less<>> scalars;
  // String keys, each one of the choices its catalogue_entry::string_keys lists.
  std::map<std::string, std::string, std::less<>> strings;
  std::uint64_t seed = 0;  // for parameters drawn at random (Genz a, u)
};

// Parameters a family draws from the seed when they are omitted (Genz a and u), by key.
using drawn_parameters = std::map<std::string, std::vector<double>, std::less<>>;

// A string-valued key and the only values it takes (the first is its default, by convention).
struct string_key {
  std::string_view key;
  std::span<const std::string_view> choices;
};

// One family: its keys, its factory and what the planner needs to know, together (a new family
// is one header of this layer and one entry of the table in catalogue.cpp).
struct catalogue_entry {
  std::string_view name;
  std::string_view description;  // formula and domain
  std::string_view smoothness;   // to_string(quadmc::smoothness) of a default instance
  std::span<const std::string_view> vector_keys;
  std::span<const std::string_view> scalar_keys;
  std::string_view parameters;  // what each key means, its default and constraints
  // Builds the family from parameters whose keys are checked and whose dimension is resolved.
  any_integrand (*make)(const integrand_params& params);
  // The values of the parameters drawn from params.seed for s = params.dimension (resolved, ≥ 1),
  // shaped by params.strings (keys checked); nullptr: the family draws none, so every instance
  // of an ensemble is the same integrand.
  drawn_parameters (*drawn)(const integrand_params& params) = nullptr;
  bool rendering = false;             // an irradiance integrand (make_irradiance_setup)
  bool vertex_sum_reference = false;  // the reference sums 2^s vertex terms (costly in s)
  std::size_t fixed_dimension = 0;    // the only s it takes (1D classics 1, irradiance 2); 0 any
  // Last, so that entries written before it (outside families) still initialise in order.
  std::span<const string_key> string_keys = {};
};

// All families, in a fixed order (Genz, classic 1D, geometry, rendering), then those added by
// add_integrands in the order they were added.
std::span<const catalogue_entry> integrand_catalogue();

// The plugin point for integrands from outside the library: a program built on quadmc::command
// (bench/examples/own_integrand/) adds its families before it runs the command, and every scene,
// plan and listing then sees them beside the built-in ones. The entries (and the strings and key
// lists they point to) must outlive every use: static storage. An entry's `make` builds an
// any_integrand whose integrand_info carries the exact integral, or NaN where none is known (the
// scene then needs `reference = <number>` or `reference = "computed"`). Throws logic_error when a
// name is already taken or an entry lacks a name or a `make`. Not thread-safe, and it invalidates
// spans returned before: call it before any lookup, as add_methods (methods/registry.hpp).
void add_integrands(std::span<const catalogue_entry> families);

// The entry named `name`, or nullptr.
const catalogue_entry* find_family(std::string_view name) noexcept;
// The catalogue entry named `name`; throws invalid_argument("integrand", name, list of names).
const catalogue_entry& find_catalogue_entry(std::string_view name);

// The dimension the family builds for `dimension` (a scene's key; 0 asks for the default):
// `dimension` itself, or the family's only s, or 1. make_integrand resolves 0 the same way.
std::size_t resolved_dimension(const catalogue_entry& entry, std::size_t dimension) noexcept;

// A key the family does not take, one given as a number where it takes an array (or the
// reverse, or a string where it takes either, or either where it takes a string), or a string
// outside its choices: which key and why. The scene planner and make_integrand both ask this one
// rule.
struct key_problem {
  std::string key;
  std::string message;
};
std::optional<key_problem> find_key_problem(const catalogue_entry& entry,
                                            const integrand_params& params);

// Builds the catalogue member `name` from `params` (validated as described above).
any_integrand make_integrand(std::string_view name, const integrand_params& params);

// The geometry behind the irradiance integrands (keys `occluder`, `radiance`), for the
// estimators that sample directions or the light instead of the integrand's own [0,1]² map.
irradiance_setup make_irradiance_setup(const integrand_params& params);

}  // namespace quadmc
