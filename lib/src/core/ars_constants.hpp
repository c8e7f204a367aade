// ARS-4x32-7's constants (Random123's ars.h: the Weyl increments of its key schedule) and the
// entry points of the batched kernels. Private to lib/src/core; the public face is
// random_stream::fill_uniform with rng_kind::ars4x32_7 (core/rng.hpp).
//
// ARS ([Salmon et al. 2011 (Random123)]): v = counter ⊕ k₀, then v = AESENC(v, k_r) for
// r = 1 … R − 1 and v = AESENCLAST(v, k_R), where k_r = key + r·(w₀, w₁) in two 64-bit lanes.
// AESENC is one AES round (ShiftRows, SubBytes, MixColumns, ⊕ round key), AESENCLAST the same
// without MixColumns ([FIPS-197] §5.1).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace quadmc::detail {

inline constexpr std::uint64_t ars_w0 = 0x9E3779B97F4A7C15ULL;  // low lane: golden ratio
inline constexpr std::uint64_t ars_w1 = 0xBB67AE8584CAA73BULL;  // high lane: √3 − 1
inline constexpr unsigned ars_rounds = 7;

// What every block of a stream shares: the seed as the key's low 64 bits (the high 64 are zero)
// and the stream id as the counter's high 64 bits; the low 64 are the block number.
struct ars_counter_key {
  std::uint64_t seed;
  std::uint64_t stream;
};

// The round keys k₀ … k_R as (low, high) 64-bit lanes.
inline std::array<std::array<std::uint64_t, 2>, ars_rounds + 1> ars_round_keys(
    std::uint64_t seed) noexcept {
  std::array<std::array<std::uint64_t, 2>, ars_rounds + 1> k{};
  k[0] = {seed, 0};
  for (unsigned r = 1; r <= ars_rounds; ++r) k[r] = {k[r - 1][0] + ars_w0, k[r - 1][1] + ars_w1};
  return k;
}

// One per instruction set; all compute the same bits. The AES ones exist only on x86-64 and run
// only where the CPU has AES-NI (and VAES, AVX512F, AVX512DQ for the AVX-512 one).
void ars_uniform_blocks_software(const ars_counter_key& k, std::uint64_t first_block,
                                 std::size_t blocks, double* out) noexcept;
void ars_uniform_blocks_aesni(const ars_counter_key& k, std::uint64_t first_block,
                              std::size_t blocks, double* out) noexcept;
void ars_uniform_blocks_avx512(const ars_counter_key& k, std::uint64_t first_block,
                               std::size_t blocks, double* out) noexcept;
std::array<std::uint32_t, 4> ars4x32_7_aesni(const std::array<std::uint32_t, 4>& counter,
                                             const std::array<std::uint32_t, 4>& key) noexcept;

}  // namespace quadmc::detail
