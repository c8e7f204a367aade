// A-priori error bounds of the composite rules, 1D and tensor product, and a grid estimate of
// the derivative bounds M_k = max|f⁽ᵏ⁾| they need.
//
// Use them to draw the "theory" line beside a measured convergence curve, or to choose n for a
// target accuracy when M_k is known. They are worst-case: tight (within a small factor) when f⁽ᵏ⁾
// keeps one sign and varies little, loose when it oscillates. Not a-posteriori estimates (see
// romberg.hpp), and meaningless without a true M_k — max_abs_derivative() only estimates one.
//
// Sources (h = node spacing (b − a)/n, H = panel width):
//   rectangle   |E| ≤ (b − a)h·M₁/2           Burden & Faires, "Numerical Analysis", §4.4
//   midpoint    |E| ≤ (b − a)h²·M₂/24         same, Thm 4.6 (composite midpoint)
//   trapezoid   |E| ≤ (b − a)h²·M₂/12         same, Thm 4.5
//   Simpson     |E| ≤ (b − a)h⁴·M₄/180        same, Thm 4.4 (h = node spacing, n even)
//   Gauss, m    |E| ≤ (b − a)H^{2m}(m!)⁴/((2m + 1)((2m)!)³)·M_{2m}
//                                             Davis & Rabinowitz, "Methods of Numerical
//                                             Integration", 2nd ed., eq. 2.7.12
// Tensor product over Π[a_j, b_j]: I − Q₁⊗⋯⊗Q_s = Σ_j Q₁⊗⋯⊗Q_{j−1}⊗(I_j − Q_j)⊗I_{j+1}⊗⋯⊗I_s.
// With positive weights summing to the interval length (true for every rule here) each Q_i acts
// like I_i on a bound, so |E| ≤ Σ_j E_j(M_{k,j}) · Π_{i≠j}(b_i − a_i), where M_{k,j} =
// max|∂ᵏf/∂x_jᵏ| over the box.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/rectangle_rule.hpp"
#include "quadmc/rules/rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"

#include <fmt/format.h>
#include <boost/math/differentiation/autodiff.hpp>

#include <cmath>
#include <cstdint>
#include <span>

