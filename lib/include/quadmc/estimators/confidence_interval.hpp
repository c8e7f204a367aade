// Confidence intervals for a Monte Carlo estimate (docs/theory.md#confidence-intervals;
// [Ramamoorthi 2009, §2.2.2]).
//
//  - clt_interval: F ± z·σ̂/√N with z = Φ⁻¹((1 + c)/2) (core/normal_quantile.hpp: z =
//    normal_quantile_975() ≈ 1.96 for c = 0.95, the same bits). Asymptotic: its coverage is
//    c only as N → ∞ and only if σ̂ estimates the estimator's standard deviation (not for
//    unjittered points, whose std_error is NaN, giving a NaN interval).
//  - chebyshev_interval: Chebyshev's inequality P(|F − I| ≥ √(V[Y]/(Nδ))) ≤ δ
//    (docs/theory.md#confidence-intervals).
//    Valid for any N when V[Y] is the true variance, and wide: 4.47σ/√N for δ = 0.05 against the
//    CLT's 1.96σ/√N. With the estimated V̂[Y] it is no longer a strict bound.
// Both use the estimate's own std_error (std_error = √(variance/N) for every estimator here).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/normal_quantile.hpp"
#include "quadmc/estimators/estimate.hpp"

#include <cmath>

namespace quadmc {

struct confidence_interval {
  double lower = 0.0;
  double upper = 0.0;
  constexpr bool contains(double x) const noexcept { return lower <= x && x <= upper; }
  constexpr double half_width() const noexcept { return 0.5 * (upper - lower); }
};

inline confidence_interval clt_interval(const estimate& e, double confidence = 0.95) {
  require(confidence > 0.0 && confidence < 1.0, "confidence", confidence, "0 < confidence < 1");
  const double z = normal_quantile(0.5 * (1.0 + confidence));
  return {e.value - z * e.std_error, e.value + z * e.std_error};
}

inline confidence_interval chebyshev_interval(const estimate& e, double delta = 0.05) {
  require(delta > 0.0 && delta < 1.0, "delta", delta, "0 < δ < 1");
  const double half = std::sqrt(e.variance / (static_cast<double>(e.evaluations) * delta));
  return {e.value - half, e.value + half};
}

}  // namespace quadmc
