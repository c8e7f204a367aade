// Genz's six test families on [0,1]^s (A. Genz, "Testing multidimensional integration routines",
// in Tools, Methods and Languages for Scientific and Engineering Computation, 1984, 81–94; and
// "A package for testing multiple integration subroutines", 1987), with closed-form integrals:
//
// clang-format off
//   oscillatory    cos(2πu₁ + Σ aᵢxᵢ)       ∫ = cos(2πu₁ + Σaᵢ/2)·Π sin(aᵢ/2)/(aᵢ/2)
//   product_peak   Π 1/(aᵢ⁻² + (xᵢ − uᵢ)²)   ∫ = Π aᵢ[atan(aᵢ(1 − uᵢ)) + atan(aᵢuᵢ)]
//   corner_peak    (1 + Σ aᵢxᵢ)^−(s+1)       ∫ = Σ_{v∈{0,1}^s} (−1)^{|v|}/(1 + a·v) / (s!·Π aᵢ)
//   gaussian       exp(−Σ aᵢ²(xᵢ − uᵢ)²)     ∫ = Π √π/(2aᵢ)[erf(aᵢ(1 − uᵢ)) + erf(aᵢuᵢ)]
//   continuous     exp(−Σ aᵢ|xᵢ − uᵢ|)       ∫ = Π [2 − e^{−aᵢuᵢ} − e^{−aᵢ(1−uᵢ)}]/aᵢ
//   discontinuous  0 if x_c > u_c for a c in cut, else exp(Σ aᵢxᵢ)
//                                            ∫ = Π_{i∈cut}(e^{aᵢuᵢ} − 1)/aᵢ · Π_{i∉cut}(e^{aᵢ} − 1)/aᵢ
// clang-format on
// The oscillatory form is Re[e^{i2πu₁} Π (e^{iaⱼ} − 1)/(iaⱼ)] with (e^{ia} − 1)/(ia) =
// e^{ia/2}·sin(a/2)/(a/2), which has no cancellation for small a. The product-peak convention is
// aᵢ⁻² (Genz's own code). The discontinuous family cuts x₁ and x₂ by default (Genz's code; only
// x₁ when s = 1); `cut` = {1, …, s} gives the every-coordinate convention of other collections.
//
// Corner peak accuracy: its closed form is an alternating sum over 2^s vertices that cancels
// catastrophically (docs/theory.md#corner-peak-cancellation). Measured
// (tests/functions/genz_test.cpp, random weights with Genz's Σa = 1.85, against 100-digit
// arithmetic): summed in double it errs 5.5e-12 relative at s = 8, 2.2e-10 at s = 10, 8e-7 at
// s = 14, 1.6e-5 at s = 16; in long double 8e-15, 8e-14, 6e-10 and 1.5e-8. So it is summed in
// 50-digit arithmetic (inclusion_exclusion.hpp): exact to double precision (≤ 2e-16 relative) for
// every s ≤ 14 measured against 100 digits; its rounding bound is 7e-32 at s = 16 and 2e-27 at
// s = 20. The constructor still computes that bound and throws unless it is ≤ 1e-10 relative (it
// fires only for extreme a, e.g. aᵢ = 1e-6 at s = 12). s > 20 is rejected for cost (2^s terms: ~1 s
// at s = 20 at -O2).
//
// Difficulty normalisation ([Genz 1987], used in many comparisons; docs/theory.md#genz-difficulty):
// aᵢ = b·wᵢ/Σw with b = (9.0, 7.25, 1.85, 7.03, 20.4, 4.3) for the six families in the order above
// (genz_normalise). genz_random_parameters draws w and u from a random_stream.
//
// Use them for multi-dimensional convergence studies with known answers. Derivative bounds in
// info() are max over the cube of |∂ᵏf/∂xⱼᵏ| maximised over j; where only an upper bound is known
// it is said below. Not for s where the closed form is untrustworthy (corner peak, see above).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/core/vector_math.hpp"
#include "quadmc/functions/endpoint_derivatives.hpp"
#include "quadmc/functions/integrand.hpp"

#include <boost/math/special_functions/sinc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace quadmc {

enum class genz_family {
  oscillatory,
  product_peak,
  corner_peak,
  gaussian,
  continuous,
  discontinuous
};

constexpr std::string_view to_string(genz_family f) noexcept {
  constexpr std::array<std::string_view, 6> names = {"genz_oscillatory", "genz_product_peak",
                                                     "genz_corner_peak", "genz_gaussian",
                                                     "genz_continuous",  "genz_discontinuous"};
  return names[static_cast<std::size_t>(f)];
}

// Genz's difficulty b_f: the value of Σaᵢ after normalisation.
constexpr double genz_difficulty(genz_family f) noexcept {
  constexpr std::array<double, 6> b = {9.0, 7.25, 1.85, 7.03, 20.4, 4.3};
  return b[static_cast<std::size_t>(f)];
}

