// The Python module `quadmc` (bench/python/): a front end over the library like the `quadmc`
// command, for scripts and notebooks that want the suite's points, discrepancies and integrands
// as numpy arrays. The extension `_quadmc` is registered in module.cpp from one file per concept,
// each adding its functions through one add_… below; a new concept is a new file and one line
// there. quadmc/__init__.py re-exports it, so Python-side classes can join it later.
//
// Contract of every function: arrays are float64, row-major (n, s), the layout of the batch
// contract (docs/design.md#hot-path-contract); the library's one-line errors
// (quadmc::invalid_argument) reach Python as ValueError with the same text; the GIL is released
// while C++ computes, never while Python objects are touched.
#pragma once

#include "quadmc/core/rng.hpp"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc_python {

void add_errors(pybind11::module_& m);       // errors.cpp: the exception translation
void add_points(pybind11::module_& m);       // points.cpp: quadmc.points
void add_discrepancy(pybind11::module_& m);  // discrepancy.cpp: quadmc.discrepancy
void add_catalogue(pybind11::module_& m);    // catalogue.cpp: integrands(), methods(), point_sets()
void add_integrand(pybind11::module_& m);    // integrand.cpp: quadmc.integrand, its class
void add_integrate(pybind11::module_& m);    // integrate.cpp: quadmc.integrate's C++ half
void add_run(pybind11::module_& m);          // run.cpp: quadmc.run's C++ half, SceneRun

// A Python value as an error message quotes it: a string as a command line gives it (owen, not
// 'owen'), anything else as repr() shows it.
std::string quoted(const pybind11::handle& value);

// A Python int or float that is not a bool: what a scene's number is (TOML has no bool-as-int).
bool is_number(const pybind11::handle& value);

// The items of an iterable as doubles when every one is_number, else nullopt (empty for an empty
// iterable): a scene's array of numbers.
std::optional<std::vector<double>> numbers_of(const pybind11::handle& iterable);

// A Python int as a count in [minimum, 2^64 − 1], else invalid_argument naming `parameter`
// (pybind11's own conversion would raise TypeError for −1 without naming it).
std::uint64_t to_count(const pybind11::handle& value, std::string_view parameter,
                       std::uint64_t minimum);

// The keyword `rng` of a function that draws a method's random numbers: "philox4x32_10" or
// "ars4x32_7" as a scene's top-level `rng` names the generator (core/rng.hpp), else
// invalid_argument naming rng (a non-string too, which pybind11 would make a TypeError).
quadmc::rng_kind to_rng(const pybind11::handle& value);

}  // namespace quadmc_python
