// Verdict of a fitted slope against the theoretical one: agrees, steeper or shallower.
//
// Use it for the verdict column of slopes.csv and README.md. Not for comparing two runs with each
// other (report/compare.hpp does that with both intervals).
//
// Rule: agrees when |slope − theory| ≤ band, band = max(CI half-width, r·|theory|), r = 0.1.
// The first term is "theory ∈ 95% CI" (the interval is symmetric). The second is a floor on the
// band for ladders so clean that the CI is far narrower than the known pre-asymptotic bias of a
// finite ladder (constants, log factors such as the (log N)^s of QMC, a jump's non-monotone error):
// a fit within 10% of the theoretical exponent is read as agreement. Otherwise "steeper" when the
// slope is more negative (faster than theory), "shallower" when less negative (slower).
#pragma once

#include "quadmc/analysis/power_law_fit.hpp"

#include <optional>
#include <string_view>

namespace quadmc {

enum class slope_verdict { agrees, steeper, shallower, no_theory, no_fit };

const char* to_string(slope_verdict verdict) noexcept;
// Inverse of to_string; throws invalid_argument for another string.
slope_verdict parse_slope_verdict(std::string_view text);

// The band above; NaN when the fit failed or there is no theory.
double verdict_band(const power_law_fit& fit, std::optional<double> theory,
                    double relative_tolerance = 0.1);

slope_verdict judge_slope(const power_law_fit& fit, std::optional<double> theory,
                          double relative_tolerance = 0.1);

}  // namespace quadmc
