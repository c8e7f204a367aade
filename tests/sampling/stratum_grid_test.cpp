#include "quadmc/sampling/stratum_grid.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/invalid_argument_message.hpp"

namespace {

using quadmc::stratum_grid;

using quadmc::test_support::message_of;

TEST(StratumGrid, ValidSizesArePerfectPowers) {
  EXPECT_TRUE(stratum_grid::is_valid_size(2, 16));
  EXPECT_TRUE(stratum_grid::is_valid_size(3, 27));
  EXPECT_TRUE(stratum_grid::is_valid_size(1, 7));
  EXPECT_FALSE(stratum_grid::is_valid_size(2, 15));
  EXPECT_FALSE(stratum_grid::is_valid_size(0, 1));
  EXPECT_FALSE(stratum_grid::is_valid_size(2, 0));
  // Large exact powers, where pow(n, 1/s) is inexact.
  EXPECT_TRUE(stratum_grid::is_valid_size(2, 94906265ULL * 94906265ULL));
  EXPECT_EQ(stratum_grid::root_floor(94906265ULL * 94906265ULL - 1, 2), 94906264ULL);
  EXPECT_EQ(stratum_grid::for_size(3, 1000).per_axis(), 10u);
}

TEST(StratumGrid, RejectsNThatIsNotAPowerNamingTheNearestValidSizes) {
  const std::string m = message_of([] { stratum_grid::for_size(2, 20); });
  EXPECT_NE(m.find("invalid number of points N = 20"), std::string::npos) << m;
  EXPECT_NE(m.find("16 = 4^2 or 25 = 5^2"), std::string::npos) << m;
  const std::string m3 = message_of([] { stratum_grid::for_size(3, 100); });
  EXPECT_NE(m3.find("64 = 4^3 or 125 = 5^3"), std::string::npos) << m3;
}

TEST(StratumGrid, RejectsOverflowingStrataCounts) {
  const std::string m = message_of([] { stratum_grid(64, 2); });  // 2^64 strata
  EXPECT_NE(m.find("invalid strata per axis k = 2"), std::string::npos) << m;
  EXPECT_NE(m.find("overflows"), std::string::npos) << m;
  EXPECT_THROW(stratum_grid(2, 1ULL << 32), quadmc::invalid_argument);  // 2^64
  EXPECT_NO_THROW(stratum_grid(53, 2));                                 // exactly 2^53
}

TEST(StratumGrid, RejectsZeroDimensionAndZeroPoints) {
  EXPECT_NE(message_of([] { stratum_grid::for_size(0, 4); }).find("dimension s = 0"),
            std::string::npos);
  EXPECT_NE(message_of([] { stratum_grid::for_size(2, 0); }).find("number of points N = 0"),
            std::string::npos);
  EXPECT_THROW(stratum_grid(2, 0), quadmc::invalid_argument);
}

TEST(StratumGrid, CellsAreRowMajorLastAxisFastest) {
  const stratum_grid g(3, 4);
  std::uint64_t cell[3];
  g.cell(1 * 16 + 2 * 4 + 3, cell);
  EXPECT_EQ(cell[0], 1u);
  EXPECT_EQ(cell[1], 2u);
  EXPECT_EQ(cell[2], 3u);
  EXPECT_EQ(g.strata(), 64u);
  EXPECT_EQ(g.stratum_volume(), 1.0 / 64.0);
}

}  // namespace
