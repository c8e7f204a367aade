// The paired timing of the time-to-error winners (scene/paired_timing.hpp).
#include "quadmc/scene/paired_timing.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/scene/cell_scheduler.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <string>
#include <utility>

namespace quadmc {
namespace {

std::string cell_name(const time_to_error_cell& c) {
  return fmt::format("{}, s = {}, tolerance {:g}{}", c.family, c.s, c.tolerance,
                     c.relative ? "·|I|" : "");
}

}  // namespace

bool may_pair_time_to_error(const scene& sc) {
  bool tolerance = false;
  bool peer = false;
  bool own = false;
  for (const method_spec& m : sc.methods) {
    tolerance = tolerance || m.control == cell_control::tolerance;
    (is_peer_method(m.label) ? peer : own) = true;
  }
  return tolerance && peer && own;
}

std::size_t winning_plan_cell(const plan& p, const convergence_table& table, std::size_t row) {
  require(row < table.rows.size(), fmt::format("row of {} × {}", table.method, table.integrand),
          row, fmt::format("a row of the table (it has {})", table.rows.size()));
  const convergence_row& r = table.rows[row];
  const bool to_tolerance = !std::isnan(r.tolerance);
  for (std::size_t k = 0; k < p.cells.size(); ++k) {
    const plan_cell& c = p.cells[k];
    // The first instance's cell: the runner times an ensemble's cell on it (scene/run.hpp).
    if (c.instance != 0 || c.dimension != table.s) continue;
    if (p.source.methods[c.method].label != table.method) continue;
    if (p.source.integrands[c.integrand].name != table.integrand) continue;
    if (to_tolerance ? c.tolerance == r.tolerance : c.nominal_N == r.n) return k;
  }
  throw invalid_argument(
      fmt::format("{} × {}", table.method, table.integrand),
      to_tolerance ? fmt::format("tolerance {}", r.tolerance) : fmt::format("N = {}", r.n),
      "a cell of the plan the table was run from");
}

paired_timing_outcome time_pairs(const plan& p, std::span<const convergence_table> tables,
                                 const paired_timing_options& options, const cell_timer& timer) {
  paired_timing_outcome out;
  out.rounds = options.rounds;
  if (options.rounds == 0) return out;
  const auto start = std::chrono::steady_clock::now();
  for (const time_to_error_cell& c : time_to_error_cells(tables)) {
    if (!c.has_both()) continue;
    if (options.budget_spent) {
      if (const std::optional<std::string> why = options.budget_spent()) {
        out.not_paired.push_back(fmt::format("{}: {}", cell_name(c), *why));
        continue;
      }
    }
    const time_to_error_entry& q = c.methods[*c.best_quadmc];
    const time_to_error_entry& r = c.methods[*c.best_peer];
    const convergence_table& qt = tables[q.table];
    const convergence_table& rt = tables[r.table];
    time_to_error_pair pair;
    pair.family = c.family;
    pair.integrand = c.integrand;
    pair.s = c.s;
    pair.tolerance = c.tolerance;
    pair.relative = c.relative;
    pair.quadmc_method = q.method;
    pair.quadmc_n = qt.rows[q.row].n;
    pair.quadmc_evaluations = q.evaluations;
    pair.peer_method = r.method;
    pair.peer_n = rt.rows[r.row].n;
    pair.peer_evaluations = r.evaluations;
    try {
      const std::size_t quadmc_cell = winning_plan_cell(p, qt, q.row);
      const std::size_t peer_cell = winning_plan_cell(p, rt, r.row);
      for (std::size_t round = 0; round < options.rounds; ++round) {
        // Interleaved, quadmc first: q, p, q, p, … Every call after the first follows one of
        // the other side's, so a slow spell of the machine falls on both sides' rounds alike
        // instead of on whichever cell the run happened to time during it.
        pair.quadmc_seconds.push_back(timer(quadmc_cell));
        pair.peer_seconds.push_back(timer(peer_cell));
      }
      (void)summarise_pair(pair);  // every time usable: finite and > 0
    } catch (const std::exception& e) {
      // The cells ran once already, so this is rare (a peer's process that failed this time);
      // the run's results stand, and the page says which cell keeps its single ratio and why.
      out.not_paired.push_back(
          fmt::format("{}: {} × {}: {}", cell_name(c), q.method, r.method, e.what()));
      continue;
    }
    out.pairs.push_back(std::move(pair));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

paired_timing_outcome run_paired_timing(const plan& p, std::span<const convergence_table> tables,
                                        const run_options& options, double run_seconds) {
  const std::uint64_t rounds = p.source.budget.paired_timing_rounds;
  require(valid_paired_timing_rounds(rounds), "budget.paired_timing_rounds", rounds,
          paired_timing_rounds_expected);
  // The run's threads and stable-timing minimum, resolved as the run resolved them.
  const run_session session(p, options);
  paired_timing_options o;
  o.rounds = static_cast<std::size_t>(rounds);
  const std::optional<double> max_seconds = p.source.budget.max_seconds;
  if (max_seconds) {
    o.budget_spent = [&]() -> std::optional<std::string> {
      const double elapsed = run_seconds + session.elapsed();
      if (elapsed <= *max_seconds) return std::nullopt;
      return fmt::format("budget.max_seconds = {} s spent ({:.1f} s elapsed)", *max_seconds,
                         elapsed);
    };
  }
  const cell_timer timer = [&](std::size_t index) {
    return time_cell_estimate(p, index, session.context(), session.timing_min_seconds())
        .seconds_per_estimate;
  };
  return time_pairs(p, tables, o, timer);
}

}  // namespace quadmc
