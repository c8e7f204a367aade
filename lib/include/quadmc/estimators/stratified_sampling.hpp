// The stratified estimator ([Ramamoorthi 2009, §4.2]): k^s equal strata of the integrand's box, m
// uniform points in each (nᵢ = vᵢn with n = m·k^s), F = Σ vᵢFᵢ, and its own variance estimate
// V̂[F] = Σ vᵢ²σ̂ᵢ²/nᵢ from the per-stratum sample variances (needs m ≥ 2; with m = 1 the
// second-difference estimate of jittered_points.hpp is used instead).
//
// Use it to measure the theorem V_strat = (1/n)Σvᵢσᵢ² ≤ V_random
// (docs/theory.md#stratified-vs-random; [Stratified vs random 2023]), or whenever N can be m·k^s.
// Not for high s (k^s strata).
#pragma once

#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/stratum_grid.hpp"

#include <cstdint>

namespace quadmc {

template <integrand F>
estimate stratified_sampling(const F& f, std::uint64_t strata_per_axis,
                             std::uint64_t points_per_stratum, std::uint64_t seed,
                             std::uint64_t stream, unsigned threads = 1) {
  const jittered_points points(stratum_grid(f.dimension(), strata_per_axis), points_per_stratum,
                               seed, stream);
  return monte_carlo(f, points, threads);
}

}  // namespace quadmc
