// Padding of a 2D sequence across pairs of dimensions ([Pharr et al. 2023];
// docs/theory.md#padded-sobol): coordinates (2g, 2g + 1) of point i are pair g's own sequence at
// index π_g(i), π_0 the identity and π_g (g ≥ 1) independent random permutations of [0, N), so
// that every pair's projection is its sequence's first N points while the pairs are associated at
// random; a trailing coordinate (odd s) is a pair of one.
//
// Use it for a set built from one 2D construction (padded_sobol_points, pmj02_points), which says
// what coordinate c of its sequence's point q is; the permutations and the batching live here,
// once. Not for sets whose groups are not sequences indexed by the point (padded jittered points
// place strata, not indices).
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/random_permutation.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace quadmc {

class padded_pairs {
 public:
  // π_g for g ≥ 1 keyed by word 2^64 − 1 − (key_offset + g) of the stream, at the top of the
  // counter space that no point's uniforms reach (point_set.hpp).
  padded_pairs(std::size_t s, std::uint64_t n, const random_stream& rng, std::uint64_t key_offset)
      : s_(s) {
    const std::size_t groups = (s + 1) / 2;
    shuffles_.reserve(groups > 0 ? groups - 1 : 0);
    for (std::size_t g = 1; g < groups; ++g) {
      shuffles_.emplace_back(n,
                             rng.bits(std::numeric_limits<std::uint64_t>::max() - key_offset - g));
    }
  }

  // out[p·s + c] = coordinate(q, c) for the points first + p of the batch, q the index of the
  // point in the sequence of pair c div 2: runs of 64 points, each permutation over consecutive
  // points at once (random_permutation::apply), the indices on the stack.
  template <class Coordinate>
  void generate(std::uint64_t first, std::span<double> out, Coordinate&& coordinate) const {
    const std::uint64_t count = out.size() / s_;
    std::array<std::uint64_t, 64> index;
    for (std::uint64_t begin = 0; begin < count; begin += index.size()) {
      const auto run =
          static_cast<std::size_t>(std::min<std::uint64_t>(index.size(), count - begin));
      const std::span<std::uint64_t> q = std::span(index).first(run);
      for (std::size_t j = 0; j < s_; j += 2) {
        const std::size_t g = j / 2;
        if (g == 0) {
          for (std::size_t p = 0; p < run; ++p) q[p] = first + begin + p;
        } else {
          shuffles_[g - 1].apply(first + begin, q);
        }
        for (std::size_t c = j; c < std::min(j + 2, s_); ++c) {
          for (std::size_t p = 0; p < run; ++p) out[(begin + p) * s_ + c] = coordinate(q[p], c);
        }
      }
    }
  }

 private:
  std::size_t s_;
  std::vector<random_permutation> shuffles_;  // π_g for g ≥ 1
};

}  // namespace quadmc
