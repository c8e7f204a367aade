// Halton points ([Halton 1960]): coordinate j of point i is the radical inverse of i in the j-th
// prime base, φ_b(i) = Σ_k a_k b^(−k) for i = Σ_k a_k b^(k−1); with the randomizations of
// randomized quasi-Monte Carlo as types (pbrt-v4's RadicalInverse, ScrambledRadicalInverse and
// OwenScrambledRadicalInverse are the same three, [Pharr et al. 2023, §8.6]).
//
// Use it where N is not a power of two or s is large (up to 10 000 dimensions here): any N
// is a prefix of the sequence, and its star discrepancy is O((log N)^s / N)
// ([Niederreiter 1992, Thm 3.6]). Not the best choice in high s without scrambling: the
// projections on pairs of large bases are badly correlated for N below the bases' product, which
// the randomizations break up. Point 0 is the origin (unrandomized).
//
// Randomizations (the `randomization` of the `halton` method):
//  - unrandomized_radical_inverse: φ_b(i) itself.
//  - random_digit_permutation: digit k of every point goes through one random permutation π_(j,k)
//    of {0, …, b − 1} per base and digit position, over as many digits as a double resolves
//    (b^(−D) ≤ 2^(−53), so trailing zero digits are permuted too and every coordinate is uniform).
//  - nested_digit_scramble: Owen's nested scrambling in base b ([Owen 1995]): the permutation of
//    digit k depends on the digits before it, i.e. on i mod b^(k−1). Past the depth d at which
//    b^d exceeds the largest index every point has its own prefix, so the remaining digits are
//    one uniform number per point, drawn from its prefix (the same distribution as scrambling
//    every later digit).
// The permutations are the affine maps a ↦ (h·a + g) mod b with h uniform in [1, b) and g uniform
// in [0, b) (b is prime, so each is a permutation): every scrambled digit is uniform, and two
// distinct digits go to a uniform pair of distinct digits. Owen's variance formula for scrambled
// points depends on the permutations only through these pairs ([Owen 1997b]; the same argument as
// for the linear scrambles of [Owen 2003]), so they cost two multiplications instead of a table.
// Keys come from the top of the philox stream's counter space (point_set.hpp). One randomized
// run cannot estimate its own error: variance() is not_estimable (replicates give the error bar,
// docs/theory.md#replicate-error-bars).
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

// The first `max_halton_dimension` primes, 2, 3, 5, …, 104729 (a sieve of Eratosthenes run once).
inline constexpr std::size_t max_halton_dimension = 10000;
std::span<const std::uint32_t> halton_bases();

namespace detail {
__extension__ using uint128 = unsigned __int128;  // GCC/Clang; __extension__: no -Wpedantic
// ⌊x·b / 2^64⌋: a uniform integer in [0, b) from 64 uniform bits, biased by at most b/2^64.
inline std::uint64_t uniform_below(std::uint64_t bits, std::uint64_t b) noexcept {
  return static_cast<std::uint64_t>((static_cast<uint128>(bits) * b) >> 64);
}
// The affine digit permutation a ↦ (h·a + g) mod b drawn from one 64-bit key.
struct affine_digit_map {
  std::uint64_t h = 1;
  std::uint64_t g = 0;
  static affine_digit_map draw(std::uint64_t key, std::uint64_t b) noexcept {
    return {1 + uniform_below(mix64(key), b - 1),
            uniform_below(mix64(key ^ 0x3c6ef372fe94f82bULL), b)};
  }
  std::uint64_t operator()(std::uint64_t a, std::uint64_t b) const noexcept {
    return (h * a + g) % b;
  }
};
}  // namespace detail

