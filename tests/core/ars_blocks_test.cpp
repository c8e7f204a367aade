// Tests for lib/src/core/ars_blocks*.cpp: ARS-4x32-7 behind random_stream computes Random123's own
// ARS (ars.h) bit for bit, in software and with AES-NI and VAES, at every instruction-set level
// this CPU has (core/simd_level.hpp), for any start and length.
//
// Known answers: Random123 1.14, tests/kat_vectors (Debian's librandom123-doc,
// /usr/share/doc/librandom123-dev/tests/kat_vectors.gz), the three lines "ars4x32 10 …" (counter
// words, then key words, then the output, low word first). They are for 10 rounds, the only ARS
// vectors Random123 publishes; the 7-round stream is checked against ars.h itself.
#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"
#include "support/simd_level_guard.hpp"

#if defined(QUADMC_ARS_REFERENCE)
#include "core/ars_reference.hpp"
#endif

#include <gtest/gtest.h>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace {

using ars_block = std::array<std::uint32_t, 4>;
using quadmc::test_support::simd_level_guard;

struct ars_known_answer {
  ars_block counter, key, output;
};

// Random123 tests/kat_vectors: ars4x32 10 (ctr, key → output).
const ars_known_answer ars4x32_10_kat[] = {
    {{0x00000000, 0x00000000, 0x00000000, 0x00000000},
     {0x00000000, 0x00000000, 0x00000000, 0x00000000},
     {0x8d73ee19, 0x506401ef, 0x13c2dbe4, 0x0cbe9c0d}},
    {{0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344},
     {0xa4093822, 0x299f31d0, 0x082efa98, 0xec4e6c89},
     {0xa516e7d6, 0x8357ad74, 0x5b59b3ec, 0x8763fff3}},
    {{0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff},
     {0xffffffff, 0xffffffff, 0x00000000, 0x00000000},
     {0xbb3743b1, 0x9f635551, 0xecbc87fc, 0xa19478a9}},
};

bool cpu_has_aes_ni() {
#if defined(__x86_64__)
  return __builtin_cpu_supports("aes") != 0;
#else
  return false;
#endif
}

// Counters and keys that cross every word boundary: zeros, ones, π's digits, a carry in each
// 64-bit half of the key schedule (which adds its Weyl constants per 64-bit lane, not per word).
std::vector<std::pair<ars_block, ars_block>> ars_varied_inputs() {
  std::vector<std::pair<ars_block, ars_block>> inputs;
  for (const ars_known_answer& kat : ars4x32_10_kat) inputs.emplace_back(kat.counter, kat.key);
  inputs.push_back({{1, 2, 3, 4}, {0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff}});
  inputs.push_back({{0xdeadbeef, 0, 0, 0x80000000}, {0x61c88646, 0xffffffff, 0x4a3a2a1a, 0}});
  for (std::uint32_t i = 0; i < 64; ++i) {
    const std::uint64_t a = quadmc::mix64(i), b = quadmc::mix64(a), c = quadmc::mix64(b);
    inputs.push_back({{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(a >> 32),
                       static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(b >> 32)},
                      {static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(c >> 32),
                       i % 2 == 0 ? 0u : static_cast<std::uint32_t>(i * 0x9e3779b9u), 0u}});
  }
  return inputs;
}

TEST(Ars4x32, SoftwareAesMatchesRandom123PublishedKnownAnswers) {
  for (const ars_known_answer& kat : ars4x32_10_kat) {
    EXPECT_EQ(quadmc::detail::ars4x32_software(kat.counter, kat.key, 10), kat.output)
        << std::hex << "counter word 0 " << kat.counter[0];
  }
}

#if defined(QUADMC_ARS_REFERENCE)
TEST(Ars4x32, Random123ItselfGivesItsPublishedKnownAnswers) {
  if (!cpu_has_aes_ni()) GTEST_SKIP() << "this CPU has no AES-NI, which Random123's ars.h needs";
  for (const ars_known_answer& kat : ars4x32_10_kat) {
    EXPECT_EQ(quadmc::test_support::random123_ars4x32(10, kat.counter, kat.key), kat.output);
  }
}

TEST(Ars4x32, SoftwareAndAesNiEqualRandom123AtSevenAndTenRounds) {
  if (!cpu_has_aes_ni()) GTEST_SKIP() << "this CPU has no AES-NI, which Random123's ars.h needs";
  const simd_level_guard guard;
  for (const auto& [counter, key] : ars_varied_inputs()) {
    for (const unsigned rounds : {7u, 10u}) {
      EXPECT_EQ(quadmc::detail::ars4x32_software(counter, key, rounds),
                quadmc::test_support::random123_ars4x32(rounds, counter, key))
          << rounds << " rounds, counter word 0 " << counter[0];
    }
    const ars_block reference = quadmc::test_support::random123_ars4x32(7, counter, key);
    for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
      quadmc::set_simd_level(level);
      EXPECT_EQ(quadmc::detail::ars4x32_7(counter, key), reference)
          << "level " << quadmc::to_string(level);
    }
  }
}

// Uniform number `index` of (seed, stream) straight from Random123's ars.h and rng.hpp's
// documented layout (key = (seed low, seed high, 0, 0), counter = (index/2 as two ars_block, stream
// as two ars_block), word index%2, top 53 bits): an independent reference, not random_stream
// itself.
double ars_reference_uniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
  const std::uint64_t block = index >> 1;
  const ars_block r = quadmc::test_support::random123_ars4x32(
      7,
      {static_cast<std::uint32_t>(block), static_cast<std::uint32_t>(block >> 32),
       static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(stream >> 32)},
      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32), 0, 0});
  const std::size_t w = 2 * static_cast<std::size_t>(index & 1);
  const std::uint64_t word = (static_cast<std::uint64_t>(r[w + 1]) << 32) | r[w];
  return static_cast<double>(word >> 11) * 0x1.0p-53;
}

