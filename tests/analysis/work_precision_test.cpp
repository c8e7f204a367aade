// Tests for work_precision.hpp: log-log interpolation between ladder points.
#include "quadmc/analysis/work_precision.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace quadmc {
namespace {

TEST(WorkPrecision, InterpolatesLogLogBetweenLadderPoints) {
  // t = 1, 10, 100 s at error 1e-1, 1e-3, 1e-5: a power law t ∝ e^(−1/2), so 1e-2 costs √10 s,
  // 1e-4 costs √1000 s, and 1e-3 is a ladder point.
  const std::vector<double> seconds = {1.0, 10.0, 100.0};
  const std::vector<double> error = {1e-1, 1e-3, 1e-5};
  const std::vector<double> targets = {1.0, 1e-2, 1e-3, 1e-4, 1e-8};
  const auto table = work_precision(seconds, error, targets);
  ASSERT_EQ(table.size(), 5u);
  EXPECT_EQ(table[0].status, target_status::reached_at_first_point);
  EXPECT_DOUBLE_EQ(*table[0].seconds, 1.0);
  EXPECT_EQ(table[1].status, target_status::reached);
  EXPECT_NEAR(*table[1].seconds, std::sqrt(10.0), 1e-13);
  EXPECT_NEAR(*table[2].seconds, 10.0, 1e-13);
  EXPECT_NEAR(*table[3].seconds, std::sqrt(1000.0), 1e-12);
  EXPECT_EQ(table[4].status, target_status::not_reached);
  EXPECT_FALSE(table[4].seconds.has_value());
}

TEST(WorkPrecision, FirstCrossingOfANonMonotoneLadder) {
  // A jump's error dips below 1e-2 at the second point, rises, and falls again: the first
  // crossing counts.
  const std::vector<double> seconds = {1.0, 2.0, 4.0, 8.0};
  const std::vector<double> error = {1e-1, 1e-3, 1e-1, 1e-4};
  const auto table = work_precision(seconds, error, std::vector<double>{1e-2});
  EXPECT_NEAR(*table[0].seconds, std::exp(0.5 * std::log(2.0)), 1e-14);
}

TEST(WorkPrecision, ZeroTimeAndZeroErrorAreHandled) {
  const std::vector<double> seconds = {0.0, 2.0};
  const std::vector<double> error = {1e-1, 1e-3};
  EXPECT_NEAR(*work_precision(seconds, error, std::vector<double>{1e-2})[0].seconds, 1.0, 1e-14)
      << "linear in t when a time is 0";
  const std::vector<double> exact = {1e-1, 0.0};
  EXPECT_DOUBLE_EQ(*work_precision(seconds, exact, std::vector<double>{1e-2})[0].seconds, 2.0);
}

TEST(WorkPrecision, DefaultTargetsAndBadInput) {
  EXPECT_EQ(work_precision(std::vector<double>{1.0}, std::vector<double>{1.0}).size(), 7u);
  EXPECT_THROW(work_precision(std::vector<double>{1.0}, std::vector<double>{-1.0}),
               invalid_argument);
  EXPECT_THROW(work_precision(std::vector<double>{1.0, 2.0}, std::vector<double>{1.0}),
               invalid_argument);
  EXPECT_THROW(
      work_precision(std::vector<double>{1.0}, std::vector<double>{1.0}, std::vector<double>{0.0}),
      invalid_argument);
}

}  // namespace
}  // namespace quadmc
