// Correlated multi-jittered points ([Kensler 2013]; docs/theory.md#correlated-multi-jittered):
// N = m·n points in an m × n grid of cells, one point per cell, whose fine positions also put
// exactly one point in each of the N columns and N rows of the N × N fine grid, padded across
// pairs of dimensions as padded_jittered_points pads its 2D groups.
//
// Use it where a renderer wants a 2D pattern that is jittered and Latin at once (Pixar's sampler
// of [Kensler 2013]), for any N that is a near-square m·n: at small N its error is well below
// jittered sampling's. Not for large N on a smooth f: the offsets shared along rows and columns
// cost the rate (RMSE N^(−3/4) in 2D against jittered's N^(−1),
// docs/theory.md#correlated-multi-jittered). Not a stratification of the whole cube beyond
// s = 2: pairs are associated by random permutations, so interactions across pairs are sampled
// like plain Monte Carlo (the padded rate).
//
// Construction, pair g (axes 2g, 2g + 1), point i: its sample c = π_g(i) (π_0 the identity,
// π_g for g ≥ 1 independent random permutations of [0, N), which decorrelate the pairs), cell
// (column a = c mod m, row b = c div m), and
//   x = (a + (σ_g(b) + u)/n)/m,   y = (b + (τ_g(a) + v)/m)/n,
// with σ_g a random permutation of the n rows and τ_g one of the m columns, u and v uniform
// numbers i·s + 2g and i·s + 2g + 1. The fine column of x, a·n + σ_g(b), and the fine row of y,
// b·m + τ_g(a), are bijections of c: the Latin property. "Correlated": every cell of a column
// shares τ_g's offset and every cell of a row σ_g's, Kensler's choice, which keeps the cells'
// sub-positions as even as a canonical N-rooks pattern's while one permutation per axis is
// drawn, not one per row. A trailing 1D group (odd s) is (π_g(i) + u)/N.
//
// Sizes: m = ⌊√N⌋ and n = N/m must be m or m + 1 (N = k² or k(k + 1)), so that cells have
// aspect ratio at most (k + 1)/k and widths O(N^(−1/2)) along both axes, which the
// one-point-per-stratum rate needs (a prime N would give 1 × N). Any N in 1D.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/random_permutation.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

class cmj_points {
 public:
  cmj_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed, std::uint64_t stream,
             rng_kind rng = rng_kind::philox4x32_10)
      : s_(dimension), n_(n), rng_(seed, stream, rng) {
    require_point_set_size(dimension, n);
    if (!is_valid_size(s_, n_)) {
      const std::uint64_t k = integer_root(n_, 2);
      const std::uint64_t below = k * (k + 1) <= n_ ? k * (k + 1) : k * k;
      const std::uint64_t above = k * (k + 1) > n_ ? k * (k + 1) : (k + 1) * (k + 1);
      throw invalid_argument("number of points N", quote(n_),
                             "N = k² or k(k + 1) for correlated multi-jittered points in s ≥ 2 "
                             "(an m × n grid with n = m or m + 1); nearest valid: " +
                                 std::to_string(below) + " and " + std::to_string(above));
    }
    columns_ = s_ == 1 ? n_ : integer_root(n_, 2);
    rows_ = n_ / columns_;
    // Keys from the top of the counter space, which no jitter reaches (point_set.hpp): per group
    // g, word 3g keys π_g (g ≥ 1; π_0 is the identity), 3g + 1 σ_g and 3g + 2 τ_g.
    const auto key = [&](std::uint64_t w) {
      return rng_.bits(std::numeric_limits<std::uint64_t>::max() - w);
    };
    const std::size_t groups = (s_ + 1) / 2;
    samples_.reserve(groups - 1);
    row_offsets_.reserve(groups);
    column_offsets_.reserve(groups);
    for (std::size_t g = 0; g < groups; ++g) {
      if (g > 0) samples_.emplace_back(n_, key(3 * g));
      row_offsets_.emplace_back(rows_, key(3 * g + 1));
      column_offsets_.emplace_back(columns_, key(3 * g + 2));
    }
  }

  // Whether the set holds exactly n points in s dimensions: k² or k(k + 1) for s ≥ 2, any n in 1D.
  static bool is_valid_size(std::size_t s, std::uint64_t n) noexcept {
    if (s == 0 || n == 0) return false;
    if (s == 1) return true;
    const std::uint64_t k = integer_root(n, 2);
    return n == k * k || n == k * (k + 1);
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  std::uint64_t grid_columns() const noexcept { return columns_; }  // m, along axis 2g
  std::uint64_t grid_rows() const noexcept { return rows_; }        // n, along axis 2g + 1
  // σ̂²/N: an approximate upper bound, as for padded jittered points (each pair's projection is a
  // proportional stratification, which never increases the variance).
  variance_structure variance() const noexcept { return {variance_kind::independent_bound, 1}; }

  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    rng_.fill_uniform(first * s_, out);
    const double m = static_cast<double>(columns_);
    const double n = static_cast<double>(rows_);
    const double inv_n = 1.0 / static_cast<double>(n_);
    const std::uint64_t count = out.size() / s_;
    // Group by group over runs of 64 points: each permutation runs over consecutive samples
    // (random_permutation::apply), its values kept on the stack.
    std::array<std::uint64_t, 64> samples;
    for (std::uint64_t begin = 0; begin < count; begin += samples.size()) {
      const auto run =
          static_cast<std::size_t>(std::min<std::uint64_t>(samples.size(), count - begin));
      for (std::size_t j = 0; j < s_; j += 2) {
        const std::size_t g = j / 2;
        const std::span<std::uint64_t> c = std::span(samples).first(run);
        if (g == 0) {
          for (std::size_t p = 0; p < run; ++p) c[p] = first + begin + p;
        } else {
          samples_[g - 1].apply(first + begin, c);
        }
        for (std::size_t p = 0; p < run; ++p) {
          double* x = out.data() + (begin + p) * s_;
          if (j + 1 == s_) {
            x[j] = std::min((static_cast<double>(c[p]) + x[j]) * inv_n, largest_below_one);
            continue;
          }
          const std::uint64_t a = c[p] % columns_;
          const std::uint64_t b = c[p] / columns_;
          const auto sub_row = static_cast<double>(row_offsets_[g](b));
          const auto sub_column = static_cast<double>(column_offsets_[g](a));
          x[j] = std::min((static_cast<double>(a) + (sub_row + x[j]) / n) / m, largest_below_one);
          x[j + 1] = std::min((static_cast<double>(b) + (sub_column + x[j + 1]) / m) / n,
                              largest_below_one);
        }
      }
    }
  }

 private:
  std::size_t s_;
  std::uint64_t n_;
  std::uint64_t columns_ = 1;  // m
  std::uint64_t rows_ = 1;     // n
  random_stream rng_;
  std::vector<random_permutation> samples_;         // π_g for g ≥ 1
  std::vector<random_permutation> row_offsets_;     // σ_g over the n rows
  std::vector<random_permutation> column_offsets_;  // τ_g over the m columns
};

}  // namespace quadmc
