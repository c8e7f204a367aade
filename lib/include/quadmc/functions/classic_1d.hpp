// The classic one-dimensional test integrands of numerical-analysis textbooks
// ([Burden & Faires, §4.3–4.4]; [Davis & Rabinowitz]), each with its exact integral and the exact
// maxima M_k = max|f⁽ᵏ⁾| on its interval that the Newton–Cotes error terms need (midpoint/trapezoid
// use M₂, Simpson M₄; docs/theory.md#newton-cotes-errors).
//
//   catalogue name      f(x)              interval      smoothness     ∫
//   poly                x⁵                [lo, hi]      analytic       (hi⁶ − lo⁶)/6
//   exp                 eˣ                [lo, hi]      analytic       e^hi − e^lo
//   sin                 sin x             [lo, hi]      analytic       cos lo − cos hi
//   inverse_quadratic   1/(1 + x²)        [0, 1]        analytic       π/4
//   sqrt                √x                [0, 1]        singular       2/3   (f' unbounded at 0)
//   abs_kink            |x − c|           [0, 1]        C⁰             (c² + (1 − c)²)/2
//   step                1 if x ≥ c else 0 [0, 1]        discontinuous  1 − c
//
// Use them to reproduce the 1D rates of docs/theory.md#tensor-rules (O(h²) midpoint, O(h⁴) Simpson,
// O(n^−1.5) for √x, O(n^−1) for a jump). x⁵ is the lowest monomial Simpson does not integrate
// exactly. Not for multi-dimensional studies (dimension() is 1). Derivative bounds are exact
// maxima; a bound is absent where the derivative is unbounded or undefined (√x from k = 1; the kink
// and the step beyond the order they are smooth on either side of c, where f' or f'' is a Dirac).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/endpoint_derivatives.hpp"
#include "quadmc/functions/integrand.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

namespace detail {

// Finite bounds with a finite width: rules and samplers place points at lower + (upper − lower)·t,
// which is NaN when the width overflows (lower = −1e308, upper = 1e308).
inline void validate_interval(double lo, double hi) {
  require_finite(lo, "lower");
  require_finite(hi, "upper");
  require(lo < hi, "upper", hi, fmt::format("upper > lower = {}", lo));
  require(std::isfinite(hi - lo), "upper", hi,
          fmt::format("a finite width upper − lower (lower = {}: too far apart for double)", lo));
}

inline integrand_info info_1d(std::string name, std::string formula, double lo, double hi,
                              double exact, smoothness regularity) {
  return integrand_info{.name = std::move(name),
                        .formula = std::move(formula),
                        .domain = box{{lo}, {hi}},
                        .exact = exact,
                        .reference = "closed form",
                        .regularity = regularity};
}

// max |sin x| over [lo, hi]: 1 if the interval holds a point π/2 + kπ, else the larger end value
// (|sin| is monotone between its extrema).
inline double max_abs_sin(double lo, double hi) {
  const double k = std::ceil((lo - std::numbers::pi / 2) / std::numbers::pi);
  if (std::numbers::pi / 2 + k * std::numbers::pi <= hi) return 1.0;
  return std::max(std::abs(std::sin(lo)), std::abs(std::sin(hi)));
}

}  // namespace detail

class poly_1d {
 public:
  // Largest |lower|, |upper|: the closed form needs x⁶ finite, |x| ≤ DBL_MAX^(1/6) ≈ 5.6e51.
  static constexpr double max_abs_bound = 1e51;

  explicit poly_1d(double lower = 0.0, double upper = 1.0) : lo_(lower), hi_(upper) {
    detail::validate_interval(lo_, hi_);
    require(std::abs(lo_) <= max_abs_bound, "lower", lo_,
            "|lower| ≤ 1e51 (the integral (upper⁶ − lower⁶)/6 must stay finite)");
    require(std::abs(hi_) <= max_abs_bound, "upper", hi_,
            "|upper| ≤ 1e51 (the integral (upper⁶ − lower⁶)/6 must stay finite)");
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double x2 = x[i] * x[i];
      y[i] = x2 * x2 * x[i];
    }
  }
  integrand_info info() const {
    auto info = detail::info_1d("poly", "x⁵", lo_, hi_, (std::pow(hi_, 6) - std::pow(lo_, 6)) / 6.0,
                                smoothness::analytic);
    // f⁽ᵏ⁾ = 5!/(5−k)!·x^(5−k): |·| is largest where |x| is.
    const double m = std::max(std::abs(lo_), std::abs(hi_));
    const double falling[5] = {1.0, 5.0, 20.0, 60.0, 120.0};
    for (int k = 0; k <= 4; ++k) info.derivative_bound[k] = falling[k] * std::pow(m, 5 - k);
    const auto derivative = [](double x) {
      return [x](std::size_t k) {
        double d = 1.0;
        for (std::size_t j = 0; j < k; ++j) d *= static_cast<double>(5 - j);  // 0 from k = 6
        return k > 5 ? 0.0 : d * std::pow(x, static_cast<double>(5 - k));
      };
    };
    info.endpoint_derivatives = endpoint::product_of(
        1.0, {endpoint::factor_of(derivative(lo_), derivative(hi_), lo_, hi_, info.exact)});
    return info;
  }

 private:
  double lo_, hi_;
};