// aᵢ = b_f·wᵢ/Σw. Requires w non-empty, finite, wᵢ ≥ 0 and Σw > 0.
inline std::vector<double> genz_normalise(genz_family f, std::span<const double> w) {
  require(!w.empty(), "w", w.size(), "at least one weight");
  double total = 0.0;
  for (double wi : w) {
    require(std::isfinite(wi) && wi >= 0.0, "w", wi, "finite weights ≥ 0");
    total += wi;
  }
  require(total > 0.0, "w", total, "a positive sum of weights");
  std::vector<double> a(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) a[i] = genz_difficulty(f) * w[i] / total;
  return a;
}

// The weights the difficulty is spread over when a is drawn (the scene key `coefficient_decay`):
// none keeps wⱼ = 1 − Uⱼ; quadratic multiplies them by j⁻², exponential by 2⁻ʲ (1-based j), and
// genz_normalise then restores Σa = b. The same b spread over decaying weights puts most of the
// variation into the first coordinates: a lower effective dimension at the same difficulty
// (docs/theory.md#genz-difficulty).
enum class genz_decay { none, quadratic, exponential };

constexpr std::array<std::string_view, 3> genz_decay_names = {"none", "quadratic", "exponential"};

constexpr std::string_view to_string(genz_decay d) noexcept {
  return genz_decay_names[static_cast<std::size_t>(d)];
}

// The decay named `name`; throws invalid_argument("coefficient_decay", …) naming the choices.
inline genz_decay genz_decay_from(std::string_view name) {
  for (std::size_t i = 0; i < genz_decay_names.size(); ++i) {
    if (genz_decay_names[i] == name) return static_cast<genz_decay>(i);
  }
  throw invalid_argument("coefficient_decay", fmt::format("\"{}\"", name),
                         "one of \"none\", \"quadratic\", \"exponential\"");
}

struct genz_parameters {
  std::vector<double> a;  // difficulty, normalised so that Σa = genz_difficulty(family)
  std::vector<double> u;  // shift, in [0,1)
};

// w_j = 1 − U_j (in (0,1], so no aᵢ is 0: the product peak and Gaussian need aᵢ > 0) and
// u_j = U_{s+j}, U_k = random_stream(seed, stream_id({family})).uniform(k); w_j times the decay's
// factor (j⁻² or 2⁻ʲ, 1-based j); then normalised. The U_k do not depend on the decay, so the
// three decays of one seed share u and differ only in how b is spread (a paired comparison).
// genz_decay::none is bit for bit the draw without a decay. An exponential decay makes aⱼ ≈ b·2⁻ʲ,
// subnormal beyond j ≈ 1020, which the families refuse (validate_genz), as they refuse products
// Π aⱼ that underflow.
inline genz_parameters genz_random_parameters(genz_family f, std::size_t s, std::uint64_t seed,
                                              genz_decay decay = genz_decay::none) {
  require(s >= 1, "dimension", s, "s ≥ 1");
  const random_stream rng(seed, stream_id({static_cast<std::uint64_t>(f)}));
  std::vector<double> w(s), u(s);
  for (std::size_t j = 0; j < s; ++j) {
    w[j] = 1.0 - rng.uniform(j);
    u[j] = rng.uniform(s + j);
    const double index = static_cast<double>(j + 1);  // exact: s ≤ 2^53
    // One rounding for j⁻² (j² is exact for j < 2^26); 2⁻ʲ by ldexp is exact while w stays normal.
    if (decay == genz_decay::quadratic) w[j] /= index * index;
    if (decay == genz_decay::exponential) w[j] = std::ldexp(w[j], -static_cast<int>(j + 1));
  }
  return {genz_normalise(f, w), std::move(u)};
}

