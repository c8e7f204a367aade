// xoshiro256+ ([Blackman & Vigna 2021]; reference code prng.di.unimi.it/xoshiro256plus.c), the
// generator of the hand-written reference loop that quadmc's plain Monte Carlo is measured against.
//
// Use it only in that loop: it is the fastest generator a user would plausibly write by hand for
// doubles (one add, a few shifts and xors per 64 bits; the low bits are weak, which the top-53-bit
// conversion below discards, as its authors advise). Not for the library: its state must be
// advanced in order, so a sample cannot be regenerated alone and a parallel run would depend on
// the schedule (docs/design.md#hot-path-contract asks for counter-based streams,
// quadmc::random_stream).
#pragma once

#include <cstdint>

namespace quadmc::bench {

class xoshiro256plus {
 public:
  // The state is filled by SplitMix64 from the seed, as the authors recommend (an all-zero state
  // would be a fixed point).
  explicit xoshiro256plus(std::uint64_t seed) noexcept {
    for (auto& word : state_) {
      seed += 0x9e3779b97f4a7c15ULL;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      word = z ^ (z >> 31);
    }
  }

  std::uint64_t next() noexcept {
    const std::uint64_t result = state_[0] + state_[3];
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = (state_[3] << 45) | (state_[3] >> 19);
    return result;
  }

  // In [0, 1), a multiple of 2^-53: the top 53 bits (the low bits of xoshiro256+ fail linearity
  // tests, the top ones do not).
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_[4];
};

}  // namespace quadmc::bench
