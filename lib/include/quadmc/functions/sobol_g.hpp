// Sobol's g-function on [0,1]^s: f(x) = Π (|4xᵢ − 2| + aᵢ)/(1 + aᵢ), aᵢ ≥ 0 (Saltelli & Sobol',
// "About the use of rank transformation in sensitivity analysis of model output", Reliab. Eng.
// Syst. Safety 50, 1995). Each factor integrates to exactly 1 over [0,1], so ∫ f = 1; a small aᵢ
// makes coordinate i important, a large one makes it nearly irrelevant (factor ≈ 1).
//
// Use it for a C⁰ integrand (kink at xᵢ = 1/2) with controllable effective dimension. Beware
// (docs/theory.md#sobol-g-with-even-panels): a tensor midpoint/trapezoid rule with an even number
// of panels per axis puts the kink on a node and is exact; use odd n to see the C⁰ rate. Default
// aᵢ = (i − 1)/2 (1-based), a common choice that makes the first coordinates matter most.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/endpoint_derivatives.hpp"
#include "quadmc/functions/integrand.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace quadmc {

class sobol_g {
 public:
  explicit sobol_g(std::vector<double> a) : a_(std::move(a)) {
    require(!a_.empty(), "a", a_.size(), "a non-empty vector (its length is the dimension s ≥ 1)");
    for (double ai : a_) require(std::isfinite(ai) && ai >= 0.0, "a", ai, "finite aᵢ ≥ 0");
    for (double ai : a_) inv_1pa_.push_back(1.0 / (1.0 + ai));
    // f's largest value, at the corners, is Π (2 + aᵢ)/(1 + aᵢ) ≤ 2^s; every factor is ≥ 1, so
    // a finite total means finite partial products. It overflows only when s nears 1024 with
    // small aᵢ (2^1024 > DBL_MAX).
    peak_ = 1.0;
    for (double ai : a_) peak_ *= (2.0 + ai) / (1.0 + ai);
    require(std::isfinite(peak_), "a", fmt::format("[{}]", fmt::join(a_, ", ")),
            fmt::format("parameters whose largest value Π (2 + aᵢ)/(1 + aᵢ) is finite (s = {}: "
                        "raise some aᵢ above 0)",
                        a_.size()));
  }
  // aᵢ = (i − 1)/2, i = 1..s.
  static std::vector<double> default_a(std::size_t s) {
    require(s >= 1, "dimension", s, "s ≥ 1");
    std::vector<double> a(s);
    for (std::size_t i = 0; i < s; ++i) a[i] = 0.5 * static_cast<double>(i);
    return a;
  }
  std::size_t dimension() const noexcept { return a_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    const std::size_t s = a_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double p = 1.0;
      for (std::size_t j = 0; j < s; ++j) {
        p *= (std::abs(4.0 * x[i * s + j] - 2.0) + a_[j]) * inv_1pa_[j];
      }
      y[i] = p;
    }
  }
  integrand_info info() const {
    integrand_info info{.name = "sobol_g",
                        .formula = "Π (|4xᵢ − 2| + aᵢ)/(1 + aᵢ)",
                        .domain = box::unit(a_.size()),
                        .exact = 1.0,
                        .reference = "closed form: each factor integrates to 1",
                        .regularity = smoothness::c0};
    // Each factor peaks at xᵢ ∈ {0, 1} with (2 + aᵢ)/(1 + aᵢ); its slope is ±4/(1 + aᵢ).
    const double peak = peak_;
    double slope = 0.0;
    for (double ai : a_)
      slope = std::max(slope, peak * (4.0 / (1.0 + ai)) / ((2.0 + ai) / (1.0 + ai)));
    info.derivative_bound[0] = peak;
    info.derivative_bound[1] = slope;
    // Each factor is linear on both sides of x = 1/2, where its slope jumps from −4/(1 + a) to
    // +4/(1 + a): the end-point data of a kinked product (rules/euler_maclaurin.hpp).
    std::vector<std::optional<endpoint_factor>> factors;
    for (double ai : a_) {
      const double s = 4.0 / (1.0 + ai), top = (2.0 + ai) / (1.0 + ai);
      const auto end = [s, top](double slope_sign) {
        return [s, top, slope_sign](std::size_t k) {
          return k == 0 ? top : (k == 1 ? slope_sign * s : 0.0);
        };
      };
      derivative_jump kink{0.5, std::vector<std::complex<double>>(endpoint_derivative_count)};
      kink.jumps[1] = 2.0 * s;
      factors.push_back(endpoint::factor_of(end(-1.0), end(1.0), 0.0, 1.0, 1.0, {std::move(kink)}));
    }
    info.endpoint_derivatives = endpoint::product_of(1.0, std::move(factors));
    // E g = 1 and E g² = 1 + 1/(3(1 + a)²) (E|4x − 2|² = 4/3, E|4x − 2| = 1).
    separable_moments moments;
    for (double ai : a_) {
      const double square = 1.0 + 1.0 / (3.0 * (1.0 + ai) * (1.0 + ai));
      moments.factors.push_back({1.0, square, square});
    }
    info.moments = std::move(moments);
    return info;
  }
  const std::vector<double>& a() const noexcept { return a_; }

 private:
  std::vector<double> a_, inv_1pa_;
  double peak_;
};

}  // namespace quadmc
