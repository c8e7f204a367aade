// Unjittered stratified points: the centre of each of the k^s strata ([Pharr et al. 2016, §7.3],
// the StratifiedSampler's unjittered mode; docs/theory.md#unjittered), optionally with one random
// shift of the whole grid.
//
// Use it only to compare against jittered points: unshifted it is the tensor-product midpoint
// rule, a deterministic rule with error O(N^(−2/s)) for smooth f (docs/theory.md#tensor-products)
// and aliasing on periodic or discontinuous integrands. With a seed, the grid is shifted by one
// uniform vector Δ modulo 1 (a Cranley–Patterson rotation, [Cranley & Patterson 1976]):
// every point is then uniform, so the mean over points is unbiased and repetitions give an RMSE,
// but all points share Δ, so one run cannot estimate its own error: estimators report NaN as its
// standard error (variance_kind::not_estimable). N must be k^s (see stratum_grid.hpp).
// Shift Δ: uniform numbers 0…s−1 of the stream.
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/stratum_grid.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

class unjittered_points {
 public:
  // The centres themselves (deterministic).
  unjittered_points(std::size_t dimension, std::uint64_t n)
      : grid_(stratum_grid::for_size(dimension, n)), shift_(dimension, 0.0) {
    require_point_set_size(dimension, n);
  }
  // The centres shifted by one random Δ ∈ [0,1)^s modulo 1.
  unjittered_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                    std::uint64_t stream, rng_kind rng = rng_kind::philox4x32_10)
      : unjittered_points(dimension, n) {
    random_stream(seed, stream, rng).fill_uniform(0, shift_);
  }

  std::uint64_t size() const noexcept { return grid_.strata(); }
  std::size_t dimension() const noexcept { return grid_.dimension(); }
  const stratum_grid& grid() const noexcept { return grid_; }
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }

  void generate(std::uint64_t first, std::span<double> out) const {
    const std::size_t s = grid_.dimension();
    require_batch(s, size(), first, out);
    const double inv_k = 1.0 / static_cast<double>(grid_.per_axis());
    std::array<std::uint64_t, 16> small{};
    std::vector<std::uint64_t> large(s > small.size() ? s : 0);
    std::span<std::uint64_t> cell = s > small.size() ? std::span<std::uint64_t>(large)
                                                     : std::span<std::uint64_t>(small).first(s);
    const std::uint64_t count = out.size() / s;
    for (std::uint64_t p = 0; p < count; ++p) {
      grid_.cell(first + p, cell);
      for (std::size_t j = 0; j < s; ++j) {
        // Centre plus shift, wrapped into [0,1): x ∈ [0, 2) before the wrap.
        double x = (static_cast<double>(cell[j]) + 0.5) * inv_k + shift_[j];
        x = x >= 1.0 ? x - 1.0 : x;
        out[p * s + j] = std::min(x, largest_below_one);
      }
    }
  }

 private:
  stratum_grid grid_;
  std::vector<double> shift_;
};

}  // namespace quadmc
