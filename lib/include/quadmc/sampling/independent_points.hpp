// Independent uniform points in [0,1)^s: plain Monte Carlo (docs/theory.md#plain-monte-carlo).
//
// Use it as the baseline every other point set is measured against, and where nothing is known
// about the integrand. Its error is σ/√N in any dimension
// (docs/theory.md#the-monte-carlo-estimator); for smooth integrands in low dimension, jittered or
// Latin hypercube points converge faster.
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace quadmc {

class independent_points {
 public:
  independent_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                     std::uint64_t stream, rng_kind rng = rng_kind::philox4x32_10)
      : s_(dimension), n_(n), rng_(seed, stream, rng) {
    require_point_set_size(dimension, n);
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  variance_structure variance() const noexcept { return {variance_kind::independent, 1}; }

  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    // Coordinate j of point i is uniform number i·s + j: the batch is one contiguous run.
    rng_.fill_uniform(first * s_, out);
  }

 private:
  std::size_t s_;
  std::uint64_t n_;
  random_stream rng_;
};

}  // namespace quadmc