namespace detail {

// Checks a and u of one Genz family; a_positive for families whose formula divides by aᵢ.
// Subnormal aᵢ (|aᵢ| < DBL_MIN ≈ 2.2e-308) are refused: the closed forms divide by aᵢ or by
// aᵢ·t, which then carry only a few significant bits.
inline void validate_genz(std::span<const double> a, std::span<const double> u, bool a_positive) {
  require(!a.empty(), "a", a.size(), "a non-empty vector (its length is the dimension s ≥ 1)");
  require(u.size() == a.size(), "u", fmt::format("a vector of length {}", u.size()),
          fmt::format("length s = {} (the length of a)", a.size()));
  for (double ai : a) {
    const bool normal_or_zero = ai == 0.0 || std::abs(ai) >= std::numeric_limits<double>::min();
    require(std::isfinite(ai) && (!a_positive || ai > 0.0) && normal_or_zero, "a", ai,
            a_positive ? "finite aᵢ > 0, not subnormal (≥ 2.2250738585072014e-308)"
                       : "finite aᵢ, 0 or not subnormal (|aᵢ| ≥ 2.2250738585072014e-308)");
  }
  for (double ui : u) require(ui >= 0.0 && ui <= 1.0, "u", ui, "uᵢ in [0, 1]");
}

// Π factors, the product a closed form needs. In double as the factors come (the usual case, bit
// for bit what a loop gives); when that over- or underflows on the way, or ends outside the normal
// range, again in 50-digit arithmetic (exponent range ±2^31), which rounds only the final value:
// a product of 1e200, 1e200 and 1e-300 is 1e100, not inf.
double scaled_product(std::span<const double> factors);  // lib/src/functions/genz.cpp

// Refuses parameters whose reference a double cannot carry: `exact` must be finite, and for the
// positive families (every Genz family but the oscillatory one) at least DBL_MIN, since a
// subnormal or zero reference leaves no relative error to measure. `factors`, when the exact
// value is their product, give the message its order of magnitude (Σ log₁₀ of them).
inline void require_representable(double exact, bool positive, std::span<const double> a,
                                  std::string_view family, std::span<const double> factors = {}) {
  const bool ok =
      std::isfinite(exact) && (!positive || exact >= std::numeric_limits<double>::min());
  if (ok) return;
  std::string value = fmt::format("{:.3g}", exact);
  if (!factors.empty()) {
    double log10 = 0.0;
    for (double f : factors) log10 += std::log10(std::abs(f));
    value = fmt::format("about 1e{:.0f}", std::floor(log10));
  }
  throw invalid_argument(
      "a", fmt::format("[{}]", fmt::join(a, ", ")),
      fmt::format("parameters whose integral of {} is a normal double (it is "
                  "{}, {})",
                  family, value, std::isfinite(exact) ? "below 2.2e-308" : "beyond 1.8e308"));
}

// M_k where finite; empty where the bound overflows (it is a bound, not a value f reaches).
inline std::optional<double> finite_bound(double bound) {
  if (std::isfinite(bound)) return bound;
  return std::nullopt;
}

inline double max_abs(std::span<const double> a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::abs(v));
  return m;
}

inline integrand_info genz_info(genz_family f, std::string formula, std::size_t s, double exact,
                                std::string reference, smoothness regularity) {
  return integrand_info{.name = std::string(to_string(f)),
                        .formula = std::move(formula),
                        .domain = box::unit(s),
                        .exact = exact,
                        .reference = std::move(reference),
                        .regularity = regularity};
}

// The one-variable integrals over [0, 1] the product families' closed forms, end-point data and
// moments are built from (one expression each, so that all three agree bit for bit).
// ∫₀¹ e^{−a²(x−u)²} dx = √π/(2a)[erf(a(1 − u)) + erf(au)].
inline double gaussian_factor_integral(double a, double u) {
  return std::sqrt(std::numbers::pi) / (2.0 * a) * (std::erf(a * (1.0 - u)) + std::erf(a * u));
}
// ∫₀¹ e^{−a|x−u|} dx = [2 − e^{−au} − e^{−a(1−u)}]/a, as −expm1(−au) − expm1(−a(1−u)): no
// cancellation for small a.
inline double continuous_factor_integral(double a, double u) {
  return (-std::expm1(-a * u) - std::expm1(-a * (1.0 - u))) / a;
}
// ∫₀¹ dx/(1 + a²(x−u)²) = [atan(a(1 − u)) + atan(au)]/a.
inline double peak_factor_integral(double a, double u) {
  return (std::atan(a * (1.0 - u)) + std::atan(a * u)) / a;
}
// ∫₀^upper e^{ax} dx = expm1(a·upper)/a, = upper at a = 0.
inline double exponential_integral(double a, double upper) {
  return a == 0.0 ? upper : std::expm1(a * upper) / a;
}

}  // namespace detail

