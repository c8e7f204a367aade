// Counter-based random streams: Philox4x32-10 ([Salmon et al. 2011 (Random123)]), from Debian's
// librandom123-dev.
//
// Why counter-based: value number i of a stream is a pure function of (seed, stream, i), so any
// sample can be regenerated alone, chunks can run on any thread in any order, and a parallel run
// is bitwise equal to a serial one (docs/design.md#hot-path-contract). There is no state to
// advance, share or lock.
//
// Layout of one Philox call: key = seed (2 × 32 bits), counter = (block index: 64 bits,
// stream id: 64 bits). One call yields 128 bits = two 64-bit words = two uniforms, so uniform
// number i comes from block i/2, word i%2. Streams with different ids never share a counter,
// hence never overlap (Philox is a bijection of the counter for a fixed key).
//
// Contract: uniform() lies in [0, 1), never 1; it takes the top 53 bits of a 64-bit word, so
// every value is a multiple of 2^-53 and 0.0 occurs with probability 2^-53.
#pragma once

#include <Random123/philox.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>

namespace quadmc {

namespace detail {
// out[2k], out[2k + 1] = the two uniforms of block first_block + k of the stream with this key and
// stream id, for k < blocks: Philox4x32-10 on several counters at once, on the instruction set
// simd_level.hpp chooses, bitwise equal to the scalar engine (lib/src/core/philox_blocks.cpp).
void philox_uniform_blocks(std::uint32_t key0, std::uint32_t key1, std::uint32_t stream_lo,
                           std::uint32_t stream_hi, std::uint64_t first_block, std::size_t blocks,
                           double* out);
}  // namespace detail

// SplitMix64's finaliser ([Steele, Lea & Flood 2014]): a bijective 64-bit mixer, used to
// turn structured ids (integrand, method, N, repetition, …) into well-spread stream ids.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Names a stream by the parts that identify a cell of an experiment, e.g.
// stream_id({integrand_index, method_index, N, repetition}). Order matters. Distinct tuples map
// to distinct ids except with probability ~k²/2^65 for k streams (a 64-bit hash).
constexpr std::uint64_t stream_id(std::initializer_list<std::uint64_t> parts) noexcept {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::uint64_t p : parts) h = mix64(h ^ mix64(p + 0x9e3779b97f4a7c15ULL));
  return h;
}

// A name as a stream part: 64-bit FNV-1a (offset basis 14695981039346656037, prime
// 1099511628211) over its bytes, fixed by its definition, so the same on every machine. The
// planner names an integrand's draws by its family and a cell's streams by the integrand's name
// and the method's label, not by their positions in the scene: one row re-run in a scene of its
// own draws the same numbers.
constexpr std::uint64_t name_id(std::string_view name) noexcept {
  std::uint64_t h = 14695981039346656037ULL;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h;
}

class philox_stream {
 public:
  using engine = r123::Philox4x32;  // Philox4x32_R<10>: 10 rounds, the Crush-resistant default

  constexpr philox_stream(std::uint64_t seed, std::uint64_t stream) noexcept
      : key_{{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}},
        stream_lo_(static_cast<std::uint32_t>(stream)),
        stream_hi_(static_cast<std::uint32_t>(stream >> 32)) {}

  // The raw 128-bit block number `block` as four 32-bit words (used by the known-answer tests).
  engine::ctr_type block(std::uint64_t block) const noexcept {
    const engine::ctr_type ctr = {{static_cast<std::uint32_t>(block),
                                   static_cast<std::uint32_t>(block >> 32), stream_lo_,
                                   stream_hi_}};
    return engine{}(ctr, key_);
  }

  // 64 random bits, word number `index` of the stream.
  std::uint64_t bits(std::uint64_t index) const noexcept {
    const auto r = block(index >> 1);
    const std::size_t w = 2 * static_cast<std::size_t>(index & 1);
    return (static_cast<std::uint64_t>(r.v[w + 1]) << 32) | r.v[w];
  }

  // Uniform number `index` of the stream, in [0, 1) with 53 random bits.
  double uniform(std::uint64_t index) const noexcept { return to_unit(bits(index)); }

  // out[k] = uniform(first + k): the batch form every point set uses. One Philox call serves
  // two outputs; the whole blocks in between run through the vector kernel (several counters per
  // instruction), whose bits equal the scalar engine's, so the result does not depend on how a
  // range is split into batches.
  void fill_uniform(std::uint64_t first, std::span<double> out) const {
    std::size_t k = 0;
    std::uint64_t index = first;
    if ((index & 1) != 0 && k < out.size()) out[k++] = uniform(index++);
    const std::size_t blocks = (out.size() - k) / 2;
    detail::philox_uniform_blocks(key_[0], key_[1], stream_lo_, stream_hi_, index >> 1, blocks,
                                  out.data() + k);
    k += 2 * blocks;
    index += 2 * blocks;
    if (k < out.size()) out[k] = uniform(index);
  }

  static constexpr double to_unit(std::uint64_t bits) noexcept {
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
  }

 private:
  engine::key_type key_;
  std::uint32_t stream_lo_;
  std::uint32_t stream_hi_;
};

}  // namespace quadmc
