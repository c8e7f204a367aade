// Where and in which order the cells of a plan run: the one seam between run_plan and the
// processes that compute cells (docs/design.md#many-processes).
//
// run_plan(plan, options, scheduler) sets a run up once (threads, stable-timing minimum, the
// clock, the progress counts: a run_session), hands the session to the scheduler, and finishes
// the run_output (threads used, wall time). The scheduler decides which cells this process runs,
// runs them through the session (so budget skips, progress and timing are the same for every
// scheduler) and files them, in plan order, into the run_assembly. Two exist:
//  - local_scheduler: every cell here, in plan order (what `quadmc run` uses in one process, and
//    run_plan(plan, options) without a scheduler);
//  - the MPI scheduler of the quadmc command (bench/quadmc/mpi_run.hpp): cells placed on ranks
//    by scene/schedule.hpp, gathered on rank 0.
// A repetition's result is a pure function of (plan, cell, repetition, seed)
// (docs/design.md#hot-path-contract), so a scheduler changes where and when cells run, never the
// series: filed in plan order, they are bitwise what local_scheduler gives.
//
// After run_cells returns, run_scene may time cells again on the process that speaks for the run
// (the paired timing of a time-to-error scene, scene/paired_timing.hpp), one call at a time as
// the run did. A scheduler's other processes must then be idle, not computing nor polling the
// cores those timings use: the MPI scheduler's ranks other than 0 wait for rank 0 in a barrier
// that sleeps between polls (bench/quadmc/mpi_run.hpp).
//
// Not for per-sample work: one virtual call per run.
#pragma once

#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>

namespace quadmc {

// One run's settings and counters, shared by every scheduler.
class run_session {
 public:
  // Resolves options against the plan's scene (threads: 0 = all cores; the timing minimum,
  // checked) and starts the run's clock.
  run_session(const plan& p, const run_options& options);

  const plan& source() const noexcept { return *plan_; }
  const run_context& context() const noexcept { return context_; }
  unsigned threads_allowed() const noexcept { return context_.threads; }
  double timing_min_seconds() const noexcept { return timing_min_seconds_; }
  // Seconds since the session started.
  double elapsed() const;

  // Whether budget.max_seconds has passed at `elapsed` seconds (never, without a budget).
  bool budget_spent(double elapsed) const noexcept;
  // The record of cell `index` not run because the budget was spent at `elapsed`.
  plan_skip budget_skip(std::size_t index, double elapsed) const;

  // Runs every repetition of cell `index` here, stable timing to `timing_min_seconds` (0: the
  // cell is timed once, by its own call), and reports progress after each repetition and at the
  // end when this session reports. Throws run_error naming the cell when it fails.
  cell_run run_cell(std::size_t index, double timing_min_seconds);

  // Which cells the progress counts: by default every cell of the plan, reported when
  // options.on_progress is set. A scheduler that runs only some cells here sets its own totals,
  // and a process that does not speak for the run (an MPI rank other than 0) turns reporting off.
  void count_progress_of(std::size_t cells, std::uint64_t evaluations, bool report);

 private:
  const plan* plan_;
  const run_options* options_;
  run_context context_;
  double timing_min_seconds_;
  std::chrono::steady_clock::time_point start_;
  run_progress progress_;
  bool report_;
};

class cell_scheduler {
 public:
  virtual ~cell_scheduler() = default;
  // Runs the cells of session.source() where this scheduler places them and files each, in plan
  // order, into `assembly` (run or skipped). A process that does not speak for the run files
  // nothing. Throws run_error when a cell fails.
  virtual void run_cells(run_session& session, run_assembly& assembly) = 0;
};

// Every cell in this process, in plan order; a cell is skipped once budget.max_seconds has passed.
class local_scheduler final : public cell_scheduler {
 public:
  void run_cells(run_session& session, run_assembly& assembly) override;
};

// The run of `p` with `scheduler` placing its cells.
run_output run_plan(const plan& p, const run_options& options, cell_scheduler& scheduler);

}  // namespace quadmc
