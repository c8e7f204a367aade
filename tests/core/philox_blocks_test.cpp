// Tests for lib/src/core/philox_blocks*.cpp: the vector Philox kernels behind
// random_stream::fill_uniform compute Random123's Philox4x32-10, bit for bit, at every
// instruction-set level this CPU has (core/simd_level.hpp), for any start and length.
#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"
#include "support/simd_level_guard.hpp"

#include <gtest/gtest.h>

#include <Random123/philox.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace {

using engine = r123::Philox4x32;

// Uniform number `index` of (seed, stream), straight from Random123's engine and rng.hpp's
// documented layout (key = seed, counter = (index/2 as two words, stream as two words), word
// index%2, top 53 bits): an independent reference, not random_stream itself.
double reference_uniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
  const std::uint64_t block = index >> 1;
  const engine::ctr_type ctr = {
      {static_cast<std::uint32_t>(block), static_cast<std::uint32_t>(block >> 32),
       static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(stream >> 32)}};
  const engine::key_type key = {
      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}};
  const auto r = engine{}(ctr, key);
  const std::size_t w = 2 * static_cast<std::size_t>(index & 1);
  const std::uint64_t word = (static_cast<std::uint64_t>(r.v[w + 1]) << 32) | r.v[w];
  return static_cast<double>(word >> 11) * 0x1.0p-53;
}

// Restores the process-wide level when a test ends.
using quadmc::test_support::simd_level_guard;

TEST(PhiloxBlocks, EveryLevelEqualsRandom123ForAnyStartAndLength) {
  const simd_level_guard guard;
  // Starts chosen to cross the tails of every kernel (2, 8, 16 blocks per step), odd indices,
  // and the carry from the low to the high counter word at block 2³² (index 2³³).
  const std::uint64_t starts[] = {0,
                                  1,
                                  7,
                                  31,
                                  1000,
                                  (std::uint64_t{1} << 33) - 37,
                                  std::numeric_limits<std::uint64_t>::max() - 600};
  const std::size_t lengths[] = {0, 1, 2, 3, 5, 16, 17, 31, 32, 33, 255, 256, 257, 513};
  const std::uint64_t seed = 0x0123456789abcdefULL;
  const std::uint64_t stream = quadmc::stream_id({7, 11});
  for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
    quadmc::set_simd_level(level);
    const quadmc::random_stream rng(seed, stream);
    for (const std::uint64_t first : starts) {
      for (const std::size_t length : lengths) {
        std::vector<double> out(length, -1.0);
        rng.fill_uniform(first, out);
        for (std::size_t k = 0; k < length; ++k) {
          ASSERT_EQ(out[k], reference_uniform(seed, stream, first + k))
              << "level " << quadmc::to_string(level) << ", first " << first << ", length "
              << length << ", k " << k;
        }
      }
    }
  }
}

TEST(PhiloxBlocks, EveryLevelGivesTheSameBitsOnALongRun) {
  // 2¹⁶ + 3 values from an odd start: the kernels' main loops, not only their tails.
  const simd_level_guard guard;
  const quadmc::random_stream rng(42, quadmc::stream_id({3}));
  quadmc::set_simd_level(quadmc::simd_level::scalar);
  std::vector<double> scalar((1u << 16) + 3);
  rng.fill_uniform(5, scalar);
  for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
    quadmc::set_simd_level(level);
    std::vector<double> vector(scalar.size());
    rng.fill_uniform(5, vector);
    EXPECT_EQ(vector, scalar) << "level " << quadmc::to_string(level);
  }
}

}  // namespace
