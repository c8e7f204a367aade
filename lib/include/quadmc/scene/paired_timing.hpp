// Paired timing: the two winners of every time-to-error cell — quadmc's best and the best peer
// (analysis/time_to_error_cells.hpp) — timed again after the run, alternately, so that their
// ratio does not depend on the moment each was measured (docs/design.md#stable-timing).
//
// Use it through run_scene (scene/run_scene.hpp), which runs it after analysing the series; or
// time_pairs with a timer of your own (tests inject a fake one). Not for scenes without a
// time-to-error table: a scene with no tolerance cell or no `peer_*` method has no pair, and
// pays nothing.
//
// The procedure, per cell where both a quadmc best and a best peer reach the target, in the
// table's order of cells: rounds × (one stable timing of quadmc's winning cell, then one of the
// peer's), i.e. q, p, q, p, …; each round's ratio is q/p and the page shows their median with
// their min–max. A stable timing is the runner's own (scene/run.hpp, time_cell_estimate:
// repetition 1's call timed once, then repeated in batches until timing_min_seconds), on the
// run's threads, one timed call at a time as during the run. The winning cell of a method is the
// one time_to_error_cells chose (its tolerance cell, or its smallest ladder N whose RMSE meets
// the target); for an ensemble, the first instance's cell, the one the runner timed.
//
// Budget: a pair is started only while budget.max_seconds (counted from the start of the run)
// has not passed; a pair not started, or whose call failed, is listed in
// paired_timing_outcome::not_paired with the reason, and its cell keeps its single ratio. A pair
// is timed whole or not at all: a ratio on the page is always the median of all its rounds.
//
// Under mpirun only rank 0 calls run_scene; the other ranks have finished their cells and wait,
// without polling, for rank 0 to end (bench/quadmc/mpi_run.hpp), so rank 0 times the pairs alone.
#pragma once

#include "quadmc/analysis/time_to_error_cells.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"
#include "quadmc/scene/scene.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <span>

namespace quadmc {

// Whether a run of `sc` can pair anything: a method run to tolerances, a `peer_*` method and a
// method that is not one (which cells have both winners only the run tells).
bool may_pair_time_to_error(const scene& sc);

// The plan cell whose stable timing is the figure of row `row` of `table`: the table's
// (integrand, method), instance 0, and the row's N or tolerance. Throws invalid_argument when the
// plan has no such cell (a table of another plan).
std::size_t winning_plan_cell(const plan& p, const convergence_table& table, std::size_t row);

// One stable timing of plan cell `index`: seconds per estimate.
using cell_timer = std::function<double(std::size_t index)>;

struct paired_timing_options {
  std::size_t rounds = min_paired_timing_rounds;  // 0: nothing is timed
  // Asked before each pair: whether the budget is spent, and why (for not_paired); nullopt =
  // go on. Empty: never spent.
  std::function<std::optional<std::string>()> budget_spent;
};

// The pairs of `tables` (the run of `p`), timed by `timer` as above. rounds = 0 gives an empty
// outcome.
paired_timing_outcome time_pairs(const plan& p, std::span<const convergence_table> tables,
                                 const paired_timing_options& options, const cell_timer& timer);

// The pass as run_scene runs it: budget.paired_timing_rounds rounds, the timer time_cell_estimate
// with the options' threads and stable-timing minimum (as the run had them), and the budget
// budget.max_seconds less `run_seconds`, the time the run already took.
paired_timing_outcome run_paired_timing(const plan& p, std::span<const convergence_table> tables,
                                        const run_options& options, double run_seconds);

}  // namespace quadmc
