// Statistics of one cell of a convergence study: R repetitions of one (integrand, s, method, N)
// measured against the integrand's reference value I.
//
// Use it to turn the repetitions of a cell into the numbers a convergence table shows
// (docs/design.md#data-flow: estimates are analysed into a convergence table). Not for one
// estimator's own error bar: that is the estimator's std_error σ̂/√N, computed from its samples,
// not from repetitions.
//
// With errors e_r = v_r − I:
//   rmse              √(Σe_r²/R): the error measure every slope of the suite is fitted to
//                     (docs/theory.md#conventions: slopes are of RMSE or |error|); R = 1 gives |e|.
//   mean_abs_error    Σ|e_r|/R.
//   std_error_of_rmse delta method ([Casella & Berger, §5.5.4]): with
//                     MSE = mean of e_r² and se(MSE) = sd(e_r²)/√R, d√m/dm = 1/(2√m) gives
//                     se(RMSE) ≈ se(MSE)/(2·RMSE). NaN ("not estimated", an empty CSV field) for
//                     R = 1: one repetition has no spread to measure. A deterministic rule runs
//                     once per N (docs/design.md#skip-what-a-scene-does-not-need), so its |error|
//                     is exact and this field stays empty rather than claiming a measured 0. 0 when
//                     every e_r = 0.
//   coverage_95       fraction of r with |e_r| ≤ z·std_error_r, z = Φ⁻¹(0.975) ≈ 1.96
//                     (normal_quantile_975(), core/normal_quantile.hpp): how often
//                     the CLT interval F ± 1.96 σ̂/√N (docs/theory.md#confidence-intervals) holds
//                     I. ≈ 0.95 for a method whose std_error is honest. NaN when any repetition has
//                     no std_error (NaN): deterministic rules, methods without a variance estimate.
//   seconds           total over the R repetitions; evals_per_second = Σevaluations / Σseconds
//                     (NaN when the clock read 0).
//   error_estimate    √(Σ ê_r²/R) of the repetitions' own error estimates ê_r, comparable with
//                     rmse; NaN when any repetition has none.
//   estimate_covers   fraction of r with |e_r| ≤ ê_r (and estimate_covers_3x: ≤ 3·ê_r): how often
//                     the method's own claim held. An honest 1σ claim (Monte Carlo's σ̂/√N, VEGAS's
//                     σ̂) covers ≈ 68% at 1× and ≈ 99.7% at 3×; a deterministic bound (a-priori,
//                     an embedded rule's difference) should cover every cell. NaN when any
//                     repetition has no estimate.
//   chi2_per_dof, q_value  means over the repetitions of VEGAS's χ²/dof of its combined iterations
//                     and of its Q = P(χ²_{K−1} ≥ χ²) (≈ 1 and ≈ 0.5 when the iterations agree
//                     within their σ̂); NaN when any repetition has none.
//   replicate_std_error  s_R/√R, s_R the standard deviation of the R values (divisor R − 1): the
//                     standard error of estimate_mean, whose 95% interval is
//                     estimate_mean ± t(0.975, R − 1)·replicate_std_error; NaN for R = 1.
//   *_discrepancy     √(Σ D_r²/R) of the repetitions' point-set discrepancies
//                     (sampling/discrepancy.hpp), over the repetitions that measured them (an
//                     ensemble measures its first instance's: the others' points are more
//                     randomizations of the same set); NaN when none did.
//
// Error bars from replicates (error_bars::replicates: randomized quasi-Monte Carlo, whose single
// run cannot estimate its own error, docs/theory.md#replicate-error-bars): the R repetitions are
// R independent randomizations, so
//   error_estimate    is s_R, the replicates' own estimate of the error of one of them (for an
//                     unbiased method E[s_R²] = MSE): comparable with rmse, as for Monte Carlo;
//   coverage_95       is the fraction of r with |e_r| ≤ t(0.975, R − 2)·s_(−r), s_(−r) the standard
//                     deviation of the other R − 1 values: when the replicate errors are normal,
//                     (v_r − I)/s_(−r) has Student's t law with R − 2 degrees of freedom exactly
//                     (v_r is independent of the others), so ≈ 0.95 means the replicate error
//                     bars can be trusted, and a lower value means heavier tails than the t
//                     interval assumes; NaN for R < 3.
// All sums are compensated (Neumaier); the spread of e_r² uses Welford's update.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace quadmc {

