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
#include <cstdint>
#include <span>

namespace quadmc {

class random_permutation {
 public:
  random_permutation(std::uint64_t n, std::uint64_t key) : n_(n) {
    require(n >= 1 && n <= (std::uint64_t{1} << 62), "permutation size n", n, "1 ≤ n ≤ 2^62");
    const int bits = std::bit_width(n - 1);
    mask_ = bits == 0 ? 0 : (~std::uint64_t{0} >> (64 - bits));
    // Half the width (at least 1): each xorshift folds the high half into the low half, which
    // multiplication modulo 2^w alone never does (low bits of a product depend only on low bits).
    shift_ = (bits + 1) / 2 > 0 ? (bits + 1) / 2 : 1;
    std::uint64_t h = mix64(key ^ 0x6a09e667f3bcc909ULL);
    for (auto& k : keys_) {
      h = mix64(h + 0x9e3779b97f4a7c15ULL);
      k = h;
    }
    for (int r = 0; r < rounds; ++r) {
      keys_[2 * r + 1] |= 1;  // multipliers must be odd
      keys_[2 * r] &= mask_;  // x ^ (k & mask) = (x ^ k) & mask for x < 2^w: mask once, here
    }
  }

  std::uint64_t size() const noexcept { return n_; }

  // Element i of the permutation, i in [0, n).
  std::uint64_t operator()(std::uint64_t i) const noexcept {
    std::uint64_t x = i;
    do {
      x = bijection(x);
    } while (x >= n_);
    return x;
  }

  // out[k] = (*this)(first + k) for k < out.size(). One pass of the bijection over the whole
  // run first (independent iterations without a branch, which the CPU overlaps), then the cycle
  // walk only for the values that landed in [n, 2^w): fewer than half of them, none when n is a
  // power of two.
  // (A copy of *this is used: out and the keys are both uint64_t, so without it every store to
  // out would force the keys to be reloaded.)
  void apply(std::uint64_t first, std::span<std::uint64_t> out) const noexcept {
    const random_permutation p = *this;
#pragma GCC unroll 4
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = p.bijection(first + k);
    for (std::uint64_t& x : out) {
      while (x >= p.n_) x = p.bijection(x);
    }
  }

 private:
  // Three rounds: two leave visible structure for small n (consecutive i map to an arithmetic
  // progression modulo 2^w before the last xorshift); three pass the uniformity test of
  // random_permutation_test.cpp.
  static constexpr int rounds = 3;

  // The keyed bijection of [0, 2^w) that the permutation walks.
  std::uint64_t bijection(std::uint64_t x) const noexcept {
    for (int r = 0; r < rounds; ++r) {
      x ^= keys_[2 * r];
      x = (x * keys_[2 * r + 1]) & mask_;
      x ^= x >> shift_;
    }
    return x;
  }

  std::uint64_t n_;
  std::uint64_t mask_ = 0;
  int shift_ = 1;
  std::uint64_t keys_[2 * rounds] = {};
};

}  // namespace quadmc