class genz_oscillatory {
 public:
  genz_oscillatory(std::vector<double> a, std::vector<double> u)
      : a_(std::move(a)), u_(std::move(u)) {
    detail::validate_genz(a_, u_, false);
    phase_ = 2.0 * std::numbers::pi * u_[0];
    // evaluate() sums 2πu₁ + Σaᵢxᵢ; each partial sum is at most 2π + Σ|aᵢ| in magnitude
    // (rounding is monotone), so that bound finite means no inf, and no cos(inf) = NaN.
    double bound = 2.0 * std::numbers::pi;
    for (double ai : a_) bound += std::abs(ai);
    require(std::isfinite(bound), "a", fmt::format("[{}]", fmt::join(a_, ", ")),
            "parameters with a finite 2π + Σ|aᵢ| (the phase of cos must stay finite)");
    const exact_value e = exact();
    require(e.error <= 1e-12, "a", fmt::format("[{}]", fmt::join(a_, ", ")),
            fmt::format("parameters whose closed form is accurate to 1e-12 of its amplitude "
                        "Π|sin(aᵢ/2)/(aᵢ/2)| (its bound is {:.2g}: the phase 2πu₁ + Σaᵢ/2 is too "
                        "large to carry in two doubles)",
                        e.error));
  }
  std::size_t dimension() const noexcept { return a_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = a_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double t = phase_;
      for (std::size_t j = 0; j < s; ++j) t += a_[j] * x[i * s + j];
      y[i] = t;
    }
    vector_cos(y, y);
  }
  // cos(2πu₁ + Σaᵢ/2)·Π sin(aᵢ/2)/(aᵢ/2), with `error` a bound on its absolute error relative
  // to the amplitude Π|sin(aᵢ/2)/(aᵢ/2)|. Summed in one double, the phase lost its fraction of a
  // period once Σaᵢ/2 was large (relative error 8e-8 at a₁ = 1e10, the wrong sign at 1e16). Here
  // it is kept as an unevaluated sum hi + lo, TwoSum at every step
  // (docs/theory.md#a-phase-carried-in-two-doubles): |hi + lo − phase| ≤ γ²ₙ·Σ|terms| ≈
  // (n·u)²·Σ|terms|. aᵢ/2 is exact,
  // and glibc's cos and sin reduce any double argument exactly and round to within an ulp, so
  // cos(hi + lo) = cos hi·cos lo − sin hi·sin lo adds at most 8u, and the s factors sin(t)/t and
  // their product 3u each: error ≤ (3s + 8)·u + the phase's.
  struct exact_value {
    double value;
    double error;
  };
  exact_value exact() const {
    const double u = std::numeric_limits<double>::epsilon() / 2.0;
    double hi = phase_;
    double lo = 0.0;
    double magnitude = std::abs(phase_);
    double product = 1.0;
    for (const double ai : a_) {
      const double term = 0.5 * ai;
      const double sum = hi + term;  // TwoSum: sum + err = hi + term exactly
      const double back = sum - hi;
      lo += (hi - (sum - back)) + (term - back);
      hi = sum;
      magnitude += std::abs(term);
      product *= boost::math::sinc_pi(term);
    }
    const double n = static_cast<double>(a_.size() + 1);
    const double phase_error = (n * u) * (n * u) * magnitude;
    const double cosine = std::cos(hi) * std::cos(lo) - std::sin(hi) * std::sin(lo);
    return {cosine * product, static_cast<double>(3 * a_.size() + 8) * u + phase_error};
  }

  integrand_info info() const {
    auto info =
        detail::genz_info(genz_family::oscillatory, "cos(2πu₁ + Σ aᵢxᵢ)", a_.size(), exact().value,
                          "closed form cos(2πu₁ + Σaᵢ/2)·Π sin(aᵢ/2)/(aᵢ/2), the phase "
                          "summed in two doubles",
                          smoothness::analytic);
    // |∂ᵏf/∂xⱼᵏ| = |aⱼ|ᵏ·|cos or sin| ≤ |aⱼ|ᵏ (an upper bound, attained when the phase allows).
    const double m = detail::max_abs(a_);
    for (int k = 0; k <= 4; ++k) info.derivative_bound[k] = detail::finite_bound(std::pow(m, k));
    // f = Re[e^{i2πu₁}·Π e^{iaⱼxⱼ}]; ∫₀¹ e^{iax} dx = e^{ia/2}·sin(a/2)/(a/2), no cancellation.
    std::vector<std::optional<endpoint_factor>> factors;
    for (double ai : a_) {
      const std::complex<double> rate(0.0, ai);
      factors.push_back(endpoint::exponential(
          rate, 0.0, 1.0, std::exp(0.5 * rate) * boost::math::sinc_pi(0.5 * ai)));
    }
    info.endpoint_derivatives = endpoint::product_of(std::polar(1.0, phase_), std::move(factors));
    // The moments of h = e^{iax}: E h = e^{ia/2}·sinc(a/2), E|h|² = 1, E h² = e^{ia}·sinc(a).
    separable_moments moments{std::polar(1.0, phase_), {}};
    for (double ai : a_) {
      moments.factors.push_back({std::polar(boost::math::sinc_pi(0.5 * ai), 0.5 * ai), 1.0,
                                 std::polar(boost::math::sinc_pi(ai), ai)});
    }
    info.moments = std::move(moments);
    return info;
  }
  const std::vector<double>& a() const noexcept { return a_; }
  const std::vector<double>& u() const noexcept { return u_; }

 private:
  std::vector<double> a_, u_;
  double phase_;
};

