// A scene run to results in memory in one call: parse → plan → run → analyse (→ the paired
// timing of a time-to-error scene), the pipeline of `quadmc run` below its results folder
// (report/write_results.hpp writes that).
//
// Use run_scene(file) for a whole run on this process; plan_scene and run_scene(plan, …,
// scheduler) when something must happen between planning and running (the quadmc command checks
// its results folder there, so that a refusal costs nothing) or when the cells run elsewhere (its
// MPI scheduler). Not for one cell or one method: scene/run.hpp and methods/registry.hpp.
//
// The results are those of the command, bit for bit: same plan, same streams, same analysis
// (every figure but the timings).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/scene/cell_scheduler.hpp"
#include "quadmc/scene/paired_timing.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"
#include "quadmc/scene/scene.hpp"

#include <cstddef>
#include <filesystem>
#include <string_view>
#include <vector>

namespace quadmc {

// Everything a run of a scene computed.
struct scene_results {
  quadmc::plan plan;  // with the options' overrides in plan.source
  run_output run;
  std::vector<convergence_table> tables;  // one per series of `run`, in plan order
  // The time-to-error winners timed again alternately after the run (scene/paired_timing.hpp);
  // empty when the scene has no such cell or budget.paired_timing_rounds = 0.
  paired_timing_outcome paired_timing;
  // The cells that ran: the plan's less those budget.max_seconds skipped.
  std::size_t cells_ran() const noexcept { return plan.cells.size() - run.skips.size(); }
};

// The scene with the options' threads and timing_min_seconds written in, planned: the plan's
// header then shows what the run will use. Throws scene_error for a bad file.
plan plan_scene(scene s, const run_options& options = {});
plan plan_scene(const std::filesystem::path& scene_file, const run_options& options = {});

// Throws std::runtime_error "<what>: no cell to run: …" when the plan skips every cell.
void require_cells(const plan& p, std::string_view what);

// Runs the plan through `scheduler`, analyses every series, then times the time-to-error
// winners in pairs (scene/paired_timing.hpp) on this process: `scheduler`'s other processes, if
// any, must be idle by then (cell_scheduler.hpp). Throws std::runtime_error when the plan has no
// cell or budget.max_seconds was spent before the first one, run_error when a cell fails. Under a
// scheduler whose process does not speak for the run (an MPI rank other than 0), use run_plan: this
// process has nothing to analyse.
scene_results run_scene(plan p, const run_options& options, cell_scheduler& scheduler);
// The same with every cell in this process.
scene_results run_scene(plan p, const run_options& options = {});
scene_results run_scene(const std::filesystem::path& scene_file, const run_options& options = {});

}  // namespace quadmc
