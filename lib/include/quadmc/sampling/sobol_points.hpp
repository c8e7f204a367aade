// Sobol' points in base 2 ([Sobol' 1967]; direction numbers of [Joe & Kuo 2008] from Boost's
// table), in Gray-code order, with the point at index 0 (the origin) kept, and the randomizations
// of randomized quasi-Monte Carlo as types (the shape of pbrt-v4's SobolSample(a, dimension,
// randomizer), [Pharr et al. 2023, §8.7]).
//
// Use it for smooth integrands in low to moderate dimension (s ≤ 3667, the table's size):
// N = 2^m points of an Owen-scrambled Sobol' sequence form a scrambled (t, m, s)-net whose RMSE
// on a smooth f falls as N^(−3/2) up to log factors ([Owen 1997b]; docs/theory.md#scrambled-nets).
// Not for N other than 2^m with a randomization: the first N points of the sequence are then no
// net, and the rate drops to N^(−1) ([Owen 2022]; docs/theory.md#sobol-anti-patterns); the
// methods refuse such N unless `allow_any_n = true` asks for it. Dropping point 0 (Boost's
// sobol_engine does, its documentation says so) has the same cost.
//
// Layout: coordinate j of point i is the 32-digit binary fraction C_j·g(i), g(i) = i ⊕ (i >> 1)
// the Gray code of i and C_j the generator matrix of dimension j (sobol_matrices): consecutive
// points differ by one column, x(i + 1) = x(i) ⊕ C_j[ctz(i + 1)], so a batch costs one XOR per
// coordinate after the first point, which is computed directly (O(32)). A randomizer maps that
// 32-digit fraction (held in the top half of a 64-bit word) to a 64-digit one whose top 53 bits
// become the double: with a randomization every coordinate is uniform on [0, 1) in 2^-53 steps.
//
// Randomness is counter-based: every key of a randomizer is a word of
// random_stream(seed, stream) taken from the top of its counter space (point_set.hpp), so a point
// is a pure function of (s, N, seed, stream, i) and batches may run in any order on any thread.
// One run of a randomized net cannot estimate its own error (its points are not independent):
// variance() is not_estimable, and the error bar comes from independent replicates
// (docs/theory.md#replicate-error-bars).
#pragma once

#include "quadmc/core/rng.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/sobol_blocks.hpp"

#include <algorithm>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace quadmc {

// The generator matrices C_1 … C_s of the Sobol' sequence: column k of dimension j is the
// direction number v_(j,k) = m_(j,k)/2^(k+1) as a 32-bit integer whose most significant bit is
// the digit of 2^-1. Dimension 1 is the van der Corput sequence (C = identity); dimension j ≥ 2
// takes the primitive polynomial and initial m of Boost's table (boost/random/detail/
// sobol_table.hpp, Joe and Kuo's new-joe-kuo-6.21201 cut at 3667 dimensions) and extends the m
// by the recurrence of [Bratley & Fox 1988] as [Joe & Kuo 2008, eq. 3] writes it.
class sobol_matrices {
 public:
  static constexpr std::size_t max_dimension = 3667;
  static constexpr unsigned digits = 32;  // N ≤ 2^32 points

  explicit sobol_matrices(std::size_t dimension);

  std::size_t dimension() const noexcept { return columns_.size() / digits; }
  // The 32 columns of dimension j (0-based), column k multiplying bit k of the Gray code.
  std::span<const std::uint32_t, digits> columns(std::size_t j) const noexcept {
    return std::span<const std::uint32_t, digits>(columns_.data() + j * digits, digits);
  }

 private:
  std::vector<std::uint32_t> columns_;
};

// The 32-digit fraction of dimension j for Gray-code index g: ⊕ of the columns of g's set bits.
inline std::uint32_t sobol_digits(std::span<const std::uint32_t, sobol_matrices::digits> columns,
                                  std::uint32_t gray) noexcept {
  std::uint32_t v = 0;
  for (; gray != 0; gray &= gray - 1) v ^= columns[static_cast<unsigned>(std::countr_zero(gray))];
  return v;
}

// A word of the randomization keys of one (seed, stream): word `index` counted from the top of
// the counter space, which no point set's uniforms reach (point_set.hpp).
inline std::uint64_t randomization_key(const random_stream& rng, std::uint64_t index) noexcept {
  return rng.bits(std::numeric_limits<std::uint64_t>::max() - index);
}

