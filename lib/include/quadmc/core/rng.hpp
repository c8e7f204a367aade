// Counter-based random streams: Philox4x32-10 (the default) or ARS-4x32-7, both from
// [Salmon et al. 2011 (Random123)], whose Debian package librandom123-dev provides the reference
// implementations the kernels are tested against bit for bit.
//
// Why counter-based: value number i of a stream is a pure function of (generator, seed, stream,
// i), so any sample can be regenerated alone, chunks can run on any thread in any order, and a
// parallel run is bitwise equal to a serial one (docs/design.md#hot-path-contract). There is no
// state to advance, share or lock.
//
// Layout of one call, the same for both generators: key = seed (2 × 32 bits; ARS's 128-bit key
// has zeros above them), counter = (block index: 64 bits, stream id: 64 bits). One call yields
// 128 bits = two 64-bit words = two uniforms, so uniform number i comes from block i/2, word i%2.
// Streams with different ids never share a counter, hence never overlap (each generator is a
// bijection of the counter for a fixed key).
//
// The two generators (docs/theory.md#counter-based-generators): Philox's ten rounds are 32×32-bit
// multiplies; ARS's seven are AES rounds with a Weyl key schedule, which AES-NI computes one block
// per instruction and VAES four (run-time dispatch, core/simd_level.hpp). Both pass BigCrush with
// margin. They give different numbers for the same seed: a scene's `rng` names the one it used.
//
// Contract: uniform() lies in [0, 1), never 1; it takes the top 53 bits of a 64-bit word, so
// every value is a multiple of 2^-53 and 0.0 occurs with probability 2^-53.
#pragma once

#include <Random123/philox.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>

namespace quadmc {

// The counter-based generators a random_stream can run (a scene's `rng`).
enum class rng_kind : std::uint8_t {
  philox4x32_10,  // Philox4x32-10: the default, so a scene without `rng` draws what it always drew
  ars4x32_7,      // ARS-4x32-7: AES rounds, far cheaper where the CPU has AES-NI or VAES
};
std::string_view to_string(rng_kind generator) noexcept;
// Parses "philox4x32_10" or "ars4x32_7"; throws invalid_argument naming `parameter` otherwise.
rng_kind parse_rng_kind(std::string_view text, std::string_view parameter = "rng");
// "philox4x32_10, ars4x32_7": the names, default first, for help texts and messages.
std::string_view rng_kind_names() noexcept;

namespace detail {
// out[2k], out[2k + 1] = the two uniforms of block first_block + k of the stream with this key and
// stream id, for k < blocks: the generator on several counters at once, on the instruction set
// simd_level.hpp chooses, bitwise equal to the scalar engine (lib/src/core/philox_blocks.cpp,
// ars_blocks.cpp).
void philox_uniform_blocks(std::uint32_t key0, std::uint32_t key1, std::uint32_t stream_lo,
                           std::uint32_t stream_hi, std::uint64_t first_block, std::size_t blocks,
                           double* out);
void ars_uniform_blocks(std::uint32_t key0, std::uint32_t key1, std::uint32_t stream_lo,
                        std::uint32_t stream_hi, std::uint64_t first_block, std::size_t blocks,
                        double* out);

// One ARS-4x32 block: counter and key as Random123's ars4x32_ctr_t/ars4x32_key_t words (word 0
// the low 32 bits of the 128-bit AES state).
using ars_words = std::array<std::uint32_t, 4>;
// ARS-4x32-7 with AES-NI where the active level is not scalar and the CPU has it, else in
// software: the same bits either way.
ars_words ars4x32_7(const ars_words& counter, const ars_words& key) noexcept;
// ARS-4x32 with `rounds` (1 … 10) rounds, AES in software only ([FIPS-197] §5.1: SubBytes,
// ShiftRows, MixColumns, AddRoundKey): the portable form, which also runs Random123's published
// 10-round known answers.
ars_words ars4x32_software(const ars_words& counter, const ars_words& key,
                           unsigned rounds) noexcept;
// Which ARS kernel fill_uniform runs at the active level: "vaes" (4 blocks per AVX-512
// instruction), "aesni" (1 per instruction) or "software".
std::string_view ars_kernel() noexcept;
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

// A stream of uniforms named by (seed, stream id) for one generator. Small and immutable: copy it
// freely; every call is a pure function of its arguments.
class random_stream {
 public:
  using block_type = std::array<std::uint32_t, 4>;

  constexpr random_stream(std::uint64_t seed, std::uint64_t stream,
                          rng_kind generator = rng_kind::philox4x32_10) noexcept
      : key0_(static_cast<std::uint32_t>(seed)),
        key1_(static_cast<std::uint32_t>(seed >> 32)),
        stream_lo_(static_cast<std::uint32_t>(stream)),
        stream_hi_(static_cast<std::uint32_t>(stream >> 32)),
        generator_(generator) {}

  constexpr rng_kind generator() const noexcept { return generator_; }

  // The raw 128-bit block number `block` as four 32-bit words, word 0 the lowest (used by the
  // known-answer tests).
  block_type block(std::uint64_t block) const noexcept {
    const block_type ctr = {static_cast<std::uint32_t>(block),
                            static_cast<std::uint32_t>(block >> 32), stream_lo_, stream_hi_};
    if (generator_ == rng_kind::ars4x32_7) return detail::ars4x32_7(ctr, {key0_, key1_, 0, 0});
    const auto r = r123::Philox4x32{}({{ctr[0], ctr[1], ctr[2], ctr[3]}}, {{key0_, key1_}});
    return {r.v[0], r.v[1], r.v[2], r.v[3]};
  }

  // 64 random bits, word number `index` of the stream.
  std::uint64_t bits(std::uint64_t index) const noexcept {
    const block_type r = block(index >> 1);
    const std::size_t w = 2 * static_cast<std::size_t>(index & 1);
    return (static_cast<std::uint64_t>(r[w + 1]) << 32) | r[w];
  }

  // Uniform number `index` of the stream, in [0, 1) with 53 random bits.
  double uniform(std::uint64_t index) const noexcept { return to_unit(bits(index)); }

  // out[k] = uniform(first + k): the batch form every point set uses. One call of the generator
  // serves two outputs; the whole blocks in between run through the vector kernel (several
  // counters per instruction), whose bits equal the scalar engine's, so the result does not
  // depend on how a range is split into batches.
  void fill_uniform(std::uint64_t first, std::span<double> out) const {
    std::size_t k = 0;
    std::uint64_t index = first;
    if ((index & 1) != 0 && k < out.size()) out[k++] = uniform(index++);
    const std::size_t blocks = (out.size() - k) / 2;
    if (generator_ == rng_kind::ars4x32_7) {
      detail::ars_uniform_blocks(key0_, key1_, stream_lo_, stream_hi_, index >> 1, blocks,
                                 out.data() + k);
    } else {
      detail::philox_uniform_blocks(key0_, key1_, stream_lo_, stream_hi_, index >> 1, blocks,
                                    out.data() + k);
    }
    k += 2 * blocks;
    index += 2 * blocks;
    if (k < out.size()) out[k] = uniform(index);
  }

  static constexpr double to_unit(std::uint64_t bits) noexcept {
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
  }

 private:
  std::uint32_t key0_, key1_;
  std::uint32_t stream_lo_, stream_hi_;
  rng_kind generator_;
};

}  // namespace quadmc
