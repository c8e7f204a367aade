// The time-to-error table of a results page: per (integrand family, s, tolerance), the time and
// evaluations each method needs to reach the tolerance, quadmc's best method against the best
// peer (a method named `peer_*`, bench/peers), their ratio, and a summary over the cells.
//
// Use it for a scene that runs methods to tolerances beside peers (bench/scenes/
// time_to_error.toml); a scene without tolerance cells or without a peer gets no table (empty
// text). Not an extrapolation: a tolerance no cell reached is "not reached".
//
// Per cell, the target is the error the tolerance asks for: tolerance·|I| for a relative
// tolerance (convergence_table::relative_tolerance), the tolerance itself for an absolute one.
//   - A method run to the tolerance (its convergence_table has a row at that tolerance) reaches
//     it when that row's true error — RMSE over its repetitions, |error| for one — is ≤ the
//     target: its own estimate saying so is not enough. Its time is the row's seconds per
//     estimate, the stable timing of the whole call to the tolerance (analysis/cell_timing.hpp).
//   - A method on the N ladder reaches it at the smallest N whose RMSE is ≤ the target: RMSE,
//     not "every repetition", because it is the error one run has on average over the seeds
//     (docs/theory.md#conventions), the same measure a tolerance method is judged by; requiring
//     every repetition would make a method's figure depend on how many repetitions it ran. Its
//     time is that cell's seconds per estimate, no interpolation between ladder points: the N a
//     user would have to pick.
// quadmc's best is the fastest non-peer method that reaches the target, the best peer the
// fastest peer; ratio = quadmc's best time / the best peer's (< 1: quadmc faster).
//
// Summary: over the analytic cells (smoothness::analytic) that some method reaches, the fraction
// where quadmc's best reaches it in at most the best peer's time (counted met where no peer
// reaches it); and the largest ratio over every cell a peer reaches (infinite where quadmc's
// methods do not reach it).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

struct time_to_error_entry {
  std::string method;
  bool peer = false;
  bool ran = false;      // the method has a cell for this target (a ladder or this tolerance)
  bool reached = false;  // … and one meets it
  double seconds = std::numeric_limits<double>::quiet_NaN();  // per estimate, when reached
  std::uint64_t evaluations = 0;                              // per estimate, when reached
};

struct time_to_error_cell {
  std::string family;  // the integrand's name without the "_s<s>" of a dimensions list
  std::string integrand;
  std::size_t s = 0;
  double tolerance = 0.0;
  bool relative = false;
  double target = 0.0;  // absolute
  smoothness regularity = smoothness::analytic;
  std::vector<time_to_error_entry> methods;  // in the tables' order
  std::optional<std::size_t> best_quadmc;    // index into methods
  std::optional<std::size_t> best_peer;
  // best_quadmc's time / best_peer's; +inf when a peer reaches it and quadmc does not; NaN when
  // no peer reaches it.
  double ratio = std::numeric_limits<double>::quiet_NaN();
};

struct time_to_error_summary {
  std::size_t analytic_cells = 0;  // analytic cells that some method reaches
  std::size_t analytic_met = 0;    // … where quadmc's best ≤ the best peer (or no peer reaches)
  std::size_t peer_cells = 0;      // cells (any class) a peer reaches
  double worst_ratio = std::numeric_limits<double>::quiet_NaN();  // over peer_cells
  std::optional<std::size_t> worst_cell;                          // index of the worst
};

// Whether a method is a peer: its name starts with "peer_" (bench/peers' methods).
bool is_peer_method(std::string_view method);

// The cells, grouped by (integrand, s) in order of first appearance, tolerances in the order of
// the first table run to them. Empty when no table has tolerance rows or no method is a peer.
std::vector<time_to_error_cell> time_to_error_cells(std::span<const convergence_table> tables);
time_to_error_summary summarise_time_to_error(std::span<const time_to_error_cell> cells);

// The page's section (heading, explanation, table, summary); empty when there are no cells.
std::string time_to_error_markdown(std::span<const convergence_table> tables);

}  // namespace quadmc
