// A random permutation of [0, n) evaluated one element at a time, in O(1) time and memory.
//
// Use it where a point set needs "shuffle the strata" (Latin hypercube, padded jittered points)
// but must regenerate point i alone, in any order, for any N: storing N-element permutations
// would cost 8N bytes per dimension and tie a point to the batch that built the table. Not a
// cryptographic permutation, and not for n > 2^62 (point sets never ask for more).
//
// Method (the idea of [Kensler 2013], whose permute() [Pharr et al. 2023] uses as
// PermutationElement; our own rounds and 64-bit domain): a keyed
// bijection on w-bit words, w = bit width of n − 1, built only from operations invertible modulo
// 2^w (xor with a key, multiplication by an odd key, x ^= x >> r, addition of a key); then
// "cycle walking": re-apply the bijection until the value falls in [0, n). Following a cycle of a
// bijection of [0, 2^w) until it re-enters [0, n) is a bijection of [0, n)
// ([Black & Rogaway 2002]), and since n > 2^(w−1) the expected number of walks is below 2.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

namespace quadmc {

namespace detail {

// The keyed bijection of [0, 2^w) that a random_permutation walks, and its key schedule: three
// rounds of x ^= key, x = x·odd key mod 2^w, x ^= x >> shift. Exact integer arithmetic, so the
// vector kernels below give the scalar bits.
struct permutation_schedule {
  // Three rounds: two leave visible structure for small n (consecutive i map to an arithmetic
  // progression modulo 2^w before the last xorshift); three pass the uniformity test of
  // random_permutation_test.cpp.
  static constexpr int rounds = 3;
  std::uint64_t n = 1;
  std::uint64_t mask = 0;
  int shift = 1;
  std::uint64_t keys[2 * rounds] = {};

  std::uint64_t bijection(std::uint64_t x) const noexcept {
    for (int r = 0; r < rounds; ++r) {
      x ^= keys[2 * r];
      x = (x * keys[2 * r + 1]) & mask;
      x ^= x >> shift;
    }
    return x;
  }
};

// out[k] = element first + k of the permutation for k < count, at the active SIMD level
// (core/simd_level.hpp): AVX-512DQ multiplies 8 lanes of 64 bits at once (vpmullq), AVX2 4 lanes
// with the 64-bit product built from three 32-bit ones; SSE2 and scalar run the scalar loop.
// lib/src/sampling/permutation_blocks*.cpp.
void permutation_blocks(const permutation_schedule& p, std::uint64_t first, std::size_t count,
                        std::uint64_t* out) noexcept;

}  // namespace detail

class random_permutation {
 public:
  random_permutation(std::uint64_t n, std::uint64_t key) {
    require(n >= 1 && n <= (std::uint64_t{1} << 62), "permutation size n", n, "1 ≤ n ≤ 2^62");
    p_.n = n;
    const int bits = std::bit_width(n - 1);
    p_.mask = bits == 0 ? 0 : (~std::uint64_t{0} >> (64 - bits));
    // Half the width (at least 1): each xorshift folds the high half into the low half, which
    // multiplication modulo 2^w alone never does (low bits of a product depend only on low bits).
    p_.shift = (bits + 1) / 2 > 0 ? (bits + 1) / 2 : 1;
    std::uint64_t h = mix64(key ^ 0x6a09e667f3bcc909ULL);
    for (auto& k : p_.keys) {
      h = mix64(h + 0x9e3779b97f4a7c15ULL);
      k = h;
    }
    for (int r = 0; r < rounds; ++r) {
      p_.keys[2 * r + 1] |= 1;    // multipliers must be odd
      p_.keys[2 * r] &= p_.mask;  // x ^ (k & mask) = (x ^ k) & mask for x < 2^w: mask once, here
    }
  }

  std::uint64_t size() const noexcept { return p_.n; }

  // The bijection's parameters, for kernels that evaluate several permutations at once
  // (detail::latin_hypercube_place).
  const detail::permutation_schedule& schedule() const noexcept { return p_; }

  // Element i of the permutation, i in [0, n).
  std::uint64_t operator()(std::uint64_t i) const noexcept {
    std::uint64_t x = i;
    do {
      x = p_.bijection(x);
    } while (x >= p_.n);
    return x;
  }

  // out[k] = (*this)(first + k) for k < out.size(): one pass of the bijection over the whole run
  // in vector lanes, then the cycle walk for the lanes that landed in [n, 2^w) (fewer than half,
  // none when n is a power of two); detail::permutation_blocks.
  void apply(std::uint64_t first, std::span<std::uint64_t> out) const noexcept {
    detail::permutation_blocks(p_, first, out.size(), out.data());
  }

 private:
  static constexpr int rounds = detail::permutation_schedule::rounds;

  detail::permutation_schedule p_;
};

}  // namespace quadmc
