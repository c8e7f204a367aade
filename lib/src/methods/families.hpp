// The pieces the method families of lib/src/methods/ share (one family per file; registry.cpp
// declares and lists them). Private to the methods layer: the rest of the library reaches
// methods through registry.hpp only.
#pragma once

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/estimators/sample_mean.hpp"
#include "quadmc/methods/method.hpp"

#include <span>

namespace quadmc::methods {

// The `point_set` option of the methods that draw their u from a chosen pattern; `independent`
// when absent. `given` says whether the table set it (it then joins the default label).
struct point_set_choice {
  const point_set_entry* set = nullptr;
  bool given = false;
};
point_set_choice read_point_set(option_reader& options);

// N → the largest count the set holds (k^s for stratified sets): a cell size for Monte Carlo.
sizing point_set_sizing(const point_set_entry& set, std::uint64_t N, std::size_t s);

// Where a cell's error bars come from for points of this error source: a randomized
// quasi-Monte Carlo set's single run has no error estimate of its own, its replicates do.
inline error_bars error_bars_of(error_source source) noexcept {
  return source == error_source::replicates ? error_bars::replicates : error_bars::own;
}

// Whether the estimators of a point set (its monte_carlo, importance and irradiance, all a
// sample mean, estimators/sample_mean.hpp) share their chunks between the processes of a split
// cell (method::shares_chunks): their chunk result's declaration.
inline constexpr bool sample_mean_shares_chunks = shareable_chunk_result<sample_statistics>;

// A Monte Carlo estimate as one repetition: its standard error is also its own error estimate.
repetition_result from_estimate(const estimate& e);

}  // namespace quadmc::methods
