// Theoretical slopes; the table's conventions are in theoretical_rate.hpp, its rows in
// docs/theory.md#rate-table.
#include "quadmc/analysis/theoretical_rate.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace quadmc {
namespace {

constexpr std::array<std::string_view, 13> methods = {
    "left_rectangle",  "right_rectangle", "midpoint",  "trapezoid", "simpson",
    "gauss_legendre",  "romberg",         "plain_mc",  "jittered",  "unjittered",
    "padded_jittered", "latin_hypercube", "importance"};
constexpr std::array<std::string_view, 5> classes = {"analytic", "smooth", "C0", "discontinuous",
                                                     "singular"};

constexpr const char* newton_cotes_source = "docs/theory.md#tensor-rules; [Burden & Faires, §4.4]";
constexpr const char* jump_source = "docs/theory.md#jumps";
constexpr const char* kink_source = "docs/theory.md#kinks";
constexpr const char* sqrt_source = "docs/theory.md#endpoint-singularities";

// A tensor Newton–Cotes rule of order r on smooth f; the other classes cap the order.
theoretical_rate newton_cotes(int order, std::string_view cls, double s, double alpha) {
  if (cls == "analytic" || cls == "smooth") {
    return {-order / s, fmt::format("order {} rule, f ∈ C^{} assumed", order, order),
            newton_cotes_source};
  }
  if (cls == "C0") {
    // A kink costs O(h²) in its panel; rules of order < 2 keep their own order.
    const int r = std::min(order, 2);
    return {-r / s, "piecewise C² with a kink: order capped at 2", kink_source};
  }
  if (cls == "discontinuous") {
    return {-1.0 / s, "jump: O(n^-1), not monotone in n", jump_source};
  }
  // singular with a known exponent, f ~ x^α: the panel at the singularity errs by
  // ∫₀ʰ x^α dx = O(h^(1+α)) (docs/theory.md#endpoint-singularities; [Davis & Rabinowitz, §2.12]),
  // the others by O(h^r): the rate is n^−min(r, 1+α); for α = 0 (log x) up to a log n factor.
  if (std::isfinite(alpha)) {
    const double rate = std::min(static_cast<double>(order), 1.0 + alpha);
    return {-rate / s,
            fmt::format("endpoint singularity f ~ x^{}: order min(r, 1 + α) = {}{}", alpha, rate,
                        alpha == 0.0 ? " (log x: up to a log n factor)" : ""),
            "docs/theory.md#endpoint-singularities; [Davis & Rabinowitz, §2.12]"};
  }
  // singular: √x-type endpoint singularity. Rectangles keep O(h) (f monotone, bounded variation).
  if (order == 1) {
    return {-1.0 / s, "√x-type singularity: f of bounded variation keeps O(h)",
            "docs/theory.md#endpoint-singularities (rectangles); [Burden & Faires, §4.4]"};
  }
  return {-1.5 / s, "√x-type endpoint singularity assumed", sqrt_source};
}

}  // namespace

std::span<const std::string_view> tabulated_methods() noexcept {
  return methods;
}
std::span<const std::string_view> smoothness_classes() noexcept {
  return classes;
}

