// Verdict of a convergence series: its fitted slope against the theoretical one (agrees, steeper,
// shallower), or, for a deterministic rule on a jump, its errors against their a-priori envelope
// (within_envelope, above_envelope).
//
// Use it for the verdict column of slopes.csv and README.md. Not for comparing two runs with each
// other (report/compare.hpp does that with both intervals).
//
// Slope rule: agrees when |slope − theory| ≤ band, band = max(CI half-width, r·|theory|), r = 0.1.
// The first term is "theory ∈ 95% CI" (the interval is symmetric). The second is a floor on the
// band for ladders so clean that the CI is far narrower than the known pre-asymptotic bias of a
// finite ladder (constants, log factors such as the (log N)^s of QMC, the non-monotone error of a
// jump across a curved or oblique surface): a fit within 10% of the theoretical exponent is read
// as agreement. Otherwise "steeper" when the slope is more negative
// (faster than theory), "shallower" when less negative (slower).
//
// Envelope rule: a rule's error on a jump depends on where the jump falls in its cell, not
// monotonically on n, so theory bounds it (rules/jump_error_envelope.hpp) instead of predicting a
// slope: the ladder of a jump whose position has a run of ones in binary can stay flat over
// several doublings and fit "shallower" with every point under the bound. within_envelope when
// every judged point's error is ≤ its envelope; above_envelope when one is not, which no
// discretisation can explain: a wrong weight, node or reference (a bug). The fitted slope, its
// interval and the theory slope are still reported beside it.
//
// Verdicts that name a computed reason (analysis/convergence_table.hpp decides them; the reason
// itself is in the table's verdict_reason, docs/theory.md#verdict):
//   superconvergent  a leading term of the rule's Euler–Maclaurin expansion vanishes on this f
//                    (or every one does: exponential convergence), the theory column holds the
//                    order of the first term that does not, and the measured points agree with
//                    the predicted ones (rules/euler_maclaurin.hpp);
//   pre_asymptotic   the predicted curve agrees with the measured points, its local slope
//                    approaches the asymptotic one only from some N on, and the slope fitted
//                    from there agrees (or the ladder ends before it): the whole-ladder slope
//                    measured the regime before the leading term takes over; or the proven
//                    bound has a log factor (theoretical_rate::log_power) and the slope agrees
//                    with the bound's local slope over the fitted range, or lies between it
//                    and the bound's rate; or an adaptive Monte
//                    Carlo method's slope agrees with that of the error estimates it reported
//                    (theoretical_rate::adaptive: its variance changed while it adapted);
//   at_floor         the ladder reached its rounding floor (the precision f is evaluated in and
//                    the method's accumulator: rounding_floor.hpp) before three points could be
//                    fitted.
// agrees, steeper and shallower keep their meaning; steeper and shallower remain only where no
// computed reason explains the slope: findings.
#pragma once

#include "quadmc/analysis/power_law_fit.hpp"

#include <optional>
#include <span>
#include <string_view>

namespace quadmc {

enum class slope_verdict {
  agrees,
  steeper,
  shallower,
  no_theory,
  no_fit,
  within_envelope,
  above_envelope,
  superconvergent,
  pre_asymptotic,
  at_floor
};

const char* to_string(slope_verdict verdict) noexcept;
// Inverse of to_string; throws invalid_argument for another string.
slope_verdict parse_slope_verdict(std::string_view text);

// The band above; NaN when the fit failed or there is no theory.
double verdict_band(const power_law_fit& fit, std::optional<double> theory,
                    double relative_tolerance = 0.1);

slope_verdict judge_slope(const power_law_fit& fit, std::optional<double> theory,
                          double relative_tolerance = 0.1);

// within_envelope when errors[k] ≤ envelopes[k] for every k, above_envelope otherwise; no_fit
// when there is no point to judge. The caller chooses the points (the non-floor ones) and puts
// any rounding allowance into the envelopes. Throws invalid_argument when the sizes differ, an
// error is negative or not finite, or an envelope is NaN or negative.
slope_verdict judge_envelope(std::span<const double> errors, std::span<const double> envelopes);

}  // namespace quadmc