class exp_1d {
 public:
  // Largest upper bound: e^upper, f's largest value and the integral's leading term, stays finite
  // up to ln(DBL_MAX) ≈ 709.78.
  static constexpr double max_upper = 709.78;

  explicit exp_1d(double lower = 0.0, double upper = 1.0) : lo_(lower), hi_(upper) {
    detail::validate_interval(lo_, hi_);
    require(hi_ <= max_upper, "upper", hi_,
            "upper ≤ 709.78 (e^upper must stay finite: ln of the largest double)");
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::exp(x[i]);
  }
  integrand_info info() const {
    auto info =
        detail::info_1d("exp", "eˣ", lo_, hi_, std::exp(hi_) - std::exp(lo_), smoothness::analytic);
    for (int k = 0; k <= 4; ++k) info.derivative_bound[k] = std::exp(hi_);
    info.endpoint_derivatives =
        endpoint::product_of(1.0, {endpoint::exponential(1.0, lo_, hi_, info.exact)});
    return info;
  }

 private:
  double lo_, hi_;
};

class sin_1d {
 public:
  explicit sin_1d(double lower = 0.0, double upper = std::numbers::pi) : lo_(lower), hi_(upper) {
    detail::validate_interval(lo_, hi_);
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::sin(x[i]);
  }
  integrand_info info() const {
    auto info = detail::info_1d("sin", "sin x", lo_, hi_, std::cos(lo_) - std::cos(hi_),
                                smoothness::analytic);
    // Even derivatives are ±sin, odd ones ±cos = ±sin(· + π/2).
    const double ms = detail::max_abs_sin(lo_, hi_);
    const double mc = detail::max_abs_sin(lo_ + std::numbers::pi / 2, hi_ + std::numbers::pi / 2);
    for (int k = 0; k <= 4; ++k) info.derivative_bound[k] = k % 2 == 0 ? ms : mc;
    // sin⁽ᵏ⁾(x) = sin(x + kπ/2), taken from the four values sin, cos, −sin, −cos (no rounding
    // of kπ/2 into the argument).
    const auto derivative = [](double x) {
      return [s = std::sin(x), c = std::cos(x)](std::size_t k) {
        const double cycle[4] = {s, c, -s, -c};
        return cycle[k % 4];
      };
    };
    info.endpoint_derivatives = endpoint::product_of(
        1.0, {endpoint::factor_of(derivative(lo_), derivative(hi_), lo_, hi_, info.exact)});
    return info;
  }

 private:
  double lo_, hi_;
};

