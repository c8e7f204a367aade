// The Philox4x32-10 constants (Random123's philox.h: PHILOX_M4x32_0/1, PHILOX_W32_0/1) and the
// entry points of the batched kernels. Private to lib/src/core; the public face is
// random_stream::fill_uniform (core/rng.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace quadmc::detail {

inline constexpr std::uint32_t philox_m0 = 0xD2511F53u;  // multiplier of word 0
inline constexpr std::uint32_t philox_m1 = 0xCD9E8D57u;  // multiplier of word 2
inline constexpr std::uint32_t philox_w0 = 0x9E3779B9u;  // key bump: golden ratio
inline constexpr std::uint32_t philox_w1 = 0xBB67AE85u;  // key bump: √3 − 1
inline constexpr int philox_rounds = 10;

// The parts of a Philox call that are the same for every block of a stream: the key (the seed)
// and the high half of the counter (the stream id); the low half is the block number.
struct philox_counter_key {
  std::uint32_t key0, key1, stream_lo, stream_hi;
};

// One per instruction set; all compute the same bits. The vector ones exist only on x86-64.
void philox_uniform_blocks_scalar(const philox_counter_key& k, std::uint64_t first_block,
                                  std::size_t blocks, double* out) noexcept;
void philox_uniform_blocks_sse2(const philox_counter_key& k, std::uint64_t first_block,
                                std::size_t blocks, double* out) noexcept;
void philox_uniform_blocks_avx2(const philox_counter_key& k, std::uint64_t first_block,
                                std::size_t blocks, double* out) noexcept;
void philox_uniform_blocks_avx512(const philox_counter_key& k, std::uint64_t first_block,
                                  std::size_t blocks, double* out) noexcept;

}  // namespace quadmc::detail
