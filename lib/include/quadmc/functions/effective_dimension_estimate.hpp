// Effective dimensions estimated from evaluations of f, for integrands that are not products of
// one-variable factors (those have exact ones: effective_dimension.hpp). Pick-freeze estimators
// of Sobol' indices (docs/theory.md#estimated-effective-dimension): with two independent uniform
// samples A, B (n rows each) and hybrid rows that take some coordinates from A and the rest from
// B,
//  - truncation: the closed share of x₁…x_d, 1 − E(f(A) − f(A_{≤d}, B_{>d}))²/(2σ²)
//    [Jansen 1999], found by bisection over d (the curve rises with d; its estimate need not
//    exactly, and the bisection then finds a crossing of q, not necessarily the first);
//  - superposition: the first-order share Σⱼ Sⱼ, Sⱼσ² = E f(B)·(f(A with xⱼ from B) − f(A))
//    [Saltelli 2002], [Saltelli et al. 2010], and the mean dimension Σⱼ Tⱼ = Σ_u |u|σ²_u/σ²
//    [Liu & Owen 2006], Tⱼσ² = E(f(A) − f(A with xⱼ from B))²/2 [Jansen 1999], from s more
//    evaluations per row: d_S = 1 where the first-order share's interval lies above q, d_S ≥ 2
//    where it lies below.
// Every share is a ratio of two means over the same rows, its interval from the delta method
// (the variance of u − R·w, R = ū/w̄), both cut to [0, 1] (the mean dimension to [1, s]).
// Deterministic: one Philox stream from `seed`, one thread.
//
// Use it beside the exact form; never for an integrand whose evaluations cost more than the run
// itself can spend (about (3·log₂ s + 4)·n evaluations, plus s·n' for the superposition part).
// Not for s above a few thousand: every evaluation reads s coordinates.
#pragma once

#include "quadmc/functions/any_integrand.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace quadmc {

// A share of the variance (or the mean dimension) and its interval.
struct estimated_share {
  double value = 0.0;
  double low = 0.0;
  double high = 0.0;
};

struct effective_dimension_estimate_options {
  std::size_t samples = 4096;  // n: rows of A and of B
  double share = 0.99;         // q
  double confidence = 0.95;    // two-sided, of every interval
  // The superposition part evaluates f at s hybrid rows of s coordinates per row of A, s² per
  // row: it uses the first n' = min(n, first_order_coordinates / s²) rows (n' = 64 at s = 1024),
  // and is skipped when n' < 64.
  std::uint64_t first_order_coordinates = std::uint64_t{1} << 26;
};

struct effective_dimension_estimate {
  double share = 0.99;
  double confidence = 0.95;
  std::size_t samples = 0;        // n
  std::uint64_t evaluations = 0;  // of f, in all
  double variance = 0.0;          // σ̂², from the 2n rows of A and B
  // d_T from the point estimates; the interval's ends are the d at which the upper and the lower
  // bound of the closed share reach q.
  std::size_t truncation = 0;
  std::size_t truncation_low = 0;
  std::size_t truncation_high = 0;
  estimated_share first_coordinate;  // the closed share of x₁ alone
  // nullopt where 64 rows would take more than first_order_coordinates.
  std::optional<estimated_share> first_order;     // Σⱼ Sⱼ
  std::optional<estimated_share> mean_dimension;  // Σⱼ Tⱼ
  std::size_t first_order_samples = 0;            // n'
  // d_S ∈ [superposition_low, superposition_high] as the share of order 1 decides it: [1, 1]
  // where its interval lies above q, [2, 0] where below, [1, 0] where it holds q (0: no upper
  // bound known); [0, 0] where it was not estimated.
  std::size_t superposition_low = 0;
  std::size_t superposition_high = 0;
};

// nullopt for s < 2, or when f's estimated variance is 0 or not finite; throws invalid_argument
// for samples < 2, a share outside (0, 1] or a confidence outside (0, 1).
std::optional<effective_dimension_estimate> estimate_effective_dimensions(
    const any_integrand& f, std::uint64_t seed, const effective_dimension_estimate_options& = {});

}  // namespace quadmc
