// Runs a plan: every cell, every repetition, timed, into one convergence series per
// (integrand, method) — the input of analysis/convergence_table.hpp.
//
// Dispatch happens once per repetition (a switch on the method name, then templates below);
// the integrand is type-erased per batch only. Randomness: repetition r of a cell uses the
// Philox stream stream_id({cell.stream_parts…, r}) keyed by the scene seed, so a result
// depends on neither thread count nor run order (docs/design.md#hot-path-contract).
//
// Ensembles (K random instances of a family): the instances' errors are pooled into one series.
// Each estimate is shifted by (Ī − I_k), Ī the mean of the instances' references, so that the
// series' reference is Ī and every error is the error of its own instance.
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/scene/plan.hpp"

#include <functional>
#include <string>
#include <vector>

namespace quadmc {

struct run_progress {
  std::size_t cells_done = 0;
  std::size_t cells_total = 0;
  std::uint64_t evaluations_done = 0;
  std::uint64_t evaluations_total = 0;
};

struct run_options {
  unsigned threads = 0;  // 0 = the scene's threads (which may itself be 0 = all cores)
  // Called after each repetition and after each cell (cells_done counts finished cells).
  std::function<void(const run_progress&)> on_progress;
};

struct run_output {
  std::vector<convergence_series> series;  // in plan order: integrand, then method
  std::vector<plan_skip> skips;            // cells not run because max_seconds ran out
  double seconds = 0.0;                    // wall time of the whole run
  unsigned threads = 1;                    // threads actually used
};

run_output run_plan(const plan& p, const run_options& options = {});

}  // namespace quadmc
