// The pieces the method families of lib/src/methods/ share (one family per file; registry.cpp
// declares and lists them). Private to the methods layer: the rest of the library reaches
// methods through registry.hpp only.
#pragma once

#include "external.hpp"

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/estimators/sample_mean.hpp"
#include "quadmc/methods/method.hpp"
#include "quadmc/methods/registry.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc::methods {

// The `point_set` option of the methods that draw their u from a chosen pattern; `independent`
// when absent. `given` says whether the table set it (it then joins the default label). With
// point_set = "external_points" the u are the rows of the user's files (`file`, read with the keys
// of external_points: external.hpp) and `set` is null.
struct point_set_choice {
  const point_set_entry* set = nullptr;
  std::optional<point_file_options> file;
  bool given = false;

  // The set's name as the label and the messages give it.
  std::string_view name() const noexcept;
  // A catalogue set maps N as its own method does; a file holds N rows exactly.
  sizing size_for(std::uint64_t N, std::size_t s) const;
  // The files' `points`, else none (the cells follow budget.N).
  std::vector<sizing> explicit_sizes() const;
  std::string explicit_sizes_key() const { return file ? "points" : ""; }
  // A file's rows are one realization: their error bars come from the replicates.
  quadmc::error_bars error_bars() const noexcept;
};
point_set_choice read_point_set(option_reader& options);

// What a method maps the u of each sample to: `s` of them (`who` takes them, `why`), which a
// file's column count must match.
struct uniform_use {
  std::size_t s;
  std::string_view who;
  std::string_view why;
};
// With files, reads and checks the file of every repetition of a cell of this size (the
// method's check_inputs); without, nothing.
void check_uniform_files(const point_set_choice& points, const uniform_use& use,
                         const cell_size& size, std::uint64_t repetitions);
// The checked file of one repetition of a cell, read once outside the per-sample loop.
point_file_data read_uniform_file(const point_set_choice& points, const uniform_use& use,
                                  const method_cell& cell);

// N → the largest count the set holds (k^s for stratified sets): a cell size for Monte Carlo.
sizing point_set_sizing(const point_set_entry& set, std::uint64_t N, std::size_t s);

// Where a cell's error bars come from for points of this error source: a randomized
// quasi-Monte Carlo set's single run has no error estimate of its own, its replicates do; a set
// with neither reports its own, none (NaN), as a deterministic rule does.
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
