// Romberg integration: Richardson extrapolation of the trapezoid rule on 1, 2, 4, …, 2^k panels.
//
// Use it for smooth (C^∞ or at least C^{2k+2}) 1D integrands when an error estimate is wanted
// along with the value: the trapezoid error has an expansion in even powers of h
// (Euler–Maclaurin), and each column of the table R(k, j) = R(k, j−1) + (R(k, j−1) −
// R(k−1, j−1))/(4^j − 1) removes one more term (Burden & Faires, "Numerical Analysis", §4.5;
// Stoer & Bulirsch, "Introduction to Numerical Analysis", §3.4). Each level evaluates only the
// 2^(k−1) new midpoints, like Boost.Math's trapezoidal (boost/math/quadrature/trapezoidal.hpp).
// Not for integrands with kinks, jumps or end-point singularities (the expansion does not exist
// and extrapolation can make things worse), and not for smooth periodic integrands over a period
// (the plain trapezoid rule already converges exponentially; extrapolation only adds rounding).
//
// Error estimate: |R(k, k) − R(k−1, k−1)|, the change of the last diagonal entry. On smooth f the
// previous entry's error dominates, so this over-estimates |R(k, k) − I|. It is floored at the
// rounding level 8ε·L1 (L1 = trapezoid value of ∫|f|): the sums are compensated, each f value is
// taken to be good to ~1 ulp, and the extrapolation weights amplify rounding by at most
// Π_j (4^j + 1)/(4^j − 1) < 2, so below that floor the difference of two entries measures noise.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/rule_result.hpp"
#include "quadmc/rules/tensor_product.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

