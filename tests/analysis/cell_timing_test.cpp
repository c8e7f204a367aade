// Tests for cell_timing.hpp: the median and min–max spread of a cell's timing batches, "timed
// once", and the inputs it refuses.
#include "quadmc/analysis/cell_timing.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace quadmc {
namespace {

TEST(CellTiming, MedianAndMinMaxSpreadOfAnOddNumberOfBatches) {
  // Sorted 1, 2, 3, 4, 10: median 3, spread (10 − 1)/3 = 3 — the outlier widens the spread, it
  // does not move the median.
  const std::vector<double> samples{4.0, 1.0, 10.0, 3.0, 2.0};
  const cell_timing t = summarise_timing(samples, 50);
  EXPECT_EQ(t.seconds_per_estimate, 3.0);
  EXPECT_EQ(t.spread, 3.0);
  EXPECT_EQ(t.estimates, 50u);
  EXPECT_TRUE(t.timed());
  EXPECT_FALSE(t.timed_once());
}

TEST(CellTiming, MedianOfAnEvenNumberOfBatchesIsTheMeanOfTheMiddleTwo) {
  const std::vector<double> samples{0.5, 0.25, 1.0, 0.75};
  const cell_timing t = summarise_timing(samples, 4);
  EXPECT_EQ(t.seconds_per_estimate, 0.625);
  EXPECT_EQ(t.spread, 0.75 / 0.625);
}

TEST(CellTiming, OneCallIsTimedOnceWithoutSpread) {
  const std::vector<double> samples{0.2};
  const cell_timing t = summarise_timing(samples, 1);
  EXPECT_TRUE(t.timed_once());
  EXPECT_EQ(t.seconds_per_estimate, 0.2);
  EXPECT_TRUE(std::isnan(t.spread));
}

TEST(CellTiming, BatchesBelowTheClockHaveZeroSpread) {
  const std::vector<double> samples{0.0, 0.0};
  const cell_timing t = summarise_timing(samples, 2);
  EXPECT_EQ(t.seconds_per_estimate, 0.0);
  EXPECT_EQ(t.spread, 0.0);
}

TEST(CellTiming, AnUntimedCellSaysSo) {
  const cell_timing t;
  EXPECT_FALSE(t.timed());
  EXPECT_TRUE(std::isnan(t.seconds_per_estimate));
}

TEST(CellTiming, RefusesBadInput) {
  EXPECT_THROW(summarise_timing(std::vector<double>{}, 1), invalid_argument);
  EXPECT_THROW(summarise_timing(std::vector<double>{1.0, 2.0}, 1), invalid_argument);
  EXPECT_THROW(summarise_timing(std::vector<double>{-1.0}, 1), invalid_argument);
  EXPECT_THROW(summarise_timing(std::vector<double>{std::numeric_limits<double>::infinity()}, 1),
               invalid_argument);
}

}  // namespace
}  // namespace quadmc
