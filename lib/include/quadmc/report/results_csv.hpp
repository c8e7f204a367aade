// The two CSV files of a results folder and their fixed column contract.
//
//   convergence.csv  one row per cell (integrand, s, method, N):
//     scene, integrand, s, method, N, evaluations, repetitions, reference, estimate_mean, rmse,
//     mean_abs_error, std_error_of_rmse, coverage_95, seconds, evals_per_second,
//     then added columns: floor, smoothness, envelope, tolerance, error_estimate, estimate_covers,
//     estimate_covers_3x, chi2_per_dof, q_value, replicate_std_error, l2_star_discrepancy,
//     centered_discrepancy, wraparound_discrepancy,
//     predicted_error, prediction_ratio, local_slope, rounding_level, seconds_per_estimate,
//     seconds_spread, timed_estimates
//   slopes.csv  one row per series (integrand, s, method):
//     scene, integrand, s, method, slope, ci_low, ci_high, theory, verdict, points_used,
//     floor_points, then added columns: smoothness, fit_status, attainable_accuracy, theory_note,
//     envelope_ratio, verdict_reason, class_theory, asymptotic_from_n, asymptotic_slope,
//     predicted_points, worst_prediction_ratio, rounding_model
//
// Contract: columns may be added at the end, never renamed or removed (compare reads old folders
// with new code). Missing values (NaN: no std_error, no coverage for a deterministic rule, no
// theory, no fit) are empty fields. `reference` has 17 significant digits (every double round
// trips); other numbers use the shortest text that reads back to the same double. `evaluations`
// is per repetition, `seconds` the total over repetitions (cell_statistics.hpp); `floor` is 1 for
// a rounding-floor point (rounding_floor.hpp). `envelope` is the cell's a-priori bound on |error|
// (a rule on a jump, rules/jump_error_envelope.hpp), empty where there is none; `envelope_ratio`
// the largest error/envelope over the series' non-floor cells, empty for a slope-verdict series.
// `tolerance` is the error a cell was run to (control = "tolerance"; N is then 0), empty for a
// sized cell; `error_estimate` the root mean square of the repetitions' own error estimates
// (cell_statistics.hpp), empty where the method has none; `estimate_covers` (`_3x`) the fraction of
// repetitions whose |error| was at most (3×) their own error estimate, empty where there is none;
// `chi2_per_dof` and `q_value` the means of VEGAS's χ²/dof and Q over the repetitions, empty for
// every other method (for randomized quasi-Monte Carlo `error_estimate` is the standard deviation
// of the replicates); `replicate_std_error` the standard error of
// estimate_mean from the spread of the repetitions (empty for one repetition); the three
// `*_discrepancy` columns the root mean square over the repetitions of the L2-star, centered and
// wrap-around discrepancies of the points (sampling/discrepancy.hpp), computed by the
// quasi-Monte Carlo methods at N ≤ 1024 with N²·s ≤ 2^24 and empty elsewhere. `predicted_error` is
// the |error| a rule's Euler–Maclaurin expansion predicts for the cell
// (analysis/convergence_table.hpp), empty where there is no prediction or the next term moves it by
// more than 1%; `prediction_ratio` the measured/predicted error (signed for a deterministic rule:
// (estimate − I)/(predicted estimate − I)); `local_slope` d log(error)/d log N from the previous
// distinct N; `rounding_level` ℓ(N) of the series' rounding model (analysis/rounding_floor.hpp: the
// evaluation precision and the accumulator). `verdict` is one of slope_verdict.hpp's strings:
// agrees, steeper, shallower, no_theory, no_fit, superconvergent, pre_asymptotic, at_floor (slope
// verdicts) or within_envelope, above_envelope (envelope verdicts); `verdict_reason` says why in
// one line. `theory` is the rate judged against (for a superconvergent series the order of the
// first non-vanishing Euler–Maclaurin term), `class_theory` the method's rate for the smoothness
// class; `asymptotic_from_n` the N from which the predicted local slope stays within 10% of
// `theory` (it may exceed the ladder's last N), `asymptotic_slope` the slope fitted over the points
// from there (empty with fewer than three); `predicted_points` how many cells were judged against
// the prediction and `worst_prediction_ratio` the judged ratio farthest from 1 (empty when none);
// `rounding_model` e.g. "float evaluation, pairwise sum". `seconds_per_estimate` is the stable time
// of one estimate (analysis/cell_timing.hpp: the median over batches of repeated calls of
// repetition 1's work), `seconds_spread` the batches' (max − min)/median (empty when timed once),
// `timed_estimates` the calls timed (1 = timed once: the first call already took at least the
// minimum); `seconds` keeps its meaning, the wall time of the repetitions the statistics come from.
// Work-precision figures use seconds_per_estimate (seconds/repetitions for a file from before it).
//
// Use the readers for compare and tests; they accept added columns and throw naming the file and
// the column when one of the contract's columns is missing.
#pragma once

#include "quadmc/analysis/convergence_table.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

inline constexpr std::array<std::string_view, 15> convergence_csv_columns = {
    "scene",          "integrand",         "s",           "method",        "N",
    "evaluations",    "repetitions",       "reference",   "estimate_mean", "rmse",
    "mean_abs_error", "std_error_of_rmse", "coverage_95", "seconds",       "evals_per_second"};
