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
  convergence_table table;
  table.integrand = series.integrand;
  table.s = series.s;
  table.method = series.method;
  table.smoothness = series.smoothness;
  table.reference = series.reference;
  // Validates smoothness and s before any work.
  table.theory =
      theoretical_slope(series.method_name.empty() ? series.method : series.method_name,
                        series.smoothness, series.s, series.order, series.singularity_exponent);

  std::vector<const convergence_cell*> cells;
  for (const convergence_cell& cell : series.cells) cells.push_back(&cell);
  std::stable_sort(
      cells.begin(), cells.end(),
      [](const convergence_cell* a, const convergence_cell* b) { return a->n < b->n; });

  for (const convergence_cell* cell : cells) {
    const std::string where = fmt::format("cell N = {} of {} / s = {} / {}", cell->n,
                                          series.integrand, series.s, series.method);
    require(table.rows.empty() || cell->n != table.rows.back().n, "N", cell->n,
            "distinct N in a series (" + where + ")");
    require(std::isnan(cell->error_envelope) || cell->error_envelope >= 0.0, "error_envelope",
            cell->error_envelope, "a bound >= 0 on |error|, or NaN for none (" + where + ")");
    require(std::isnan(cell->error_envelope) == std::isnan(series.cells.front().error_envelope),
            "error_envelope", cell->error_envelope,
            "an envelope on every cell of the series or on none (" + where + ")");
    convergence_row row;
    row.n = cell->n;
    row.per_axis = cell->per_axis;
    row.envelope = cell->error_envelope;
    try {
      row.stats = compute_cell_statistics(cell->repetitions, series.reference);
    } catch (const invalid_argument& e) {
      throw invalid_argument(fmt::format("{}: {}", where, e.what()));
    }
    require(table.rows.empty() || row.stats.evaluations > table.rows.back().stats.evaluations,
            "evaluations", row.stats.evaluations,
            "more evaluations than the previous N of the ladder (" + where + ")");
    table.rows.push_back(row);
  }

  std::vector<double> evaluations, errors, seconds;
  double largest_error = 0.0;
  for (const convergence_row& row : table.rows) {
    evaluations.push_back(static_cast<double>(row.stats.evaluations));
    errors.push_back(row.stats.rmse);
    seconds.push_back(row.stats.seconds_per_repetition());
    largest_error = std::max(largest_error, row.stats.rmse);
  }
  const double scale = series.reference != 0.0 ? std::abs(series.reference) : largest_error;
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
      in_series([&] { return detect_rounding_floor(evaluations, errors, scale, options.floor); });

  std::vector<double> fit_n, fit_error;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    table.rows[k].floor = table.floor.flags[k];
    if (!table.rows[k].floor) {
      fit_n.push_back(evaluations[k]);
      fit_error.push_back(errors[k]);
    }
  }
  table.fit = in_series([&] { return fit_power_law(fit_n, fit_error, options.confidence); });
  if (table.has_envelope()) {
    std::vector<double> judged_error, allowed;
    for (std::size_t k = 0; k < table.rows.size(); ++k) {
      const convergence_row& row = table.rows[k];
      if (row.floor) continue;
      judged_error.push_back(errors[k]);
      allowed.push_back(row.envelope + rounding_level(evaluations[k], scale, options.floor));
      const double ratio =
          row.envelope > 0.0 ? errors[k] / row.envelope : std::numeric_limits<double>::infinity();
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
