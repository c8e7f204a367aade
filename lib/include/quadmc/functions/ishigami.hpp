// The Ishigami function [Ishigami & Homma 1990], the standard test of global sensitivity
// analysis, on [0,1]³ through Xᵢ = π(2xᵢ − 1), Xᵢ uniform on [−π, π]:
//   f(x) = sin X₁ + a·sin² X₂ + b·X₃⁴·sin X₁.
// Its mean is a/2: sin X₁ and X₃⁴·sin X₁ average to 0 (sin is odd), sin² X₂ to 1/2
// (docs/theory.md#the-ishigami-function). The default a = 7, b = 0.1 is the one the sensitivity
// literature uses.
//
// Use it for an analytic integrand whose variance sits unevenly in its coordinates and in their
// interactions: X₃ matters only through its product with X₁ (docs/theory.md#the-ishigami-function
// has the variance and its split).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/integrand.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>

namespace quadmc {

class ishigami {
 public:
  explicit ishigami(double a = 7.0, double b = 0.1) : a_(a), b_(b) {
    require(std::isfinite(a), "a", a, "a finite number");
    require(std::isfinite(b), "b", b, "a finite number");
    // |f| ≤ 1 + |a| + |b|π⁴: every value and the mean a/2 finite when this is.
    require(std::isfinite(1.0 + std::abs(a) + std::abs(b) * pi4), "b", b,
            "a and b with 1 + |a| + |b|·π⁴ finite");
  }
  std::size_t dimension() const noexcept { return 3; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    constexpr double pi = std::numbers::pi;
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double x1 = pi * (2.0 * x[3 * i] - 1.0);
      const double x2 = pi * (2.0 * x[3 * i + 1] - 1.0);
      const double x3 = pi * (2.0 * x[3 * i + 2] - 1.0);
      const double s1 = std::sin(x1), s2 = std::sin(x2), x3sq = x3 * x3;
      y[i] = s1 + a_ * s2 * s2 + b_ * x3sq * x3sq * s1;
    }
  }
  integrand_info info() const {
    integrand_info info{.name = "ishigami",
                        .formula = "sin X₁ + a·sin² X₂ + b·X₃⁴·sin X₁, Xᵢ = π(2xᵢ − 1)",
                        .domain = box::unit(3),
                        .exact = a_ / 2.0,
                        .reference = "closed form: a/2",
                        .regularity = smoothness::analytic};
    // Largest |∂ᵏf/∂xⱼᵏ| over the cube, each coordinate's (the chain rule gives a factor 2π per
    // derivative): x₁: (2π)ᵏ(1 + bπ⁴), x₂: a·2^(k−1)(2π)ᵏ (k ≥ 1, as a·sin² X₂ = a(1 − cos 2X₂)/2),
    // x₃: b·4!/(4 − k)!·π^(4−k)(2π)ᵏ; and |f| ≤ 1 + a + bπ⁴. Each is attained (sin X₁ = ±1 with
    // X₃ = ±π, and so on) when a, b ≥ 0, so only then are they given: with a sign mixed, the
    // sum is a bound but not the maximum the field holds.
    if (a_ >= 0.0 && b_ >= 0.0) {
      constexpr double two_pi = 2.0 * std::numbers::pi, pi = std::numbers::pi;
      info.derivative_bound[0] = 1.0 + a_ + b_ * pi4;
      double scale = 1.0, falling = 1.0;  // (2π)ᵏ and 4!/(4 − k)!
      for (int k = 1; k <= 4; ++k) {
        scale *= two_pi;
        falling *= static_cast<double>(5 - k);
        const double d1 = scale * (1.0 + b_ * pi4);
        const double d2 = a_ * std::ldexp(1.0, k - 1) * scale;
        const double d3 = b_ * falling * std::pow(pi, 4 - k) * scale;
        info.derivative_bound[static_cast<std::size_t>(k)] = std::max({d1, d2, d3});
      }
    }
    return info;
  }
  double a() const noexcept { return a_; }
  double b() const noexcept { return b_; }

 private:
  static constexpr double pi4 =
      std::numbers::pi * std::numbers::pi * std::numbers::pi * std::numbers::pi;
  double a_, b_;
};

}  // namespace quadmc
