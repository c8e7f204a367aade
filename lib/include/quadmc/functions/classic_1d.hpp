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
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>
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

// A closed form's value with a bound on its absolute rounding error.
struct bounded_value {
  double value;
  double error;
};

// Refuses an interval whose closed form cannot be trusted to 12 digits: error > 1e-12·scale,
// scale = (upper − lower)·max|f| ≥ ∫|f| ≥ |∫f|, the size of the sum Σ|w·f| whose rounding every
// rule's estimate carries anyway (so a tiny integral of a large f, sin over a whole period, is
// judged by absolute error, as the results are). An absolute floor of 8 subnormal spacings
// (8·2^−1074) in every bound makes an integral that underflows a refusal, not an exact 0.
inline void require_accurate_closed_form(const bounded_value& v, double scale, double lo, double hi,
                                         std::string_view integral) {
  const double floor = 8.0 * std::numeric_limits<double>::denorm_min();
  require(v.error + floor <= 1e-12 * scale, "upper", hi,
          fmt::format("an interval [lower = {}, upper] on which the closed form {} = {} is "
                      "accurate to 1e-12 of (upper − lower)·max|f| = {} (its rounding error is up "
                      "to {}: the integral underflows or cancels below what double carries)",
                      quote(lo), integral, v.value, scale, v.error + floor));
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
    const double m = std::max(std::abs(lo_), std::abs(hi_));
    detail::require_accurate_closed_form(integral(lo_, hi_), (hi_ - lo_) * std::pow(m, 5), lo_, hi_,
                                         "(upper⁶ − lower⁶)/6");
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double x2 = x[i] * x[i];
      y[i] = x2 * x2 * x[i];
    }
  }
  // (upper⁶ − lower⁶)/6 without cancellation: x⁵ is odd, so over [lo, hi] with lo < 0 < hi it is
  // ±∫ over [min(|lo|, hi), max(|lo|, hi)]; on 0 ≤ a ≤ b, b⁶ − a⁶ = (b − a)·Σ_{k≤5} b^(5−k)·a^k has
  // six terms of one sign, so the only cancellation is b − a, which rounds once (exact by Sterbenz
  // when a ≥ b/2). About 12 roundings of relative u each: error ≤ 16u·|value|.
  static detail::bounded_value integral(double lo, double hi) {
    double sign = 1.0;
    double a = lo;
    double b = hi;
    if (hi <= 0.0) {  // [lo, hi] ⊂ (−∞, 0]: ∫ x⁵ = −∫ over [|hi|, |lo|]
      sign = -1.0;
      a = -hi;
      b = -lo;
    } else if (lo < 0.0) {
      a = std::min(-lo, hi);
      b = std::max(-lo, hi);
      sign = hi >= -lo ? 1.0 : -1.0;
    }
    double sum = 0.0;  // Σ_{k≤5} b^(5−k)·a^k
    for (int k = 0; k <= 5; ++k) sum += std::pow(b, 5 - k) * std::pow(a, k);
    const double value = sign * (b - a) * sum / 6.0;
    return {value, 16.0 * std::numeric_limits<double>::epsilon() * std::abs(value)};
  }

  integrand_info info() const {
    auto info =
        detail::info_1d("poly", "x⁵", lo_, hi_, integral(lo_, hi_).value, smoothness::analytic);
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
    detail::require_accurate_closed_form(integral(lo_, hi_), (hi_ - lo_) * std::exp(hi_), lo_, hi_,
                                         "e^upper − e^lower");
  }

  // e^hi − e^lo without cancellation: for d = hi − lo < 1, e^lo·expm1(d) (d rounds once, exactly
  // when lo and hi are within a factor 2 (Sterbenz); expm1 is accurate to an ulp for every d);
  // for d ≥ 1, e^hi·(1 − e^−d) loses at most the factor 1/(1 − e^−1) ≈ 1.6 to the subtraction.
  // Error ≤ 8u·|value|, plus e^lo's own loss when it is subnormal (the absolute floor of
  // require_accurate_closed_form).
  static detail::bounded_value integral(double lo, double hi) {
    const double d = hi - lo;
    const double value = d < 1.0 ? std::exp(lo) * std::expm1(d) : std::exp(hi) - std::exp(lo);
    return {value, 8.0 * std::numeric_limits<double>::epsilon() * std::abs(value)};
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::exp(x[i]);
  }
  integrand_info info() const {
    auto info =
        detail::info_1d("exp", "eˣ", lo_, hi_, integral(lo_, hi_).value, smoothness::analytic);
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
    detail::require_accurate_closed_form(integral(lo_, hi_),
                                         (hi_ - lo_) * detail::max_abs_sin(lo_, hi_), lo_, hi_,
                                         "cos lower − cos upper");
  }

  // cos lo − cos hi, by whichever of two forms is the more accurate: the difference itself (two
  // cosines of exact arguments, error ≤ 4u absolute), or 2·sin(m)·sin(d/2) with d = hi − lo and
  // m = lo + d/2 (no cancellation; m rounds by up to u·|m|, which moves the value by at most
  // u·|m|·d, so error ≤ u·(|m|·d + 4|value|)). On a narrow interval the second is exact to a few
  // ulps where the first keeps only the digits of d: [0.3, 0.3 + 1e-10] lost 6 of them.
  static detail::bounded_value integral(double lo, double hi) {
    const double u = std::numeric_limits<double>::epsilon();
    const double d = hi - lo;
    const double m = lo + 0.5 * d;
    const double product = 2.0 * std::sin(m) * std::sin(0.5 * d);
    const double product_error = u * (std::abs(m) * d + 4.0 * std::abs(product));
    if (std::isfinite(product) && product_error < 4.0 * u) return {product, product_error};
    return {std::cos(lo) - std::cos(hi), 4.0 * u};
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::sin(x[i]);
  }
  integrand_info info() const {
    auto info =
        detail::info_1d("sin", "sin x", lo_, hi_, integral(lo_, hi_).value, smoothness::analytic);
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
