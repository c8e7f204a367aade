// Slope and envelope verdicts; the rules and why are in slope_verdict.hpp.
#include "quadmc/analysis/slope_verdict.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace quadmc {

const char* to_string(slope_verdict verdict) noexcept {
  switch (verdict) {
    case slope_verdict::agrees:
      return "agrees";
    case slope_verdict::steeper:
      return "steeper";
    case slope_verdict::shallower:
      return "shallower";
    case slope_verdict::no_theory:
      return "no_theory";
    case slope_verdict::no_fit:
      return "no_fit";
    case slope_verdict::within_envelope:
      return "within_envelope";
    case slope_verdict::above_envelope:
      return "above_envelope";
    case slope_verdict::superconvergent:
      return "superconvergent";
    case slope_verdict::pre_asymptotic:
      return "pre_asymptotic";
    case slope_verdict::at_floor:
      return "at_floor";
  }
  return "?";
}

slope_verdict parse_slope_verdict(std::string_view text) {
  for (slope_verdict v :
       {slope_verdict::agrees, slope_verdict::steeper, slope_verdict::shallower,
        slope_verdict::no_theory, slope_verdict::no_fit, slope_verdict::within_envelope,
        slope_verdict::above_envelope, slope_verdict::superconvergent,
        slope_verdict::pre_asymptotic, slope_verdict::at_floor}) {
    if (text == to_string(v)) return v;
  }
  throw invalid_argument("verdict", std::string(text),
                         "one of agrees, steeper, shallower, no_theory, no_fit, within_envelope, "
                         "above_envelope, superconvergent, pre_asymptotic, at_floor");
}

double verdict_band(const power_law_fit& fit, std::optional<double> theory,
                    double relative_tolerance) {
  if (!fit.ok() || !theory) return std::numeric_limits<double>::quiet_NaN();
  return std::max(fit.half_width(), relative_tolerance * std::abs(*theory));
}

slope_verdict judge_slope(const power_law_fit& fit, std::optional<double> theory,
                          double relative_tolerance) {
  require(std::isfinite(relative_tolerance) && relative_tolerance >= 0.0, "relative_tolerance",
          relative_tolerance, "finite and >= 0");
  if (!fit.ok()) return slope_verdict::no_fit;
  if (!theory) return slope_verdict::no_theory;
  const double band = verdict_band(fit, theory, relative_tolerance);
  if (std::abs(fit.slope - *theory) <= band) return slope_verdict::agrees;
  return fit.slope < *theory ? slope_verdict::steeper : slope_verdict::shallower;
}

slope_verdict judge_envelope(std::span<const double> errors, std::span<const double> envelopes) {
  require(errors.size() == envelopes.size(), "envelopes.size()", envelopes.size(),
          fmt::format("the size of errors ({})", errors.size()));
  if (errors.empty()) return slope_verdict::no_fit;
  bool within = true;
  for (std::size_t k = 0; k < errors.size(); ++k) {
    require(std::isfinite(errors[k]) && errors[k] >= 0.0, fmt::format("errors[{}]", k), errors[k],
            "finite and >= 0");
    // +inf is a valid (vacuous) bound; NaN is not a bound at all.
    require(envelopes[k] >= 0.0, fmt::format("envelopes[{}]", k), envelopes[k], ">= 0, not NaN");
    within = within && errors[k] <= envelopes[k];
  }
  return within ? slope_verdict::within_envelope : slope_verdict::above_envelope;
}

}  // namespace quadmc
