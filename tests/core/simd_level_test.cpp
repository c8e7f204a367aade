// Tests for core/simd_level.hpp: names round-trip, bad names and unsupported levels are refused
// with the parameter named, and the level set is the level used.
#include "quadmc/core/simd_level.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

TEST(SimdLevel, NamesRoundTrip) {
  for (auto level : {quadmc::simd_level::scalar, quadmc::simd_level::sse2, quadmc::simd_level::avx2,
                     quadmc::simd_level::avx512}) {
    EXPECT_EQ(quadmc::parse_simd_level(quadmc::to_string(level)), level);
  }
}

TEST(SimdLevel, RejectsAnUnknownNameNamingTheParameter) {
  try {
    quadmc::parse_simd_level("avx3", "--simd");
    FAIL() << "avx3 accepted";
  } catch (const quadmc::invalid_argument& e) {
    EXPECT_EQ(e.parameter(), "--simd");
    EXPECT_NE(std::string(e.what()).find("avx3"), std::string::npos) << e.what();
  }
}

TEST(SimdLevel, SetLevelIsTheActiveLevelAndScalarIsAlwaysSupported) {
  const quadmc::simd_level saved = quadmc::active_simd_level();
  EXPECT_LE(saved, quadmc::detected_simd_level());
  quadmc::set_simd_level(quadmc::simd_level::scalar);
  EXPECT_EQ(quadmc::active_simd_level(), quadmc::simd_level::scalar);
  quadmc::set_simd_level(saved);
  EXPECT_EQ(quadmc::active_simd_level(), saved);
}

TEST(SimdLevel, AvailableLevelsRunFromScalarToTheDetectedOneAndAreAccepted) {
  const std::vector<quadmc::simd_level> levels = quadmc::available_simd_levels();
  ASSERT_FALSE(levels.empty());
  EXPECT_EQ(levels.front(), quadmc::simd_level::scalar);
  EXPECT_EQ(levels.back(), quadmc::detected_simd_level());
  EXPECT_EQ(levels.size(), static_cast<std::size_t>(quadmc::detected_simd_level()) + 1);
  const quadmc::simd_level saved = quadmc::active_simd_level();
  for (const quadmc::simd_level level : levels) EXPECT_NO_THROW(quadmc::set_simd_level(level));
  quadmc::set_simd_level(saved);
}

TEST(SimdLevel, RefusesALevelAboveWhatTheCpuHas) {
  if (quadmc::detected_simd_level() == quadmc::simd_level::avx512) {
    GTEST_SKIP() << "this CPU has every level";
  }
  const auto above =
      static_cast<quadmc::simd_level>(static_cast<int>(quadmc::detected_simd_level()) + 1);
  EXPECT_THROW(quadmc::set_simd_level(above), quadmc::invalid_argument);
}

}  // namespace
