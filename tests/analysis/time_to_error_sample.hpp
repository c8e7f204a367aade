// The time-to-error tables of the analysis and report tests: one integrand (genz_x_s2, I = 2) run
// to the relative tolerances 1e-3 and 1e-6 (targets 2e-3 and 2e-6) by genz_malik and
// peer_hcubature, and on an N ladder by plain_mc, each cell with a stable timing of its own.
#pragma once

#include "quadmc/analysis/time_to_error_cells.hpp"
#include "series_builder.hpp"
#include "support/floating_point.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace quadmc::test {

inline constexpr double sample_reference = 2.0;

inline cell_timing timed_at(double seconds) {
  cell_timing t;
  t.seconds_per_estimate = seconds;
  t.spread = 0.1;
  t.estimates = 100;
  return t;
}

// A method run to the relative tolerances 1e-3 and 1e-6: its true error, evaluations (100, then
// 1000) and stable time at each (its own estimate claims the tolerance every time).
inline convergence_table to_tolerance(const std::string& method, double error3, double seconds3,
                                      double error6, double seconds6) {
  convergence_series series = series_of("genz_x_s2", 2, method, smoothness::analytic,
                                        sample_reference, rule_theory(2, smoothness::analytic, 2));
  series.relative_tolerance = true;
  const double tolerances[] = {1e-3, 1e-6};
  const double errors[] = {error3, error6};
  const double seconds[] = {seconds3, seconds6};
  const std::uint64_t evaluations[] = {100, 1000};
  for (int k = 0; k < 2; ++k) {
    repetition_result r =
        repetition(sample_reference + errors[k], test_support::nan, evaluations[k], seconds[k]);
    r.error_estimate = tolerances[k] * sample_reference;
    convergence_cell cell = cell_at(0, {r});
    cell.tolerance = tolerances[k];
    cell.timing = timed_at(seconds[k]);
    series.cells.push_back(cell);
  }
  return analyse_convergence(series);
}

// tables[0] genz_malik: meets 1e-3 (error 1e-3 ≤ 2e-3) in 1e-5 s; misses 1e-6 (1e-5 > 2e-6).
// tables[1] peer_hcubature: meets both, in 2e-5 s and 1e-4 s.
// tables[2] plain_mc: RMSE 1e-2 at N = 64, 1.5e-3 at 256 (≤ 2e-3: reached there, in 3e-5 s),
// 1e-3 at 1024; never 2e-6.
inline std::vector<convergence_table> time_to_error_sample_tables() {
  std::vector<convergence_table> tables;
  tables.push_back(to_tolerance("genz_malik", 1e-3, 1e-5, 1e-5, 4e-5));
  tables.push_back(to_tolerance("peer_hcubature", 5e-4, 2e-5, 1e-6, 1e-4));
  convergence_series mc = series_of("genz_x_s2", 2, "plain_mc", smoothness::analytic,
                                    sample_reference, monte_carlo_theory(smoothness::analytic, 2));
  const std::uint64_t ns[] = {64, 256, 1024};
  const double rmse[] = {1e-2, 1.5e-3, 1e-3};
  const double seconds[] = {1e-6, 3e-5, 9e-5};
  for (int k = 0; k < 3; ++k) {
    // Two repetitions ±e: RMSE e.
    convergence_cell cell =
        cell_at(ns[k], {repetition(sample_reference + rmse[k], rmse[k], ns[k], 1e-9),
                        repetition(sample_reference - rmse[k], rmse[k], ns[k], 1e-9)});
    cell.timing = timed_at(seconds[k]);
    mc.cells.push_back(cell);
  }
  tables.push_back(analyse_convergence(mc));
  return tables;
}

// A pair of the 1e-3 cell (genz_malik against peer_hcubature) with the given rounds.
inline time_to_error_pair sample_pair(std::vector<double> quadmc_seconds,
                                      std::vector<double> peer_seconds) {
  time_to_error_pair p;
  p.family = "genz_x";
  p.integrand = "genz_x_s2";
  p.s = 2;
  p.tolerance = 1e-3;
  p.relative = true;
  p.quadmc_method = "genz_malik";
  p.quadmc_evaluations = 100;
  p.peer_method = "peer_hcubature";
  p.peer_evaluations = 100;
  p.quadmc_seconds = std::move(quadmc_seconds);
  p.peer_seconds = std::move(peer_seconds);
  return p;
}

}  // namespace quadmc::test
