// Z-ordered Sobol' points of an image ([Ahmed & Wonka 2020]; pbrt-v4's ZSobolSampler,
// [Pharr et al. 2023]; docs/theory.md#z-ordered-sobol): one Owen-scrambled 2D Sobol' sequence
// shared by all the pixels of a W × H image, pixel (c, r) taking the 2^k points of the index
// block of its Morton code, with the base-4 digits of the index permuted at random.
//
// Use it for an image whose neighbouring pixels integrate nearly the same function: the 4^j
// pixels of an aligned 2^j × 2^j Morton tile share one block of 4^j·2^k consecutive indices, a
// scrambled (0, 2j + k, 2)-net, so their errors partly cancel and the error image loses power at
// low frequencies (blue noise). Not for a pixel alone: its own 2^k points are a scrambled
// (0, k, 2)-net like `sobol`'s, with the same error; the gain shows only once neighbouring pixels
// are averaged, by a low-pass filter or the eye.
//
// Sample i of pixel (c, r): the Morton index M = (morton(c, r) << k) | i, morton interleaving the
// bits of c (even) and r (odd) over the 2^R × 2^R square, R = ⌈log₂ max(W, H)⌉; its T = 2R + k
// bits read as base-4 digits from the top (the lowest a single bit when T is odd), each replaced
// by π(digit), π one of the 24 permutations of {0, 1, 2, 3} chosen by a hash of (key, the digits
// above it): a nested scramble of the index, so every aligned tile still takes an aligned block
// of indices, in a random order. Coordinate d of the point is the owen_scramble of Sobol'
// dimension d (natural order, x = C_d·index) with keys of random_stream(seed, stream), depth T.
// Every sample is a pure function of (W, H, spp, seed, stream, c, r, i).
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

namespace quadmc {

class zsobol_points {
 public:
  // The permutation keys: a word above the owen_scramble's two (randomization_key 0 and 1).
  static constexpr std::uint64_t permutation_key = 2;

  // W, H ≥ 1 and spp = 2^k with 2R + k ≤ 32 (the Sobol' digits index 2^32 points).
  zsobol_points(std::size_t width, std::size_t height, std::uint64_t spp, std::uint64_t seed,
                std::uint64_t stream)
      : width_(width),
        height_(height),
        sample_bits_(checked_sample_bits(width, height, spp)),
        index_bits_(2 * resolution_bits(width, height) + sample_bits_),
        scramble_(2, index_bits_, random_stream(seed, stream)),
        key_(randomization_key(random_stream(seed, stream), permutation_key)),
        matrices_(2) {}

  std::uint64_t samples_per_pixel() const noexcept { return std::uint64_t{1} << sample_bits_; }
  unsigned index_bits() const noexcept { return index_bits_; }

  // The 2·spp coordinates (x₀, y₀, x₁, y₁, …) of pixel (column, row)'s samples.
  void generate(std::size_t column, std::size_t row, std::span<double> out) const {
    require(column < width_, "pixel column", column, "a column of the image, < its width");
    require(row < height_, "pixel row", row, "a row of the image, < its height");
    require(out.size() == 2 * samples_per_pixel(), "output size", out.size(),
            "2 × samples per pixel");
    const std::uint64_t pixel = morton(column, row) << sample_bits_;
    // The digits above the sample bits are the pixel's: permuted once, not once per sample.
    const std::uint64_t pixel_index = permuted_digits(pixel, index_bits_, sample_bits_);
    for (std::uint64_t i = 0; i < samples_per_pixel(); ++i) {
      const auto index =
          static_cast<std::uint32_t>(pixel_index | permuted_digits(pixel | i, sample_bits_, 0));
      for (std::size_t d = 0; d < 2; ++d) {
        const std::uint64_t digits = std::uint64_t{sobol_digits(matrices_.columns(d), index)} << 32;
        out[2 * i + d] = fraction_to_unit(scramble_(digits, d));
      }
    }
  }

