// The periodizing variable transforms of a lattice rule (docs/theory.md#lattice-periodizations):
// φ maps [0, 1] onto itself, increasing, with φ(0) = 0, φ(1) = 1, and ∫f = ∫f(φ(x))∏φ'(x_j)dx,
// so the rule averages g(x) = f(φ(x))∏φ'(x_j) instead of f. φ' vanishes to order m at 0 and 1,
// which makes g periodic with its first m − 1 derivatives for any smooth f: a randomly shifted
// lattice then gains m orders over f itself ([Sidi 1993]; [Laurie 1996]; [Sloan & Joe 1994]).
// The names are QMCPy's `periodization_transform` options ([QMCPy]):
//
//   c0     φ = 3x² − 2x³                            φ' = 6x(1 − x)                  m = 1
//   c1     φ = x³(10 − 15x + 6x²)                   φ' = 30x²(1 − x)²               m = 2
//   c1sin  φ = x − sin(2πx)/(2π)          (Sidi)    φ' = 1 − cos(2πx) = 2sin²(πx)   m = 2
//   c2sin  φ = (8 − 9cos(πx) + cos(3πx))/16         φ' = (3π/4)sin³(πx)             m = 3
//   c3sin  φ = (12πx − 8sin(2πx) + sin(4πx))/(12π)  φ' = (8/3)sin⁴(πx)              m = 4
//
// Use them only through a weighted estimator (estimators/periodized_monte_carlo.hpp): unlike the
// baker's map (sampling/rank1_lattice_points.hpp) they do not preserve the uniform measure, so the
// points φ(x) with equal weights would integrate the wrong function. Not for high s without
// care: ∏φ' has variance (∫φ'²)^s − 1 on f = 1 (docs/theory.md#lattice-periodizations).
//
// Accuracy: every φ is odd about (1/2, 1/2), φ(1 − u) = 1 − φ(u), and φ' even, so each is
// evaluated at u = min(x, 1 − x) ≤ 1/2 (1 − x is exact there, Sterbenz) and reflected. On
// [0, 1/2] the forms below keep φ and φ' to a few ulps *relative*, down to the smallest u: the sin
// forms as products of sines (no 1 − cos cancellation), and x − sin(2πx)/(2π) and c3sin's φ,
// which cancel to O(x³) and O(x⁵), by their Taylor series for small arguments. So φ(x) > 0 for
// every x ≥ 2^−53 — a shifted lattice's coordinates are multiples of 2^−53 (core/rng.hpp's
// uniforms) — and an integrand singular at 0 is never evaluated at 0 unless x is (the unshifted
// lattice's origin). Above 1/2, φ = 1 − φ(u) is clamped to largest_below_one,
// as the points' [0, 1) contract requires.
#pragma once

#include "quadmc/sampling/point_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <numbers>
#include <span>
#include <string_view>

