// The integrand interface: what every test function provides and every rule/estimator consumes.
//
// Batch contract (the layout of cubature's integrand_v): a batch of n points in s dimensions is
// one contiguous row-major block, x[i*s + j] = coordinate j of point i, and the integrand writes
// f(point i) into y[i]; y.size() == n == x.size() / s. Points are in the integrand's own domain
// (its box), not in [0,1)^s: mapping the unit cube to the box is the caller's job. Kernels take
// integrands as template parameters (static dispatch, inlined); the runner uses any_integrand,
// which costs one virtual call per batch, never per point.
//
// Metadata (integrand_info) travels with each function so that a convergence study never needs
// to look a reference value up elsewhere: the exact integral, the smoothness class that decides
// the theoretical rate, derivative bounds M_k = max|f^(k)| that the a-priori error bounds of
// the rules need, for a discontinuous f that is a product of one-variable pieces its jumps
// (separable_factors), from which a rule's error envelope is bounded, for a smooth or kinked f
// that is (the real part of) a product of one-variable factors the end-point derivatives of each
// factor (endpoint_derivatives), from which the Euler–Maclaurin expansion predicts a composite
// rule's error (rules/euler_maclaurin.hpp), and the precision f is evaluated in, which sets the
// rounding floor.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/evaluation_precision.hpp"
#include "quadmc/core/smoothness.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <concepts>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

// An axis-aligned box Π[lower_j, upper_j].
struct box {
  std::vector<double> lower;
  std::vector<double> upper;

  std::size_t dimension() const noexcept { return lower.size(); }
  double volume() const noexcept {
    double v = 1.0;
    for (std::size_t j = 0; j < lower.size(); ++j) v *= upper[j] - lower[j];
    return v;
  }
  static box unit(std::size_t s) {
    return box{std::vector<double>(s, 0.0), std::vector<double>(s, 1.0)};
  }
};

// A jump of a function g of one variable at c = `location`: size = |g(c+) − g(c−)|. At an end
// point of the interval, size = |g(c) − the limit from inside| (a single point value that differs:
// rules with a node there see it). The value g(c) at an interior jump lies between the two
// one-sided limits (it equals one of them for every family here): the jump envelopes of
// rules/jump_error_envelope.hpp rely on that.
struct jump_discontinuity {
  double location = NAN;
  double size = NAN;
};

// One factor g_j of a separable integrand f(x) = Π_j g_j(x_j): a function of coordinate j on
// [domain.lower[j], domain.upper[j]], smooth between finitely many jumps (in 1D, f itself).
struct piecewise_smooth_factor {
  std::vector<jump_discontinuity> jumps{};  // ascending locations; empty: smooth on the interval
  // M_k = sup |g⁽ᵏ⁾| over the open pieces between the jumps (one-sided limits at them), k = 0…4;
  // empty where unknown. 0 for k ≥ 1 on a piecewise-constant factor.
  std::array<std::optional<double>, 5> derivative_bound{};
  double integral = NAN;  // ∫ g_j over its interval
};

// How many derivatives an endpoint_factor carries: g⁽ᵏ⁾ for k = 0 … endpoint_derivative_count − 1,
// enough for the first three non-vanishing Euler–Maclaurin terms of every rule of rules/ even when
// every other term vanishes (Simpson on 1/(1 + x²) needs f⁽¹³⁾).
inline constexpr std::size_t endpoint_derivative_count = 24;

// A simple pole of a factor g(x) continued to complex x: g(x) ≈ residue/(x − location) near it.
struct simple_pole {
  std::complex<double> location;  // z, in the factor's own coordinate x (Im z ≠ 0)
  std::complex<double> residue;   // r
};

// A point inside a factor's interval where g is continuous but a derivative jumps (a kink):
// jumps[k] = g⁽ᵏ⁾(c+) − g⁽ᵏ⁾(c−) in the unit variable t of endpoint_factor (jumps[0] = 0).
struct derivative_jump {
  double location = NAN;  // c, in the factor's own coordinate x
  std::vector<std::complex<double>> jumps;
};

// One factor g_j(x_j) of f(x) = Re[scale·Π_j g_j(x_j)] on [lower_j, upper_j], described in the
// unit variable t = (x − lower)/(upper − lower), G(t) = g(lower + (upper − lower)·t), so that a
// box of any width (10⁻¹⁰⁰, 10¹⁰⁰) carries finite numbers: at_lower[k] = G⁽ᵏ⁾(0), at_upper[k] =
// G⁽ᵏ⁾(1) (one-sided, from inside), k = 0 … endpoint_derivative_count − 1. Complex so that
// cos(φ + Σaⱼxⱼ) is the real part of a product of e^{iaⱼxⱼ}; a real factor has zero imaginary
// parts.
struct endpoint_factor {
  std::complex<double> integral;  // ∫ g_j dx_j over [lower_j, upper_j] (x units, not t)
  std::vector<std::complex<double>> at_lower;
  std::vector<std::complex<double>> at_upper;
  std::vector<derivative_jump> kinks;  // ascending interior kinks; empty where g is smooth
  // The simple poles of g off the real axis, in x: g = r/(x − z) + (analytic near the strip).
  // They set a composite rule's coarse-grid term, e^(−2π|Im z|/H) (rules/euler_maclaurin.hpp,
  // docs/theory.md#coarse-grid-term), which the end-point series does not show. Empty where g
  // is entire or its singularities are not known in closed form.
  std::vector<simple_pole> poles;
};

// f as Re[scale·Π_j g_j(x_j)], one factor per axis: the end-point data an Euler–Maclaurin error
// prediction needs (rules/euler_maclaurin.hpp), exact in closed form. Re[scale·Π ∫g_j] is the
// exact integral.
struct separable_derivatives {
  std::complex<double> scale{1.0, 0.0};
  std::vector<endpoint_factor> factors;
};