inline constexpr std::array<std::string_view, 27> convergence_csv_added_columns = {
    "floor",
    "smoothness",
    "envelope",
    "tolerance",
    "error_estimate",
    "estimate_covers",
    "estimate_covers_3x",
    "chi2_per_dof",
    "q_value",
    "replicate_std_error",
    "l2_star_discrepancy",
    "centered_discrepancy",
    "wraparound_discrepancy",
    "predicted_error",
    "prediction_ratio",
    "local_slope",
    "rounding_level",
    "seconds_per_estimate",
    "seconds_spread",
    "timed_estimates",
    "reached",
    "instances",
    "mse_mean",
    "mse_ci95_low",
    "mse_ci95_high",
    "mse_median",
    "mse_worst"};
inline constexpr std::array<std::string_view, 11> slopes_csv_columns = {
    "scene",   "integrand", "s",       "method",      "slope",       "ci_low",
    "ci_high", "theory",    "verdict", "points_used", "floor_points"};
inline constexpr std::array<std::string_view, 12> slopes_csv_added_columns = {
    "smoothness",       "fit_status",       "attainable_accuracy",    "theory_note",
    "envelope_ratio",   "verdict_reason",   "class_theory",           "asymptotic_from_n",
    "asymptotic_slope", "predicted_points", "worst_prediction_ratio", "rounding_model"};

// Text of the two files (header line first).
std::string convergence_csv_text(std::string_view scene, std::span<const convergence_table> tables);
std::string slopes_csv_text(std::string_view scene, std::span<const convergence_table> tables);

// One row of convergence.csv as read back. NaN for empty numeric fields.
struct convergence_record {
  std::string scene;
  std::string integrand;
  std::size_t s = 0;
  std::string method;
  std::uint64_t n = 0;
  std::uint64_t evaluations = 0;
  std::size_t repetitions = 0;
  double reference = 0.0;
  double estimate_mean = 0.0;
  double rmse = 0.0;
  double mean_abs_error = 0.0;
  double std_error_of_rmse = 0.0;
  double coverage_95 = 0.0;
  double seconds = 0.0;
  double evals_per_second = 0.0;
  bool floor = false;  // false when the column is absent (a file from before it was added)
  double envelope = std::numeric_limits<double>::quiet_NaN();        // NaN: empty or column absent
  double tolerance = std::numeric_limits<double>::quiet_NaN();       // NaN: a sized cell, or absent
  double error_estimate = std::numeric_limits<double>::quiet_NaN();  // NaN: none, or absent
  double estimate_covers = std::numeric_limits<double>::quiet_NaN();         // NaN: none, or absent
  double estimate_covers_3x = std::numeric_limits<double>::quiet_NaN();      // NaN: none, or absent
  double chi2_per_dof = std::numeric_limits<double>::quiet_NaN();            // NaN: none, or absent
  double q_value = std::numeric_limits<double>::quiet_NaN();                 // NaN: none, or absent
  double replicate_std_error = std::numeric_limits<double>::quiet_NaN();     // NaN: or absent
  double l2_star_discrepancy = std::numeric_limits<double>::quiet_NaN();     // NaN: or absent
  double centered_discrepancy = std::numeric_limits<double>::quiet_NaN();    // NaN: or absent
  double wraparound_discrepancy = std::numeric_limits<double>::quiet_NaN();  // NaN: or absent
  double predicted_error = std::numeric_limits<double>::quiet_NaN();         // NaN: none, or absent
  double prediction_ratio = std::numeric_limits<double>::quiet_NaN();        // NaN: none, or absent
  double seconds_per_estimate = std::numeric_limits<double>::quiet_NaN();    // NaN: absent
  double seconds_spread = std::numeric_limits<double>::quiet_NaN();  // NaN: timed once, or absent
  std::uint64_t timed_estimates = 0;                                 // 0: absent
  // A tolerance cell: the fraction of repetitions whose own error estimate reached the target
  // (cell_statistics::reached). NaN: a sized cell, or absent.
  double reached = std::numeric_limits<double>::quiet_NaN();

  // Seconds of one estimate: the stable timing where the file has it, else seconds/repetitions.
  double time_per_estimate() const noexcept {
    if (timed_estimates > 0) return seconds_per_estimate;
    return repetitions > 0 ? seconds / static_cast<double>(repetitions) : 0.0;
  }
};

// One row of slopes.csv as read back. NaN for empty numeric fields.
struct slope_record {
  std::string scene;
  std::string integrand;
  std::size_t s = 0;
  std::string method;
  double slope = 0.0;
  double ci_low = 0.0;
  double ci_high = 0.0;
  double theory = 0.0;
  std::string verdict;
  std::size_t points_used = 0;
  std::size_t floor_points = 0;
  double envelope_ratio = std::numeric_limits<double>::quiet_NaN();  // NaN: empty or absent
  std::string verdict_reason;                                        // empty when absent
  double class_theory = std::numeric_limits<double>::quiet_NaN();    // NaN: empty or absent
};

// Throw invalid_argument naming file, line and column for a missing column or unparsable value.
std::vector<convergence_record> read_convergence_csv(const std::filesystem::path& file);
std::vector<slope_record> read_slopes_csv(const std::filesystem::path& file);

}  // namespace quadmc