TEST(ArsBlocks, EveryLevelEqualsRandom123ForAnyStartAndLength) {
  if (!cpu_has_aes_ni()) GTEST_SKIP() << "this CPU has no AES-NI, which Random123's ars.h needs";
  const simd_level_guard guard;
  // Starts crossing the tails of every kernel (8 and 32 blocks per step, 4 per VAES register),
  // odd indices, and the carry from the low to the high counter word at block 2³² (index 2³³).
  const std::uint64_t starts[] = {0,
                                  1,
                                  7,
                                  63,
                                  1000,
                                  (std::uint64_t{1} << 33) - 37,
                                  std::numeric_limits<std::uint64_t>::max() - 600};
  const std::size_t lengths[] = {0, 1, 2, 3, 5, 7, 8, 9, 16, 17, 63, 64, 65, 127, 255, 257, 513};
  const std::uint64_t seed = 0x0123456789abcdefULL;
  const std::uint64_t stream = quadmc::stream_id({7, 11});
  for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
    quadmc::set_simd_level(level);
    const quadmc::random_stream rng(seed, stream, quadmc::rng_kind::ars4x32_7);
    for (const std::uint64_t first : starts) {
      for (const std::size_t length : lengths) {
        std::vector<double> out(length, -1.0);
        rng.fill_uniform(first, out);
        for (std::size_t k = 0; k < length; ++k) {
          ASSERT_EQ(out[k], ars_reference_uniform(seed, stream, first + k))
              << "level " << quadmc::to_string(level) << " (" << quadmc::detail::ars_kernel()
              << "), first " << first << ", length " << length << ", k " << k;
        }
        if (length > 0) {
          ASSERT_EQ(rng.uniform(first), ars_reference_uniform(seed, stream, first));
        }
      }
    }
  }
}
#endif

TEST(ArsBlocks, EveryLevelGivesTheSameBitsOnALongRun) {
  // 2¹⁶ + 3 values from an odd start: the kernels' main loops, not only their tails; the
  // software kernel (the scalar level) is the reference, so this runs on any CPU.
  const simd_level_guard guard;
  const quadmc::random_stream rng(42, quadmc::stream_id({3}), quadmc::rng_kind::ars4x32_7);
  quadmc::set_simd_level(quadmc::simd_level::scalar);
  ASSERT_EQ(quadmc::detail::ars_kernel(), "software");
  std::vector<double> software((1u << 16) + 3);
  rng.fill_uniform(5, software);
  for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
    quadmc::set_simd_level(level);
    std::vector<double> vector(software.size());
    rng.fill_uniform(5, vector);
    EXPECT_EQ(vector, software) << "level " << quadmc::to_string(level) << " ("
                                << quadmc::detail::ars_kernel() << ")";
  }
}

TEST(ArsBlocks, TheWidestKernelThisCpuHasRunsAtTheTopLevel) {
  // So that the tests above exercise VAES and AES-NI where the CPU has them, not software twice.
  const simd_level_guard guard;
  quadmc::set_simd_level(quadmc::detected_simd_level());
#if defined(__x86_64__)
  // CPUID leaf 7, ECX bit 9: VAES (clang 14's __builtin_cpu_supports does not know it).
  unsigned a = 0, b = 0, c = 0, d = 0;
  const bool vaes = __get_cpuid_count(7, 0, &a, &b, &c, &d) != 0 && (c & (1u << 9)) != 0 &&
                    __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  const std::string_view expected =
      !cpu_has_aes_ni() || quadmc::detected_simd_level() == quadmc::simd_level::scalar ? "software"
      : vaes && quadmc::detected_simd_level() == quadmc::simd_level::avx512            ? "vaes"
                                                                                       : "aesni";
  EXPECT_EQ(quadmc::detail::ars_kernel(), expected);
#else
  EXPECT_EQ(quadmc::detail::ars_kernel(), "software");
#endif
}

TEST(RngKind, ParsesItsNamesAndRefusesOthersNamingTheParameter) {
  EXPECT_EQ(quadmc::parse_rng_kind("philox4x32_10"), quadmc::rng_kind::philox4x32_10);
  EXPECT_EQ(quadmc::parse_rng_kind("ars4x32_7"), quadmc::rng_kind::ars4x32_7);
  EXPECT_EQ(quadmc::to_string(quadmc::rng_kind::ars4x32_7), "ars4x32_7");
  try {
    quadmc::parse_rng_kind("ars", "rng");
    FAIL() << "no error";
  } catch (const quadmc::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("rng"), std::string::npos) << what;
    EXPECT_NE(what.find("\"ars\""), std::string::npos) << what;
    EXPECT_NE(what.find("philox4x32_10, ars4x32_7"), std::string::npos) << what;
  }
}

TEST(RandomStream, TheDefaultGeneratorIsPhiloxAndTheTwoDiffer) {
  const quadmc::random_stream philox(7, 9);
  EXPECT_EQ(philox.generator(), quadmc::rng_kind::philox4x32_10);
  const quadmc::random_stream ars(7, 9, quadmc::rng_kind::ars4x32_7);
  EXPECT_NE(philox.bits(0), ars.bits(0));
}

}  // namespace
