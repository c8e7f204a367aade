// analyse_convergence: cell statistics → floor → fit → theory → verdict (slope or envelope) →
// work-precision.
#include "quadmc/analysis/convergence_table.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

namespace quadmc {

convergence_table analyse_convergence(const convergence_series& series,
                                      const analysis_options& options) {
  require(!series.cells.empty(), "cells", series.cells.size(),
          fmt::format("at least one cell for {} / {}", series.integrand, series.method));
  require(series.s >= 1, "s", series.s,
          fmt::format("a dimension >= 1 for {} / {}", series.integrand, series.method));
  convergence_table table;
  table.integrand = series.integrand;
  table.s = series.s;
  table.method = series.method;
  table.regularity = series.regularity;
  table.reference = series.reference;
  table.theory = series.theory;

  // Sized cells in increasing N; cells run to a tolerance in decreasing tolerance, the order in
  // which a convergent method spends more.
  const bool to_tolerance = !std::isnan(series.cells.front().tolerance);
  std::vector<const convergence_cell*> cells;
  for (const convergence_cell& cell : series.cells) {
    require(std::isnan(cell.tolerance) != to_tolerance, "tolerance", cell.tolerance,
            fmt::format("cells of one kind in a series, all sized or all run to a tolerance ({} / "
                        "s = {} / {})",
                        series.integrand, series.s, series.method));
    cells.push_back(&cell);
  }
  std::stable_sort(cells.begin(), cells.end(),
                   [&](const convergence_cell* a, const convergence_cell* b) {
                     return to_tolerance ? a->tolerance > b->tolerance : a->n < b->n;
                   });

  for (const convergence_cell* cell : cells) {
    const std::string where =
        to_tolerance ? fmt::format("cell tolerance = {} of {} / s = {} / {}", cell->tolerance,
                                   series.integrand, series.s, series.method)
                     : fmt::format("cell N = {} of {} / s = {} / {}", cell->n, series.integrand,
                                   series.s, series.method);
    if (to_tolerance) {
      require(table.rows.empty() || cell->tolerance != table.rows.back().tolerance, "tolerance",
              cell->tolerance, "distinct tolerances in a series (" + where + ")");
    } else {
      require(table.rows.empty() || cell->n != table.rows.back().n, "N", cell->n,
              "distinct N in a series (" + where + ")");
    }
    require(std::isnan(cell->error_envelope) || cell->error_envelope >= 0.0, "error_envelope",
            cell->error_envelope, "a bound >= 0 on |error|, or NaN for none (" + where + ")");
    require(std::isnan(cell->error_envelope) == std::isnan(series.cells.front().error_envelope),
            "error_envelope", cell->error_envelope,
            "an envelope on every cell of the series or on none (" + where + ")");
    convergence_row row;
    row.n = cell->n;
    row.tolerance = cell->tolerance;
    row.per_axis = cell->per_axis;
    row.envelope = cell->error_envelope;
    try {
      row.stats = compute_cell_statistics(cell->repetitions, series.reference, series.errors);
    } catch (const invalid_argument& e) {
      throw invalid_argument(fmt::format("{}: {}", where, e.what()));
    }
    // Equal counts are one computation reached twice (a tolerance met at the same level, a
    // budget not spent); fewer is a ladder out of order.
    require(table.rows.empty() || row.stats.evaluations >= table.rows.back().stats.evaluations,
            "evaluations", row.stats.evaluations,
            fmt::format("at least the evaluations of the previous {} ({})",
                        to_tolerance ? "(looser) tolerance" : "N of the ladder", where));
    table.rows.push_back(row);
  }

  // The ladder the floor rule, the fit and the work-precision table see: one point per distinct
  // evaluation count, the first row that spent it (fixed-size cells are distinct already: the
  // plan skips a repeated grid; a budget or tolerance cell may stop where a smaller one did).
  std::vector<std::size_t> ladder;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    if (ladder.empty() ||
        table.rows[k].stats.evaluations != table.rows[ladder.back()].stats.evaluations) {
      ladder.push_back(k);
    }
  }
  std::vector<double> evaluations, errors, seconds, amplification;
  double largest_error = 0.0;
  for (const std::size_t k : ladder) {
    const convergence_row& row = table.rows[k];
    evaluations.push_back(static_cast<double>(row.stats.evaluations));
    errors.push_back(row.stats.rmse);
    seconds.push_back(row.stats.seconds_per_repetition());
    largest_error = std::max(largest_error, row.stats.rmse);
    // A rule with weights of both signs amplifies rounding by Σ|w| (cell_statistics.hpp).
    const double w = row.stats.absolute_weight_sum;
    amplification.push_back(std::isnan(w) ? 1.0 : std::max(1.0, w));
  }
  const double scale = series.reference != 0.0 ? std::abs(series.reference) : largest_error;
  std::vector<double> scales;
  for (const double a : amplification) scales.push_back(scale * a);
  // The floor, fit and work-precision steps name their inputs by position ("error[0]"); the
  // series they came from goes in front, so a failure says which integrand and method.
  const auto in_series = [&](auto&& step) {
    try {
      return step();
    } catch (const invalid_argument& e) {
      throw invalid_argument(
          fmt::format("{} / s = {} / {}: {}", series.integrand, series.s, series.method, e.what()));
    }
  };
  table.floor =
      in_series([&] { return detect_rounding_floor(evaluations, errors, scales, options.floor); });

  // A row shares the floor flag of the ladder point that spent its evaluations; the table's
  // floor is then stated per row, like everything else in it.
  std::vector<double> fit_n, fit_error;
  std::vector<bool> row_flags(table.rows.size(), false);
  for (std::size_t p = 0; p < ladder.size(); ++p) {
    const std::size_t end = p + 1 < ladder.size() ? ladder[p + 1] : table.rows.size();
    for (std::size_t k = ladder[p]; k < end; ++k) {
      table.rows[k].floor = table.floor.flags[p];
      row_flags[k] = table.floor.flags[p];
    }
    if (!table.floor.flags[p]) {
      fit_n.push_back(evaluations[p]);
      fit_error.push_back(errors[p]);
    }
  }
  if (table.floor.first) table.floor.first = ladder[*table.floor.first];
  table.floor.flags = std::move(row_flags);
  table.fit = in_series([&] { return fit_power_law(fit_n, fit_error, options.confidence); });
  if (table.has_envelope()) {
    std::vector<double> judged_error, allowed;
    for (const convergence_row& row : table.rows) {
      if (row.floor) continue;
      const double error = row.stats.rmse;
      const auto n = static_cast<double>(row.stats.evaluations);
      judged_error.push_back(error);
      const double w = row.stats.absolute_weight_sum;
      allowed.push_back(
          row.envelope +
          rounding_level(n, scale * (std::isnan(w) ? 1.0 : std::max(1.0, w)), options.floor));
      const double ratio =
          row.envelope > 0.0 ? error / row.envelope : std::numeric_limits<double>::infinity();
      table.envelope_ratio =
          std::isnan(table.envelope_ratio) ? ratio : std::max(table.envelope_ratio, ratio);
    }
    table.verdict = judge_envelope(judged_error, allowed);
  } else {
    table.verdict = judge_slope(table.fit, table.theory.slope, options.verdict_tolerance);
  }
  table.work_precision =
      in_series([&] { return work_precision(seconds, errors, options.error_targets); });
  return table;
}

}  // namespace quadmc
