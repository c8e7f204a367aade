// Closed-form derivatives of the one-variable factors the families are built from, and the
// builder of their end-point data (integrand.hpp: endpoint_factor), from which the Euler–Maclaurin
// expansion predicts a composite rule's error (rules/euler_maclaurin.hpp).
//
// Use it in a family's info() to fill integrand_info::endpoint_derivatives. Every formula is
// exact (no numerical differentiation): e^{λx} (λ complex: the oscillatory family's factors are
// e^{iaⱼxⱼ}), 1/(1 + t²) by partial fractions, e^{−t²} by Hermite polynomials, (1 − cos x)/x² by
// its Taylor series; tests/functions checks each against Boost.Math's automatic differentiation.
// Not for a factor with a jump (separable_factors bound those) or a singular one (√x, log x: the
// expansion has terms in h^(1+α) that these data cannot express).
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>
#include <vector>

namespace quadmc::endpoint {

// d^k/dt^k 1/(1 + t²) = (−1)^k·k!·Im[(t − i)^−(k+1)], from 1/(1 + t²) = Im[1/(t − i)]. The power
// is built by k + 1 multiplications with 1/(t − i) = (t + i)/(1 + t²), |·| ≤ 1 (no overflow); at
// t = 0 and t = ±1 every step is exact, so the derivatives that vanish there (f⁽ᵏ⁾(0) for odd k,
// f⁽⁴ᵐ⁺³⁾(1)) come out as exact zeros, which the Euler–Maclaurin terms rely on.
inline double inverse_quadratic(std::size_t k, double t) {
  const double d = 1.0 + t * t;
  const std::complex<double> inverse(t / d, 1.0 / d);
  std::complex<double> power = inverse;
  double factorial = 1.0;
  for (std::size_t j = 1; j <= k; ++j) {
    power *= inverse;
    factorial *= static_cast<double>(j);
  }
  return (k % 2 == 0 ? 1.0 : -1.0) * factorial * power.imag();
}

// The poles of 1/(1 + a²(x − u)²) = (1/(2ia))·[1/(x − u − i/a) − 1/(x − u + i/a)]: u ± i/a with
// residues ∓i/(2a), at distance d = 1/a from the real axis (a = 1, u = 0: 1/(1 + x²), ±i).
inline std::vector<simple_pole> inverse_quadratic_poles(double a, double u) {
  const std::complex<double> residue(0.0, -1.0 / (2.0 * a));
  return {{{u, 1.0 / a}, residue}, {{u, -1.0 / a}, -residue}};
}

// d^k/dt^k e^{−t²} = (−1)^k·H_k(t)·e^{−t²} with the physicists' Hermite polynomials,
// H₀ = 1, H₁ = 2t, H_{k+1} = 2t·H_k − 2k·H_{k−1} ([Abramowitz & Stegun], 22.7.13 and 22.2.14).
inline double gaussian(std::size_t k, double t) {
  double previous = 1.0, current = 2.0 * t;  // H₀, H₁
  double hermite = k == 0 ? previous : current;
  for (std::size_t j = 1; j < k; ++j) {
    const double next = 2.0 * t * current - 2.0 * static_cast<double>(j) * previous;
    previous = current;
    current = next;
    hermite = current;
  }
  return (k % 2 == 0 ? 1.0 : -1.0) * hermite * std::exp(-t * t);
}

// d^k/dx^k (1 − cos x)/x² from its Taylor series Σ_m (−1)^m x^{2m}/(2m + 2)!, which converges for
// every x; at |x| ≤ 1 the terms fall below 1e-30 of the sum within 30 terms past k/2.
inline double cosc(std::size_t k, double x) {
  double sum = 0.0;
  const std::size_t first = (k + 1) / 2;  // terms with 2m < k differentiate to 0
  for (std::size_t m = first; m < first + 30; ++m) {
    // (−1)^m · (2m)!/(2m − k)! · x^{2m−k} / (2m + 2)!
    double term = (m % 2 == 0 ? 1.0 : -1.0);
    for (std::size_t j = 2 * m - k + 1; j <= 2 * m; ++j) term *= static_cast<double>(j);
    for (std::size_t j = 2; j <= 2 * m + 2; ++j) term /= static_cast<double>(j);
    term *= std::pow(x, static_cast<double>(2 * m - k));
    sum += term;
  }
  return sum;
}

// The end-point data of a factor g on [lower, upper] from its x-derivatives at the two ends
// (one-sided, from inside): G⁽ᵏ⁾ = w^k·g⁽ᵏ⁾ with w = upper − lower, for k <
// endpoint_derivative_count. nullopt when a value is not finite (a derivative or wᵏ overflows): no
// prediction then.
template <class AtLower, class AtUpper>
std::optional<endpoint_factor> factor_of(AtLower&& at_lower, AtUpper&& at_upper, double lower,
                                         double upper, std::complex<double> integral,
                                         std::vector<derivative_jump> kinks = {}) {
  endpoint_factor f;
  f.integral = integral;
  const double w = upper - lower;
  // Sized once: an ensemble's plan builds these for every axis of every instance (2^20 at most).
  f.at_lower.reserve(endpoint_derivative_count);
  f.at_upper.reserve(endpoint_derivative_count);
  double power = 1.0;
  for (std::size_t k = 0; k < endpoint_derivative_count; ++k, power *= w) {
    const std::complex<double> a = power * std::complex<double>(at_lower(k));
    const std::complex<double> b = power * std::complex<double>(at_upper(k));
    if (!std::isfinite(a.real()) || !std::isfinite(a.imag()) || !std::isfinite(b.real()) ||
        !std::isfinite(b.imag())) {
      return std::nullopt;
    }
    f.at_lower.push_back(a);
    f.at_upper.push_back(b);
  }
  for (derivative_jump& kink : kinks) {
    power = 1.0;
    for (std::size_t k = 0; k < kink.jumps.size(); ++k, power *= w) {
      kink.jumps[k] *= power;
      if (!std::isfinite(kink.jumps[k].real()) || !std::isfinite(kink.jumps[k].imag())) {
        return std::nullopt;
      }
    }
  }
  if (!std::isfinite(integral.real()) || !std::isfinite(integral.imag())) return std::nullopt;
  f.kinks = std::move(kinks);
  return f;
}

// e^{λx} on [lower, upper]: g⁽ᵏ⁾ = λ^k·e^{λx}; ∫ given by the caller (it knows a form without
// cancellation for small λ).
inline std::optional<endpoint_factor> exponential(std::complex<double> rate, double lower,
                                                  double upper, std::complex<double> integral) {
  const std::complex<double> at_a = std::exp(rate * lower), at_b = std::exp(rate * upper);
  return factor_of([&](std::size_t k) { return std::pow(rate, static_cast<int>(k)) * at_a; },
                   [&](std::size_t k) { return std::pow(rate, static_cast<int>(k)) * at_b; }, lower,
                   upper, integral);
}

// Wraps factors into the data of f = Re[scale·Π factors]; nullopt as soon as one is missing.
inline std::optional<separable_derivatives> product_of(
    std::complex<double> scale, std::vector<std::optional<endpoint_factor>> factors) {
  separable_derivatives out;
  out.scale = scale;
  out.factors.reserve(factors.size());
  for (auto& f : factors) {
    if (!f) return std::nullopt;
    out.factors.push_back(std::move(*f));
  }
  return out;
}

}  // namespace quadmc::endpoint
