// One-dimensional warps by inversion of the CDF, X = P⁻¹(U) (docs/theory.md#inversion;
// [Ramamoorthi 2009, §3.1]).
//
// Use them to importance-sample integrands shaped like xⁿ on [0,1] (Blinn microfacet lobes)
// or like e^(−ax) on [0,∞) (free paths in participating media). Not for
// densities without a closed-form inverse CDF (use rejection, or tabulate).
//
//  - power_warp: p(x) = (n+1)xⁿ on [0,1], P(x) = x^(n+1), X = U^(1/(n+1)); any real n > −1.
//  - exponential_warp: p(x) = a·e^(−ax) on [0,∞), P(x) = 1 − e^(−ax), X = −ln(1−U)/a.
//    [Ramamoorthi 2009, §3.1.2] ends by simplifying to "X = −U′/a", dropping the logarithm; that is
//    wrong (it yields values in (−1/a, 0]); the correct form keeps it, −ln(U′)/a with U′ = 1 − U.
//    We use −log1p(−U)/a: U ∈ [0,1) so 1 − U ∈ (0,1] and the log is finite (U = 0 gives X = 0),
//    and log1p keeps full relative accuracy for small U, where X ≈ U/a.
//  - truncated_exponential_warp: p(x) = λe^(λx)/(e^λ − 1) on [0,1], λ ≠ 0,
//    P(x) = (e^(λx) − 1)/(e^λ − 1), X = log1p(U·expm1(λ))/λ (expm1/log1p: no cancellation for
//    small λ). With λ = 1 it is p ∝ eˣ, the zero-variance density for ∫₀¹eˣdx
//    (docs/theory.md#zero-variance).
// All densities are with respect to length on the real line.
#pragma once

#include "quadmc/core/errors.hpp"

#include <cmath>
#include <cstddef>
#include <span>

namespace quadmc {

class power_warp {
 public:
  // Largest exponent whose samples follow p closely enough. For large n, X = U^(1/(n+1)) lies
  // just below 1, where doubles are 2^-53 apart: the rounded X̂ = X(1 + η), |η| ≤ 2^-52 (pow's
  // ≤ 1 ulp plus the rounding of 1/(n+1)), and p(x)/p(x̂) = (1 + η)^-n, so the estimator
  // f(X̂)/p(X̂) is biased by up to n·2^-52 relative. n ≤ 10^5 keeps that ≤ 2.2e-11, inside the
  // 1e-10 the catalogue's references promise; at n ≈ 10^16 every sample rounds to X̂ = 1 and the
  // estimate is f(1)/(n + 1), whatever f is. Near n = −1 nothing breaks: samples that underflow
  // to 0 carry weight f(0)/p(0) = 0, the limit of f(x)/p(x) = f(x)x^(−n)/(n+1).
  static constexpr double max_exponent = 1e5;

  explicit power_warp(double n) : n_(n) {
    require(std::isfinite(n) && n > -1.0 && n <= max_exponent, "power exponent n", n,
            "a finite n with −1 < n ≤ 1e5 (larger n round every sample to 1)");
  }
  std::size_t input_dimension() const noexcept { return 1; }
  std::size_t output_dimension() const noexcept { return 1; }

  double sample(double u) const noexcept { return std::pow(u, 1.0 / (n_ + 1.0)); }
  double pdf(double x) const noexcept {
    return (x >= 0.0 && x <= 1.0) ? (n_ + 1.0) * std::pow(x, n_) : 0.0;
  }
  double cdf(double x) const noexcept {
    return x <= 0.0 ? 0.0 : (x >= 1.0 ? 1.0 : std::pow(x, n_ + 1.0));
  }
  void sample(std::span<const double> u, std::span<double> x) const noexcept {
    x[0] = sample(u[0]);
  }
  double pdf(std::span<const double> x) const noexcept { return pdf(x[0]); }

 private:
  double n_;
};

class exponential_warp {
 public:
  explicit exponential_warp(double a) : a_(a) {
    require(std::isfinite(a) && a > 0.0, "rate a", a, "a finite a > 0");
  }
  std::size_t input_dimension() const noexcept { return 1; }
  std::size_t output_dimension() const noexcept { return 1; }

  double sample(double u) const noexcept { return -std::log1p(-u) / a_; }
  double pdf(double x) const noexcept { return x >= 0.0 ? a_ * std::exp(-a_ * x) : 0.0; }
  double cdf(double x) const noexcept { return x <= 0.0 ? 0.0 : -std::expm1(-a_ * x); }
  void sample(std::span<const double> u, std::span<double> x) const noexcept {
    x[0] = sample(u[0]);
  }
  double pdf(std::span<const double> x) const noexcept { return pdf(x[0]); }

 private:
  double a_;
};

class truncated_exponential_warp {
 public:
  // Largest |λ|. The normalisation λ/(e^λ − 1) and the pdf's extreme values, |λ|·e^{±|λ|}/
  // |e^λ − 1|, are finite and normal while e^|λ| ≤ DBL_MAX (|λ| ≤ ln DBL_MAX ≈ 709.78) and
  // e^−|λ| ≥ DBL_MIN (|λ| ≤ −ln DBL_MIN ≈ 708.40); 700 leaves a margin of e^8 on both. Accuracy is
  // not the binding limit: X = log1p(U·expm1(λ))/λ is off by a few ε absolute, which moves
  // p(X) = norm·e^{λX} by a factor e^{±λ·4ε}, ≤ 3e-13 relative at |λ| = 700.
  static constexpr double max_abs_rate = 700.0;

  explicit truncated_exponential_warp(double lambda) : lambda_(lambda) {
    require(std::isfinite(lambda) && lambda != 0.0 && std::abs(lambda) <= max_abs_rate, "rate λ",
            lambda, "a rate 0 < |λ| ≤ 700 (e^λ must stay finite)");
    norm_ = lambda_ / std::expm1(lambda_);
  }
  std::size_t input_dimension() const noexcept { return 1; }
  std::size_t output_dimension() const noexcept { return 1; }

  double sample(double u) const noexcept { return std::log1p(u * std::expm1(lambda_)) / lambda_; }
  double pdf(double x) const noexcept {
    return (x >= 0.0 && x <= 1.0) ? norm_ * std::exp(lambda_ * x) : 0.0;
  }
  double cdf(double x) const noexcept {
    return x <= 0.0 ? 0.0 : (x >= 1.0 ? 1.0 : std::expm1(lambda_ * x) / std::expm1(lambda_));
  }
  void sample(std::span<const double> u, std::span<double> x) const noexcept {
    x[0] = sample(u[0]);
  }
  double pdf(std::span<const double> x) const noexcept { return pdf(x[0]); }

 private:
  double lambda_;
  double norm_ = 1.0;
};

}  // namespace quadmc
