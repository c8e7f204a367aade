// The point-set interface: N points in [0,1)^s, generated in batches by index.
//
// Use it for every Monte Carlo estimator of this library: estimators are templates over a
// point_set, so independent, stratified, padded and Latin hypercube points share one kernel.
// Not for warped samples (sampling/warp.hpp maps a point of [0,1)^s to a domain and a pdf).
//
// Contract (docs/design.md#hot-path-contract):
//  - generate(first, out) writes points [first, first + out.size()/s) row-major into out,
//    out[i*s + j] = coordinate j of point first + i, every coordinate in [0, 1).
//  - A point is a pure function of (the set's parameters, seed, stream, point index): batches
//    may be generated in any order and on any thread with bitwise identical results. Uniform
//    number i·s + j of quadmc::random_stream(seed, stream) is the jitter of coordinate j of point
//    i; permutation keys come from the top of the counter space (index 2^64 − 1 − g), which no
//    point reaches because N·s < 2^62 is required.
//  - Only the dimensions asked for are generated: s is the integrand's dimension.
//
// A point set also says how an estimator can estimate its own error from one run
// (variance_structure), because the textbook σ̂²/N is right for independent points only:
// stratified points have a smaller variance (docs/theory.md#stratified-vs-random), and a
// grid of centres has none that one run can see.
#pragma once

#include "quadmc/core/errors.hpp"

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

namespace quadmc {

// How the sampling error of a mean over the points can be estimated from the points themselves.
enum class variance_kind {
  // Independent points: V̂[F] = σ̂²/N with the sample variance σ̂²
  // (docs/theory.md#the-monte-carlo-estimator).
  independent,
  // `group` ≥ 2 consecutive points per equal-volume stratum (K = N/group strata): the stratified
  // estimator's own estimate V̂[F] = Σ vᵢ²σ̂ᵢ²/nᵢ = Σ σ̂ᵢ²/(K²·group)
  // (docs/theory.md#stratified-vs-random).
  within_strata,
  // One point per stratum, strata in row-major order with rows of `group` strata along the last
  // axis: σᵢ² cannot be estimated from one point, so triples of neighbouring strata in a row give
  // (a − 2b + c)²/6, whose mean is (σa² + 4σb² + σc²)/6 + (μa − 2μb + μc)²/6. Second differences
  // cancel the linear trend of a smooth f across strata (the bias is O(h⁴) against σ² = O(h²));
  // at a discontinuity the bias is positive (conservative). The successive-difference estimators
  // of systematic sampling ([Wolter, ch. 8]; docs/theory.md#jittered-error-estimate).
  stratum_differences,
  // Dependent points whose variance has no unbiased one-run estimate (Latin hypercube, padded):
  // σ̂²/N is reported. For Latin hypercube it is an upper bound up to N/(N − 1): V_LHS ≤
  // σ²/(N − 1) ([Owen 1997]). For padded jittered points it is an approximate upper bound (each
  // group is stratified, which never increases variance under proportional allocation).
  independent_bound,
  // No one-run error estimate exists: stratum centres (deterministic, or all shifted by one
  // shared random vector). NaN is reported, never a made-up number.
  not_estimable,
};

struct variance_structure {
  variance_kind kind = variance_kind::independent;
  std::uint64_t group = 1;  // see variance_kind: points per stratum, or strata per row

  // Number of consecutive points an estimator must see together (never split across chunks).
  constexpr std::uint64_t points_per_group() const noexcept {
    switch (kind) {
      case variance_kind::within_strata:
        return group;
      case variance_kind::stratum_differences:
        return 3;
      default:
        return 1;
    }
  }
};

template <class P>
concept point_set = requires(const P& p, std::uint64_t first, std::span<double> out) {
  { p.size() } -> std::convertible_to<std::uint64_t>;
  { p.dimension() } -> std::convertible_to<std::size_t>;
  { p.generate(first, out) } -> std::same_as<void>;
  { p.variance() } -> std::convertible_to<variance_structure>;
};

// Largest 2^-53 multiple below 1: coordinates (c + u)/k can round up to exactly 1 when
// u > 1 − 2^-53·c, and the contract promises [0, 1).
inline constexpr double largest_below_one = 0x1.fffffffffffffp-1;

// Validates (s, N) at construction, so generate() never checks per point. N·s < 2^62 keeps the
// uniform counter i·s + j below the permutation keys at the top of the counter space.
inline void require_point_set_size(std::size_t s, std::uint64_t n) {
  require(s >= 1, "dimension s", s, "s ≥ 1");
  require(n >= 1, "number of points N", n, "N ≥ 1");
  require(n <= (std::uint64_t{1} << 62) / s, "number of points N", n,
          "N·s < 2^62 (the counter space of one random stream)");
}

// Validates a generate() request: whole points, inside [0, N). Once per batch, not per point.
inline void require_batch(std::size_t s, std::uint64_t n, std::uint64_t first,
                          std::span<const double> out) {
  require(out.size() % s == 0, "batch size", out.size(), "a multiple of the dimension s");
  require(first <= n && out.size() / s <= n - first, "batch first point", first,
          "a batch inside [0, N)");
}

}  // namespace quadmc
