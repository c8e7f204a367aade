// Test-only: checks an integrand's separable_factors against the integrand itself. For factor j
// the other coordinates sit at `base` (where every other factor is known), so f along axis j is
// g_j times a constant: the listed jumps must be jumps of f of that size with f(c) between the
// limits, no other jump may hide between them (on a grid of 20001 points, f moves by at most
// M₁·Δx + rounding between neighbours that do not straddle a listed jump), and the factors'
// integrals must multiply to the exact integral.
#pragma once

#include "quadmc/functions/integrand.hpp"
#include "reference_quadrature.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace quadmc::test {

// `scale_at_base[j]` = Π_{i≠j} g_i(base_i), the constant f carries along axis j.
template <class F>
void expect_factors_describe(const F& f, const std::vector<double>& base,
                             const std::vector<double>& scale_at_base) {
  const integrand_info info = f.info();
  const std::size_t s = info.dimension();
  ASSERT_EQ(info.separable_factors.size(), s) << info.name;
  double product = 1.0;
  for (std::size_t j = 0; j < s; ++j) {
    const piecewise_smooth_factor& g = info.separable_factors[j];
    const double a = info.domain.lower[j], b = info.domain.upper[j];
    auto along = [&](double t) {
      std::vector<double> x = base;
      x[j] = t;
      return at(f, std::span<const double>(x)) / scale_at_base[j];
    };
    // δ = 1e-9: far above the rounding of the switch point, far below any feature of g.
    constexpr double delta = 1e-9;
    for (const jump_discontinuity& jump : g.jumps) {
      const double c = jump.location;
      ASSERT_TRUE(c >= a && c <= b) << info.name << " jump at " << c;
      const double left = c > a ? along(c - delta) : along(c);
      const double right = c < b ? along(c + delta) : along(c);
      const double at_c = along(c);
      // An end-point jump: the value at the end against the limit from inside.
      const double size = c == a   ? std::abs(at_c - right)
                          : c == b ? std::abs(at_c - left)
                                   : std::abs(right - left);
      // The limits move by at most M₁·δ over δ.
      const double slack = g.derivative_bound[1].value_or(0.0) * delta + 1e-12;
      EXPECT_NEAR(size, jump.size, slack) << info.name << " axis " << j << " jump at " << c;
      EXPECT_GE(at_c, std::min(left, right) - slack) << info.name << " f(c) between the limits";
      EXPECT_LE(at_c, std::max(left, right) + slack) << info.name << " f(c) between the limits";
    }
    ASSERT_TRUE(g.derivative_bound[1].has_value()) << info.name;
    const std::size_t points = 20001;
    const double dx = (b - a) / static_cast<double>(points - 1);
    double previous = along(a);
    for (std::size_t i = 1; i < points; ++i) {
      const double x0 = a + dx * static_cast<double>(i - 1), x1 = a + dx * static_cast<double>(i);
      const double value = along(x1);
      const bool straddles = std::any_of(g.jumps.begin(), g.jumps.end(), [&](const auto& jump) {
        return jump.location >= x0 && jump.location <= x1;
      });
      if (!straddles) {
        EXPECT_LE(std::abs(value - previous), *g.derivative_bound[1] * dx * (1 + 1e-9) + 1e-12)
            << info.name << " axis " << j << ": an unlisted jump in [" << x0 << ", " << x1 << "]";
      }
      EXPECT_LE(std::abs(value), *g.derivative_bound[0] * (1 + 1e-12)) << info.name << " M0";
      previous = value;
    }
    product *= g.integral;
  }
  EXPECT_NEAR(product, info.exact, 4 * std::numeric_limits<double>::epsilon() * info.exact)
      << info.name << ": the factors' integrals multiply to ∫f";
}

}  // namespace quadmc::test