class genz_product_peak {
 public:
  // f = C·Π 1/(1 + aᵢ²(xᵢ − uᵢ)²) with C = Π aᵢ², the peak at x = u: every factor is in (0, 1],
  // so no partial product overflows on the way (Π 1/(aᵢ⁻² + d²) would for a = (1e200, 1e-200)
  // although f ≤ 1). C and the integral must be finite and normal, or the parameters are refused.
  genz_product_peak(std::vector<double> a, std::vector<double> u)
      : a_(std::move(a)), u_(std::move(u)) {
    detail::validate_genz(a_, u_, true);
    std::vector<double> squares, factors;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double a2 = a_[j] * a_[j];
      require(std::isfinite(a2), "a", a_[j], "aᵢ ≤ 1.3e154 (aᵢ² must stay finite)");
      a2_.push_back(a2);
      squares.push_back(a2);
      factors.push_back(a_[j] * (std::atan(a_[j] * (1.0 - u_[j])) + std::atan(a_[j] * u_[j])));
    }
    peak_ = detail::scaled_product(squares);
    require(std::isfinite(peak_) && peak_ >= std::numeric_limits<double>::min(), "a",
            fmt::format("[{}]", fmt::join(a_, ", ")),
            fmt::format("parameters whose peak Π aᵢ² at x = u is a normal double (it is {:.3g})",
                        peak_));
    exact_ = detail::scaled_product(factors);
    detail::require_representable(exact_, true, a_, "genz_product_peak", factors);
  }
  std::size_t dimension() const noexcept { return a_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    const std::size_t s = a_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double p = 1.0;
      for (std::size_t j = 0; j < s; ++j) {
        const double d = x[i * s + j] - u_[j];
        p *= 1.0 / (1.0 + a2_[j] * (d * d));
      }
      y[i] = peak_ * p;
    }
  }
  integrand_info info() const {
    auto info =
        detail::genz_info(genz_family::product_peak, "Π 1/(aᵢ⁻² + (xᵢ − uᵢ)²)", a_.size(), exact_,
                          "closed form Π aᵢ[atan(aᵢ(1 − uᵢ)) + atan(aᵢuᵢ)]", smoothness::analytic);
    info.derivative_bound[0] = peak_;  // at x = u, inside the cube
    // f = peak·Π g_j, g_j(x) = 1/(1 + a²(x − u)²): g⁽ᵏ⁾ = aᵏ·r⁽ᵏ⁾(a(x − u)), r(t) = 1/(1 + t²).
    std::vector<std::optional<endpoint_factor>> factors;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double a = a_[j], u = u_[j];
      const auto at = [a, u](double x) {
        return [a, u, x](std::size_t k) {
          return std::pow(a, static_cast<double>(k)) * endpoint::inverse_quadratic(k, a * (x - u));
        };
      };
      auto factor =
          endpoint::factor_of(at(0.0), at(1.0), 0.0, 1.0, detail::peak_factor_integral(a, u));
      // Poles u ± i/a: the coarse-grid term of docs/theory.md#coarse-grid-term.
      if (factor) factor->poles = endpoint::inverse_quadratic_poles(a, u);
      factors.push_back(std::move(factor));
    }
    info.endpoint_derivatives = endpoint::product_of(peak_, std::move(factors));
    // g = 1/(1 + a²t²), t = x − u: E g = [atan(a(1 − u)) + atan(au)]/a and, with v = at,
    // E g² = (1/a)∫dv/(1 + v²)² = [F(a(1 − u)) − F(−au)]/(2a), F(v) = v/(1 + v²) + atan v.
    separable_moments moments{peak_, {}};
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double a = a_[j], u = u_[j];
      const auto F = [](double v) { return v / (1.0 + v * v) + std::atan(v); };
      const double mean = detail::peak_factor_integral(a, u);
      const double square = (F(a * (1.0 - u)) - F(-a * u)) / (2.0 * a);
      moments.factors.push_back({mean, square, square});
    }
    info.moments = std::move(moments);
    return info;
  }
  const std::vector<double>& a() const noexcept { return a_; }
  const std::vector<double>& u() const noexcept { return u_; }

 private:
  std::vector<double> a_, u_, a2_;
  double peak_, exact_;
};

class genz_corner_peak {
 public:
  // Largest s accepted before the accuracy test: the closed form costs 2^s terms.
  static constexpr std::size_t max_dimension = 20;
  // Largest accepted rounding bound of the closed form, relative.
  static constexpr double max_relative_error = 1e-10;

