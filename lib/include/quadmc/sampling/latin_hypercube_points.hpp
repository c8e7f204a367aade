// Latin hypercube points: any N, any s; along every axis each of the N equal rows holds exactly
// one point ([McKay et al. 1979]; [Pharr et al. 2016, §7.3]; docs/theory.md#latin-hypercube).
//
// Use it when N cannot be k^s or s is too high to stratify the cube: it removes the additive part
// of f from the error, Var = (1/N)∫e² + o(1/N) with e = f − additive part ([Stein 1987]), and its
// variance never exceeds σ²/(N − 1) ([Owen 1997]). Not a faster rate in general (still N^−½), and
// for an f dominated by interactions it is no better than plain Monte Carlo.
//
// Coordinate j of point i is (π_j(i) + u)/N, with π_j an independent random permutation per axis
// (random_permutation, evaluated element by element: O(1) time per coordinate, memory constant in
// N, any point regenerated alone) and u uniform number i·s + j: jittered within the cell.
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/random_permutation.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace quadmc {

class latin_hypercube_points {
 public:
  latin_hypercube_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                         std::uint64_t stream)
      : s_(dimension), n_(n), rng_(seed, stream) {
    require_point_set_size(dimension, n);
    permutations_.reserve(s_);
    for (std::size_t j = 0; j < s_; ++j) {
      // Keys from the top of the counter space, never reached by a jitter (point_set.hpp).
      permutations_.emplace_back(n_, rng_.bits(std::numeric_limits<std::uint64_t>::max() - j));
    }
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  variance_structure variance() const noexcept { return {variance_kind::independent_bound, 1}; }

  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    rng_.fill_uniform(first * s_, out);
    const double inv_n = 1.0 / static_cast<double>(n_);
    const std::uint64_t count = out.size() / s_;
    // Axis by axis over runs of 64 points: each permutation runs over consecutive indices
    // (random_permutation::apply), its rows kept in a buffer on the stack.
    std::array<std::uint64_t, 64> rows;
    for (std::uint64_t begin = 0; begin < count; begin += rows.size()) {
      const auto run =
          static_cast<std::size_t>(std::min<std::uint64_t>(rows.size(), count - begin));
      for (std::size_t j = 0; j < s_; ++j) {
        permutations_[j].apply(first + begin, std::span(rows).first(run));
        for (std::size_t p = 0; p < run; ++p) {
          double& x = out[(begin + p) * s_ + j];
          // rows < n ≤ 2^62: through int64_t the conversion is one instruction (uint64_t's
          // needs a branch on baseline x86-64), and the same double.
          const auto row = static_cast<double>(static_cast<std::int64_t>(rows[p]));
          x = std::min((row + x) * inv_n, largest_below_one);
        }
      }
    }
  }

 private:
  std::size_t s_;
  std::uint64_t n_;
  philox_stream rng_;
  std::vector<random_permutation> permutations_;
};

}  // namespace quadmc
