// Tests for core/ulp_distance.hpp: neighbours are 1 apart, signed zeros 0, the two smallest
// subnormals of opposite sign 2, and the count is symmetric and additive across zero.
#include "quadmc/core/ulp_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using quadmc::ulp_distance;

TEST(UlpDistance, CountsTheDoublesInBetween) {
  constexpr double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(ulp_distance(1.0, 1.0), 0u);
  EXPECT_EQ(ulp_distance(0.0, -0.0), 0u);
  EXPECT_EQ(ulp_distance(1.0, std::nextafter(1.0, 2.0)), 1u);
  EXPECT_EQ(ulp_distance(std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0)), 2u);
  EXPECT_EQ(ulp_distance(-tiny, tiny), 2u);
  EXPECT_EQ(ulp_distance(0.0, tiny), 1u);
  // Between 1 and 2 every double is a multiple of 2⁻⁵²: 2⁵² of them.
  EXPECT_EQ(ulp_distance(1.0, 2.0), std::uint64_t{1} << 52);
  EXPECT_EQ(ulp_distance(2.0, 1.0), ulp_distance(1.0, 2.0));
  EXPECT_EQ(ulp_distance(-1.0, 1.0), 2 * ulp_distance(0.0, 1.0));
}

}  // namespace
