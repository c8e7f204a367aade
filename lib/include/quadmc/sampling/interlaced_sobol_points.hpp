// Higher-order digital nets by digit interlacing ([Dick 2008]; docs/theory.md#interlaced-nets):
// the Sobol' points of α·s dimensions (sampling/sobol_points.hpp), randomized there, mapped to s
// dimensions by the interlacing function D_α. Output coordinate j takes the binary digits of
// input coordinates (j − 1)α + 1 … jα in turn: digit (a − 1)α + i of y_j is digit a of input
// coordinate (j − 1)α + i.
//
// Use it for integrands smoother than one mixed derivative: N = 2^m points of an interlaced
// (t, m, αs)-net form an order-α digital net, whose error on f with square-integrable mixed
// derivatives of order δ falls as N^(−min(α, δ)) up to log factors, deterministic or digitally
// shifted ([Dick 2008]), and whose RMSE falls as N^(−min(α, δ) − 1/2) when the αs-dimensional
// net is Owen-scrambled before interlacing ([Dick 2011]). Not for rough f: an interlaced net is
// a poorer order-1 net (larger t) than the Sobol' points of s dimensions, so a kink or a jump
// gains nothing and may lose; not for N other than 2^m (no net:
// docs/theory.md#sobol-anti-patterns). α = 1 is the identity (sobol_points itself); the methods use
// sobol_points then, so that the default keeps its bits.
//
// Randomization: the Randomizer acts on the αs coordinates before interlacing. Owen's nested
// scramble there is [Dick 2011]'s scrambled higher-order net; a digital shift there is a digital
// shift of the output (XOR commutes with the digit permutation D_α: D_α(x ⊕ Δ) = D_α(x) ⊕ D_α(Δ)).
//
// Precision: a Sobol' coordinate has 32 digits, so an unrandomized output has 32α; a double keeps
// 53. For α = 2 the top 32 digits of each input give 64 output digits, for α = 3 the top 21 give
// 63: both cover the 53 kept. The αs-dimensional points come from sobol_points::generate (its
// vector kernel), whose doubles are exact multiples of 2^−53 holding their top 53 digits, so the
// digits read back from them are the randomizer's own. Outputs lie in [0, 1): the top 53 digits
// of a fraction are at most 1 − 2^−53 (fraction_to_unit).
//
// Like sobol_points, a point is a pure function of (s, α, N, seed, stream, i) and batches may run
// in any order on any thread; variance() is not_estimable (replicates give the error bar).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace quadmc {

// The interlacing factors the methods offer: α = 3 already needs 3s Sobol' dimensions and keeps
// only 18 digits of each input within a double's 53 (docs/theory.md#interlaced-nets).
inline constexpr unsigned max_interlacing = 3;

namespace detail {

// Bit k of x moved to bit 2k (k < 32).
constexpr std::uint64_t spread_by_two(std::uint64_t x) noexcept {
  x &= 0xffffffffULL;
  x = (x | (x << 16)) & 0x0000ffff0000ffffULL;
  x = (x | (x << 8)) & 0x00ff00ff00ff00ffULL;
  x = (x | (x << 4)) & 0x0f0f0f0f0f0f0f0fULL;
  x = (x | (x << 2)) & 0x3333333333333333ULL;
  x = (x | (x << 1)) & 0x5555555555555555ULL;
  return x;
}

// Bit k of x moved to bit 3k (k < 21).
constexpr std::uint64_t spread_by_three(std::uint64_t x) noexcept {
  x &= 0x1fffffULL;
  x = (x | (x << 32)) & 0x001f00000000ffffULL;
  x = (x | (x << 16)) & 0x001f0000ff0000ffULL;
  x = (x | (x << 8)) & 0x100f00f00f00f00fULL;
  x = (x | (x << 4)) & 0x10c30c30c30c30c3ULL;
  x = (x | (x << 2)) & 0x1249249249249249ULL;
  return x;
}

}  // namespace detail

