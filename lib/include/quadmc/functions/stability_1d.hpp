// One-dimensional integrands that stress floating point rather than the rule: shifted and scaled
// domains, catastrophic cancellation written naively and stably, integrable singularities, and
// float twins of two classics. The stress scene (bench/scenes/stress.toml) runs them to show where
// each rule stops converging because of rounding, and why.
//
//   catalogue name           f(x)                                domain         ∫
//   shifted_exp              e^((x − lo)/w)/w,  w = hi − lo      [lo, hi]       e − 1 for any box
//   cosc_naive               (1 − cos x)/x², written as such     [0, 1]         Si(1) − (1 − cos 1)
//   cosc_stable              2·sin²(x/2)/x², the same function   [0, 1]         Si(1) − (1 − cos 1)
//   inverse_sqrt             1/√x  (0 at x = 0)                  [0, 1]         2
//   log                      log x (0 at x = 0)                  [0, 1]         −1
//   exp_float                eˣ, x rounded to float, expf        [lo, hi]       e^hi − e^lo
//   inverse_quadratic_float  1/(1 + x²) in float                 [0, 1]         π/4
//
// Why each one:
//  - shifted_exp is e^t on [0,1] carried to any box and scaled so that ∫ stays e − 1: relative
//    errors on [10⁸, 10⁸ + 1], [0, 10⁻¹⁰⁰], [−10¹⁰⁰, 10¹⁰⁰] compare directly with [0, 1]. A box far
//    from 0 and narrow has a floor the library cannot remove: the nodes a + w·t themselves are
//    rounded to the spacing ulp(a) (1.49e-8 at 10⁸), so t = (x − a)/w is known only to ulp(a)/2w
//    and the relative error of ∫ cannot go below ≈ ulp(a)/(2w)·max|g'|/|∫g| (Higham §1.7: the
//    data, not the algorithm, is perturbed).
//  - cosc_naive loses 1 − cos x to cancellation: for x ≪ 1 its absolute error is ≈ ε, so f has
//    error ≈ ε/x² and a rule whose nodes come within h of 0 adds Σ h·ε/x_k² ≈ ε/h = ε·n: its error
//    curve turns back up like ε·n. cosc_stable uses 1 − cos x = 2 sin²(x/2) (no subtraction) and
//    keeps full relative accuracy (Goldberg, "What every computer scientist should know about
//    floating-point arithmetic", 1991, §1.4 on rewriting to avoid cancellation). f(0) = 1/2, the
//    limit, for both.
//  - inverse_sqrt and log are integrable but unbounded at 0. A rule that samples x = 0
//    (trapezoid, Simpson, left rectangle) would see ∞; f(0) := 0 is the classical "ignoring the
//    singularity" device (Davis & Rabinowitz, "Methods of Numerical Integration", 2nd ed.,
//    §2.12.7), stated in the formula, so every rule runs and shows its reduced rate: midpoint on
//    1/√x converges like n^(−1/2), on log x like log(n)/n.
//  - the float twins evaluate in single precision (ε_f = 2⁻²⁴ ≈ 6e-8) and return the float value
//    as double; the rule then sums in double. The rounding of each value (x to float, then the
//    float function) looks random from node to node, so the rule averages it: the error behaves
//    like ε_f·|I|/√N, far below ε_f·|I|, until N passes the number of floats in the domain
//    (2²³ per binade): from there the same float inputs repeat and the error stalls near
//    ε_f·|I|/√(#floats) ≈ 1e-10 (measured in results/stress/: 4e-11…1e-10 for every rule).
// Not for: rate studies of the rules themselves (classic_1d.hpp has the clean members).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/classic_1d.hpp"
#include "quadmc/functions/endpoint_derivatives.hpp"
#include "quadmc/functions/integrand.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>

