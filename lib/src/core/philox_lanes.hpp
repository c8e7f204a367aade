// Philox4x32-10 on several counters at once: the body of the SSE2, AVX2 and AVX-512 kernels
// behind random_stream::fill_uniform (core/rng.hpp). Private to lib/src/core.
//
// Why lanes of 64 bits holding 32-bit words: a Philox round is two 32×32→64-bit products per
// block (Salmon et al., SC'11, §4.1: hi/lo = mulhilo(M, c)), and x86 multiplies exactly that in
// every 64-bit lane with one instruction (pmuludq: SSE2 2 lanes, AVX2 4, AVX-512 8). Compilers do
// not find this themselves (GCC 12 leaves the scalar loop unvectorized: "unsupported use in
// stmt"), hence the intrinsics. A lane holds one block; `groups` independent registers per step
// hide the multiply's latency across the 10 dependent rounds.
//
// Each ISA file (philox_blocks_<isa>.cpp) is compiled with that ISA's flag and includes this
// header with its own Lanes type, and calls no inline function of a shared header: an
// out-of-line copy of one, compiled for AVX2, could be chosen by the linker for the whole program
// (the ODR hazard of per-file -m flags). Its own lane types live in anonymous namespaces.
#pragma once

#include "philox_constants.hpp"

#include <cstddef>
#include <cstdint>

namespace quadmc::detail {

// Lanes must provide: reg; lanes; broadcast(u64); iota(u64 first) → first + 0, 1, …;
// low32/high32 (u64 → its 32-bit halves, in the low half of the lane); mul32 (low 32 bits of each
// lane, full 64-bit product); xor_; and to_unit(hi, lo) → double lanes hi·2⁻³² + (lo ≫ 11)·2⁻⁵³
// (the top 53 bits of the word hi:lo, exactly; random_stream::to_unit), stored with store_unit.
template <class Lanes, int groups>
inline void philox_uniform_tiles(const philox_counter_key& k, std::uint64_t first_block,
                                 std::size_t blocks, double* out) {
  using reg = typename Lanes::reg;
  constexpr std::size_t step = Lanes::lanes * groups;
  const reg m0 = Lanes::broadcast(philox_m0);
  const reg m1 = Lanes::broadcast(philox_m1);
  const reg stream_lo = Lanes::broadcast(k.stream_lo);
  const reg stream_hi = Lanes::broadcast(k.stream_hi);
  std::size_t b = 0;
  for (; b + step <= blocks; b += step) {
    reg c0[groups], c1[groups], c2[groups], c3[groups];
    // Unrolled so that the state stays in registers (GCC -O2 keeps loops over small arrays rolled
    // and spills them to memory).
#pragma GCC unroll 8
    for (int g = 0; g < groups; ++g) {
      const reg block = Lanes::iota(first_block + b + static_cast<std::size_t>(g) * Lanes::lanes);
      c0[g] = Lanes::low32(block);
      c1[g] = Lanes::high32(block);
      c2[g] = stream_lo;
      c3[g] = stream_hi;
    }
    std::uint32_t key0 = k.key0, key1 = k.key1;
#pragma GCC unroll 10
    for (int round = 0; round < philox_rounds; ++round) {
      const reg kk0 = Lanes::broadcast(key0), kk1 = Lanes::broadcast(key1);
#pragma GCC unroll 8
      for (int g = 0; g < groups; ++g) {
        // (c0, c1, c2, c3) ← (hi(M1·c2) ⊕ c1 ⊕ k0, lo(M1·c2), hi(M0·c0) ⊕ c3 ⊕ k1, lo(M0·c0))
        const reg p0 = Lanes::mul32(m0, c0[g]);
        const reg p1 = Lanes::mul32(m1, c2[g]);
        c0[g] = Lanes::xor_(Lanes::xor_(Lanes::high32(p1), c1[g]), kk0);
        c2[g] = Lanes::xor_(Lanes::xor_(Lanes::high32(p0), c3[g]), kk1);
        c1[g] = Lanes::low32(p1);
        c3[g] = Lanes::low32(p0);
      }
      key0 += philox_w0;  // the Weyl key schedule; the extra bump after round 10 is unused
      key1 += philox_w1;
    }
#pragma GCC unroll 8
    for (int g = 0; g < groups; ++g) {
      // Word 0 of a block is c1:c0, word 1 is c3:c2 (random_stream::bits).
      Lanes::store_unit(out + 2 * (b + static_cast<std::size_t>(g) * Lanes::lanes),
                        Lanes::to_unit(c1[g], c0[g]), Lanes::to_unit(c3[g], c2[g]));
    }
  }
  philox_uniform_blocks_scalar(k, first_block + b, blocks - b, out + 2 * b);
}

}  // namespace quadmc::detail
