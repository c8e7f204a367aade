// Where the cells of a plan run when K processes share it: each (integrand, method) series' cost
// model, each cell's cost, and the assignment of cells to processes — largest first, each to the
// least-loaded process (LPT), and the costliest cells whose methods share chunks run by all of
// them together (split). The MPI runner of the quadmc command (bench/quadmc/mpi_run.hpp) times
// the probes this file chooses and applies the assignment it returns; everything here is pure
// logic on the plan and the timings, so it is tested in one process (tests/scene/schedule_test).
//
// Cost model: a repetition of a cell costs fixed + evaluations × per_evaluation seconds, fitted
// per series from two timings, its smallest cell (the fixed part: set-up, thread hand-off) and its
// largest cell of at most probe_evaluations (the slope). One timing of the smallest cell alone
// would not do: a series starting at N = 1 spends microseconds of set-up on one evaluation, and
// that figure times 10⁹ evaluations made a stress-scene cell look 10⁴ times its cost.
//
// LPT ([Graham 1969], docs/design.md#many-processes): with the cells in decreasing cost, each given
// to the least-loaded process, the makespan is at most total/K + the largest cell. A cell above a
// quarter of the fair share total/K is split when its method shares chunks, so no unsplit cell can
// take more than 1.25 × total/K: an efficiency of at least 80 %.
#pragma once

#include "quadmc/methods/method.hpp"
#include "quadmc/scene/plan.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// Which cells all processes run together: `automatic` splits the cells above a quarter of the
// fair share whose method shares chunks (cell_shares_chunks); `all` splits every cell, those
// whose method does not share chunks too (each process then computes such a cell whole, which is
// exact and not faster: it is for tests); `none` splits none. Results do not depend on it.
enum class split_policy { automatic, all, none };
// "auto", "all" or "none" (`quadmc run --split-cells`); throws std::invalid_argument otherwise.
split_policy parse_split_policy(std::string_view text);

// Whether cell `index` of `p` is worth splitting: its configured method's kernels share chunk
// results between processes (method::shares_chunks, methods/method.hpp), so each of K processes
// does about 1/K of its work.
bool cell_shares_chunks(const plan& p, std::size_t index);

// The largest cell a series is timed at for its slope.
inline constexpr std::uint64_t probe_evaluations = std::uint64_t{1} << 16;

// The plan's series, in order of first appearance, and the two cells that price each.
struct cost_probes {
  std::vector<std::size_t> series_of;  // per plan cell: its series
  std::vector<std::size_t> smallest;   // per series: its cell of fewest evaluations (the first)
  // Per series: its largest cell of at most probe_evaluations, or its smallest cell when every
  // cell is larger.
  std::vector<std::size_t> probe;
};
cost_probes choose_cost_probes(const plan& p);

// A series' seconds per repetition ≈ fixed + per_evaluation × evaluations.
struct series_cost {
  double fixed = 0.0;
  double per_evaluation = 1e-8;  // the nominal cost of a series that could not be timed
};
// The line through the smallest cell's timing (n0, t0) and the probe's (n1, t1): fixed = t0 and the
// slope. A slope lost in the noise (t1 ≤ t0) is replaced by the probe's mean time per evaluation
// t1/n1, and a series timed at one size (n1 = n0) has that mean and no fixed part.
// per_evaluation is at least 1e-12 s, so no cell costs nothing.
series_cost fit_series_cost(std::uint64_t n0, double t0, std::uint64_t n1, double t1);

// Every series' cost, timed on this process: each probe is the fastest of three timings of one
// repetition (a cell of microseconds is at the mercy of one preemption, which can price a series
// hundreds of times too high; a cell above probe_evaluations, a series that starts above the
// probe size, is timed once), fitted by fit_series_cost. A series whose probe fails gets the
// nominal cost: the run proper reports its error, with the cell and repetition.
std::vector<series_cost> time_series_costs(const plan& p, const cost_probes& probes,
                                           const run_context& context);

// Each cell's cost: repetitions × (fixed + evaluations × per_evaluation) of its series.
std::vector<double> cell_costs(const plan& p, const cost_probes& probes,
                               std::span<const series_cost> series);

// Where one cell runs.
struct cell_placement {
  bool split = false;  // run by all processes together
  unsigned rank = 0;   // else the process that runs it whole
};

// The assignment of cells with costs `cost` (non-negative) to `processes` ≥ 1 processes, as
// above. `shares_chunks[i]` says whether cell i may be split under split_policy::automatic. Ties
// in cost keep plan order, and ties in load go to the lowest rank, so every process computes the
// same assignment from the same costs.
std::vector<cell_placement> assign_cells(std::span<const double> cost,
                                         const std::vector<bool>& shares_chunks, unsigned processes,
                                         split_policy policy);

// The plan's cells with their method's shares_chunks and their placement, as CSV (`quadmc run
// --cells-csv FILE`): integrand, instance, s, method (the label), N (empty for a tolerance
// cell), tolerance, evaluations, repetitions, shares_chunks (1 or 0), placement ("split" or
// "rank R"; a cell without an entry in `placement` ran on rank 0). bench/scaling.py's model reads
// shares_chunks from it, so the model splits only the cells the planner would.
std::string cells_csv(const plan& p, std::span<const cell_placement> placement);

}  // namespace quadmc
