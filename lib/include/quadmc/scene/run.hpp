// Runs a plan: every cell, every repetition, timed, into one convergence series per
// (integrand, method) — the input of analysis/convergence_table.hpp.
//
// Dispatch happens once per repetition (one virtual call on the configured method the plan holds,
// methods/method.hpp, then templates below); the integrand is type-erased per batch only.
// Randomness: repetition r of a cell uses the Philox stream stream_id({cell.stream_parts…, r})
// keyed by the scene seed, so a result depends on neither thread count nor run order
// (docs/design.md#hot-path-contract).
//
// Timing (analysis/cell_timing.hpp): the repetitions are timed one clock reading each (their
// total is cell_statistics::seconds); apart from them, each cell's stable time per estimate
// repeats repetition 1's call (same stream, same work) in batches until timing_min_seconds has
// passed, batches sized to ~1/10 of it. A cell whose repetition 1 already took at least the
// minimum is timed once, by that call. A tolerance cell's estimate is the whole call to the
// tolerance. An ensemble's cell is timed on its first instance.
//
// Ensembles (K random instances of a family): the instances' errors are pooled into one series.
// Each estimate is shifted by (Ī − I_k), Ī the mean of the instances' references, so that the
// series' reference is Ī and every error is the error of its own instance.
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/methods/method.hpp"
#include "quadmc/scene/plan.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadmc {

// A cell failed while it ran: an integrand value that is not finite (the cause names the point,
// functions/integrand.hpp), an estimate or standard error that overflowed, or an estimator that
// refused its sample (importance sampling where the pdf is 0). The message starts with the cell,
// "plain_mc × exp, N = 64 (64 evaluations), repetition 3 of 32: ", then the cause. make_plan
// refuses what it can foresee; this is for what only the run can see.
class run_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct run_progress {
  std::size_t cells_done = 0;
  std::size_t cells_total = 0;
  std::uint64_t evaluations_done = 0;
  std::uint64_t evaluations_total = 0;
};

struct run_options {
  // Threads allowed: empty = the scene's `threads`; 0, given here or in the scene, = all cores
  // (core/parallel_reduce.hpp, resolve_threads).
  std::optional<unsigned> threads;
  // Stable timing's minimum per cell in seconds: empty = the scene's budget.timing_min_seconds.
  std::optional<double> timing_min_seconds;
  // Called after each repetition and after each cell (cells_done counts finished cells).
  std::function<void(const run_progress&)> on_progress;
};

struct run_output {
  std::vector<convergence_series> series;  // in plan order: integrand, then method
  std::vector<plan_skip> skips;            // cells not run because max_seconds ran out
  double seconds = 0.0;                    // wall time of the whole run
  // Threads actually used: the most any cell ran on. A cell with fewer chunks of work than the
  // threads allowed runs on fewer (parallel_reduce_peak_threads), so this can be below
  // threads_allowed, the limit after resolving 0 to the core count.
  unsigned threads = 1;
  unsigned threads_allowed = 1;
};

// Every cell in this process, in plan order (local_scheduler). Another placement of the cells (the
// MPI runner's) goes through run_plan(plan, options, scheduler) of scene/cell_scheduler.hpp, which
// gives the same series.
run_output run_plan(const plan& p, const run_options& options = {});

// The two halves of run_plan, for a scheduler whose cells do not all run on this process (the MPI
// runner of the quadmc command, scene/cell_scheduler.hpp): a repetition's result is a pure function
// of (plan, cell, repetition, seed), so cells may run anywhere, in any order, and filed here in
// plan order give the series a one-process run gives.
//
// One cell's repetitions, and its stable timing where it was timed.
struct cell_run {
  std::vector<repetition_result> repetitions;
  cell_timing timing;  // untimed (estimates = 0) unless repetition 1 of instance 1 ran here
};

// The minimum of stable timing for a run: options' if given, else the scene's; checked.
double resolved_timing_min_seconds(const plan& p, const run_options& options);

// Runs repetitions [first, last) of cell `index` (the estimate shifted to the series' reference,
// checked finite); a failure throws run_error naming the cell and repetition. Repetition 1 of
// an ensemble's first instance (of every cell outside ensembles) is then timed as above, to
// timing_min_seconds (0: timed once, by its own call). on_done, if set, is called after each
// repetition.
cell_run run_cell_repetitions(const plan& p, std::size_t index, std::uint64_t first,
                              std::uint64_t last, const run_context& context,
                              double timing_min_seconds,
                              const std::function<void(const repetition_result&)>& on_done = {});

// One more stable timing of cell `index`, apart from its run: repetition 1's call (same stream,
// same work) timed once, then, below timing_min_seconds, repeated in batches as above — the
// procedure run_cell_repetitions times a cell by, through the same code. For cells timed again
// after the run (scene/paired_timing.hpp). Throws run_error naming the cell when the call fails,
// invalid_argument for an index outside the plan or a minimum that is not finite and ≥ 0.
cell_timing time_cell_estimate(const plan& p, std::size_t index, const run_context& context,
                               double timing_min_seconds);

// Files whole cells into series, in plan order (an index lower than the last one added, or a
// cell without all its repetitions, is refused).
class run_assembly {
 public:
  explicit run_assembly(const plan& p);
  void add(std::size_t index, cell_run run);
  void skip(plan_skip skipped);
  // The series and skips; seconds and threads are the caller's to fill in.
  run_output finish() &&;

 private:
  const plan* plan_;
  run_output output_;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> series_index_;
  std::size_t added_ = 0;
  std::size_t last_added_ = 0;
};

}  // namespace quadmc