  genz_corner_peak(std::vector<double> a, std::vector<double> u)
      : a_(std::move(a)), u_(std::move(u)) {
    detail::validate_genz(a_, u_, true);
    const std::size_t s = a_.size();
    require(s <= max_dimension, "dimension", s,
            "s ≤ 20 (the corner-peak closed form sums 2^s terms)");
    const auto [exact, bound] = closed_form(a_);
    exact_ = exact;
    error_bound_ = bound;
    require(
        bound <= max_relative_error, "a",
        fmt::format("[{}] (s = {}, relative rounding bound {:.3g})", fmt::join(a_, ", "), s, bound),
        "parameters whose inclusion–exclusion closed form is accurate to 1e-10 relative "
        "(larger aᵢ or a smaller s)");
    detail::require_representable(exact_, true, a_, "genz_corner_peak");
  }
  // The closed form and a bound on its relative rounding error (of the 50-digit sum, before the
  // final rounding to double), for any a > 0.
  static std::pair<double, double> closed_form(std::span<const double> a);  // genz.cpp
  std::size_t dimension() const noexcept { return a_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    const std::size_t s = a_.size();
    const double exponent = -static_cast<double>(s + 1);
    for (std::size_t i = 0; i < y.size(); ++i) {
      double t = 1.0;
      for (std::size_t j = 0; j < s; ++j) t += a_[j] * x[i * s + j];
      y[i] = std::pow(t, exponent);
    }
  }
  integrand_info info() const {
    auto info = detail::genz_info(
        genz_family::corner_peak, "(1 + Σ aᵢxᵢ)^−(s+1)", a_.size(), exact_,
        fmt::format("closed form Σ_v (−1)^|v|/(1 + a·v)/(s!·Π aᵢ) over the 2^s vertices, 50 "
                    "digits, relative rounding bound {:.2g}",
                    error_bound_),
        smoothness::analytic);
    // |∂ᵏf/∂xⱼᵏ| = (s+1)(s+2)…(s+k)·aⱼᵏ·(1 + a·x)^−(s+1+k), largest at x = 0.
    const double m = detail::max_abs(a_);
    double rising = 1.0;
    for (int k = 0; k <= 4; ++k) {
      info.derivative_bound[k] = detail::finite_bound(rising * std::pow(m, k));
      rising *= static_cast<double>(a_.size() + 1 + static_cast<std::size_t>(k));
    }
    return info;
  }
  double relative_error_bound() const noexcept { return error_bound_; }
  const std::vector<double>& a() const noexcept { return a_; }
  const std::vector<double>& u() const noexcept { return u_; }

 private:
  std::vector<double> a_, u_;
  double exact_, error_bound_;
};

class genz_gaussian {
 public:
  genz_gaussian(std::vector<double> a, std::vector<double> u) : a_(std::move(a)), u_(std::move(u)) {
    detail::validate_genz(a_, u_, true);
    // aᵢ² = inf would make aᵢ²·0 = NaN at xᵢ = uᵢ.
    for (double ai : a_) {
      a2_.push_back(ai * ai);
      require(std::isfinite(a2_.back()), "a", ai, "aᵢ ≤ 1.3e154 (aᵢ² must stay finite)");
    }
    // Every factor √π/(2aᵢ)·[erf(aᵢ(1 − uᵢ)) + erf(aᵢuᵢ)] is in (0, 1].
    std::vector<double> factors;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      factors.push_back(detail::gaussian_factor_integral(a_[j], u_[j]));
    }
    exact_ = detail::scaled_product(factors);
    detail::require_representable(exact_, true, a_, "genz_gaussian", factors);
  }
  std::size_t dimension() const noexcept { return a_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = a_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double e = 0.0;
      for (std::size_t j = 0; j < s; ++j) {
        const double d = x[i * s + j] - u_[j];
        e += a2_[j] * d * d;
      }
      y[i] = -e;
    }
    vector_exp(y, y);
  }
  integrand_info info() const {
    auto info = detail::genz_info(genz_family::gaussian, "exp(−Σ aᵢ²(xᵢ − uᵢ)²)", a_.size(), exact_,
                                  "closed form Π √π/(2aᵢ)[erf(aᵢ(1 − uᵢ)) + erf(aᵢuᵢ)]",
                                  smoothness::analytic);
    // d^k/dt^k e^{−a²t²} = (−a)^k H_k(at) e^{−a²t²}: |·| peaks at t = 0 for k = 0, 2, 4 (values
    // 1, 2a², 12a⁴, attained at x = u); for k = 1 the sup over ℝ, √2·e^{−1/2}·a, is an upper bound.
    const double m = detail::max_abs(a_);
    info.derivative_bound[0] = 1.0;
    info.derivative_bound[1] = std::sqrt(2.0) * std::exp(-0.5) * m;
    info.derivative_bound[2] = 2.0 * m * m;
    info.derivative_bound[4] = detail::finite_bound(12.0 * m * m * m * m);
    // g_j(x) = e^{−a²(x − u)²}: g⁽ᵏ⁾ = aᵏ·(d/dt)ᵏe^{−t²} at t = a(x − u) (Hermite polynomials).
    std::vector<std::optional<endpoint_factor>> factors;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double a = a_[j], u = u_[j];
      const auto at = [a, u](double x) {
        return [a, u, x](std::size_t k) {
          return std::pow(a, static_cast<double>(k)) * endpoint::gaussian(k, a * (x - u));
        };
      };
      factors.push_back(
          endpoint::factor_of(at(0.0), at(1.0), 0.0, 1.0, detail::gaussian_factor_integral(a, u)));
    }
    info.endpoint_derivatives = endpoint::product_of(1.0, std::move(factors));
    // E g is the factor's integral; E g² = E e^{−2a²(x−u)²}, the same with a√2.
    separable_moments moments;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double square = detail::gaussian_factor_integral(std::numbers::sqrt2 * a_[j], u_[j]);
      moments.factors.push_back({detail::gaussian_factor_integral(a_[j], u_[j]), square, square});
    }
    info.moments = std::move(moments);
    return info;
  }
  const std::vector<double>& a() const noexcept { return a_; }
  const std::vector<double>& u() const noexcept { return u_; }

 private:
  std::vector<double> a_, u_, a2_;
  double exact_;
};

