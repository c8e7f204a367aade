// The convergence table of one (integrand, s, method) series: every cell's statistics, the
// rounding floor, the fitted slope with its interval, the theoretical slope, the verdict and the
// work-precision row. The unit the report layer writes (docs/design.md#data-flow: one
// convergence table per (integrand, method)).
//
// Use analyse_convergence once per series after the runner has all its cells. Not incremental:
// the floor rule and the fit look at the whole ladder.
//
// The error of a cell is its RMSE over repetitions (|error| for one repetition), the x axis its
// evaluations per repetition (docs/theory.md#conventions: N = evaluations). Floor points, flagged
// by rounding_floor.hpp, are excluded from the fit (a zero error is always a floor point, so every
// fitted error is > 0); so are errors below 10 times the uncertainty of a reference that is not
// exact, and the points after them (add_reference_floor). The floor scale is |reference|; when
// the reference is 0 it falls back to the largest RMSE of the ladder, a crude magnitude of f
// (documented in the slopes table). The
// floor's level knows the precision f is evaluated in and the method's accumulator
// (convergence_series::rounding); a cell whose rule reports Σ|w| > 1 (weights of both signs: a
// sparse grid) has its floor scale multiplied by Σ|w|, the factor by which its sum amplifies
// rounding (rounding_floor.hpp).
//
// With an error prediction (error_prediction.hpp: a composite rule's Euler–Maclaurin curve) every
// cell also gets its predicted error where the next term of the expansion moves it by at most
// analysis_options::prediction_validity (1%), and the ratio measured/predicted; cells whose error
// is above prediction_rounding_margin (100) times their rounding level are judged: within
// prediction_tolerance (10%) the prediction is confirmed. A confirmed prediction may explain a
// slope the class theory does not (slope_verdict.hpp: superconvergent, pre_asymptotic): the
// predicted local slope, d log|P|/d log N between n and 2n panels, says from which N the leading
// term carries the curve (within verdict_tolerance of the asymptotic slope), and the slope fitted
// from there is set beside the whole-ladder one. Every verdict carries its reason in words
// (verdict_reason).
#pragma once

#include "quadmc/analysis/cell_statistics.hpp"
#include "quadmc/analysis/cell_timing.hpp"
#include "quadmc/analysis/ensemble_statistics.hpp"
#include "quadmc/analysis/error_prediction.hpp"
#include "quadmc/analysis/power_law_fit.hpp"
#include "quadmc/analysis/rounding_floor.hpp"
#include "quadmc/analysis/slope_verdict.hpp"
#include "quadmc/analysis/theoretical_rate.hpp"
#include "quadmc/analysis/work_precision.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace quadmc {

// Input: one cell of the ladder — the scene's N (or tolerance) and the repetitions run at it.
struct convergence_cell {
  // The N the scene asked for (the plan's ladder value: an exact size, or the budget an adaptive
  // method may spend); 0 for a cell run to a tolerance.
  std::uint64_t n = 0;
  // The error the method was asked to reach (control = "tolerance"); NaN for a sized cell.
  double tolerance = std::numeric_limits<double>::quiet_NaN();
  std::vector<repetition_result> repetitions;
  std::uint64_t per_axis = 0;  // rules: panels n per axis (the plan cell's); 0 otherwise
  // An a-priori bound on |error| of every repetition (for an ensemble, the largest of its
  // instances'): a rule's envelope on a jump (rules/jump_error_envelope.hpp). NaN = none. A series
  // gives it for every cell or for none; with it the verdict is the envelope verdict.
  double error_envelope = std::numeric_limits<double>::quiet_NaN();
  // The stable time of one estimate (cell_timing.hpp); untimed (estimates = 0) in a cell built
  // by hand, whose time per estimate is then its repetitions' mean.
  cell_timing timing;
  // The instances of an ensemble whose repetitions the cell pools, R each, in instance order
  // (ensemble_statistics.hpp); 1 for one integrand.
  std::size_t instances = 1;
};

// Input: one series, as the runner assembles it.
struct convergence_series {
  std::string integrand;
  std::size_t s = 1;
  std::string method;  // display name (the scene's label), e.g. "midpoint_naive"
  smoothness regularity = smoothness::analytic;  // integrand_info::regularity
  double reference = 0.0;                        // integrand_info::exact
  // The reference's absolute uncertainty: 0 for an exact value; for a given or computed one,
  // errors below rounding_floor_options::reference_factor (10) times it are floor points
  // (rounding_floor.hpp, add_reference_floor).
  double reference_uncertainty = 0.0;
  // The method's rate on this integrand (its descriptor chose it, methods/method.hpp).
  theoretical_rate theory;
  std::vector<convergence_cell> cells;
  // Where the cells' error bars come from (cell_statistics.hpp): the repetitions' own, or their
  // spread (randomized quasi-Monte Carlo).
  error_bars errors = error_bars::own;
  // How f's values are rounded and summed: the rounding floor's level (rounding_floor.hpp).
  rounding_model rounding;
  // The method's predicted error per cell (a rule's Euler–Maclaurin curve), or none.
  std::optional<error_prediction> prediction;
  // The cells' tolerances are fractions of |reference| (method_spec::relative_tolerance), so
  // the error a cell was asked for is tolerance·|reference|.
  bool relative_tolerance = false;
};

