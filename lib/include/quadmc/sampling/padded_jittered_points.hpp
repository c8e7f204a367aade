// Padded jittered points: 2D (and, for odd s, one 1D) stratified patterns over groups of
// dimensions, randomly associated across groups ([Pharr et al. 2016, §7.3], "padding"; the Latin
// supercube sampling of [Owen 1998] is the same construction with any component sets;
// docs/theory.md#padded-jittered).
//
// Use it when s is too high for k^s strata but the integrand's important interactions are
// between pairs of coordinates (dimensions 2g and 2g+1 form group g): each group's projection is
// stratified, for any N and any s. Not a stratification of the whole cube: interactions across
// groups are sampled like plain Monte Carlo.
//
// Any N: a 2D group uses the kx × ky grid with kx·ky = N and kx the largest divisor of N with
// kx ≤ √N, found once at construction in O(√N) steps (a square grid when N is a square; for
// prime N it degrades to 1 × N, i.e. stratified in one coordinate only — documented, not
// hidden). A 1D group is N strata of width 1/N.
// Point i takes stratum π_g(i) in group g, with π_0 = identity and π_g (g ≥ 1) independent random
// permutations (random_permutation: O(1) per point, memory constant in N) — the shuffle that
// decorrelates the groups. Jitter of coordinate j of point i: uniform number i·s + j.
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/random_permutation.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace quadmc {

class padded_jittered_points {
 public:
  padded_jittered_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                         std::uint64_t stream)
      : s_(dimension), n_(n), rng_(seed, stream) {
    require_point_set_size(dimension, n);
    kx_ = 1;
    for (std::uint64_t d = 1; d * d <= n_; ++d) {
      if (n_ % d == 0) kx_ = d;
    }
    ky_ = n_ / kx_;
    const std::size_t groups = (s_ + 1) / 2;
    permutations_.reserve(groups);
    for (std::size_t g = 0; g < groups; ++g) {
      permutations_.emplace_back(n_, rng_.bits(std::numeric_limits<std::uint64_t>::max() - g));
    }
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
  philox_stream rng_;
  std::vector<random_permutation> permutations_;
};

}  // namespace quadmc