namespace quadmc {

namespace detail {

inline integrand_info stability_info(std::string name, std::string formula, double lo, double hi,
                                     double exact, std::string reference, smoothness regularity) {
  return integrand_info{.name = std::move(name),
                        .formula = std::move(formula),
                        .domain = box{{lo}, {hi}},
                        .exact = exact,
                        .reference = std::move(reference),
                        .regularity = regularity};
}

// Si(1) − (1 − cos 1) = ∫₀¹ (1 − cos x)/x² dx (integrate by parts: −(1 − cos x)/x + ∫ sin x/x).
// Si(1) = Σ_k (−1)^k/((2k+1)·(2k+1)!) (A&S 5.2.14); the terms fall below 1e-22 by k = 9, summed
// in long double smallest first, so the value is correctly rounded to double.
inline double cosc_integral() {
  long double term[10];
  long double factorial = 1.0L;  // (2k+1)!
  for (int k = 0; k < 10; ++k) {
    if (k > 0) factorial *= static_cast<long double>((2 * k) * (2 * k + 1));
    term[k] = (k % 2 == 0 ? 1.0L : -1.0L) / (static_cast<long double>(2 * k + 1) * factorial);
  }
  long double si = 0.0L;
  for (int k = 9; k >= 0; --k) si += term[k];
  return static_cast<double>(si - (1.0L - std::cos(1.0L)));
}

inline std::optional<separable_derivatives> cosc_endpoints(double exact) {
  return endpoint::product_of(
      1.0,
      {endpoint::factor_of([](std::size_t k) { return endpoint::cosc(k, 0.0); },
                           [](std::size_t k) { return endpoint::cosc(k, 1.0); }, 0.0, 1.0, exact)});
}

}  // namespace detail

class shifted_exp_1d {
 public:
  shifted_exp_1d(double lower, double upper) : lo_(lower), hi_(upper), width_(upper - lower) {
    require_finite(lo_, "lower");
    require_finite(hi_, "upper");
    require(lo_ < hi_, "upper", hi_, fmt::format("upper > lower = {}", quote(lo_)));
    require(std::isfinite(width_), "upper − lower", width_,
            "a finite width (the bounds are too far apart for double)");
    // f's largest value e/w, at x = upper, must be finite: w ≥ DBL_MIN (a subnormal width also
    // loses the precision of t = (x − lower)/w).
    require(width_ >= std::numeric_limits<double>::min(), "upper − lower", width_,
            "a width of at least 2.2250738585072014e-308 (a normal double: f's largest value is "
            "e/width)");
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::exp((x[i] - lo_) / width_) / width_;
  }
  integrand_info info() const {
    auto info = detail::stability_info("shifted_exp", "e^((x − lower)/w)/w, w = upper − lower", lo_,
                                       hi_, std::expm1(1.0), "closed form: ∫₀¹ eᵗ dt = e − 1",
                                       smoothness::analytic);
    // f⁽ᵏ⁾ = e^t/w^(k+1) ≤ e/w^(k+1); left empty where that overflows (w = 10⁻¹⁰⁰).
    double bound = std::numbers::e / width_;
    for (int k = 0; k <= 4; ++k, bound /= width_) {
      if (std::isfinite(bound)) info.derivative_bound[k] = bound;
    }
    // In the unit variable t every derivative of e^t/w is e^t/w: finite on any box (the
    // x-derivatives e/w^(k+1) overflow on [0, 10⁻¹⁰⁰]), so the data are written in t directly.
    endpoint_factor factor;
    factor.integral = std::expm1(1.0);
    factor.at_lower.assign(endpoint_derivative_count, 1.0 / width_);
    factor.at_upper.assign(endpoint_derivative_count, std::numbers::e / width_);
    info.endpoint_derivatives = separable_derivatives{1.0, {std::move(factor)}};
    return info;
  }

 private:
  double lo_, hi_, width_;
};

class cosc_naive_1d {
 public:
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      y[i] = x[i] == 0.0 ? 0.5 : (1.0 - std::cos(x[i])) / (x[i] * x[i]);
    }
  }
  integrand_info info() const {
    auto info = detail::stability_info(
        "cosc_naive", "(1 − cos x)/x², computed as written (1/2 at 0)", 0.0, 1.0,
        detail::cosc_integral(), "Si(1) − (1 − cos 1), Si by its Taylor series",
        smoothness::analytic);
    // The derivatives of the function it stands for (the rounding of 1 − cos x is in the
    // values, not in f): its Taylor series, which has no cancellation.
    info.endpoint_derivatives = detail::cosc_endpoints(info.exact);
    return info;
  }
};

