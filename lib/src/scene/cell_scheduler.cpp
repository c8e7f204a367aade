// The run's set-up shared by every scheduler (run_session), the one-process scheduler, and
// run_plan over a scheduler (scene/cell_scheduler.hpp).
#include "quadmc/scene/cell_scheduler.hpp"

#include "quadmc/core/parallel_reduce.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace quadmc {

run_session::run_session(const plan& p, const run_options& options)
    : plan_(&p),
      options_(&options),
      context_{p.source.seed, resolve_threads(options.threads.value_or(p.source.threads)),
               p.source.rng},
      timing_min_seconds_(resolved_timing_min_seconds(p, options)),
      start_(std::chrono::steady_clock::now()),
      report_(static_cast<bool>(options.on_progress)) {
  progress_.cells_total = p.cells.size();
  progress_.evaluations_total = p.total_evaluations;
}

double run_session::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool run_session::budget_spent(double elapsed) const noexcept {
  const std::optional<double>& max_seconds = plan_->source.budget.max_seconds;
  return max_seconds && elapsed > *max_seconds;
}

plan_skip run_session::budget_skip(std::size_t index, double elapsed) const {
  const plan& p = *plan_;
  const plan_cell& cell = p.cells.at(index);
  return plan_skip{fmt::format("{} × {}, N = {}", p.source.methods[cell.method].label,
                               p.source.integrands[cell.integrand].name, cell.nominal_N),
                   fmt::format("budget.max_seconds = {} s spent ({:.1f} s elapsed)",
                               p.source.budget.max_seconds.value_or(0.0), elapsed)};
}

cell_run run_session::run_cell(std::size_t index, double timing_min_seconds) {
  const std::uint64_t repetitions = plan_->cells.at(index).repetitions;
  std::uint64_t done = 0;
  // Reported per repetition, so a cell of 2^32 evaluations × 4 moves the bar while it runs.
  auto on_done = [&](const repetition_result& result) {
    progress_.evaluations_done += result.evaluations;
    if (report_ && ++done < repetitions) options_->on_progress(progress_);
  };
  cell_run run =
      run_cell_repetitions(*plan_, index, 0, repetitions, context_, timing_min_seconds, on_done);
  ++progress_.cells_done;
  if (report_) options_->on_progress(progress_);
  return run;
}

void run_session::count_progress_of(std::size_t cells, std::uint64_t evaluations, bool report) {
  progress_.cells_total = cells;
  progress_.evaluations_total = evaluations;
  report_ = report && static_cast<bool>(options_->on_progress);
}

void local_scheduler::run_cells(run_session& session, run_assembly& assembly) {
  const plan& p = session.source();
  for (std::size_t index = 0; index < p.cells.size(); ++index) {
    const double elapsed = session.elapsed();
    if (session.budget_spent(elapsed)) {
      assembly.skip(session.budget_skip(index, elapsed));
      continue;
    }
    assembly.add(index, session.run_cell(index, session.timing_min_seconds()));
  }
}

run_output run_plan(const plan& p, const run_options& options, cell_scheduler& scheduler) {
  parallel_reduce_peak_threads() = 0;
  run_session session(p, options);
  run_assembly assembly(p);
  scheduler.run_cells(session, assembly);
  run_output out = std::move(assembly).finish();
  out.threads_allowed = session.threads_allowed();
  // A rule evaluated inline (one chunk, or a path without parallel_reduce) used this thread.
  out.threads = std::max(1u, parallel_reduce_peak_threads());
  out.seconds = session.elapsed();
  return out;
}

run_output run_plan(const plan& p, const run_options& options) {
  local_scheduler here;
  return run_plan(p, options, here);
}

}  // namespace quadmc