// φ_b(i) unrandomized.
class unrandomized_radical_inverse {
 public:
  static constexpr bool random = false;
  unrandomized_radical_inverse(std::size_t, std::uint64_t, const random_stream&) noexcept {}
  double operator()(std::uint64_t i, std::size_t, std::uint64_t b, double inv_b) const noexcept {
    // φ_b(i) = r/b^K with r the K digits of i reversed, an integer: built exactly while b^K fits
    // 64 bits, so x is r/b^K rounded once or twice (a point k/b^K of the first b^K stays in its
    // interval [k/b^K, (k + 1)/b^K) — a Horner loop over the inexact 1/b can round it below).
    constexpr std::uint64_t most = ~std::uint64_t{0};
    std::uint64_t reversed = 0;
    std::uint64_t scale = 1;
    for (; i != 0 && scale <= most / b; i /= b) {
      reversed = reversed * b + i % b;
      scale *= b;
    }
    // Digits left over (only for i near 2^64/b): their value below 1/b^K, by Horner.
    std::uint64_t digits[64];
    int count = 0;
    for (; i != 0; i /= b) digits[count++] = i % b;
    double tail = 0.0;
    while (count > 0) tail = (static_cast<double>(digits[--count]) + tail) * inv_b;
    const double x = (static_cast<double>(reversed) + tail) / static_cast<double>(scale);
    return std::min(x, largest_below_one);
  }
};

// One random permutation per (base, digit position), over every digit a double resolves.
class random_digit_permutation {
 public:
  static constexpr bool random = true;
  random_digit_permutation(std::size_t s, std::uint64_t, const random_stream& rng) {
    const auto bases = halton_bases();
    first_.resize(s + 1);
    for (std::size_t j = 0; j < s; ++j) {
      first_[j] = maps_.size();
      const std::uint64_t b = bases[j];
      // D digits with b^D ≥ 2^53: the resolution of a double.
      double reach = 1.0;
      for (std::size_t k = 0; reach < 0x1.0p53; ++k, reach *= static_cast<double>(b)) {
        maps_.push_back(detail::affine_digit_map::draw(randomization_key(rng, maps_.size()), b));
      }
    }
    first_[s] = maps_.size();
    // Digits past the last nonzero digit of i are 0, permuted to the constant map_k(0): the
    // Horner sum over positions count − 1 … L of those constants, tail_[first_[j] + j + L], is the
    // same double for every i with L digits, so operator() starts from it and walks only i's own
    // digits (the same operations in the same order as the full walk, hence the same bits).
    tail_.resize(maps_.size() + s);
    for (std::size_t j = 0; j < s; ++j) {
      const std::uint64_t b = bases[j];
      const double inv_b = 1.0 / static_cast<double>(b);  // as halton_points' inverse_
      const std::size_t count = first_[j + 1] - first_[j];
      double* tail = tail_.data() + first_[j] + j;
      tail[count] = 0.0;
      for (std::size_t k = count; k-- > 0;) {
        tail[k] = (static_cast<double>(maps_[first_[j] + k](0, b)) + tail[k + 1]) * inv_b;
      }
    }
  }
  double operator()(std::uint64_t i, std::size_t j, std::uint64_t b, double inv_b) const noexcept {
    const detail::affine_digit_map* map = maps_.data() + first_[j];
    const std::size_t count = first_[j + 1] - first_[j];
    std::uint64_t digits[64];
    std::size_t length = 0;
    for (; i != 0 && length < count; ++length) {
      digits[length] = map[length](i % b, b);
      i /= b;
    }
    double x = tail_[first_[j] + j + length];
    for (std::size_t k = length; k-- > 0;) x = (static_cast<double>(digits[k]) + x) * inv_b;
    return std::min(x, largest_below_one);
  }
  // Every digit position walked, as before the tail table: the reference of the tests.
  double reference(std::uint64_t i, std::size_t j, std::uint64_t b, double inv_b) const noexcept {
    const detail::affine_digit_map* map = maps_.data() + first_[j];
    const std::size_t count = first_[j + 1] - first_[j];
    std::uint64_t digits[64];
    for (std::size_t k = 0; k < count; ++k) {
      digits[k] = map[k](i % b, b);
      i /= b;
    }
    double x = 0.0;
    for (std::size_t k = count; k-- > 0;) x = (static_cast<double>(digits[k]) + x) * inv_b;
    return std::min(x, largest_below_one);
  }