class cosc_stable_1d {
 public:
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      if (x[i] == 0.0) {
        y[i] = 0.5;
        continue;
      }
      const double s = std::sin(0.5 * x[i]) / x[i];
      y[i] = 2.0 * s * s;
    }
  }
  integrand_info info() const {
    auto info = detail::stability_info("cosc_stable", "2·sin²(x/2)/x² = (1 − cos x)/x² (1/2 at 0)",
                                       0.0, 1.0, detail::cosc_integral(),
                                       "Si(1) − (1 − cos 1), Si by its Taylor series",
                                       smoothness::analytic);
    info.endpoint_derivatives = detail::cosc_endpoints(info.exact);
    return info;
  }
};

class inverse_sqrt_1d {
 public:
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[i] == 0.0 ? 0.0 : 1.0 / std::sqrt(x[i]);
  }
  integrand_info info() const {
    auto info = detail::stability_info("inverse_sqrt", "1/√x (0 at x = 0)", 0.0, 1.0, 2.0,
                                       "closed form: [2√x]₀¹", smoothness::singular);
    info.singularity_exponent = -0.5;
    return info;
  }
};

class log_1d {
 public:
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[i] == 0.0 ? 0.0 : std::log(x[i]);
  }
  integrand_info info() const {
    auto info = detail::stability_info("log", "log x (0 at x = 0)", 0.0, 1.0, -1.0,
                                       "closed form: [x log x − x]₀¹", smoothness::singular);
    info.singularity_exponent = 0.0;  // log x: the α → 0 case
    return info;
  }
};

class exp_float_1d {
 public:
  explicit exp_float_1d(double lower = 0.0, double upper = 1.0) : lo_(lower), hi_(upper) {
    require_finite(lo_, "lower");
    require_finite(hi_, "upper");
    require(lo_ < hi_, "upper", hi_, fmt::format("upper > lower = {}", quote(lo_)));
    // expf overflows above ln(FLT_MAX) ≈ 88.72; it is monotone, so f's largest value is its
    // value at the upper bound, computed exactly as evaluate() does.
    peak_ = std::exp(static_cast<float>(hi_));
    require(std::isfinite(peak_), "upper", hi_,
            "upper ≤ 88.72 (f is evaluated in float, and e^upper must stay below FLT_MAX)");
  }
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::exp(static_cast<float>(x[i]));
  }
  integrand_info info() const {
    auto info = detail::stability_info("exp_float", "eˣ evaluated in float", lo_, hi_,
                                       std::exp(hi_) - std::exp(lo_),
                                       "closed form of the double function", smoothness::analytic);
    info.derivative_bound[0] = peak_;
    // The rule errs on the float values by its error on eˣ plus their rounding: the end-point
    // data are eˣ's, the floor is float's.
    info.endpoint_derivatives =
        endpoint::product_of(1.0, {endpoint::exponential(1.0, lo_, hi_, info.exact)});
    info.precision = evaluation_precision::single_precision;
    return info;
  }

 private:
  double lo_, hi_;
  float peak_;
};

class inverse_quadratic_float_1d {
 public:
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      const float xf = static_cast<float>(x[i]);
      y[i] = 1.0f / (1.0f + xf * xf);
    }
  }
  integrand_info info() const {
    auto info = detail::stability_info("inverse_quadratic_float", "1/(1 + x²) evaluated in float",
                                       0.0, 1.0, std::numbers::pi / 4,
                                       "closed form of the double function", smoothness::analytic);
    info.endpoint_derivatives = inverse_quadratic_1d::endpoint_data();
    info.precision = evaluation_precision::single_precision;
    return info;
  }
};

}  // namespace quadmc