struct analysis_options {
  double confidence = 0.95;
  double verdict_tolerance = 0.1;  // r of slope_verdict.hpp
  rounding_floor_options floor;
  std::vector<double> error_targets{default_error_targets.begin(), default_error_targets.end()};
  // A prediction is shown (and may be judged) where the next term moves it by at most this.
  double prediction_validity = 0.01;
  // Measured and predicted agree when |measured/predicted − 1| ≤ this.
  double prediction_tolerance = 0.1;
  // A cell is judged against its prediction only where its error exceeds this many times its
  // rounding level (the rounding is then at most 1% of it).
  double prediction_rounding_margin = 100.0;
};

struct convergence_row {
  std::uint64_t n = 0;
  double tolerance = std::numeric_limits<double>::quiet_NaN();  // convergence_cell::tolerance
  cell_statistics stats;
  // Per instance of an ensemble (ensemble_statistics.hpp): computed where the cell pools more
  // than one instance, else the defaults (1 instance, NaN).
  ensemble_statistics ensemble;
  bool floor = false;  // at the rounding floor: excluded from the fit and the envelope verdict
  std::uint64_t per_axis = 0;                                  // convergence_cell::per_axis
  double envelope = std::numeric_limits<double>::quiet_NaN();  // convergence_cell::error_envelope
  // ℓ(N) of the series' rounding model (rounding_floor.hpp) at this cell's evaluations.
  double rounding_level = std::numeric_limits<double>::quiet_NaN();
  // d log(error)/d log N from the previous point of the ladder; NaN at the first point, at a
  // repeated evaluation count and where an error is 0.
  double local_slope = std::numeric_limits<double>::quiet_NaN();
  // |predicted error| where the prediction is valid (analysis_options::prediction_validity);
  // NaN where there is none or the expansion is not yet predictive.
  double predicted_error = std::numeric_limits<double>::quiet_NaN();
  // measured/predicted error, signed for one repetition ((estimate − I)/(predicted estimate − I):
  // negative means opposite signs), rmse/|predicted| for several; NaN without a prediction.
  double prediction_ratio = std::numeric_limits<double>::quiet_NaN();
  bool prediction_judged = false;  // the ratio counts (valid, not a floor point, above rounding)
  cell_timing timing;              // convergence_cell::timing

  // Seconds of one estimate: the stable timing's median where the cell was timed, else the
  // repetitions' mean wall time.
  double seconds_per_estimate() const noexcept {
    return timing.timed() ? timing.seconds_per_estimate : stats.seconds_per_repetition();
  }
};

struct convergence_table {
  std::string integrand;
  std::size_t s = 1;
  std::string method;
  smoothness regularity = smoothness::analytic;
  double reference = 0.0;
  double reference_uncertainty = 0.0;  // convergence_series::reference_uncertainty
  bool relative_tolerance = false;     // convergence_series::relative_tolerance
  // In increasing N, or, for cells run to a tolerance, in decreasing tolerance.
  std::vector<convergence_row> rows;
  rounding_floor floor;
  power_law_fit fit;
  // The rate the verdict is judged against: the method's class rate, or, for a superconvergent
  // series, the order of the first non-vanishing term (then class_theory keeps the former).
  theoretical_rate theory;
  theoretical_rate class_theory;  // the method's rate for f's smoothness class, as given
  slope_verdict verdict = slope_verdict::no_fit;
  std::string verdict_reason;  // why, in one line (slope_verdict.hpp's vocabulary explained)
  rounding_model rounding;
  // With a confirmed prediction: the evaluations from which the predicted local slope stays
  // within verdict_tolerance of the theory slope (beyond the last row when the ladder ends first;
  // nullopt when not found below 2^63), and the slope fitted over the rows from there.
  std::optional<std::uint64_t> asymptotic_from;
  power_law_fit asymptotic_fit;
  // Judged cells of the prediction and the ratio measured/predicted farthest from 1 among them.
  std::size_t predicted_points = 0;
  double worst_prediction_ratio = std::numeric_limits<double>::quiet_NaN();
  // Envelope series: the largest error/envelope over the non-floor rows (≤ 1 within it, up to
  // the rounding allowance); NaN for a slope-verdict series.
  double envelope_ratio = std::numeric_limits<double>::quiet_NaN();
  std::vector<time_to_error> work_precision;

  // The verdict is judged against the error envelope, not the slope.
  bool has_envelope() const noexcept { return !rows.empty() && !std::isnan(rows.front().envelope); }
  std::size_t points_used() const noexcept { return fit.points; }
  std::size_t floor_points() const noexcept { return floor.count(); }
};

// Sorts the cells by N (tolerance cells by decreasing tolerance) and analyses them. Cells must not
// spend fewer evaluations as N grows (or the tolerance tightens); equal counts (a budget not
// spent, two tolerances met at one level) are one computation, so the floor and the fit use each
// count once, at its first row. The verdict: with error envelopes, the envelope verdict
// (slope_verdict.hpp) over the non-floor rows, each judged as error ≤ envelope + ℓ(N), ℓ the
// rounding level of rounding_floor.hpp at the same scale as the floor rule (the envelope is exact
// arithmetic; ℓ covers the sums' rounding when the error attains the envelope); without, the
// slope verdict. Throws invalid_argument for no cells, a cell without repetitions, repeated N or
// tolerance, sized and tolerance cells in one series, evaluations that decrease along the ladder,
// envelopes on some cells but not all, a negative envelope or s = 0 (and whatever
// compute_cell_statistics rejects, naming the cell).
convergence_table analyse_convergence(const convergence_series& series,
                                      const analysis_options& options = {});

}  // namespace quadmc
