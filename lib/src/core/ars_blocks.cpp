// ARS-4x32-7 behind random_stream (core/rng.hpp): AES in software, the portable reference, and the
// run-time choice among the kernels (ars_blocks_aesni.cpp, ars_blocks_avx512.cpp). Every kernel is
// tested bit for bit against Random123's own ars.h (tests/core/ars_blocks_test.cpp).
#include "ars_constants.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"

#include <bit>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace quadmc::detail {
namespace {

// Multiplication in GF(2⁸) modulo AES's polynomial x⁸ + x⁴ + x³ + x + 1 ([FIPS-197] §4.2).
constexpr std::uint8_t gf_mul(std::uint8_t a, std::uint8_t b) noexcept {
  std::uint8_t p = 0;
  for (int i = 0; i < 8; ++i) {
    if ((b & 1) != 0) p ^= a;
    const bool carry = (a & 0x80) != 0;
    a = static_cast<std::uint8_t>(a << 1);
    if (carry) a ^= 0x1b;
    b >>= 1;
  }
  return p;
}

// The S-box ([FIPS-197] §5.1.1): the multiplicative inverse (0 ↦ 0), then the affine map
// b ⊕ rotl(b,1) ⊕ rotl(b,2) ⊕ rotl(b,3) ⊕ rotl(b,4) ⊕ 0x63. Derived here rather than typed in, so
// no table can hold a typo; the known answers check the result. The inverse comes from the powers
// of the generator 3 (x = 3^k, x⁻¹ = 3^(255−k)): 255 products, where a search for each inverse
// would exceed clang's constexpr step limit.
constexpr std::array<std::uint8_t, 256> make_sbox() noexcept {
  std::array<std::uint8_t, 255> power{};  // power[k] = 3^k
  std::array<std::uint8_t, 256> log{};    // log[3^k] = k
  std::uint8_t p = 1;
  for (unsigned k = 0; k < 255; ++k) {
    power[k] = p;
    log[p] = static_cast<std::uint8_t>(k);
    p = gf_mul(p, 3);
  }
  std::array<std::uint8_t, 256> sbox{};
  for (unsigned x = 0; x < 256; ++x) {
    const std::uint8_t inverse = x == 0 ? 0 : power[(255 - log[x]) % 255];
    sbox[x] = static_cast<std::uint8_t>(inverse ^ std::rotl(inverse, 1) ^ std::rotl(inverse, 2) ^
                                        std::rotl(inverse, 3) ^ std::rotl(inverse, 4) ^ 0x63);
  }
  return sbox;
}
constexpr std::array<std::uint8_t, 256> sbox = make_sbox();

// SubBytes and MixColumns of one byte in one table ([FIPS-197] §5.1.3): a byte S at row 0 of a
// column contributes (2S, S, S, 3S) to the column's rows 0 … 3, a byte at row r the same rotated
// by r rows, i.e. the word rotated left by 8r bits.
constexpr std::array<std::uint32_t, 256> make_t0() noexcept {
  std::array<std::uint32_t, 256> t{};
  for (unsigned x = 0; x < 256; ++x) {
    const std::uint8_t s = sbox[x];
    t[x] = std::uint32_t{gf_mul(s, 2)} | (std::uint32_t{s} << 8) | (std::uint32_t{s} << 16) |
           (std::uint32_t{gf_mul(s, 3)} << 24);
  }
  return t;
}
constexpr std::array<std::uint32_t, 256> t0 = make_t0();

constexpr std::uint32_t byte_of(std::uint32_t word, int row) noexcept {
  return (word >> (8 * row)) & 0xff;
}

// The state as x86 holds it in an XMM register: word c is column c, byte r of it row r. ShiftRows
// moves row r left by r columns, so column c of the result takes row r from column c + r.
using state = std::array<std::uint32_t, 4>;

// AESENC: ShiftRows, SubBytes, MixColumns, then ⊕ key.
state aes_round(const state& v, const state& key) noexcept {
  state out;
  for (int c = 0; c < 4; ++c) {
    out[c] = t0[byte_of(v[c], 0)] ^ std::rotl(t0[byte_of(v[(c + 1) % 4], 1)], 8) ^
             std::rotl(t0[byte_of(v[(c + 2) % 4], 2)], 16) ^
             std::rotl(t0[byte_of(v[(c + 3) % 4], 3)], 24) ^ key[c];
  }
  return out;
}

// AESENCLAST: ShiftRows, SubBytes, then ⊕ key (no MixColumns).
state aes_last_round(const state& v, const state& key) noexcept {
  state out;
  for (int c = 0; c < 4; ++c) {
    out[c] = (std::uint32_t{sbox[byte_of(v[c], 0)]} |
              (std::uint32_t{sbox[byte_of(v[(c + 1) % 4], 1)]} << 8) |
              (std::uint32_t{sbox[byte_of(v[(c + 2) % 4], 2)]} << 16) |
              (std::uint32_t{sbox[byte_of(v[(c + 3) % 4], 3)]} << 24)) ^
             key[c];
  }
  return out;
}

state words_of(std::uint64_t low, std::uint64_t high) noexcept {
  return {static_cast<std::uint32_t>(low), static_cast<std::uint32_t>(low >> 32),
          static_cast<std::uint32_t>(high), static_cast<std::uint32_t>(high >> 32)};
}

std::uint64_t low_word(const state& v) noexcept {
  return (static_cast<std::uint64_t>(v[1]) << 32) | v[0];
}
std::uint64_t high_word(const state& v) noexcept {
  return (static_cast<std::uint64_t>(v[3]) << 32) | v[2];
}

bool cpu_has_aes() noexcept {
#if defined(__x86_64__)
  static const bool has = __builtin_cpu_supports("aes") != 0;
  return has;
#else
  return false;
#endif
}

// VAES with the AVX-512 state the OS saves: CPUID leaf 7 reports VAES in ECX bit 9 (clang 14's
// __builtin_cpu_supports has no "vaes"); AVX512F's check includes the OS's (XGETBV), and the
// kernel's conversion needs AVX512DQ.
bool cpu_has_vaes_avx512() noexcept {
#if defined(__x86_64__)
  static const bool has = [] {
    unsigned a = 0, b = 0, c = 0, d = 0;
    const bool vaes = __get_cpuid_count(7, 0, &a, &b, &c, &d) != 0 && (c & (1u << 9)) != 0;
    return vaes && __builtin_cpu_supports("avx512f") != 0 &&
           __builtin_cpu_supports("avx512dq") != 0;
  }();
  return has;
#else
  return false;
#endif
}

enum class ars_path { software, aesni, vaes };

// The kernel for the active level: the scalar level means portable code, so software there;
// otherwise the widest AES the CPU has.
ars_path active_path() {
  const simd_level level = active_simd_level();
  if (level == simd_level::scalar || !cpu_has_aes()) return ars_path::software;
  if (level == simd_level::avx512 && cpu_has_vaes_avx512()) return ars_path::vaes;
  return ars_path::aesni;
}

// active_path() where nothing may throw: an invalid QUADMC_SIMD gives software, the same bits;
// the batched kernels, which may throw, report it.
ars_path path_or_software() noexcept {
  try {
    return active_path();
  } catch (...) {
    return ars_path::software;
  }
}

}  // namespace

