// The time-to-error table of a results page: per (integrand family, s, tolerance), the time and
// evaluations each method needs to reach the tolerance, quadmc's best method against the best
// peer (a method named `peer_*`, bench/peers), their ratio, and a summary over the cells; and
// time_to_error_pairs.csv, the winners' paired timing.
//
// Use it for a scene that runs methods to tolerances beside peers (bench/scenes/
// time_to_error.toml); a scene without tolerance cells or without a peer gets no table (empty
// text) and no pairs file. Which method reaches a target, with which cell, and who wins are
// analysis/time_to_error_cells.hpp's, shared with the paired timing of scene/paired_timing.hpp.
//
// The ratio shown: where the run paired the two winners (paired_timing_outcome), the median of
// their alternating rounds, "median (min–max over k alternating runs)"; elsewhere the ratio of
// the two cells' own stable timings.
//
// Summary: over the analytic cells (smoothness::analytic) that some method reaches, the fraction
// where quadmc's best reaches it in at most the best peer's time, by the ratio shown (counted met
// where no peer reaches it); and the largest ratio shown over every cell a peer reaches (infinite
// where quadmc's methods do not reach it).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/analysis/time_to_error_cells.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

struct time_to_error_summary {
  std::size_t analytic_cells = 0;  // analytic cells that some method reaches
  std::size_t analytic_met = 0;    // … where quadmc's best ≤ the best peer (or no peer reaches)
  std::size_t peer_cells = 0;      // cells (any class) a peer reaches
  double worst_ratio = std::numeric_limits<double>::quiet_NaN();  // over peer_cells
  std::optional<std::size_t> worst_cell;                          // index of the worst
};

// By each cell's ratio (the paired median where attach_pairs gave it one).
time_to_error_summary summarise_time_to_error(std::span<const time_to_error_cell> cells);

// The page's section (heading, explanation, table, summary), with the paired timing's figures
// where `paired` has them; empty when there are no cells. `ranks` > 1: the run was under mpirun,
// whose rank 0 timed the pairs (said in the explanation); `csv`: the folder has the CSV files
// (the explanation then names time_to_error_pairs.csv).
std::string time_to_error_markdown(std::span<const convergence_table> tables,
                                   const paired_timing_outcome& paired = {}, unsigned ranks = 1,
                                   bool csv = true);

// time_to_error_pairs.csv: one row per pair, in the order given (the paired timing gives them in
// the table's order of cells) —
//   scene, family, integrand, s, tolerance, tolerance_kind (absolute | relative),
//   quadmc_method, quadmc_N, quadmc_evaluations, peer_method, peer_N, peer_evaluations (N = 0
//   for a cell run to a tolerance; evaluations per estimate), rounds, ratio_median, ratio_min,
//   ratio_max, quadmc_seconds_median, peer_seconds_median (seconds per estimate, the medians of
//   each side's rounds), then per round in order, separated by ';': ratios, quadmc_seconds,
//   peer_seconds.
// Numbers in the shortest text that reads back to the same double. Header only for no pairs.
inline constexpr std::string_view time_to_error_pairs_csv_file = "time_to_error_pairs.csv";
std::string time_to_error_pairs_csv_text(std::string_view scene,
                                         std::span<const time_to_error_pair> pairs);

}  // namespace quadmc
