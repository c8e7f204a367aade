// Padded Sobol' points: per pair of dimensions (2g, 2g + 1) the first two Sobol' dimensions, a
// (0, m, 2)-net for N = 2^m, randomized independently per pair and associated across pairs by
// random permutations of the point index (pbrt-v4's PaddedSobolSampler, [Pharr et al. 2023];
// docs/theory.md#padded-sobol).
//
// Use it where a renderer consumes dimensions in pairs (pixel, lens, light, BSDF…) and the
// pairs' interactions are weak: each pair's projection keeps the best 2D net there is (t = 0),
// where the Sobol' set's later pairs have t > 0 and their nets degrade with the dimension. Not a
// net of the whole cube beyond s = 2: across pairs the points are associated at random, so the
// rate falls to plain Monte Carlo's for an f whose variation is in the interactions across
// pairs (the padded rate, docs/theory.md#padded-jittered).
//
// Coordinate c of point i: the randomizer of sobol_points.hpp (owen, fast_owen, lms_shift, shift;
// its keys for dimension c, so each coordinate is scrambled independently) applied to the digits
// of Sobol' dimension c mod 2 at Gray-code index q_g = π_g(i), where g = c div 2, π_0 is the
// identity and π_g (g ≥ 1) an independent random permutation of [0, N) keyed at the top of the
// counter space. The first pair is therefore the Sobol' set's first two coordinates bit for bit
// (owen, fast_owen and shift key a dimension alone). Every pair of N = 2^m points is a scrambled
// (0, m, 2)-net ([Owen 1995]: scrambling keeps the net). A trailing 1D group (odd s) is Sobol's
// first dimension, a scrambled (0, m, 1)-net. There is no unrandomized form: without random
// permutations and scrambles every pair would be the same two coordinates.
#pragma once

#include "quadmc/sampling/padded_pairs.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

template <class Randomizer>
class padded_sobol_points {
 public:
  static_assert(Randomizer::random, "padded Sobol' points need a randomization");

  // Key words of the pair permutations, far above those of the randomizers (s + 64·s).
  static constexpr std::uint64_t permutation_keys = std::uint64_t{1} << 40;

  // N ≤ 2^32 points in s dimensions; any N is accepted here (the catalogue asks for 2^m, the nets'
  // size).
  padded_sobol_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed,
                      std::uint64_t stream, rng_kind rng = rng_kind::philox4x32_10)
      : s_(checked_dimension(dimension, n)),
        n_(n),
        randomizer_(dimension, static_cast<unsigned>(std::bit_width(n - 1)),
                    random_stream(seed, stream, rng)),
        columns_(static_cast<std::size_t>(sobol_matrices::digits) * dimension),
        pairs_(dimension, n, random_stream(seed, stream, rng), permutation_keys) {
    const sobol_matrices matrices(std::min<std::size_t>(dimension, 2));
    for (std::size_t c = 0; c < s_; ++c) {
      const auto base = matrices.columns(c % 2);
      const std::span<std::uint64_t> out(columns_.data() + c * sobol_matrices::digits,
                                         sobol_matrices::digits);
      for (unsigned k = 0; k < sobol_matrices::digits; ++k) {
        out[k] = static_cast<std::uint64_t>(base[k]) << 32;
      }
      randomizer_.prepare(c, out);
    }
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  // A randomized net cannot estimate its own error: replicates do
  // (docs/theory.md#replicate-error-bars).
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }

  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    pairs_.generate(first, out, [this](std::uint64_t q, std::size_t c) {
      return fraction_to_unit(digits(q, c));
    });
  }

  // The randomized 64-digit fraction of coordinate c at sequence index q (tests: the nets).
  std::uint64_t digits(std::uint64_t q, std::size_t c) const noexcept {
    const std::uint64_t* column = columns_.data() + c * sobol_matrices::digits;
    std::uint64_t v = 0;
    for (std::uint64_t gray = q ^ (q >> 1); gray != 0; gray &= gray - 1) {
      v ^= column[std::countr_zero(gray)];
    }
    return randomizer_(v, c);
  }

 private:
  static std::size_t checked_dimension(std::size_t s, std::uint64_t n) {
    require_point_set_size(s, n);
    require(n <= (std::uint64_t{1} << 32), "number of points N", n,
            "N ≤ 2^32 (32-digit direction numbers)");
    return s;
  }

  std::size_t s_;
  std::uint64_t n_;
  Randomizer randomizer_;
  std::vector<std::uint64_t> columns_;  // 32 per coordinate, randomized by prepare()
  padded_pairs pairs_;                  // π_g of the pairs g ≥ 1
};

}  // namespace quadmc