theoretical_rate theoretical_slope(std::string_view method, std::string_view cls,
                                   std::size_t dimension, int order, double alpha) {
  require(std::find(classes.begin(), classes.end(), cls) != classes.end(), "smoothness",
          std::string(cls), "one of analytic, smooth, C0, discontinuous, singular");
  require(dimension >= 1, "s", dimension, "a dimension >= 1");
  const double s = static_cast<double>(dimension);

  if (method == "left_rectangle" || method == "right_rectangle")
    return newton_cotes(1, cls, s, alpha);
  if (method == "midpoint" || method == "trapezoid") {
    theoretical_rate rate = newton_cotes(2, cls, s, alpha);
    if (method == "trapezoid" && cls == "analytic") {
      rate.note +=
          "; exponential instead if f is periodic (docs/theory.md#exponential-convergence)";
    }
    return rate;
  }
  if (method == "simpson") return newton_cotes(4, cls, s, alpha);
  if (method == "unjittered") {
    // pbrt's unjittered stratified sampler puts one point at each cell centre: a midpoint grid
    // (docs/theory.md#unjittered).
    theoretical_rate rate = newton_cotes(2, cls, s, alpha);
    rate.note = "cell-centre grid = tensor midpoint rule; " + rate.note;
    return rate;
  }
  if (method == "gauss_legendre" && order > 0) {
    // Composite Gauss–Legendre with m nodes per panel and n panels: error O(n^-2m) for
    // f ∈ C^2m (docs/theory.md#gauss-legendre; [Davis & Rabinowitz, §2.7]), so a fixed m is an
    // algebraic rule of order r = 2m, and a kink, jump or √x caps it like any composite rule.
    theoretical_rate rate = newton_cotes(order, cls, s, alpha);
    rate.note = fmt::format("composite Gauss–Legendre, order 2m = {}; ", order) + rate.note;
    if (cls == "analytic" || cls == "smooth") {
      rate.source = "docs/theory.md#gauss-legendre; [Davis & Rabinowitz, §2.7]";
    }
    return rate;
  }
  if (method == "gauss_legendre" || method == "romberg") {
    if (cls == "analytic") {
      return {std::nullopt, "exponential convergence: no finite algebraic slope",
              "docs/theory.md#exponential-convergence; [Trefethen ATAP, Thm 19.3]"};
    }
    if (cls == "smooth") {
      return {std::nullopt, "algebraic of the order of f's smoothness, unknown from the class",
              "docs/theory.md#exponential-convergence; [Trefethen ATAP, Thm 19.3]"};
    }
    if (method == "romberg") {
      // Richardson extrapolation assumes the Euler–Maclaurin expansion in h²; a kink, jump or
      // √x breaks it past its first term, leaving the trapezoid rate.
      theoretical_rate rate = newton_cotes(2, cls, s, alpha);
      rate.note = "extrapolation gains nothing past the trapezoid rate; " + rate.note;
      return rate;
    }
    if (cls == "discontinuous") {
      return {-1.0 / s, "jump: O(node spacing) for nodes of density ~n", jump_source};
    }
    return {std::nullopt, "not tabulated for Gauss–Legendre on this class",
            "docs/theory.md#gauss-legendre; [Trefethen ATAP, Thm 19.3] bounds only"};
  }
  const bool random_method = method == "plain_mc" || method == "jittered" ||
                             method == "unjittered" || method == "padded_jittered" ||
                             method == "latin_hypercube" || method == "importance" ||
                             method.starts_with("irradiance_");
  if (random_method && cls == "singular" && std::isfinite(alpha) && alpha <= -0.5) {
    // ∫f² = ∫x^(2α) diverges for α ≤ −1/2: no finite variance, so neither σ/√N nor the CLT
    // holds (docs/theory.md#infinite-variance); the error still shrinks, at no tabulated rate.
    return {std::nullopt, fmt::format("f ~ x^{}: infinite variance, no σ/√N rate", alpha),
            "docs/theory.md#infinite-variance"};
  }
  if (method.starts_with("irradiance_")) {
    // Uniform-hemisphere, cosine-weighted and light-area sampling are importance sampling with
    // bounded weights: finite variance, so σ/√N; only the constant σ differs
    // (docs/theory.md#irradiance-estimators).
    return {-0.5, "importance sampling with bounded f/p: finite variance, σ/√N",
            "docs/theory.md#irradiance-estimators; [Ramamoorthi 2009, §2.2.3, §4.1]"};
  }
  if (method == "plain_mc") {
    return {-0.5, "σ/√N, finite variance assumed",
            "docs/theory.md#plain-monte-carlo; [Ramamoorthi 2009, §2.2.2]"};
  }
  // In one dimension a Latin hypercube is one point per stratum: jittered sampling exactly (its
  // additive part is all of f, so Stein's residual e vanishes: docs/theory.md#latin-hypercube).
  const bool one_point_per_stratum = method == "jittered" ||
                                     (method == "padded_jittered" && dimension <= 2) ||
                                     (method == "latin_hypercube" && dimension == 1);
  if (one_point_per_stratum) {
    if (cls == "discontinuous") {
      return {-0.5 - 1.0 / (2.0 * s), "indicator of a smooth-boundary region",
              "docs/theory.md#jittered; [Mitchell 1996]; [Pilleboue et al. 2015]"};
    }
    if (cls == "singular") {
      return {std::nullopt, "not tabulated for a singular f", "docs/theory.md#jittered"};
    }
    return {-0.5 - 1.0 / s, "one point per cell, N = m^s; f Lipschitz (C0 kinks included)",
            "docs/theory.md#jittered; [Mitchell 1996]; [Pilleboue et al. 2015]"};
  }
  if (method == "padded_jittered") {
    return {-0.5,
            "padding stratifies only 2D projections: plain MC rate unless f is a sum of 2D parts",
            "docs/theory.md#padded-jittered; [Pharr et al. 2023, §8.5]; [Veach 1997, eq. 2.26]"};
  }
  if (method == "latin_hypercube") {
    return {-0.5, "removes the additive part of f; O(N^-1/2) in general",
            "docs/theory.md#latin-hypercube; [McKay et al. 1979]; [Stein 1987]; [Owen 1992]"};
  }
  if (method == "importance") {
    return {-0.5, "(∫f²/p − I²)/N; zero variance (no slope, rounding floor) iff p ∝ f ≥ 0",
            "docs/theory.md#importance; [Ramamoorthi 2009, §4.1]"};
  }
  return {std::nullopt, fmt::format("no entry for method {}", method), ""};
}

}  // namespace quadmc
