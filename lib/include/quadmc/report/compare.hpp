// Compares two results folders (A = baseline, B = candidate): slopes side by side, the error
// ratio at equal N and the time-to-error ratio, and an outcome for `quadmc compare`, which gates
// CI on it (exit 0 no regression, 1 regression, 3 incomparable).
//
// Use it on folders written by write_results_folder (it reads only convergence.csv and slopes.csv,
// so folders from older versions with fewer added columns compare fine). Not a timing benchmark:
// time ratios come from the convergence runs' wall clocks and vary with machine load; only slopes
// decide the regression flag.
//
// Regression rule: for a series (integrand, s, method) fitted in both, B regresses when its slope
// is shallower than A's by more than
//     allowed = max(tolerance, √(h_A² + h_B²)),
// h = half-width of the 95% CI. The root-sum-square is the half-width of the difference of two
// independent estimates (normal approximation), so two runs of the same method differing only in
// noise pass; `tolerance` (default 0.1) is the smallest slope loss worth failing a build over on
// clean deterministic ladders whose CIs are ~0. A series whose verdict in B is an envelope
// verdict (slope_verdict.hpp: a rule on a jump) is judged by it instead: above_envelope in B is a
// regression (an error no discretisation explains), and with within_envelope a moved slope is
// reported, not failed (a jump ladder's slope is not a rate).
//
// Incomparable: a gate that passes because there was nothing to compare is a silent pass, so the
// pair is incomparable (not "no regression") when a series of A is missing from B, when a series
// fitted in A has no fit in B (a NaN slope, too few points, every cell skipped), or when no
// series is fitted on both sides (a header-only CSV, another scene). A series only in B, or not
// fitted in A, is new and fine. A regression outranks incomparability in the outcome; the
// reason names both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace quadmc {

struct slope_comparison {
  std::string integrand;
  std::size_t s = 0;
  std::string method;
  std::optional<double> slope_a, slope_b;  // empty: missing or not fitted on that side
  double half_width_a = 0.0, half_width_b = 0.0;
  std::optional<double> theory;
  double allowed = 0.0;  // max(tolerance, √(h_A² + h_B²))
  bool regression = false;
  std::string status;  // "ok", "steeper in B", "regression", "missing in A", "missing in B",
                       // "no fit in A", "no fit in B", "above envelope in B",
                       // "slope moved, within envelope in B"
};

struct error_comparison {
  std::string integrand;
  std::size_t s = 0;
  std::string method;
  std::uint64_t n = 0;
  double rmse_a = 0.0, rmse_b = 0.0;
  double ratio = 0.0;  // rmse_b / rmse_a (NaN when rmse_a = 0)
};

struct time_comparison {
  std::string integrand;
  std::size_t s = 0;
  std::string method;
  double target = 0.0;
  std::optional<double> seconds_a, seconds_b;  // empty: not reached
  std::optional<double> ratio;                 // seconds_b / seconds_a when both reached
};

enum class compare_outcome {
  no_regression,  // every series of A fitted in B, none shallower beyond the allowance
  regression,     // at least one series regressed
  incomparable,   // no regression, but B lacks series or fits of A, or nothing was compared
};

struct compare_result {
  std::filesystem::path a, b;
  double tolerance = 0.1;
  std::vector<slope_comparison> slopes;
  std::vector<error_comparison> errors;
  std::vector<time_comparison> times;
  bool regression = false;
  std::size_t regressions = 0;
  std::size_t missing_in_b = 0;  // series of A that B does not have
  std::size_t lost_fits = 0;     // series fitted in A, present in B without a fit
  std::size_t compared = 0;      // series fitted on both sides: the ones the rule judged
  compare_outcome outcome = compare_outcome::incomparable;
  // One line saying why the outcome is not no_regression (counts, and the first series of each
  // kind); empty for no_regression.
  std::string reason;
};

// Reads a/{convergence,slopes}.csv and b/{…}; throws invalid_argument when a file is missing or
// malformed (naming file and column) or tolerance is not finite and >= 0.
compare_result compare_results(const std::filesystem::path& a, const std::filesystem::path& b,
                               double tolerance = 0.1);

// Markdown: a verdict line (with the reason), the slope table, per-series error ratios (geometric
// mean and worst) and time-to-error ratios.
std::string render_compare_markdown(const compare_result& result);

}  // namespace quadmc
