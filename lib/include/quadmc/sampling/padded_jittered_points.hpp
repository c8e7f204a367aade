// Padded jittered points: 2D (and, for odd s, one 1D) stratified patterns over groups of
// dimensions, randomly associated across groups ([Pharr et al. 2016, §7.3], "padding"; the Latin
// supercube sampling of [Owen 1998] is the same construction with any component sets;
// docs/theory.md#padded-jittered).
//
// Use it when s is too high for k^s strata but the integrand's important interactions are
// between pairs of coordinates (dimensions 2g and 2g+1 form group g): each group's projection is
// stratified, for any s. Not a stratification of the whole cube: interactions across groups are
// sampled like plain Monte Carlo.
//
// N = k² in s ≥ 2 (a 2D group is the k × k grid), any N in 1D (N strata of width 1/N); other N
// are rejected with the nearest squares, as stratum_grid rejects N ≠ k^s. The one-point-per-
// stratum rate of a 2D group (docs/theory.md#padded-jittered) needs strata of width O(N^−1/2)
// along both axes; a kx × ky grid with kx·ky = N would degrade to 1 × N for prime N (stratified
// in one coordinate only) and give a rate that depends on N's factors, not on N. The planner maps
// a scene's N to the largest k² (estimators/point_set_catalogue.hpp, point_count::perfect_square),
// so a method never asks for another N.
// Point i takes stratum π_g(i) in group g, with π_0 = identity and π_g (g ≥ 1) independent random
// permutations (random_permutation: O(1) per point, memory constant in N) — the shuffle that
// decorrelates the groups. Jitter of coordinate j of point i: uniform number i·s + j.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/random_permutation.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

class padded_jittered_points {
 public:
  padded_jittered_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                         std::uint64_t stream, rng_kind rng = rng_kind::philox4x32_10)
      : s_(dimension), n_(n), rng_(seed, stream, rng) {
    require_point_set_size(dimension, n);
    if (!is_valid_size(s_, n_)) {
      const std::uint64_t k = integer_root(n_, 2);
      throw invalid_argument("number of points N", quote(n_),
                             "N = k² for padded jittered points in s ≥ 2 (k × k strata per pair "
                             "of dimensions); nearest valid: " +
                                 std::to_string(k * k) + " = " + std::to_string(k) + "² or " +
                                 std::to_string((k + 1) * (k + 1)) + " = " + std::to_string(k + 1) +
                                 "²");
    }
    kx_ = s_ == 1 ? 1 : integer_root(n_, 2);
    ky_ = n_ / kx_;
    const std::size_t groups = (s_ + 1) / 2;
    permutations_.reserve(groups);
    for (std::size_t g = 0; g < groups; ++g) {
      permutations_.emplace_back(n_, rng_.bits(std::numeric_limits<std::uint64_t>::max() - g));
    }
  }

  // Whether the set holds exactly n points in s dimensions: n = k² for s ≥ 2, any n ≥ 1 in 1D.
  static bool is_valid_size(std::size_t s, std::uint64_t n) noexcept {
    if (s == 0 || n == 0) return false;
    if (s == 1) return true;
    const std::uint64_t k = integer_root(n, 2);
    return k * k == n;
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  std::uint64_t grid_columns() const noexcept { return kx_; }
  std::uint64_t grid_rows() const noexcept { return ky_; }
  variance_structure variance() const noexcept { return {variance_kind::independent_bound, 1}; }

  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    rng_.fill_uniform(first * s_, out);
    const double inv_kx = 1.0 / static_cast<double>(kx_);
    const double inv_ky = 1.0 / static_cast<double>(ky_);
    const double inv_n = 1.0 / static_cast<double>(n_);
    const std::uint64_t count = out.size() / s_;
    for (std::uint64_t p = 0; p < count; ++p) {
      double* x = out.data() + p * s_;
      for (std::size_t j = 0; j < s_; j += 2) {
        const std::uint64_t i = first + p;
        const std::uint64_t c = j == 0 ? i : permutations_[j / 2](i);
        if (j + 1 < s_) {
          x[j] = std::min((static_cast<double>(c / ky_) + x[j]) * inv_kx, largest_below_one);
          x[j + 1] =
              std::min((static_cast<double>(c % ky_) + x[j + 1]) * inv_ky, largest_below_one);
        } else {
          x[j] = std::min((static_cast<double>(c) + x[j]) * inv_n, largest_below_one);
        }
      }
    }
  }

 private:
  std::size_t s_;
  std::uint64_t n_;
  std::uint64_t kx_ = 1;
  std::uint64_t ky_ = 1;
  random_stream rng_;
  std::vector<random_permutation> permutations_;
};

}  // namespace quadmc