  // The sequence index of Morton index m: its base-4 digits permuted from the top, each by the
  // permutation a hash of the digits above it picks (tests: a bijection keeping aligned blocks).
  std::uint64_t permuted_index(std::uint64_t m) const noexcept {
    return permuted_digits(m, index_bits_, 0);
  }

  // Bits of c at the even positions, of r at the odd ones.
  static std::uint64_t morton(std::uint64_t c, std::uint64_t r) noexcept {
    std::uint64_t m = 0;
    for (unsigned b = 0; b < 32; ++b) {
      m |= ((c >> b) & 1) << (2 * b);
      m |= ((r >> b) & 1) << (2 * b + 1);
    }
    return m;
  }

 private:
  // The permuted digits of m at bits [low, top), read from the top in base 4; when top − low is
  // odd (T odd, and low = 0) the last digit is the single bit `low`. The pixel's digits [k, T)
  // are an even count (T − k = 2R), so they and the sample's [0, k) split as permuted_index does.
  std::uint64_t permuted_digits(std::uint64_t m, unsigned top, unsigned low) const noexcept {
    std::uint64_t out = 0;
    unsigned shift = top;
    for (; shift >= low + 2; shift -= 2) {
      const unsigned s = shift - 2;
      const auto digit = static_cast<unsigned>((m >> s) & 3);
      out |= std::uint64_t{permutations[pick(m, shift)][digit]} << s;
    }
    if (shift == low + 1) {
      out |= (((m >> low) & 1) ^ (hash(m, shift) >> 63)) << low;
    }
    return out;
  }

  static constexpr std::array<std::array<std::uint8_t, 4>, 24> permutations = [] {
    std::array<std::array<std::uint8_t, 4>, 24> all{};
    std::size_t n = 0;
    for (std::uint8_t a = 0; a < 4; ++a) {
      for (std::uint8_t b = 0; b < 4; ++b) {
        for (std::uint8_t c = 0; c < 4; ++c) {
          const auto d = static_cast<std::uint8_t>(6 - a - b - c);
          if (a != b && a != c && b != c && d < 4 && d != a && d != b && d != c) {
            all[n++] = {a, b, c, d};
          }
        }
      }
    }
    return all;
  }();

  static unsigned resolution_bits(std::size_t width, std::size_t height) noexcept {
    return static_cast<unsigned>(std::bit_width(std::max(width, height) - 1));
  }

  static unsigned checked_sample_bits(std::size_t width, std::size_t height, std::uint64_t spp) {
    require(width >= 1 && height >= 1 && width <= (std::size_t{1} << 15) &&
                height <= (std::size_t{1} << 15),
            "image width × height", width * height, "1 … 2^15 pixels per side");
    require(std::has_single_bit(spp), "samples per pixel", spp, "a power of two, spp = 2^k");
    const auto k = static_cast<unsigned>(std::countr_zero(spp));
    const unsigned r = resolution_bits(width, height);
    require(2 * r + k <= 32, "samples per pixel", spp,
            fmt::format("spp ≤ 2^{} for a {} × {} image: 4^⌈log₂ max(W, H)⌉ × spp ≤ 2^32, "
                        "the Sobol' digits' range",
                        32 - 2 * r, width, height));
    return k;
  }

  // A hash of the digits of m above bit `low` with a leading 1 marking how many there are, so
  // that prefixes of different lengths are different keys (as owen_scramble's prefixes).
  std::uint64_t hash(std::uint64_t m, unsigned low) const noexcept {
    const unsigned above = index_bits_ - low;
    const std::uint64_t prefix = (m >> low) | (std::uint64_t{1} << above);
    return mix64(key_ ^ mix64(prefix));
  }

  // One of the 24 permutations, from the top 32 bits of the hash (multiply-shift: uniform to
  // within 24 / 2^32).
  std::size_t pick(std::uint64_t m, unsigned low) const noexcept {
    return static_cast<std::size_t>(((hash(m, low) >> 32) * 24) >> 32);
  }

  std::size_t width_;
  std::size_t height_;
  unsigned sample_bits_;
  unsigned index_bits_;
  owen_scramble scramble_;
  std::uint64_t key_;
  sobol_matrices matrices_;
};

}  // namespace quadmc