class inverse_quadratic_1d {
 public:
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = 1.0 / (1.0 + x[i] * x[i]);
  }
  integrand_info info() const {
    auto info = detail::info_1d("inverse_quadratic", "1/(1 + x²)", 0.0, 1.0, std::numbers::pi / 4,
                                smoothness::analytic);
    // f' = −2x/(1+x²)², extreme at x = 1/√3: 3√3/8.  f'' = (6x² − 2)/(1+x²)³: |·| max 2 at 0.
    // f''' = 24x(1 − x²)/(1+x²)⁴, extreme where 5x⁴ − 10x² + 1 = 0, x² = 1 − 2/√5.
    // f'''' = 24(5x⁴ − 10x² + 1)/(1+x²)⁵: |·| max 24 at 0 (at x = 1 it is 3).
    const double t2 = 1.0 - 2.0 / std::sqrt(5.0);
    const double t = std::sqrt(t2);
    info.derivative_bound = {1.0, 3.0 * std::sqrt(3.0) / 8.0, 2.0,
                             24.0 * t * (1.0 - t2) / std::pow(1.0 + t2, 4), 24.0};
    info.endpoint_derivatives = endpoint_data();
    return info;
  }
  // 1/(1 + x²) on [0, 1]: odd derivatives vanish at 0 (f is even) and f⁽⁴ᵐ⁺³⁾(1) = 0, so Simpson's
  // h⁴ term vanishes (rules/euler_maclaurin.hpp); shared with the float twin.
  // Its poles ±i sit above the end x = 0 at distance 1: the coarse-grid term of
  // docs/theory.md#coarse-grid-term.
  static std::optional<separable_derivatives> endpoint_data() {
    auto factor =
        endpoint::factor_of([](std::size_t k) { return endpoint::inverse_quadratic(k, 0.0); },
                            [](std::size_t k) { return endpoint::inverse_quadratic(k, 1.0); }, 0.0,
                            1.0, std::numbers::pi / 4);
    if (factor) factor->poles = endpoint::inverse_quadratic_poles(1.0, 0.0);
    return endpoint::product_of(1.0, {std::move(factor)});
  }
};

class sqrt_1d {
 public:
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::sqrt(x[i]);
  }
  integrand_info info() const {
    auto info = detail::info_1d("sqrt", "√x", 0.0, 1.0, 2.0 / 3.0, smoothness::singular);
    info.derivative_bound[0] = 1.0;  // f' = 1/(2√x) is unbounded at 0
    info.singularity_exponent = 0.5;
    return info;
  }
};

class abs_kink_1d {
 public:
  explicit abs_kink_1d(double c = 0.3) : c_(c) {
    require(c >= 0.0 && c <= 1.0, "c", c, "the kink c in [0, 1]");
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::abs(x[i] - c_);
  }
  integrand_info info() const {
    auto info = detail::info_1d("abs_kink", "|x − c|", 0.0, 1.0,
                                (c_ * c_ + (1.0 - c_) * (1.0 - c_)) / 2.0, smoothness::c0);
    info.derivative_bound[0] = std::max(c_, 1.0 - c_);
    info.derivative_bound[1] = 1.0;  // |f'| = 1 on both sides; f'' is a Dirac at c
    // c − x left of c, x − c right of it: f' jumps by 2 at an interior c.
    const auto side = [this](double x, bool right) {
      return [x, right, this](std::size_t k) {
        const double slope = right ? 1.0 : -1.0;
        return k == 0 ? std::abs(x - c_) : (k == 1 ? slope : 0.0);
      };
    };
    std::vector<derivative_jump> kinks;
    if (c_ > 0.0 && c_ < 1.0) {
      derivative_jump kink{c_, std::vector<std::complex<double>>(endpoint_derivative_count)};
      kink.jumps[1] = 2.0;
      kinks.push_back(std::move(kink));
    }
    info.endpoint_derivatives =
        endpoint::product_of(1.0, {endpoint::factor_of(side(0.0, c_ == 0.0), side(1.0, c_ < 1.0),
                                                       0.0, 1.0, info.exact, std::move(kinks))});
    return info;
  }
  double c() const noexcept { return c_; }

 private:
  double c_;
};

class step_1d {
 public:
  explicit step_1d(double c = 0.3) : c_(c) {
    require(c >= 0.0 && c <= 1.0, "c", c, "the jump c in [0, 1]");
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[i] >= c_ ? 1.0 : 0.0;
  }
  integrand_info info() const {
    auto info =
        detail::info_1d("step", "1 if x ≥ c else 0", 0.0, 1.0, 1.0 - c_, smoothness::discontinuous);
    info.derivative_bound[0] = 1.0;
    // Constant on both sides of the jump: M₀ = 1 and M₁…M₄ = 0 on the pieces. f(c) = 1 = f(c+).
    // At c = 0 f ≡ 1 on [0, 1] (no jump at all); at c = 1 only the point value f(1) = 1 differs
    // from the limit 0 from the left, a jump of size 1 at the end point.
    piecewise_smooth_factor factor;
    if (c_ > 0.0) factor.jumps.push_back({c_, 1.0});
    factor.derivative_bound = {1.0, 0.0, 0.0, 0.0, 0.0};
    factor.integral = 1.0 - c_;
    info.separable_factors.push_back(std::move(factor));
    return info;
  }
  double c() const noexcept { return c_; }

 private:
  double c_;
};

}  // namespace quadmc
