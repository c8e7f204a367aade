// The method families of lib/src/methods/, one file each, and the pieces they share. Private to
// the methods layer: the rest of the library reaches methods through registry.hpp only.
#pragma once

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/methods/method.hpp"

#include <span>

namespace quadmc::methods {

// Each family's descriptors, in listing order (registry.cpp lists the families).
std::span<const method_descriptor> tensor_rule_methods() noexcept;
std::span<const method_descriptor> romberg_methods() noexcept;
std::span<const method_descriptor> point_set_methods() noexcept;
std::span<const method_descriptor> importance_methods() noexcept;
std::span<const method_descriptor> irradiance_methods() noexcept;

// The `point_set` option of the methods that draw their u from a chosen pattern; `independent`
// when absent. `given` says whether the table set it (it then joins the default label).
struct point_set_option {
  const point_set_entry* set = nullptr;
  bool given = false;
};
point_set_option read_point_set(option_reader& options);

// N → the largest count the set holds (k^s for stratified sets): a cell size for Monte Carlo.
sizing point_set_sizing(const point_set_entry& set, std::uint64_t N, std::size_t s);

// A Monte Carlo estimate as one repetition: its standard error is also its own error estimate.
repetition_result from_estimate(const estimate& e);

}  // namespace quadmc::methods