// --- randomizers: each maps the digits of a net's coordinate to a 64-digit fraction ----------
// Interface: R(s, depth, rng) builds the keys of s dimensions; depth = the number of leading
// digits that tell the set's points apart (bit width of the largest index: below it the
// prefixes are unique); prepare(j, columns) may rewrite dimension j's generator columns (the
// linear scramble), and r(v, j) maps a 64-digit fraction v (the net's 32 digits on top).
// `scramble` and key(j) (and depth() for owen) tell the vector kernel (sampling/sobol_blocks.hpp)
// what r does, so that it can do the same on 8 lanes.

// The net itself: no randomness; coordinates are exact multiples of 2^-32.
struct unrandomized_digits {
  static constexpr bool random = false;
  static constexpr detail::sobol_scramble scramble = detail::sobol_scramble::xor_constant;
  unrandomized_digits(std::size_t, unsigned, const random_stream&) noexcept {}
  std::uint64_t key(std::size_t) const noexcept { return 0; }
  void prepare(std::size_t, std::span<std::uint64_t>) const noexcept {}
  std::uint64_t operator()(std::uint64_t v, std::size_t) const noexcept { return v; }
};

// Digital shift: v ⊕ Δ_j with Δ_j 64 uniform random digits. Every point becomes uniform, but all
// share one shift: the net's digit structure and its discrepancy are unchanged, so the error of
// a smooth f stays O(N^−1) up to log factors (docs/theory.md#digital-shift).
class digital_shift {
 public:
  static constexpr bool random = true;
  digital_shift(std::size_t s, unsigned, const random_stream& rng) : shift_(s) {
    for (std::size_t j = 0; j < s; ++j) shift_[j] = randomization_key(rng, j);
  }
  void prepare(std::size_t, std::span<std::uint64_t>) const noexcept {}
  std::uint64_t operator()(std::uint64_t v, std::size_t j) const noexcept { return v ^ shift_[j]; }
  static constexpr detail::sobol_scramble scramble = detail::sobol_scramble::xor_constant;
  std::uint64_t key(std::size_t j) const noexcept { return shift_[j]; }

 private:
  std::vector<std::uint64_t> shift_;
};

// Random linear matrix scramble plus digital shift ([Matoušek 1998]; the default of scipy and
// QMCPy): each generator column becomes L_j·C_j with L_j a random 64 × 64 lower-triangular
// binary matrix with unit diagonal (digit r of the output is digit r of the input plus a random
// combination of the digits before it), then a digital shift. L_j is invertible and keeps every
// elementary interval's count, so the (t, m, s)-net property survives; its variance equals that
// of nested uniform scrambling for every square-integrable f ([Owen 2003]). It costs nothing per
// point: the scramble is paid once per dimension, in prepare().
class linear_matrix_scramble {
 public:
  static constexpr bool random = true;
  linear_matrix_scramble(std::size_t s, unsigned, const random_stream& rng)
      : lower_(64 * s), shift_(s) {
    for (std::size_t j = 0; j < s; ++j) {
      shift_[j] = randomization_key(rng, j);
      for (unsigned r = 0; r < 64; ++r) {
        // Row r (digit r + 1, counted from the most significant): the unit diagonal at bit
        // 63 − r and random bits strictly above it (the earlier digits); none below.
        const std::uint64_t diagonal = std::uint64_t{1} << (63 - r);
        const std::uint64_t above = r == 0 ? 0 : ~std::uint64_t{0} << (64 - r);
        lower_[64 * j + r] = diagonal | (randomization_key(rng, s + 64 * j + r) & above);
      }
    }
  }
  // Output digit r of a column is the parity of (row r & column).
  void prepare(std::size_t j, std::span<std::uint64_t> columns) const noexcept {
    for (std::uint64_t& c : columns) {
      std::uint64_t out = 0;
      for (unsigned r = 0; r < 64; ++r) {
        const auto bit = static_cast<std::uint64_t>(std::popcount(lower_[64 * j + r] & c) & 1);
        out |= bit << (63 - r);
      }
      c = out;
    }
  }
  std::uint64_t operator()(std::uint64_t v, std::size_t j) const noexcept { return v ^ shift_[j]; }
  static constexpr detail::sobol_scramble scramble = detail::sobol_scramble::xor_constant;
  std::uint64_t key(std::size_t j) const noexcept { return shift_[j]; }

