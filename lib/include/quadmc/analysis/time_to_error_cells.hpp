// Who reaches each error target first: per (integrand, s, tolerance), the time and evaluations
// each method needs, quadmc's best method against the best peer (a method named `peer_*`,
// bench/peers) and their ratio; and the record of the two winners timed again alternately.
//
// Use time_to_error_cells wherever a winner is needed: the page's time-to-error table
// (report/time_to_error_table.hpp) and the paired timing that re-times the winners after a run
// (scene/paired_timing.hpp) both call it, so they can never disagree on which cell won. A scene
// without tolerance cells or without a peer has no cells. Not an extrapolation: a tolerance no
// cell reached is "not reached".
//
// Per cell, the target is the error the tolerance asks for: tolerance·|I| for a relative
// tolerance (convergence_table::relative_tolerance), the tolerance itself for an absolute one.
//   - A method run to the tolerance (its convergence_table has a row at that tolerance) reaches
//     it when that row's true error — RMSE over its repetitions, |error| for one — is ≤ the
//     target: its own estimate saying so is not enough. Its winning cell is that row; its time is
//     the row's seconds per estimate, the stable timing of the whole call to the tolerance
//     (analysis/cell_timing.hpp).
//   - A method on the N ladder reaches it at the smallest N whose RMSE is ≤ the target: RMSE,
//     not "every repetition", because it is the error one run has on average over the seeds
//     (docs/theory.md#conventions), the same measure a tolerance method is judged by; requiring
//     every repetition would make a method's figure depend on how many repetitions it ran. Its
//     winning cell is that row, its time that cell's seconds per estimate, no interpolation
//     between ladder points: the N a user would have to pick.
// quadmc's best is the fastest non-peer method that reaches the target, the best peer the
// fastest peer (a tie goes to the method listed first); ratio = quadmc's best time / the best
// peer's (< 1: quadmc faster).
//
// Each of those times was measured at its own moment of the run, so on a loaded machine two
// close ones can swap between runs (docs/design.md#stable-timing). The paired timing therefore
// times the two winners again, alternately, k rounds: round i gives q_i and p_i, one stable timing
// each, the quadmc side first, and the ratio q_i/p_i. A time_to_error_pair records the rounds;
// its ratio is the median over them, with the smallest and largest as its spread (min–max, as
// cell_timing's spread: with 5 rounds an interquartile range would say little).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

struct time_to_error_entry {
  std::string method;
  bool peer = false;
  bool ran = false;      // the method has a cell for this target (a ladder or this tolerance)
  bool reached = false;  // … and one meets it
  double seconds = std::numeric_limits<double>::quiet_NaN();  // per estimate, when reached
  std::uint64_t evaluations = 0;                              // per estimate, when reached
  // The winning cell when reached: row `row` of tables[table] (indices into the span given to
  // time_to_error_cells and into that table's rows).
  std::size_t table = 0;
  std::size_t row = 0;
};

// The two winners of a cell timed alternately (the procedure above), with their plan cells'
// N (0 for a cell run to a tolerance) and evaluations per estimate.
struct time_to_error_pair {
  std::string family;  // time_to_error_cell::family
  std::string integrand;
  std::size_t s = 0;
  double tolerance = 0.0;
  bool relative = false;
  std::string quadmc_method;
  std::uint64_t quadmc_n = 0;
  std::uint64_t quadmc_evaluations = 0;
  std::string peer_method;
  std::uint64_t peer_n = 0;
  std::uint64_t peer_evaluations = 0;
  // Seconds per estimate of each round, in the order they were timed (round i: quadmc_seconds[i]
  // first, then peer_seconds[i]).
  std::vector<double> quadmc_seconds;
  std::vector<double> peer_seconds;

  std::size_t rounds() const noexcept { return quadmc_seconds.size(); }
};

// A pair's figures, from its rounds.
struct paired_ratio {
  std::vector<double> ratios;  // quadmc_seconds[i] / peer_seconds[i], in round order
  double median = std::numeric_limits<double>::quiet_NaN();
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  double quadmc_median_seconds = std::numeric_limits<double>::quiet_NaN();
  double peer_median_seconds = std::numeric_limits<double>::quiet_NaN();
  std::size_t rounds() const noexcept { return ratios.size(); }
};

// Throws invalid_argument for no rounds, sides of different lengths, or a time that is not
// finite and > 0 (a ratio needs both; every stable timing of a call that ran is > 0).
paired_ratio summarise_pair(const time_to_error_pair& pair);

// What the paired timing of a run did (scene/paired_timing.hpp runs it).
struct paired_timing_outcome {
  std::size_t rounds = 0;  // asked per pair (budget.paired_timing_rounds); 0 = off
  std::vector<time_to_error_pair> pairs;
  // The cells with both winners that were not paired, each "what: why" (the budget ran out, a
  // call failed); their ratio stays the single one.
  std::vector<std::string> not_paired;
  double seconds = 0.0;  // wall time of the pass
  bool ran() const noexcept { return !pairs.empty() || !not_paired.empty(); }
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
  // no peer reaches it. Where the winners were paired (attach_pairs), the paired median.
  double ratio = std::numeric_limits<double>::quiet_NaN();
  std::optional<paired_ratio> paired;

  bool has_both() const noexcept { return best_quadmc.has_value() && best_peer.has_value(); }
};

// Whether a method is a peer: its name starts with "peer_" (bench/peers' methods).
bool is_peer_method(std::string_view method);

// The cells, grouped by (integrand, s) in order of first appearance, tolerances in the order of
// the first table run to them. Empty when no table has tolerance rows or no method is a peer.
std::vector<time_to_error_cell> time_to_error_cells(std::span<const convergence_table> tables);

// Whether `pair` is the pairing of `cell`: the same integrand, s, tolerance and both winners.
bool pairs_cell(const time_to_error_pair& pair, const time_to_error_cell& cell);

// Gives every cell its pair (pairs_cell), if any: `paired` and the ratio then become the
// pair's (summarise_pair). Pairs of no cell are ignored.
void attach_pairs(std::span<time_to_error_cell> cells, std::span<const time_to_error_pair> pairs);

}  // namespace quadmc
