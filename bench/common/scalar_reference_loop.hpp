// The reference every throughput ratio is taken against: the single-thread loop a user writes by
// hand when no library is at hand. xoshiro256+, s uniforms per point, the integrand inlined,
// scalar, a plain running sum (the hand-written single-thread loop of
// docs/design.md#performance-targets).
//
// Use it as the 1.0 of the ratio_to_scalar_loop column, in both the peers program
// (bench/peers/quadmc_peers) and the Google Benchmark binary (bench/integrators_bench). Not an
// estimator to copy: it has no error estimate, its sequential generator makes a parallel run
// schedule-dependent, and its plain sum carries an εN rounding drift that quadmc's Neumaier sum
// avoids (Boost's naive_monte_carlo.hpp explains why that drift eventually exceeds σ/√N). Those
// are exactly the costs quadmc's plain Monte Carlo pays on top of this loop, which is what the
// ratio measures.
#pragma once

#include "point_adapter.hpp"
#include "xoshiro256plus.hpp"

#include <array>
#include <cstdint>

namespace quadmc::bench {

struct scalar_loop_result {
  double value = 0.0;             // the sample mean of f over the n points
  std::uint64_t evaluations = 0;  // integrand evaluations spent: n, counted by the loop
};

template <class F>
scalar_loop_result scalar_reference_loop(const F& f, std::uint64_t n, std::uint64_t seed) {
  const std::size_t s = f.dimension();
  xoshiro256plus rng(seed);
  std::array<double, 64> x{};  // s ≤ 64 (the benchmarks use s ≤ 8); no allocation in the loop
  double sum = 0.0;
  std::uint64_t evaluations = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < s; ++j) x[j] = rng.uniform();
    sum += evaluate_point(f, x.data(), s);
    ++evaluations;
  }
  return {sum / static_cast<double>(n), evaluations};
}

}  // namespace quadmc::bench
