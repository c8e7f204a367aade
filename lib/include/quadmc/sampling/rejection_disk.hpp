// Uniform points in the unit disk by rejection: draw (2U₁ − 1, 2U₂ − 1) in the square [−1,1)²
// and keep it when inside the disk (docs/theory.md#rejection). The acceptance rate is π/4 ≈ 78.5%
// (area of the disk over area of the square).
//
// Use it as [Ramamoorthi 2009, §3.2] does: a simple, obviously correct reference to check an
// inversion warp against. Not as a warp: a sample consumes a random number of uniforms, so it is no
// function of a fixed u and cannot take stratified input. Trial t reads uniforms 2t and 2t + 1 of
// the stream, so the output depends only on (seed, stream, n).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"

#include <cstdint>
#include <vector>

namespace quadmc {

struct rejection_samples {
  std::vector<double> points;  // n accepted points, row-major (x, y)
  std::uint64_t trials = 0;    // candidate points drawn, accepted or not

  // Accepted / drawn: estimates π/4 for the disk.
  double acceptance_rate() const noexcept {
    return static_cast<double>(points.size() / 2) / static_cast<double>(trials);
  }
};

inline rejection_samples rejection_sample_disk(std::uint64_t n, std::uint64_t seed,
                                               std::uint64_t stream) {
  require(n >= 1, "number of points N", n, "N ≥ 1");
  require(n <= (std::uint64_t{1} << 40), "number of points N", n,
          "N ≤ 2^40 (the samples are stored)");
  const random_stream rng(seed, stream);
  rejection_samples out;
  out.points.reserve(2 * n);
  while (out.points.size() < 2 * n) {
    const double x = 2.0 * rng.uniform(2 * out.trials) - 1.0;
    const double y = 2.0 * rng.uniform(2 * out.trials + 1) - 1.0;
    ++out.trials;
    if (x * x + y * y < 1.0) {
      out.points.push_back(x);
      out.points.push_back(y);
    }
  }
  return out;
}

}  // namespace quadmc