ars_words ars4x32_software(const ars_words& counter, const ars_words& key,
                           unsigned rounds) noexcept {
  // k_r in two 64-bit lanes, each bumped by its Weyl constant per round (ars.h's _mm_add_epi64).
  std::uint64_t k_low = (static_cast<std::uint64_t>(key[1]) << 32) | key[0];
  std::uint64_t k_high = (static_cast<std::uint64_t>(key[3]) << 32) | key[2];
  state v = {counter[0] ^ key[0], counter[1] ^ key[1], counter[2] ^ key[2], counter[3] ^ key[3]};
  for (unsigned r = 1; r < rounds; ++r) {
    k_low += ars_w0;
    k_high += ars_w1;
    v = aes_round(v, words_of(k_low, k_high));
  }
  k_low += ars_w0;
  k_high += ars_w1;
  return aes_last_round(v, words_of(k_low, k_high));
}

void ars_uniform_blocks_software(const ars_counter_key& k, std::uint64_t first_block,
                                 std::size_t blocks, double* out) noexcept {
  const state key = words_of(k.seed, 0);
  for (std::size_t b = 0; b < blocks; ++b) {
    const state r = ars4x32_software(words_of(first_block + b, k.stream), key, ars_rounds);
    out[2 * b] = random_stream::to_unit(low_word(r));
    out[2 * b + 1] = random_stream::to_unit(high_word(r));
  }
}

ars_words ars4x32_7(const ars_words& counter, const ars_words& key) noexcept {
#if defined(__x86_64__)
  if (path_or_software() != ars_path::software) return ars4x32_7_aesni(counter, key);
#endif
  return ars4x32_software(counter, key, ars_rounds);
}

void ars_uniform_blocks(std::uint32_t key0, std::uint32_t key1, std::uint32_t stream_lo,
                        std::uint32_t stream_hi, std::uint64_t first_block, std::size_t blocks,
                        double* out) {
  const ars_counter_key k{(static_cast<std::uint64_t>(key1) << 32) | key0,
                          (static_cast<std::uint64_t>(stream_hi) << 32) | stream_lo};
  switch (active_path()) {
#if defined(__x86_64__)
    case ars_path::vaes:
      return ars_uniform_blocks_avx512(k, first_block, blocks, out);
    case ars_path::aesni:
      return ars_uniform_blocks_aesni(k, first_block, blocks, out);
#endif
    default:
      return ars_uniform_blocks_software(k, first_block, blocks, out);
  }
}

std::string_view ars_kernel() noexcept {
  switch (path_or_software()) {
    case ars_path::vaes:
      return "vaes";
    case ars_path::aesni:
      return "aesni";
    default:
      return "software";
  }
}

}  // namespace quadmc::detail