 private:
  std::vector<std::uint64_t> lower_;  // 64 rows per dimension
  std::vector<std::uint64_t> shift_;
};

// Nested uniform scrambling in base 2 ([Owen 1995]), exact: digit b of the output is digit b of
// the input flipped by a random bit that depends on (seed, dimension, the input's first b − 1
// digits). The flips are the nodes of a binary tree (the root flips digit 1, the node reached by
// the first b digits flips digit b + 1), drawn six levels at a time: one keyed hash of the prefix
// at a level 6g gives 64 random bits, and bit `node` of it is the flip of the node `node` of
// the 63-node subtree below that prefix (nodes numbered level by level, 2^d − 1 + the d digits
// below the prefix at level d < 6). Every node has its own bit of its own hash, so the flips are
// independent as the hash's bits are (pbrt-v4's OwenScrambler hashes every prefix alone; six
// levels per hash draw the same tree for a sixth of the hashes, docs/theory.md#scrambled-nets).
// Flips are drawn for the first `depth` digits only: past that depth every point of the set has
// its own prefix, so the later flips of different points are independent, and the remaining
// digits are exactly as random as one uniform word drawn per point from its depth-digit prefix
// (the same distribution, one hash instead of 64 − depth). Unbiased, and a scrambled (t, m, s)-net
// stays a (t, m, s)-net with probability 1; RMSE O(N^(−3/2)(log N)^((s−1)/2)) for smooth f
// ([Owen 1997b]).
class owen_scramble {
 public:
  static constexpr bool random = true;
  static constexpr unsigned levels_per_hash = detail::owen_levels_per_hash;  // 63 nodes a hash
  owen_scramble(std::size_t s, unsigned depth, const random_stream& rng)
      : seed_(s), depth_(depth < 64 ? depth : 64) {
    for (std::size_t j = 0; j < s; ++j) seed_[j] = randomization_key(rng, j);
  }
  static constexpr detail::sobol_scramble scramble = detail::sobol_scramble::owen;
  std::uint64_t key(std::size_t j) const noexcept { return seed_[j]; }
  unsigned depth() const noexcept { return depth_; }
  void prepare(std::size_t, std::span<std::uint64_t>) const noexcept {}
  std::uint64_t operator()(std::uint64_t v, std::size_t j) const noexcept {
    const std::uint64_t seed = seed_[j];
    std::uint64_t out = v ^ flips(seed, v, 0, depth_);
    if (depth_ < 64) {
      // The tail's key has bit 63 set, which no subtree key (a prefix of ≤ 32 digits below
      // its marker bit) has: a hash of its own.
      const std::uint64_t tail = mix64(seed ^ prefix(v, depth_) ^ 0xa0761d6478bd642fULL);
      const std::uint64_t low = ~std::uint64_t{0} >> depth_;  // depth_ < 64
      out = (out & ~low) | (tail & low);
    }
    return out;
  }

  // The flips of digits first + 1 … last (0-based b in [first, last)) of v, at their bits 63 − b:
  // the scramble's tree as the vector kernel's prefix table (sampling/sobol_blocks.hpp) reads it.
  static std::uint64_t flips(std::uint64_t seed, std::uint64_t v, unsigned first,
                             unsigned last) noexcept {
    std::uint64_t out = 0;
    std::uint64_t tree = 0;
    for (unsigned b = first; b < last; ++b) {
      const unsigned d = b % levels_per_hash;
      if (d == 0 || b == first) tree = mix64(seed ^ prefix(v, b - d));
      const std::uint64_t below = d == 0 ? 0 : (v >> (64 - b)) & ((std::uint64_t{1} << d) - 1);
      const auto node = static_cast<unsigned>((std::uint64_t{1} << d) - 1 + below);
      out |= ((tree >> node) & 1) << (63 - b);
    }
    return out;
  }

  // The first b digits of v with a leading 1 marking their count, so that prefixes of different
  // lengths are different keys (mix64 is a bijection: distinct keys give distinct words).
  static std::uint64_t prefix(std::uint64_t v, unsigned b) noexcept {
    return b == 0 ? 1 : ((v >> (64 - b)) | (std::uint64_t{1} << b));
  }

 private:
  std::vector<std::uint64_t> seed_;
  unsigned depth_;
};

