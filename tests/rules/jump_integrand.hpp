// Test-only: the step 1{x < c} on [0, 1] with an irrational jump c = fl(1/√2) (never on a node),
// and the fitted convergence slope of a rule on it.
//
// Why the tolerance ±0.1 the tests use: |error|·n is set by the fractional part of n·c (which
// node falls last before the jump); by Weyl it is equidistributed, so log|error| = −log n + a
// term with variance ≈ 1 that is not monotone in n. Over ~150 log-spaced n in [8, 2·10⁴]
// (ln n spans 7.8, sd ≈ 2.25) the OLS slope scatters by ≈ 1/(2.25·√150) ≈ 0.04 around −1, so
// ±0.1 is 2.5 of those; the run is deterministic, so it either always passes or never.
#pragma once

#include "log_log_slope.hpp"
#include "quadmc/rules/tensor_product.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace quadmc::testing {

inline constexpr double jump_at = 1.0 / std::numbers::sqrt2;

// Fits log|error| on log n over the ladder; also checks |error| ≤ max_weight_sum/n, i.e. the
// error is what the few weights around the jump can make it (one panel's worth, times the
// largest weight factor of the rule: 1 for rectangle/midpoint/trapezoid, 4/3·2 for Simpson).
template <class R>
double jump_slope(const R& rule, bool even_n_only, double panels_of_error) {
  const auto f = [](double x) { return x < jump_at ? 1.0 : 0.0; };
  std::vector<double> ns;
  std::vector<double> errors;
  for (double v = 8; v <= 20000; v *= 1.05) {
    auto n = static_cast<std::uint64_t>(v);
    if (even_n_only && n % 2 == 1) ++n;
    if (!ns.empty() && ns.back() == static_cast<double>(n)) continue;
    const double error = integrate(f, 0.0, 1.0, rule, n).value - jump_at;
    EXPECT_LE(std::abs(error), panels_of_error / static_cast<double>(n))
        << rule.name() << " n = " << n;
    ns.push_back(static_cast<double>(n));
    errors.push_back(error);
  }
  return log_log_slope(ns, errors);
}

}  // namespace quadmc::testing