namespace quadmc {

struct romberg_options {
  // Stop when error_estimate ≤ relative_tolerance · L1 (L1 = ∫|f|, so an integral near zero does
  // not demand impossible relative accuracy). 0 runs all max_levels levels.
  double relative_tolerance = 1e-12;
  // Or stop when error_estimate ≤ absolute_tolerance (whichever is reached first, as cubature's
  // reqAbsError and reqRelError); 0 disables it.
  double absolute_tolerance = 0.0;
  // Levels (halvings) before the stopping test may fire: an integrand that happens to vanish at
  // the first few nodes would otherwise stop at 0 (the first 2^4 + 1 = 17 nodes must all lie).
  unsigned min_levels = 4;
  // At most 2^max_levels + 1 evaluations.
  unsigned max_levels = 24;
};

// The value is R(k, k) for the last level k reached; converged says whether the tolerance was met
// (false = the budget max_levels ran out first: check it, the value is the best available).
struct romberg_result : rule_result {
  unsigned levels = 0;
  bool converged = false;
};

// 2^40 + 1 evaluations is days of a cheap integrand on 2 cores: no sensible run asks for more.
inline constexpr unsigned romberg_max_levels = 40;

namespace detail {

// Runs the table; evaluate(x, y) fills y[i] = f(x[i]) for a batch and checks finiteness.
template <class Evaluate>
romberg_result romberg_table(Evaluate&& evaluate, double a, double b,
                             const romberg_options& options) {
  require(std::isfinite(options.relative_tolerance) && options.relative_tolerance >= 0.0,
          "relative_tolerance", options.relative_tolerance, "a finite number ≥ 0");
  require(std::isfinite(options.absolute_tolerance) && options.absolute_tolerance >= 0.0,
          "absolute_tolerance", options.absolute_tolerance, "a finite number ≥ 0");
  require(options.max_levels >= 1 && options.max_levels <= romberg_max_levels, "max_levels",
          options.max_levels, "between 1 and 40 (2^max_levels + 1 evaluations)");
  require(options.min_levels <= options.max_levels, "min_levels", options.min_levels,
          fmt::format("≤ max_levels = {}", options.max_levels));
  const double width = b - a;
  constexpr double eps = std::numeric_limits<double>::epsilon();

  std::vector<double> x(batch_points);  // once per call, not per level or point
  std::vector<double> y(batch_points);
  x[0] = a;
  x[1] = b;
  evaluate(std::span<const double>(x.data(), 2), std::span<double>(y.data(), 2));
  // T_k = (b − a)/2^k · ((f(a) + f(b))/2 + Σ interior f): the interior sum is carried, not T_k
  // itself, so the halving T_k = T_{k−1}/2 + h Σ new adds no rounding of its own.
  const double ends = 0.5 * (y[0] + y[1]);
  const double ends_abs = 0.5 * (std::abs(y[0]) + std::abs(y[1]));
  neumaier_sum interior;
  neumaier_sum interior_abs;

  std::array<double, romberg_max_levels + 1> previous{};
  std::array<double, romberg_max_levels + 1> current{};
  previous[0] = width * ends;

  romberg_result result;
  result.value = previous[0];
  result.evaluations = 2;
  for (unsigned k = 1; k <= options.max_levels; ++k) {
    // New nodes a + (b − a)(2i + 1)/2^k, i < 2^(k−1); (2i + 1)/2^k is exact in binary.
    const std::uint64_t fresh = std::uint64_t{1} << (k - 1);
    const double scale = std::ldexp(1.0, -static_cast<int>(k));
    for (std::uint64_t i = 0; i < fresh;) {
      const std::size_t count =
          static_cast<std::size_t>(std::min<std::uint64_t>(batch_points, fresh - i));
      for (std::size_t t = 0; t < count; ++t) {
        x[t] = a + width * (static_cast<double>(2 * (i + t) + 1) * scale);
      }
      const std::span<double> ys(y.data(), count);
      evaluate(std::span<const double>(x.data(), count), ys);
      // Every value goes through the compensated sum: Romberg runs at most ~2^24 points and
      // its accuracy target is near ε, where a per-batch plain or pairwise sum would show.
      for (double v : ys) {
        interior.add(v);
        interior_abs.add(std::abs(v));
      }
      i += count;
    }
    result.evaluations += fresh;
    const double h = width * scale;
    current[0] = h * (ends + interior.value());
    double factor = 1.0;
    for (unsigned j = 1; j <= k; ++j) {
      factor *= 4.0;
      current[j] = current[j - 1] + (current[j - 1] - previous[j - 1]) / (factor - 1.0);
    }
    const double l1 = h * (ends_abs + interior_abs.value());
    const double rounding_floor = 8.0 * eps * l1;
    result.value = current[k];
    result.error_estimate = std::max(std::abs(current[k] - previous[k - 1]), rounding_floor);
    result.levels = k;
    result.converged = result.error_estimate <=
                       std::max(options.relative_tolerance * l1, options.absolute_tolerance);
    if (k >= options.min_levels && result.converged) break;
    previous = current;
  }
  return result;
}

}  // namespace detail

// Romberg on a 1D batch integrand over f.info().domain. Throws invalid_argument for a domain or
// options out of range, non_finite_value if f returns NaN/±inf (naming the point).
template <integrand F>
romberg_result romberg(const F& f, const romberg_options& options = {}) {
  const integrand_info info = f.info();
  require(f.dimension() == 1, "integrand dimension s", f.dimension(),
          "1 (Romberg is a 1D rule; use integrate() with a tensor product for s > 1)");
  require(info.domain.dimension() == 1, "integrand domain dimension", info.domain.dimension(), "1");
  require_integration_box(info.domain);
  auto evaluate = [&](std::span<const double> x, std::span<double> y) {
    f.evaluate(x, y);
    check_finite_batch(info.name, x, y, 1);
  };
  return detail::romberg_table(evaluate, info.domain.lower[0], info.domain.upper[0], options);
}

// Romberg on a plain callable double(double) over [a, b].
template <class G>
requires std::is_invocable_r_v<double, const G&, double> romberg_result
romberg(const G& g, double a, double b, const romberg_options& options = {}) {
  require_finite(a, "a");
  require_finite(b, "b");
  require(a <= b, "b", b,
          fmt::format("≥ a = {} (swap the bounds for a reversed interval)", quote(a)));
  return romberg(detail::interval_function<G>(g, a, b), options);
}

}  // namespace quadmc