namespace quadmc {

namespace detail {

inline void require_bound_arguments(double a, double b, std::uint64_t n, double derivative_bound,
                                    std::string_view derivative_name) {
  require_finite(a, "a");
  require_finite(b, "b");
  require(a <= b, "b", b, fmt::format("≥ a = {}", quote(a)));
  require(n >= 1, "n", n, "at least 1 panel");
  require(std::isfinite(derivative_bound) && derivative_bound >= 0.0, derivative_name,
          derivative_bound, "a finite bound ≥ 0 on the derivative");
}

}  // namespace detail

// (b − a)h·M₁/2: left or right rectangle rule, f ∈ C¹.
inline double rectangle_error_bound(double a, double b, std::uint64_t n, double m1) {
  detail::require_bound_arguments(a, b, n, m1, "M1");
  const double h = (b - a) / static_cast<double>(n);
  return (b - a) * h * m1 / 2.0;
}

// (b − a)h²·M₂/24: midpoint rule, f ∈ C².
inline double midpoint_error_bound(double a, double b, std::uint64_t n, double m2) {
  detail::require_bound_arguments(a, b, n, m2, "M2");
  const double h = (b - a) / static_cast<double>(n);
  return (b - a) * h * h * m2 / 24.0;
}

// (b − a)h²·M₂/12: trapezoid rule, f ∈ C².
inline double trapezoid_error_bound(double a, double b, std::uint64_t n, double m2) {
  detail::require_bound_arguments(a, b, n, m2, "M2");
  const double h = (b - a) / static_cast<double>(n);
  return (b - a) * h * h * m2 / 12.0;
}

// (b − a)h⁴·M₄/180 with h the node spacing (b − a)/n: Simpson rule, n even, f ∈ C⁴.
inline double simpson_error_bound(double a, double b, std::uint64_t n, double m4) {
  detail::require_bound_arguments(a, b, n, m4, "M4");
  require(n % 2 == 0, "n", n, "an even number of panels (Simpson pairs panels)");
  const double h = (b - a) / static_cast<double>(n);
  return (b - a) * h * h * h * h * m4 / 180.0;
}

// (b − a)H^{2m}(m!)⁴/((2m + 1)((2m)!)³)·M_{2m}: m-point Gauss–Legendre on n panels of width H.
// For m = 1 the constant is 1/24, the midpoint bound. The factorials are exact integers up to
// 22! and stay below 1e246 for m ≤ 30, so the product in double loses only a few ulp.
inline double gauss_legendre_error_bound(double a, double b, std::uint64_t n, unsigned m,
                                         double m2m) {
  detail::require_bound_arguments(a, b, n, m2m, "M_2m");
  require(m >= 1 && m <= gauss_legendre_rule::max_points, "m", m, "between 1 and 30");
  double m_factorial = 1.0;
  for (unsigned i = 2; i <= m; ++i) m_factorial *= i;
  double two_m_factorial = 1.0;
  for (unsigned i = 2; i <= 2 * m; ++i) two_m_factorial *= i;
  const double constant = (m_factorial * m_factorial) * (m_factorial * m_factorial) /
                          ((2.0 * m + 1.0) * two_m_factorial * two_m_factorial * two_m_factorial);
  const double panel = (b - a) / static_cast<double>(n);
  return (b - a) * std::pow(panel, 2.0 * m) * constant * m2m;
}

// The k of the M_k each rule's bound needs, and the bound itself, by rule type: what lets one
// tensor-product bound serve every rule.
inline int bound_derivative_order(const midpoint_rule&) noexcept {
  return 2;
}
inline int bound_derivative_order(const trapezoid_rule&) noexcept {
  return 2;
}
inline int bound_derivative_order(const simpson_rule&) noexcept {
  return 4;
}
template <rectangle_side Side>
int bound_derivative_order(const rectangle_rule<Side>&) noexcept {
  return 1;
}
inline int bound_derivative_order(const gauss_legendre_rule& r) noexcept {
  return 2 * static_cast<int>(r.points());
}

inline double error_bound(const midpoint_rule&, double a, double b, std::uint64_t n, double mk) {
  return midpoint_error_bound(a, b, n, mk);
}
inline double error_bound(const trapezoid_rule&, double a, double b, std::uint64_t n, double mk) {
  return trapezoid_error_bound(a, b, n, mk);
}
inline double error_bound(const simpson_rule&, double a, double b, std::uint64_t n, double mk) {
  return simpson_error_bound(a, b, n, mk);
}
template <rectangle_side Side>
double error_bound(const rectangle_rule<Side>&, double a, double b, std::uint64_t n, double mk) {
  return rectangle_error_bound(a, b, n, mk);
}
inline double error_bound(const gauss_legendre_rule& r, double a, double b, std::uint64_t n,
                          double mk) {
  return gauss_legendre_error_bound(a, b, n, r.points(), mk);
}

// Σ_j E_j(M_{k,j})·Π_{i≠j}(b_i − a_i), n panels per axis, one M_k per axis (k =
// bound_derivative_order(rule)).
template <rule R>
double tensor_product_error_bound(const R& rule, const box& domain, std::uint64_t n,
                                  std::span<const double> derivative_bound_per_axis) {
  const std::size_t s = domain.dimension();
  require(s >= 1, "domain dimension s", s, "at least 1");
  require_integration_box(domain);
  require(derivative_bound_per_axis.size() == s, "derivative bounds per axis",
          derivative_bound_per_axis.size(), fmt::format("one per dimension, {}", s));
  double total = 0.0;
  for (std::size_t j = 0; j < s; ++j) {
    double others = 1.0;
    for (std::size_t i = 0; i < s; ++i) {
      if (i != j) others *= domain.upper[i] - domain.lower[i];
    }
    total += error_bound(rule, domain.lower[j], domain.upper[j], n, derivative_bound_per_axis[j]) *
             others;
  }
  return total;
}

// The same with M_k from the integrand's metadata (integrand_info::derivative_bound, one M_k for
// every axis). Throws invalid_argument if that M_k is not recorded (unknown or unbounded).
template <rule R>
double tensor_product_error_bound(const R& rule, const integrand_info& info, std::uint64_t n) {
  const int k = bound_derivative_order(rule);
  const bool known = k >= 0 && k < static_cast<int>(info.derivative_bound.size()) &&
                     info.derivative_bound[static_cast<std::size_t>(k)].has_value();
  require(known, fmt::format("{}: derivative_bound[{}]", info.name, k), "unknown",
          fmt::format("a known M_{} = max|∂^{}f| for the {} bound", k, k, rule.name()));
  const std::vector<double> per_axis(info.dimension(),
                                     *info.derivative_bound[static_cast<std::size_t>(k)]);
  return tensor_product_error_bound(rule, info.domain, n, per_axis);
}

// max |g⁽ᴷ⁾(x)| over `grid_points` equally spaced x in [a, b], derivatives by forward-mode
// automatic differentiation (Boost.Math autodiff: g is called once per point with a
// make_fvar<double, K> argument, so g must be generic: [](auto x) { return exp(x); }).
// A GRID ESTIMATE, not a rigorous bound: a maximum between grid points is missed, by O(spacing²)
// near a smooth interior maximum. Use the exact M_k where one is known.
template <unsigned K, class G>
double max_abs_derivative(const G& g, double a, double b, std::size_t grid_points = 4097) {
  require_finite(a, "a");
  require_finite(b, "b");
  require(a <= b, "b", b, fmt::format("≥ a = {}", quote(a)));
  require(grid_points >= 2, "grid_points", grid_points, "at least 2 (both end points)");
  double largest = 0.0;
  const double last = static_cast<double>(grid_points - 1);
  for (std::size_t i = 0; i < grid_points; ++i) {
    const double x = a + (b - a) * (static_cast<double>(i) / last);
    const auto value = g(boost::math::differentiation::make_fvar<double, K>(x));
    const double derivative = static_cast<double>(value.derivative(K));
    if (!std::isfinite(derivative)) {
      const double point[1] = {x};
      throw non_finite_value(fmt::format("derivative {} of the function", K), point, derivative);
    }
    largest = std::max(largest, std::abs(derivative));
  }
  return largest;
}

}  // namespace quadmc