// Hash-based approximation of nested uniform scrambling ([Burley 2020], after [Laine & Karras
// 2011]; pbrt-v4's FastOwenScrambler is the same idea): reverse the 32 digits, apply a keyed
// hash in which every bit depends only on itself and the bits below it (additions and
// multiplications by even constants propagate upwards only), reverse back: so digit b depends
// only on the digits before it, as in a nested scramble. It is NOT exactly nested uniform (the
// flips of different prefixes are not independent), so Owen's variance results do not carry
// over and no rate is claimed for it (docs/theory.md#scrambled-nets). Digits 33…64 come from a
// keyed 32-bit hash of the point's scrambled 32 digits, distinct for every point of N ≤ 2^32.
class fast_owen_scramble {
 public:
  static constexpr bool random = true;
  fast_owen_scramble(std::size_t s, unsigned, const random_stream& rng) : seed_(s) {
    for (std::size_t j = 0; j < s; ++j) seed_[j] = randomization_key(rng, j);
  }
  static constexpr detail::sobol_scramble scramble = detail::sobol_scramble::fast_owen;
  std::uint64_t key(std::size_t j) const noexcept { return seed_[j]; }
  void prepare(std::size_t, std::span<std::uint64_t>) const noexcept {}
  std::uint64_t operator()(std::uint64_t v, std::size_t j) const noexcept {
    const std::uint64_t seed = seed_[j];
    std::uint32_t x = reverse(static_cast<std::uint32_t>(v >> 32));
    // The four multiply-xor rounds and constants of [Burley 2020, listing 2].
    x += static_cast<std::uint32_t>(seed);
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    const std::uint32_t high = reverse(x);
    return (static_cast<std::uint64_t>(high) << 32) | low_digits(high, seed);
  }

  // Digits 33…64: MurmurHash3's 32-bit finaliser [Appleby 2011], a bijection, of the scrambled
  // digits keyed by the seed's other half: uniform for a uniform seed, distinct for every point,
  // and 32-bit arithmetic throughout (a 64-bit mixer costs the vector kernels several times more).
  static std::uint32_t low_digits(std::uint32_t high, std::uint64_t seed) noexcept {
    std::uint32_t h = high ^ static_cast<std::uint32_t>(seed >> 32);
    h = (h ^ (h >> 16)) * 0x85ebca6bu;
    h = (h ^ (h >> 13)) * 0xc2b2ae35u;
    return h ^ (h >> 16);
  }

 private:
  static std::uint32_t reverse(std::uint32_t x) noexcept {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
  }
  std::vector<std::uint64_t> seed_;
};

// The top 53 digits of a 64-digit fraction as a double in [0, 1).
constexpr double fraction_to_unit(std::uint64_t v) noexcept {
  return static_cast<double>(v >> 11) * 0x1.0p-53;
}

template <class Randomizer>
class sobol_points {
 public:
  // N ≤ 2^32 points (2^32 − 1 when the first is dropped) of s ≤ 3667 dimensions. Any N is
  // accepted here; the methods decide which N they allow (a randomized net needs N = 2^m).
  // `drop_first_point` starts at index 1: the anti-pattern of docs/theory.md#sobol-anti-patterns.
  sobol_points(std::size_t dimension, std::uint64_t n, std::uint64_t seed, std::uint64_t stream,
               bool drop_first_point = false, rng_kind rng = rng_kind::philox4x32_10)
      : s_(checked_dimension(dimension, n, drop_first_point)),
        n_(n),
        offset_(drop_first_point ? 1 : 0),
        // The largest index is N − 1 + offset: its bit width is the depth below which every
        // point of the set has its own prefix.
        randomizer_(dimension, static_cast<unsigned>(std::bit_width(n - 1 + offset_)),
                    random_stream(seed, stream, rng)),
        columns_(static_cast<std::size_t>(sobol_matrices::digits) * dimension) {
    const sobol_matrices matrices(dimension);
    for (std::size_t j = 0; j < s_; ++j) {
      const auto c = matrices.columns(j);
      const std::span<std::uint64_t> out(columns_.data() + j * sobol_matrices::digits,
                                         sobol_matrices::digits);
      for (unsigned k = 0; k < sobol_matrices::digits; ++k) {
        out[k] = static_cast<std::uint64_t>(c[k]) << 32;
      }
      randomizer_.prepare(j, out);
    }
    if constexpr (vectorized) {
      std::vector<std::uint64_t> keys(s_);
      for (std::size_t j = 0; j < s_; ++j) keys[j] = randomizer_.key(j);
      unsigned depth = 0;
      if constexpr (requires { randomizer_.depth(); }) depth = randomizer_.depth();
      blocks_ = detail::make_sobol_block_tables(columns_, s_, Randomizer::scramble, keys, depth);
    }
  }

