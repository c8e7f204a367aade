// Tests of cmj_points.hpp: one point per cell of the m × n grid and per row and column of the
// N × N fine grid, in every pair of dimensions, and the sizes it holds.
#include "quadmc/sampling/cmj_points.hpp"

#include "sampling/uniform_bins.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

static_assert(point_set<cmj_points>);

// Every pair (2g, 2g + 1): one point per cell of the m × n grid, one per fine column of x and per
// fine row of y (N of each); a trailing coordinate: one point per interval of 1/N.
void expect_pairs_stratified(std::size_t s, std::uint64_t n) {
  const cmj_points p(s, n, 3, 3);
  const std::uint64_t m = p.grid_columns(), rows = p.grid_rows();
  ASSERT_EQ(m * rows, n);
  std::vector<double> x(n * s);
  p.generate(0, x);
  for (std::size_t j = 0; j < s; j += 2) {
    std::vector<int> cells(n, 0), fine_x(n, 0), fine_y(n, 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      const double* xi = &x[i * s];
      ++fine_x[static_cast<std::uint64_t>(xi[j] * double(n))];
      if (j + 1 == s) continue;
      ++fine_y[static_cast<std::uint64_t>(xi[j + 1] * double(n))];
      ++cells[static_cast<std::uint64_t>(xi[j] * double(m)) * rows +
              static_cast<std::uint64_t>(xi[j + 1] * double(rows))];
    }
    for (std::uint64_t c = 0; c < n; ++c) {
      ASSERT_EQ(fine_x[c], 1) << "s = " << s << ", N = " << n << ", axis " << j << ", row " << c;
      if (j + 1 == s) continue;
      ASSERT_EQ(fine_y[c], 1) << "s = " << s << ", N = " << n << ", axis " << j + 1 << ", row "
                              << c;
      ASSERT_EQ(cells[c], 1) << "s = " << s << ", N = " << n << ", pair " << j / 2 << ", cell "
                             << c;
    }
  }
}

TEST(CmjPoints, EveryPairIsJitteredAndLatin) {
  expect_pairs_stratified(2, 64);
  expect_pairs_stratified(2, 72);  // 8 × 9
  expect_pairs_stratified(5, 240);
  expect_pairs_stratified(4, 1);
  expect_pairs_stratified(1, 37);
}

// Cells of aspect ratio at most (k + 1)/k: N = k² or k(k + 1) in s ≥ 2; the message names the
// nearest valid sizes.
TEST(CmjPoints, HoldsNearSquaresAndNamesTheNearestOtherwise) {
  try {
    cmj_points(2, 100 + 5, 1, 1);
    ADD_FAILURE() << "N = 105 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nearest valid: 100 and 110"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(cmj_points(2, 110, 1, 1).grid_columns(), 10u);
  EXPECT_EQ(cmj_points(2, 110, 1, 1).grid_rows(), 11u);
  EXPECT_TRUE(cmj_points::is_valid_size(3, 12));
  EXPECT_FALSE(cmj_points::is_valid_size(3, 13));
  EXPECT_TRUE(cmj_points::is_valid_size(1, 13));
}

// Each coordinate is uniform: point 17's x of pair 1 (s = 4, N = 30) over 4096 streams
// (test_support::expect_uniform_over_streams states the bound).
TEST(CmjPoints, EachCoordinateIsUniform) {
  std::vector<double> x(4);
  test_support::expect_uniform_over_streams([&](std::uint64_t r) {
    cmj_points(4, 30, 5, r).generate(17, x);
    return x[2];
  });
}

}  // namespace