 private:
  std::vector<detail::affine_digit_map> maps_;
  std::vector<std::size_t> first_;  // dimension j's maps: [first_[j], first_[j + 1])
  std::vector<double> tail_;        // count_j + 1 per dimension (see the constructor)
};

// Owen's nested scrambling in each base.
class nested_digit_scramble {
 public:
  static constexpr bool random = true;
  // `largest_index` is the largest i the set generates: it fixes the depth d_j of each base.
  nested_digit_scramble(std::size_t s, std::uint64_t largest_index, const random_stream& rng)
      : seed_(s), depth_(s) {
    const auto bases = halton_bases();
    for (std::size_t j = 0; j < s; ++j) {
      seed_[j] = randomization_key(rng, j);
      unsigned d = 0;
      for (std::uint64_t reach = 1; reach <= largest_index; reach *= bases[j]) {
        ++d;
        if (reach > largest_index / bases[j]) break;  // b^d > largest_index already
      }
      depth_[j] = d;
    }
  }
  double operator()(std::uint64_t i, std::size_t j, std::uint64_t b, double inv_b) const noexcept {
    const std::uint64_t seed = seed_[j];
    const unsigned d = depth_[j];
    std::uint64_t digits[64];
    std::uint64_t rest = i;
    std::uint64_t prefix = 0;  // i mod b^k: the digits before digit k + 1
    std::uint64_t place = 1;   // b^k
    for (unsigned k = 0; k < d; ++k) {
      const std::uint64_t a = rest % b;
      rest /= b;
      const std::uint64_t key = mix64(seed ^ mix64(prefix + 0x9e3779b97f4a7c15ULL * (k + 1)));
      digits[k] = detail::affine_digit_map::draw(key, b)(a, b);
      prefix += a * place;
      place *= b;
    }
    // The digits past depth d: one uniform number per point (prefix = i here).
    double x = fraction_to_unit(mix64(seed ^ mix64(prefix ^ 0xa0761d6478bd642fULL)));
    for (unsigned k = d; k-- > 0;) x = (static_cast<double>(digits[k]) + x) * inv_b;
    return std::min(x, largest_below_one);
  }

 private:
  std::vector<std::uint64_t> seed_;
  std::vector<unsigned> depth_;
};

template <class Randomizer>
class halton_points {
 public:
  halton_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed, std::uint64_t stream,
                rng_kind rng = rng_kind::philox4x32_10)
      : s_(checked_dimension(dimension, n)),
        n_(n),
        randomizer_(dimension, n - 1, random_stream(seed, stream, rng)),
        bases_(halton_bases().begin(), halton_bases().begin() + static_cast<std::ptrdiff_t>(s_)),
        inverse_(s_) {
    for (std::size_t j = 0; j < s_; ++j) inverse_[j] = 1.0 / static_cast<double>(bases_[j]);
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }
  const Randomizer& randomizer() const noexcept { return randomizer_; }
  std::uint64_t base(std::size_t j) const noexcept { return bases_[j]; }
  double inverse_base(std::size_t j) const noexcept { return inverse_[j]; }

  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    const std::uint64_t count = out.size() / s_;
    for (std::size_t j = 0; j < s_; ++j) {
      const std::uint64_t b = bases_[j];
      const double inv_b = inverse_[j];
      for (std::uint64_t p = 0; p < count; ++p) {
        out[p * s_ + j] = randomizer_(first + p, j, b, inv_b);
      }
    }
  }

 private:
  static std::size_t checked_dimension(std::size_t s, std::uint64_t n) {
    require_point_set_size(s, n);
    require(s <= max_halton_dimension, "dimension s", s, "s ≤ 10000 (the Halton bases tabulated)");
    return s;
  }

  std::size_t s_;
  std::uint64_t n_;
  Randomizer randomizer_;
  std::vector<std::uint64_t> bases_;
  std::vector<double> inverse_;
};

}  // namespace quadmc
