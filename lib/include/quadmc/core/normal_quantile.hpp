// The standard normal quantile Φ⁻¹, and the one value of it the suite uses for every 95% interval:
// z = Φ⁻¹(0.975), the factor of the two-sided CLT interval F ± z·σ̂/√N
// (docs/theory.md#confidence-intervals).
//
// Use normal_quantile_975() wherever a 95% interval or its coverage is computed
// (estimators/confidence_interval.hpp, analysis/cell_statistics.hpp), so that the two can never
// disagree on z, and normal_quantile(p) for other levels. Not for intervals of fitted slopes:
// those use Student's t (analysis/power_law_fit.hpp).
#pragma once

#include "quadmc/core/errors.hpp"

#include <boost/math/distributions/normal.hpp>

namespace quadmc {

// Φ⁻¹(p) by Boost.Math's normal quantile; throws invalid_argument unless 0 < p < 1.
inline double normal_quantile(double p) {
  require(p > 0.0 && p < 1.0, "p", p, "0 < p < 1");
  return boost::math::quantile(boost::math::normal_distribution<double>(0.0, 1.0), p);
}

// Φ⁻¹(0.975) rounded to the nearest double: a constant, so a hot loop or a constexpr context can
// use it. tests/core/normal_quantile_test.cpp checks that it is bit for bit normal_quantile(0.975).
constexpr double normal_quantile_975() noexcept {
  return 1.959963984540054;
}

}  // namespace quadmc