// The moments of one factor g_j(x_j) of f(x) = Re[scale·Π_j g_j(x_j)] over x_j uniform on its
// interval, from which the ANOVA of f follows in closed form (functions/effective_dimension.hpp,
// docs/theory.md#effective-dimension): E g, E|g|² and E g² (E g² = E|g|² for a real factor).
struct factor_moments {
  std::complex<double> mean;
  double mean_abs_square = NAN;
  std::complex<double> mean_square;
};

// f as Re[scale·Π_j g_j(x_j)] with each factor's moments (one per axis, in order).
struct separable_moments {
  std::complex<double> scale{1.0, 0.0};
  std::vector<factor_moments> factors;
};

struct integrand_info {
  std::string name;       // catalogue name as used in scenes, e.g. "genz_gaussian"
  std::string formula;    // one line, for `quadmc list` and the README catalogue
  box domain;             // integration domain; its dimension is s
  double exact = NAN;     // the reference value ∫ f over the domain
  std::string reference;  // how `exact` was obtained, e.g. "closed form", "Lambert polygon"
  smoothness regularity = smoothness::analytic;
  int continuous_derivatives = -1;  // k for smoothness::smooth (C^k); -1 = not applicable
  // M_k = max over the domain of |∂^k f| along one coordinate (1D: |f^(k)|), k = 0…4, where
  // known exactly; empty where unbounded or unknown. Used by the rules' a-priori bounds.
  std::array<std::optional<double>, 5> derivative_bound{};
  // For smoothness::singular in 1D: α where f behaves like x^α at the singular endpoint (α = 0
  // stands for log x). It fixes the rate of every composite rule, O(n^−min(r, 1+α)), and whether
  // f has a finite variance (α > −1/2); NaN where unknown or not of that form.
  double singularity_exponent = NAN;
  // For a discontinuous f that is a product of piecewise-smooth functions of one coordinate each
  // (in 1D: f itself): one factor per axis, the jumps with their sizes and the derivative bounds
  // of the smooth pieces, from which rules/jump_error_envelope.hpp bounds a rule's error on every
  // grid. Empty where f is not of that form: jumps across curved or oblique surfaces (the disk and
  // the half-space for s ≥ 2, the occluded irradiance) keep the slope verdict only.
  std::vector<piecewise_smooth_factor> separable_factors{};
  // For f smooth (or with kinks) and (the real part of) a product of one-variable factors: each
  // factor's end-point derivatives, in closed form. Empty where f is not of that form or has
  // jumps (separable_factors bound those), or where a derivative overflows.
  std::optional<separable_derivatives> endpoint_derivatives{};
  // For f (the real part of) a product of one-variable factors: their moments, in closed form,
  // from which its effective dimensions are exact. Empty where f is not of that form.
  std::optional<separable_moments> moments{};
  // The format f's values are computed in: float for the float twins of the stress scene (their
  // rounding floor is float's, not double's: analysis/rounding_floor.hpp).
  evaluation_precision precision = evaluation_precision::double_precision;
  // Points per call of evaluate this integrand asks the fixed-N kernels for (the Monte Carlo
  // kernel, estimators/sample_mean.hpp, and the rule kernel, rules/weighted_sum.hpp): 0 for one
  // batch of 256 (core/batching.hpp), whose points stay in L1; a Python callable, whose every
  // call costs microseconds, asks for thousands. The kernels still sum per batch, so a value
  // does not depend on it. Methods that adapt between batches (VEGAS, Genz–Malik, the adaptive
  // sparse grid) call evaluate on their own batches.
  std::size_t evaluation_block = 0;

  std::size_t dimension() const noexcept { return domain.dimension(); }
};

// Anything that evaluates a batch of points. info() is required so every integrand can say
// what it is and what its integral is.
template <class F>
concept integrand = requires(const F& f, std::span<const double> x, std::span<double> y) {
  { f.dimension() } -> std::convertible_to<std::size_t>;
  { f.evaluate(x, y) } -> std::same_as<void>;
  { f.info() } -> std::convertible_to<integrand_info>;
};

// Reports the first non-finite value of a batch with the point that produced it. One pass over
// the batch after evaluation: the branch is never taken in a healthy run, so it costs a multiply
// and an add per value, not a check inside the integrand. v·0 is 0 for finite v and NaN for ±inf
// or NaN, so interleaved sums of v·0 are NaN exactly when a value is not finite (std::isfinite
// per value does not vectorize). Sixteen independent lanes, not four: with four, each lane's
// chain of additions waited on the previous one (perf: 5.8 % of a rank-1 lattice run at s = 1,
// 3.2 % with sixteen). Any order gives the same answer, so the lane count is free.
inline void check_finite_batch(std::string_view name, std::span<const double> x,
                               std::span<const double> y, std::size_t s) {
  constexpr std::size_t lanes = 16;
  double lane[lanes] = {};
  std::size_t k = 0;
  for (; k + lanes <= y.size(); k += lanes) {
#pragma GCC unroll 16
    for (std::size_t l = 0; l < lanes; ++l) lane[l] += y[k + l] * 0.0;
  }
  double any_nan = 0.0;
  for (; k < y.size(); ++k) any_nan += y[k] * 0.0;
#pragma GCC unroll 16
  for (std::size_t l = 0; l < lanes; ++l) any_nan += lane[l];
  if (!std::isnan(any_nan)) [[likely]]
    return;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y[i])) throw non_finite_value(name, x.subspan(i * s, s), y[i]);
  }
}

}  // namespace quadmc