namespace quadmc {

// φ(x) and φ'(x) at one coordinate.
struct periodized_coordinate {
  double value = 0.0;     // φ(x) ∈ [0, 1)
  double jacobian = 0.0;  // φ'(x) ≥ 0
};

// A transform: its name (the `periodization` value), the order m to which φ' vanishes at 0 and
// 1, and φ, φ' on [0, 1/2] (`on_half`), from which periodize() makes the rest by symmetry.
template <class T>
concept periodizing_transform = requires(double u) {
  { T::name } -> std::convertible_to<std::string_view>;
  { T::jacobian_zero_order } -> std::convertible_to<int>;
  { T::on_half(u) } -> std::same_as<periodized_coordinate>;
};

namespace detail {

// Σ_k c_k z^k by Horner's rule, highest term first.
template <std::size_t K>
constexpr double horner(const std::array<double, K>& c, double z) noexcept {
  double sum = 0.0;
  for (std::size_t k = K; k-- > 0;) sum = sum * z + c[k];
  return sum;
}

constexpr double factorial(int n) noexcept {
  double f = 1.0;
  for (int i = 2; i <= n; ++i) f *= i;
  return f;
}

// (t − sin t)/t³ = Σ_{k≥0} (−1)^k t^(2k)/(2k + 3)!, in z = t²: for t < 1 the tenth term is below
// 2^−53 of the first, relative.
constexpr std::array<double, 9> t_minus_sin_series = [] {
  std::array<double, 9> c{};
  for (int k = 0; k < 9; ++k) c[k] = (k % 2 == 0 ? 1.0 : -1.0) / factorial(2 * k + 3);
  return c;
}();

// (6b − 8 sin b + sin 2b)/b⁵ = Σ_{k≥2} (−1)^k (2^(2k+1) − 8) b^(2k−4)/(2k + 1)!: the terms in b
// and b³ cancel exactly. In z = b²; for b < 3/2 the term after k = 14 is below 2^−53 of the
// first, relative.
constexpr std::array<double, 13> c3sin_series = [] {
  std::array<double, 13> c{};
  for (int k = 2; k < 15; ++k) {
    double power = 1.0;
    for (int i = 0; i < 2 * k + 1; ++i) power *= 2.0;
    c[k - 2] = (k % 2 == 0 ? 1.0 : -1.0) * (power - 8.0) / factorial(2 * k + 1);
  }
  return c;
}();

}  // namespace detail

// φ(x), φ'(x) for x ∈ [0, 1): on_half at u = min(x, 1 − x), reflected above 1/2.
template <periodizing_transform T>
inline periodized_coordinate periodize(double x) noexcept {
  if (x <= 0.5) return T::on_half(x);
  const periodized_coordinate half = T::on_half(1.0 - x);  // 1 − x exact for x ∈ [1/2, 1]
  return {std::min(1.0 - half.value, largest_below_one), half.jacobian};
}

// The points of one batch (row-major, s per point) replaced by φ(x), and weight[i] = ∏_j φ'(x_ij)
// of point i, in coordinate order (so the product's rounding is a function of the point alone).
template <periodizing_transform T>
inline void periodize_points(std::span<double> x, std::size_t s,
                             std::span<double> weight) noexcept {
  for (std::size_t i = 0; i < weight.size(); ++i) {
    double w = 1.0;
    for (std::size_t j = 0; j < s; ++j) {
      const periodized_coordinate c = periodize<T>(x[i * s + j]);
      x[i * s + j] = c.value;
      w *= c.jacobian;
    }
    weight[i] = w;
  }
}

// c0: the cubic smoothstep; g continuous and periodic, g' not (m = 1).
struct c0_transform {
  static constexpr std::string_view name = "c0";
  static constexpr int jacobian_zero_order = 1;
  static periodized_coordinate on_half(double u) noexcept {
    return {u * u * (3.0 - 2.0 * u), 6.0 * u * (1.0 - u)};
  }
};

// c1: the quintic smoothstep; g periodic with g' (m = 2).
struct c1_transform {
  static constexpr std::string_view name = "c1";
  static constexpr int jacobian_zero_order = 2;
  static periodized_coordinate on_half(double u) noexcept {
    const double v = 1.0 - u;
    return {u * u * u * (10.0 + u * (6.0 * u - 15.0)), 30.0 * (u * v) * (u * v)};
  }
};

// Sidi's sin² transform ([Sidi 1993]): φ' = 1 − cos(2πx) = 2sin²(πx) (m = 2).
struct c1sin_transform {
  static constexpr std::string_view name = "c1sin";
  static constexpr int jacobian_zero_order = 2;
  static periodized_coordinate on_half(double u) noexcept {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    const double t = two_pi * u;
    // t − sin t loses ≈ log2(6/t²) bits to cancellation: its series below t = 1, where the
    // direct form loses under 3 bits.
    const double phi = t < 1.0
                           ? t * t * t * detail::horner(detail::t_minus_sin_series, t * t) / two_pi
                           : u - std::sin(t) / two_pi;
    const double sine = std::sin(std::numbers::pi * u);
    return {phi, 2.0 * sine * sine};
  }
};

// Sidi's sin³ transform, with a = πx: 8 − 9cos a + cos 3a = 4(1 − cos a)²(2 + cos a) =
// 16sin⁴(a/2)(2 + cos a) and 9sin a − 3sin 3a = 12sin³a (cos 3a = 4cos³a − 3cos a, sin 3a =
// 3sin a − 4sin³a), so φ = sin⁴(πx/2)(2 + cos πx) and φ' = (3π/4)sin³(πx) (m = 3), both
// without cancellation.
struct c2sin_transform {
  static constexpr std::string_view name = "c2sin";
  static constexpr int jacobian_zero_order = 3;
  static periodized_coordinate on_half(double u) noexcept {
    constexpr double pi = std::numbers::pi;
    const double half = std::sin(0.5 * pi * u);
    const double sine = std::sin(pi * u);
    return {(half * half) * (half * half) * (2.0 + std::cos(pi * u)),
            0.75 * pi * sine * sine * sine};
  }
};

// Sidi's sin⁴ transform: φ' = (3 − 4cos b + cos 2b)/3 = (2/3)(1 − cos b)² = (8/3)sin⁴(πx) with
// b = 2πx (m = 4); φ = (6b − 8 sin b + sin 2b)/(12π) cancels to b⁵/(60π): its series below
// b = 3/2, where the direct form loses about 4 bits.
struct c3sin_transform {
  static constexpr std::string_view name = "c3sin";
  static constexpr int jacobian_zero_order = 4;
  static periodized_coordinate on_half(double u) noexcept {
    constexpr double twelve_pi = 12.0 * std::numbers::pi;
    const double b = 2.0 * std::numbers::pi * u;
    const double b2 = b * b;
    const double phi = b < 1.5 ? b2 * b2 * b * detail::horner(detail::c3sin_series, b2) / twelve_pi
                               : (6.0 * b - 8.0 * std::sin(b) + std::sin(2.0 * b)) / twelve_pi;
    const double sine = std::sin(std::numbers::pi * u);
    return {phi, (8.0 / 3.0) * (sine * sine) * (sine * sine)};
  }
};

}  // namespace quadmc