class genz_continuous {
 public:
  genz_continuous(std::vector<double> a, std::vector<double> u)
      : a_(std::move(a)), u_(std::move(u)) {
    detail::validate_genz(a_, u_, true);
    // Every factor is in (0, 1] (it integrates a function ≤ 1 over [0, 1]), and a normal aᵢ
    // keeps 2/aᵢ finite.
    std::vector<double> factors;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      factors.push_back(detail::continuous_factor_integral(a_[j], u_[j]));
    }
    exact_ = detail::scaled_product(factors);
    detail::require_representable(exact_, true, a_, "genz_continuous", factors);
  }
  std::size_t dimension() const noexcept { return a_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = a_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double e = 0.0;
      for (std::size_t j = 0; j < s; ++j) e += a_[j] * std::abs(x[i * s + j] - u_[j]);
      y[i] = -e;
    }
    vector_exp(y, y);
  }
  integrand_info info() const {
    auto info =
        detail::genz_info(genz_family::continuous, "exp(−Σ aᵢ|xᵢ − uᵢ|)", a_.size(), exact_,
                          "closed form Π [2 − e^{−aᵢuᵢ} − e^{−aᵢ(1−uᵢ)}]/aᵢ", smoothness::c0);
    info.derivative_bound[0] = 1.0;                  // at x = u
    info.derivative_bound[1] = detail::max_abs(a_);  // one-sided, next to x = u
    // g_j(x) = e^{−a|x − u|}: e^{a(x − u)} left of u, e^{−a(x − u)} right of it, so g⁽ᵏ⁾ is
    // aᵏ·g on the left and (−a)ᵏ·g on the right, and at an interior u every derivative of odd
    // order jumps by (−a)ᵏ − aᵏ = −2aᵏ (a kink of g' and of every odd derivative).
    std::vector<std::optional<endpoint_factor>> factors;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double a = a_[j], u = u_[j];
      const auto at = [a, u](double x, bool right) {
        return [a, u, x, right](std::size_t k) {
          const double rate = right ? -a : a;
          return std::pow(rate, static_cast<double>(k)) * std::exp(-a * std::abs(x - u));
        };
      };
      std::vector<derivative_jump> kinks;
      if (u > 0.0 && u < 1.0) {
        derivative_jump kink{u, std::vector<std::complex<double>>(endpoint_derivative_count)};
        for (std::size_t k = 1; k < endpoint_derivative_count; ++k) {
          kink.jumps[k] =
              std::pow(-a, static_cast<double>(k)) - std::pow(a, static_cast<double>(k));
        }
        kinks.push_back(std::move(kink));
      }
      factors.push_back(endpoint::factor_of(at(0.0, u == 0.0), at(1.0, u < 1.0), 0.0, 1.0,
                                            detail::continuous_factor_integral(a, u),
                                            std::move(kinks)));
    }
    info.endpoint_derivatives = endpoint::product_of(1.0, std::move(factors));
    // E g is the factor's integral; E g² = E e^{−2a|x−u|}, the same with 2a.
    separable_moments moments;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double square = detail::continuous_factor_integral(2.0 * a_[j], u_[j]);
      moments.factors.push_back({detail::continuous_factor_integral(a_[j], u_[j]), square, square});
    }
    info.moments = std::move(moments);
    return info;
  }
  const std::vector<double>& a() const noexcept { return a_; }
  const std::vector<double>& u() const noexcept { return u_; }

 private:
  std::vector<double> a_, u_;
  double exact_;
};