// D_α of α fractions x_1 … x_α (64-digit words, digit 1 the most significant bit): the top 64
// digits of y = Σ_a Σ_i x_{i,a} 2^−(i + (a − 1)α). Digit a of x_i sits at bit 64 − a; digit
// (a − 1)α + i of y at bit 64 − (a − 1)α − i. α = 2: the top 32 digits of each input fill the
// word; α = 3: the top 21 fill its top 63 bits (bit 0, digit 64, is 0). x.size() = α ∈ {1, 2, 3}.
constexpr std::uint64_t interlace_digits(std::span<const std::uint64_t> x) noexcept {
  switch (x.size()) {
    case 1:
      return x[0];
    case 2:
      // Digit a of x_1 from bit 32 − a of x_1 >> 32, spread to 64 − 2a, then one up: 65 − 2a.
      return (detail::spread_by_two(x[0] >> 32) << 1) | detail::spread_by_two(x[1] >> 32);
    default:
      // Digit a of x_i from bit 21 − a of x_i >> 43, spread to 63 − 3a, then 4 − i up.
      return (detail::spread_by_three(x[0] >> 43) << 3) |
             (detail::spread_by_three(x[1] >> 43) << 2) |
             (detail::spread_by_three(x[2] >> 43) << 1);
  }
}

template <class Randomizer>
class interlaced_sobol_points {
 public:
  // N ≤ 2^32 points of s dimensions from the Sobol' points of α·s ≤ 3667 dimensions, α ∈ {1, 2,
  // 3}. As sobol_points, any N is accepted here and the methods decide which N they allow.
  interlaced_sobol_points(std::size_t dimension, unsigned alpha, std::uint64_t n,
                          std::uint64_t seed, std::uint64_t stream, bool drop_first_point = false,
                          rng_kind rng = rng_kind::philox4x32_10)
      : s_(checked_dimension(dimension, alpha)),
        alpha_(alpha),
        inputs_(dimension * alpha),
        // The chunk of points whose αs coordinates fit the stack buffer of generate(); ≥ 1 since
        // αs ≤ 3667 < chunk_coordinates.
        chunk_(chunk_coordinates / inputs_),
        base_(inputs_, n, seed, stream, drop_first_point, rng) {}

  std::uint64_t size() const noexcept { return base_.size(); }
  std::size_t dimension() const noexcept { return s_; }
  unsigned interlacing() const noexcept { return alpha_; }
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }

  // The αs-dimensional points of the batch in chunks on the stack (no allocation), each row
  // interlaced into s coordinates.
  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, base_.size(), first, out);
    std::array<double, chunk_coordinates> in;
    const std::uint64_t count = out.size() / s_;
    for (std::uint64_t done = 0; done < count;) {
      const std::uint64_t c = std::min<std::uint64_t>(chunk_, count - done);
      base_.generate(first + done, std::span<double>(in.data(), c * inputs_));
      for (std::uint64_t p = 0; p < c; ++p) {
        interlace_row(in.data() + p * inputs_, out.data() + (done + p) * s_);
      }
      done += c;
    }
  }

 private:
  // 32 KiB of doubles: more than the largest αs (3667), few enough for any thread's stack.
  static constexpr std::size_t chunk_coordinates = 4096;

  void interlace_row(const double* in, double* out) const noexcept {
    std::array<std::uint64_t, max_interlacing> digits{};
    for (std::size_t j = 0; j < s_; ++j) {
      for (unsigned i = 0; i < alpha_; ++i) {
        // The double is (top 53 digits)·2^−53 exactly: the digits back, in the top of a word.
        digits[i] = static_cast<std::uint64_t>(in[j * alpha_ + i] * 0x1.0p53) << 11;
      }
      out[j] =
          fraction_to_unit(interlace_digits(std::span<const std::uint64_t>(digits.data(), alpha_)));
    }
  }

  static std::size_t checked_dimension(std::size_t s, unsigned alpha) {
    require(alpha >= 1 && alpha <= max_interlacing, "interlacing", alpha, "1, 2 or 3");
    require(s >= 1 && s <= sobol_matrices::max_dimension / alpha, "dimension s", s,
            fmt::format("s·α ≤ {} (the Sobol' dimensions interlaced, α = {})",
                        sobol_matrices::max_dimension, alpha));
    return s;
  }

  std::size_t s_;
  unsigned alpha_;
  std::size_t inputs_;  // α·s
  std::uint64_t chunk_;
  sobol_points<Randomizer> base_;
};

}  // namespace quadmc