// What one repetition of a cell produced. The runner fills it from an estimate (std_error =
// estimate::std_error) or a rule_result (std_error = NaN: a rule has no sampling error).
struct repetition_result {
  double value = 0.0;
  double std_error = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t evaluations = 0;
  double seconds = 0.0;
  // The method's own estimate of |value − I| (Monte Carlo: its std_error; Romberg: the last
  // extrapolants' difference; an adaptive method: what it stopped on); NaN when it has none.
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
  // Σ|w_i| of the rule that ran (unit-cube weights, Σw = 1), where it has weights of both signs
  // (a sparse grid); NaN otherwise (positive weights, or a Monte Carlo estimate: Σ|w| = 1). It
  // scales the rounding floor (rounding_floor.hpp): an error δ in every f moves the sum by up to
  // Σ|w|·δ (rules/weighted_point_set.hpp).
  double absolute_weight_sum = std::numeric_limits<double>::quiet_NaN();
  // An iterative Monte Carlo method's consistency of its iterations (VEGAS: χ²/dof and its Q);
  // NaN when it has none.
  double chi2_per_dof = std::numeric_limits<double>::quiet_NaN();
  double q_value = std::numeric_limits<double>::quiet_NaN();
  // The L2 discrepancies of the repetition's point set (quasi-Monte Carlo methods, small N);
  // NaN when not computed.
  double l2_star_discrepancy = std::numeric_limits<double>::quiet_NaN();
  double centered_discrepancy = std::numeric_limits<double>::quiet_NaN();
  double wraparound_discrepancy = std::numeric_limits<double>::quiet_NaN();
  // A cell run to a tolerance: the absolute error the method was asked to reach (a relative
  // tolerance times the instance's |I|). It reached it when its own error_estimate, what it
  // stopped on, is at or below it; above it (or none), it stopped on its evaluation budget or
  // level cap instead. NaN for a sized cell.
  double target = std::numeric_limits<double>::quiet_NaN();
};

// Where a cell's error bars come from: each repetition's own std_error and error_estimate, or
// the spread of the repetitions (independent replicates of a randomized point set).
enum class error_bars { own, replicates };

struct cell_statistics {
  std::size_t repetitions = 0;
  // Evaluations of one repetition (mean over repetitions, rounded: rejection warps may differ);
  // the N of docs/theory.md#conventions (N = evaluations) that slopes are fitted against.
  std::uint64_t evaluations = 0;
  std::uint64_t total_evaluations = 0;
  double estimate_mean = 0.0;
  double rmse = 0.0;
  double mean_abs_error = 0.0;
  double std_error_of_rmse = std::numeric_limits<double>::quiet_NaN();
  double coverage_95 = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;
  double evals_per_second = std::numeric_limits<double>::quiet_NaN();
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
  // A cell run to a tolerance: the fraction of its repetitions whose own error estimate reached
  // the target (repetition_result::target); below 1, the method ran out of budget first. NaN
  // for a sized cell.
  double reached = std::numeric_limits<double>::quiet_NaN();
  // The largest Σ|w| of the repetitions (NaN when none reports one).
  double absolute_weight_sum = std::numeric_limits<double>::quiet_NaN();
  double estimate_covers = std::numeric_limits<double>::quiet_NaN();
  double estimate_covers_3x = std::numeric_limits<double>::quiet_NaN();
  double chi2_per_dof = std::numeric_limits<double>::quiet_NaN();
  double q_value = std::numeric_limits<double>::quiet_NaN();
  double replicate_std_error = std::numeric_limits<double>::quiet_NaN();
  double l2_star_discrepancy = std::numeric_limits<double>::quiet_NaN();
  double centered_discrepancy = std::numeric_limits<double>::quiet_NaN();
  double wraparound_discrepancy = std::numeric_limits<double>::quiet_NaN();

  // Wall time of one estimate (seconds / repetitions): what a user waits for one answer.
  double seconds_per_repetition() const noexcept {
    return seconds / static_cast<double>(repetitions);
  }
};

// Throws invalid_argument for no repetitions, a non-finite reference or value, a negative or
// non-finite time, a negative std_error, error_estimate or target, targets on some repetitions
// only, a negative χ²/dof or a Q outside [0, 1]
// (NaN is allowed for each of these and means "none").
cell_statistics compute_cell_statistics(std::span<const repetition_result> repetitions,
                                        double reference, error_bars bars = error_bars::own);

}  // namespace quadmc
