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
#include <numeric>
#include <span>
#include <vector>

namespace quadmc {

namespace detail {

// The s permutations of a Latin hypercube laid out lane by lane, so that a vector register holds
// consecutive coordinates of the batch (row-major, x[i·s + j]) and each lane evaluates its own
// axis's permutation: lane l of a run of `period` = lcm(s, 8) lanes is coordinate l mod s of
// point l / s. All s permutations share n, so they share the mask and shift; only keys differ.
struct latin_hypercube_lanes {
  std::size_t s = 1;
  std::uint64_t n = 1;
  std::uint64_t mask = 0;
  int shift = 1;
  double inv_n = 1.0;
  std::size_t period = 8;
  const std::uint64_t* keys = nullptr;   // keys[k·period + l] = key k of axis l mod s
  const std::uint64_t* point = nullptr;  // point[l] = l / s
  // The same tables in 32 bits (keys reduced mod 2^32), for n ≤ 2^31 only (empty otherwise):
  // there every value is below 2^31, so 8 lanes of 32 bits compute the bijection mod 2^w.
  const std::uint32_t* keys32 = nullptr;
  const std::uint32_t* point32 = nullptr;
};

// Writes the Latin hypercube coordinates of points [first, first + count) into x in place: x
// holds their uniforms u (row-major), and coordinate j of point i becomes
// min((π_j(i) + u)·inv_n, largest_below_one), the permutation and the placement in one pass in
// the batch's layout (no buffer of rows, no strided pass). Returns false, writing nothing, when
// the active SIMD level has no such kernel (scalar and SSE2; AVX2 when n > 2^31, whose values do
// not fit 32-bit lanes); the caller then runs the per-axis loop. Bitwise the same
// as that loop: lib/src/sampling/permutation_blocks*.cpp.
bool latin_hypercube_place(const latin_hypercube_lanes& lanes, std::uint64_t first,
                           std::size_t count, double* x) noexcept;

}  // namespace detail

class latin_hypercube_points {
 public:
  latin_hypercube_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                         std::uint64_t stream, rng_kind rng = rng_kind::philox4x32_10)
      : s_(dimension), n_(n), rng_(seed, stream, rng) {
    require_point_set_size(dimension, n);
    permutations_.reserve(s_);
    for (std::size_t j = 0; j < s_; ++j) {
      // Keys from the top of the counter space, never reached by a jitter (point_set.hpp).
      permutations_.emplace_back(n_, rng_.bits(std::numeric_limits<std::uint64_t>::max() - j));
    }
    // The lane tables of detail::latin_hypercube_lanes, built once here (plan time).
    constexpr std::size_t keys = 2 * detail::permutation_schedule::rounds;
    period_ = std::lcm(s_, std::size_t{8});
    lane_keys_.resize(keys * period_);
    lane_points_.resize(period_);
    const bool narrow = n_ <= (std::uint64_t{1} << 31);
    lane_keys32_.resize(narrow ? keys * period_ : 0);
    lane_points32_.resize(narrow ? period_ : 0);
    for (std::size_t l = 0; l < period_; ++l) {
      lane_points_[l] = l / s_;
      if (narrow) lane_points32_[l] = static_cast<std::uint32_t>(l / s_);
      for (std::size_t k = 0; k < keys; ++k) {
        lane_keys_[k * period_ + l] = permutations_[l % s_].schedule().keys[k];
        if (narrow)
          lane_keys32_[k * period_ + l] = static_cast<std::uint32_t>(lane_keys_[k * period_ + l]);
      }
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
    const detail::permutation_schedule& schedule = permutations_.front().schedule();
    const detail::latin_hypercube_lanes lanes{s_,
                                              n_,
                                              schedule.mask,
                                              schedule.shift,
                                              inv_n,
                                              period_,
                                              lane_keys_.data(),
                                              lane_points_.data(),
                                              lane_keys32_.data(),
                                              lane_points32_.data()};
    if (detail::latin_hypercube_place(lanes, first, static_cast<std::size_t>(count), out.data())) {
      return;
    }
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
  random_stream rng_;
  std::vector<random_permutation> permutations_;
  // detail::latin_hypercube_lanes's tables (their pointers are taken per generate() call, so a
  // copied point set points into its own copies).
  std::size_t period_ = 8;
  std::vector<std::uint64_t> lane_keys_;
  std::vector<std::uint64_t> lane_points_;
  std::vector<std::uint32_t> lane_keys32_;
  std::vector<std::uint32_t> lane_points32_;
};

}  // namespace quadmc