class genz_discontinuous {
 public:
  // cut: 1-based indices of the coordinates that are cut at uᵢ, distinct, within 1..s; empty
  // means Genz's {1, 2} ({1} when s = 1).
  genz_discontinuous(std::vector<double> a, std::vector<double> u,
                     std::vector<std::size_t> cut = {})
      : a_(std::move(a)), u_(std::move(u)), cut_(std::move(cut)) {
    detail::validate_genz(a_, u_, false);
    const std::size_t s = a_.size();
    if (cut_.empty()) cut_ = s == 1 ? std::vector<std::size_t>{1} : std::vector<std::size_t>{1, 2};
    // Non-cut coordinates get threshold +∞ so the kernel tests every coordinate without a branch.
    threshold_.assign(s, std::numeric_limits<double>::infinity());
    for (std::size_t c : cut_) {
      require(c >= 1 && c <= s, "cut", c, fmt::format("indices in 1..{} (1-based)", s));
      require(std::isinf(threshold_[c - 1]), "cut", c, "distinct indices");
      threshold_[c - 1] = u_[c - 1];
      // f is 0 beyond a cut coordinate's uᵢ, so uᵢ = 0 makes the integral 0: refused here as u,
      // the parameter at fault (below, the zero reference was blamed on a).
      require(u_[c - 1] > 0.0, "u", u_[c - 1],
              fmt::format("uᵢ > 0 for the cut coordinate {} (f = 0 for xᵢ > uᵢ: uᵢ = 0 makes the "
                          "integral 0, which leaves no relative error to measure)",
                          c));
    }
    // f's largest value is e^peak, peak = Σ max(0, aᵢ·upperᵢ): it must be finite, or exp(Σaᵢxᵢ)
    // overflows at the corner. Then no factor of the closed form exceeds e^{aᵢ·upperᵢ}, so only
    // an underflow on the way can spoil the product, which scaled_product handles.
    std::vector<double> factors;
    for (std::size_t j = 0; j < s; ++j) {
      const double upper = std::min(threshold_[j], 1.0);
      factors.push_back(detail::exponential_integral(a_[j], upper));
      peak_ += std::max(0.0, a_[j] * upper);
    }
    require(std::exp(peak_) <= std::numeric_limits<double>::max(), "a",
            fmt::format("[{}]", fmt::join(a_, ", ")),
            fmt::format("parameters with a finite largest value e^(Σ max(0, aᵢ·upperᵢ)) "
                        "(the exponent is {:.6g}, above ln(DBL_MAX) ≈ 709.78)",
                        peak_));
    exact_ = detail::scaled_product(factors);
    detail::require_representable(exact_, true, a_, "genz_discontinuous", factors);
  }
  std::size_t dimension() const noexcept { return a_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = a_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double e = 0.0;
      for (std::size_t j = 0; j < s; ++j) e += a_[j] * x[i * s + j];
      y[i] = e;
    }
    vector_exp(y, y);
    // The cut after the exponential, not as exp(−inf): libmvec sends lanes with special values
    // to a slow scalar path, and about half the points of a typical cut lie outside.
    for (std::size_t i = 0; i < y.size(); ++i) {
      bool inside = true;
      for (std::size_t j = 0; j < s; ++j) inside &= x[i * s + j] <= threshold_[j];
      y[i] = inside ? y[i] : 0.0;
    }
  }
  integrand_info info() const {
    auto info = detail::genz_info(
        genz_family::discontinuous,
        fmt::format("0 if x_c > u_c for c in {{{}}}, else exp(Σ aᵢxᵢ)", fmt::join(cut_, ", ")),
        a_.size(), exact_, "closed form Π_{i∈cut}(e^{aᵢuᵢ} − 1)/aᵢ · Π_{i∉cut}(e^{aᵢ} − 1)/aᵢ",
        smoothness::discontinuous);
    info.derivative_bound[0] = std::exp(peak_);
    // f = Π_j g_j(x_j) with g_j(x) = e^{a_j x}, times 1{x ≤ u_j} on a cut axis. On a piece,
    // |g_j⁽ᵏ⁾| = |a_j|ᵏ e^{a_j x} ≤ |a_j|ᵏ e^{max(0, a_j·upper)} (the exponential is monotone, the
    // piece right of the cut is 0). The cut at u_j ∈ (0, 1) is a jump of size e^{a_j u_j}, with
    // g_j(u_j) the left limit (x ≤ u_j is inside); at u_j = 1 there is none; at u_j = 0 only the
    // point value g_j(0) = 1 differs from the limit 0 from the right (an end-point jump).
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double upper = std::min(threshold_[j], 1.0);
      piecewise_smooth_factor factor;
      if (upper < 1.0) factor.jumps.push_back({upper, std::exp(a_[j] * upper)});
      const double top = std::exp(std::max(0.0, a_[j] * upper));
      double power = 1.0;
      for (std::size_t k = 0; k < factor.derivative_bound.size(); ++k) {
        factor.derivative_bound[k] = power * top;
        power *= std::abs(a_[j]);
      }
      factor.integral = detail::exponential_integral(a_[j], upper);
      info.separable_factors.push_back(std::move(factor));
    }
    // E g = ∫₀^upper e^{ax} dx; E g² is the same with 2a.
    separable_moments moments;
    for (std::size_t j = 0; j < a_.size(); ++j) {
      const double upper = std::min(threshold_[j], 1.0);
      const double square = detail::exponential_integral(2.0 * a_[j], upper);
      moments.factors.push_back({detail::exponential_integral(a_[j], upper), square, square});
    }
    info.moments = std::move(moments);
    return info;
  }
  const std::vector<double>& a() const noexcept { return a_; }
  const std::vector<double>& u() const noexcept { return u_; }
  const std::vector<std::size_t>& cut() const noexcept { return cut_; }

 private:
  std::vector<double> a_, u_;
  std::vector<std::size_t> cut_;
  std::vector<double> threshold_;
  double peak_ = 0.0, exact_ = 1.0;
};

}  // namespace quadmc