  std::uint64_t size() const noexcept { return n_; }
  std::size_t dimension() const noexcept { return s_; }
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }

  // Whole blocks of the vector kernel where the CPU has one (sampling/sobol_blocks.hpp), the
  // points before the first block start and after the last block end by the scalar walk; both
  // give the same bits, so the split never shows in the points.
  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    const std::uint64_t count = out.size() / s_;
    if constexpr (vectorized) {
      const unsigned b = blocks_.log2_block;
      const std::uint64_t block = std::uint64_t{1} << b;
      const std::uint64_t index = first + offset_;
      const std::uint64_t head = std::min(count, (block - (index & (block - 1))) & (block - 1));
      const std::uint64_t blocks = (count - head) >> b;
      if (blocks > 0 &&
          detail::sobol_blocks(blocks_, (index + head) >> b, blocks, out.data() + head * s_)) {
        generate_scalar(first, head, out.data());
        const std::uint64_t done = head + (blocks << b);
        generate_scalar(first + done, count - done, out.data() + done * s_);
        return;
      }
    }
    generate_scalar(first, count, out.data());
  }

  // The point-by-point Gray-code walk, one coordinate at a time: the reference the vector
  // kernel must equal bitwise (tests), and the path of CPUs without one.
  void generate_reference(std::uint64_t first, std::span<double> out) const {
    require_batch(s_, n_, first, out);
    generate_scalar(first, out.size() / s_, out.data());
  }

  // The 64-digit fractions themselves (tests: the net property, Boost's bits), row-major.
  void generate_digits(std::uint64_t first, std::span<std::uint64_t> out) const {
    const std::uint64_t count = out.size() / s_;
    for (std::uint64_t p = 0; p < count; ++p) {
      const std::uint64_t index = first + p + offset_;
      for (std::size_t j = 0; j < s_; ++j) {
        const std::uint64_t* c = columns_.data() + j * sobol_matrices::digits;
        std::uint64_t v = 0;
        for (std::uint64_t g = index ^ (index >> 1); g != 0; g &= g - 1) {
          v ^= c[std::countr_zero(g)];
        }
        out[p * s_ + j] = randomizer_(v, j);
      }
    }
  }

 private:
  static constexpr bool vectorized = requires(const Randomizer& r) {
    { Randomizer::scramble } -> std::convertible_to<detail::sobol_scramble>;
    { r.key(std::size_t{0}) } -> std::convertible_to<std::uint64_t>;
  };

  void generate_scalar(std::uint64_t first, std::uint64_t count, double* out) const {
    if (count == 0) return;
    const std::uint64_t index = first + offset_;
    for (std::size_t j = 0; j < s_; ++j) {
      const std::uint64_t* c = columns_.data() + j * sobol_matrices::digits;
      std::uint64_t v = 0;
      for (std::uint64_t g = index ^ (index >> 1); g != 0; g &= g - 1) {
        v ^= c[std::countr_zero(g)];
      }
      double* x = out + j;
      for (std::uint64_t p = 0;; ++p) {
        x[p * s_] = fraction_to_unit(randomizer_(v, j));
        if (p + 1 == count) break;
        v ^= c[std::countr_zero(index + p + 1)];
      }
    }
  }

  static std::size_t checked_dimension(std::size_t s, std::uint64_t n, bool drop_first_point) {
    require_point_set_size(s, n);
    require(s <= sobol_matrices::max_dimension, "dimension s", s,
            "s ≤ 3667 (the dimensions of Boost's Sobol' table)");
    const std::uint64_t most = (std::uint64_t{1} << 32) - (drop_first_point ? 1 : 0);
    require(n <= most, "number of points N", n,
            drop_first_point ? "N ≤ 2^32 − 1 (32-digit direction numbers, first point dropped)"
                             : "N ≤ 2^32 (32-digit direction numbers)");
    return s;
  }

  std::size_t s_;
  std::uint64_t n_;
  std::uint64_t offset_;
  Randomizer randomizer_;
  std::vector<std::uint64_t> columns_;  // 32 per dimension, randomized by prepare()
  detail::sobol_block_tables blocks_;   // the vector kernel's tables (sobol_blocks.hpp)
};

}  // namespace quadmc
