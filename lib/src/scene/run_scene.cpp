// Parse → plan → run → analyse (scene/run_scene.hpp).
#include "quadmc/scene/run_scene.hpp"

#include "quadmc/scene/parse.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

namespace quadmc {

plan plan_scene(scene s, const run_options& options) {
  if (options.threads) s.threads = *options.threads;
  if (options.timing_min_seconds) s.budget.timing_min_seconds = *options.timing_min_seconds;
  return make_plan(s);
}

plan plan_scene(const std::filesystem::path& scene_file, const run_options& options) {
  return plan_scene(parse_scene_file(scene_file), options);
}

void require_cells(const plan& p, std::string_view what) {
  if (!p.cells.empty()) return;
  throw std::runtime_error(fmt::format(
      "{}: no cell to run: the plan skips every cell (reasons in the plan); nothing written",
      what));
}

scene_results run_scene(plan p, const run_options& options, cell_scheduler& scheduler) {
  require_cells(p, fmt::format("scene '{}'", p.source.name));
  scene_results out;
  out.plan = std::move(p);
  out.run = run_plan(out.plan, options, scheduler);
  if (out.cells_ran() == 0) {
    throw std::runtime_error(fmt::format(
        "no cell ran: budget.max_seconds = {} s was spent before the first cell; nothing written",
        out.plan.source.budget.max_seconds.value_or(0.0)));
  }
  out.tables.reserve(out.run.series.size());
  for (const convergence_series& series : out.run.series) {
    out.tables.push_back(analyse_convergence(series));
  }
  out.paired_timing = run_paired_timing(out.plan, out.tables, options, out.run.seconds);
  return out;
}

scene_results run_scene(plan p, const run_options& options) {
  local_scheduler here;
  return run_scene(std::move(p), options, here);
}

scene_results run_scene(const std::filesystem::path& scene_file, const run_options& options) {
  plan p = plan_scene(scene_file, options);
  require_cells(p, scene_file.string());
  return run_scene(std::move(p), options);
}

}  // namespace quadmc
