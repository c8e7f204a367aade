// The table of theoretical convergence rates: the slope of RMSE (or |error| for a deterministic
// rule) against N = total evaluations, for a method × smoothness class × dimension s.
//
// Use it to put a "theory" column beside every fitted slope and to decide the verdict
// (slope_verdict.hpp). Every entry carries its source: the row of docs/theory.md#rate-table and
// its references ([Key] entries of docs/references.md). Not a bound with a constant: only the
// exponent; pre-asymptotic ladders can show other slopes (docs/theory.md#pre-asymptotic-ladders:
// fit slopes, never compare with an asymptotic formula such as (log N)^s/N).
//
// Methods are the scene names: left_rectangle, right_rectangle, midpoint, trapezoid, simpson,
// gauss_legendre, romberg, plain_mc, jittered, unjittered, padded_jittered, latin_hypercube,
// importance. Smoothness classes are quadmc::to_string(smoothness): analytic, smooth, C0,
// discontinuous, singular (taken as a string so this layer needs only core).
// Deterministic rules are tensor products with n nodes per axis, N = nˢ, so a 1D rate n^−r
// becomes N^(−r/s). Assumptions the class string cannot carry are stated in the note:
// "smooth" means smooth enough for the rule's full order; "singular" means an integrable
// endpoint singularity of the √x kind (docs/theory.md#endpoint-singularities), and plain Monte
// Carlo needs finite variance (1/√x has none: docs/theory.md#infinite-variance).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

struct theoretical_rate {
  std::optional<double> slope;  // empty: no finite algebraic slope (exponential) or no entry
  std::string note;             // the assumption or why there is no slope
  std::string source;           // where the rate comes from
};

// Throws invalid_argument for an unknown smoothness class or s = 0. An unknown method returns an
// empty slope with the note "no entry for method …", so a new method never stops a run.
// `order` is the rule's order r where the method's name does not fix it (gauss_legendre: 2m);
// 0 when unknown. `singularity_exponent` is α for a "singular" f ~ x^α at an endpoint (α = 0
// for log x): composite rules then converge as n^−min(r, 1+α), and Monte Carlo has no finite
// variance for α ≤ −1/2. NaN = not given: the √x case (α = 1/2) is assumed
// (docs/theory.md#endpoint-singularities).
theoretical_rate theoretical_slope(
    std::string_view method, std::string_view smoothness, std::size_t s, int order = 0,
    double singularity_exponent = std::numeric_limits<double>::quiet_NaN());

// The method names and smoothness classes the table knows, in table order.
std::span<const std::string_view> tabulated_methods() noexcept;
std::span<const std::string_view> smoothness_classes() noexcept;

}  // namespace quadmc
