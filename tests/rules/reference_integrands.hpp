// Smooth 1D test integrands with exact integrals and exact derivative bounds M_k = max|f⁽ᵏ⁾|,
// shared by the rule tests (test-only: the catalogue of the library lives in functions/).
// Each M_k is derived in the comment beside it; error_bounds_test.cpp re-checks every one against
// an autodiff grid estimate.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace quadmc::testing {

struct smooth_case {
  std::string name;
  double (*f)(double);
  double a;
  double b;
  double exact;  // ∫_a^b f, closed form
  double m0;     // max|f|
  double m1;     // max|f′|
  double m2;     // max|f″|
  double m4;     // max|f⁽⁴⁾|
};

inline std::vector<smooth_case> smooth_cases() {
  using std::numbers::pi;
  const double e = std::numbers::e;
  return {
      // eˣ on [0, 1]: every derivative is eˣ, largest at x = 1. ∫ = e − 1 (expm1 rounds once).
      {"exp", [](double x) { return std::exp(x); }, 0.0, 1.0, std::expm1(1.0), e, e, e, e},
      // sin on [0, π]: derivatives ±sin, ±cos, all reach 1 on [0, π]. ∫ = 2 (up to (π − fl(π))²/2
      // ≈ 1.5e-32 because b = fl(π)).
      {"sin", [](double x) { return std::sin(x); }, 0.0, pi, 2.0, 1.0, 1.0, 1.0, 1.0},
      // 1/(1 + x²) on [0, 1], ∫ = π/4. f′ = −2x/(1 + x²)², extreme where f″ = 0: x = 1/√3,
      // |f′| = 3√3/8. f″ = (6x² − 2)/(1 + x²)³; f‴ = 24x(1 − x²)/(1 + x²)⁴ vanishes at 0 and 1
      // only,
      // |f″(0)| = 2 > |f″(1)| = 1/2. f⁽⁴⁾ = 24(5x⁴ − 10x² + 1)/(1 + x²)⁵; f⁽⁵⁾ ∝ x(3x⁴ − 10x² + 3)
      // vanishes at 0 and 1/√3: f⁽⁴⁾(0) = 24, f⁽⁴⁾(1/√3) = −10.125, f⁽⁴⁾(1) = −3, so M₄ = 24.
      {"runge", [](double x) { return 1.0 / (1.0 + x * x); }, 0.0, 1.0, pi / 4.0, 1.0,
       3.0 * std::sqrt(3.0) / 8.0, 2.0, 24.0},
      // cos 3x on [0, 1], ∫ = sin(3)/3. f⁽ᵏ⁾ = 3ᵏ·(±cos or ±sin)(3x); 3x ∈ [0, 3] contains 0 and
      // π/2,
      // so both reach 1: M_k = 3ᵏ.
      {"cos3x", [](double x) { return std::cos(3.0 * x); }, 0.0, 1.0, std::sin(3.0) / 3.0, 1.0, 3.0,
       9.0, 81.0},
      // x⁵ on [0, 1], ∫ = 1/6. f′ = 5x⁴, f″ = 20x³, f⁽⁴⁾ = 120x, all largest at x = 1.
      {"x^5", [](double x) { return x * x * x * x * x; }, 0.0, 1.0, 1.0 / 6.0, 1.0, 5.0, 20.0,
       120.0},
      // ln(1 + x) on [0, 1], ∫ = 2 ln 2 − 1. f′ = 1/(1 + x), f″ = −1/(1 + x)², f⁽⁴⁾ = −6/(1 + x)⁴,
      // all largest in magnitude at x = 0; max|f| = ln 2 at x = 1.
      {"log1p", [](double x) { return std::log1p(x); }, 0.0, 1.0, 2.0 * std::numbers::ln2 - 1.0,
       std::numbers::ln2, 1.0, 1.0, 6.0},
  };
}

// Rounding allowance for a computed rule value against the exact integral: each f value is good
// to ~2 ulp (libm) and its node to 1 ulp, which moves f by ≤ M₁·ε·max(|a|, |b|); the compensated
// sums add ≤ 2ε·Σ|w f|; the reference carries 1 ulp. 16ε·(b − a)·(M₀ + M₁·max(|a|, |b|)) covers
// all of it with room.
inline double rounding_allowance(const smooth_case& c) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  return 16.0 * eps * (c.b - c.a) * (c.m0 + c.m1 * std::max(std::abs(c.a), std::abs(c.b)));
}

}  // namespace quadmc::testing
