#include "quadmc/sampling/padded_jittered_points.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

// Every 2D group (axes 2g, 2g+1) is stratified on the k × k grid and a trailing 1D group on N
// rows, for any s.
void expect_groups_stratified(std::size_t s, std::uint64_t n) {
  const padded_jittered_points p(s, n, 3, 3);
  const std::uint64_t kx = p.grid_columns(), ky = p.grid_rows();
  ASSERT_EQ(kx * ky, n);
  std::vector<double> x(n * s);
  p.generate(0, x);
  for (std::size_t j = 0; j < s; j += 2) {
    std::vector<int> hits(n, 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      const double* xi = &x[i * s];
      const std::uint64_t cell =
          j + 1 < s ? std::uint64_t(xi[j] * double(kx)) * ky + std::uint64_t(xi[j + 1] * double(ky))
                    : std::uint64_t(xi[j] * double(n));
      ++hits[cell];
    }
    for (std::uint64_t c = 0; c < n; ++c) {
      ASSERT_EQ(hits[c], 1) << "s = " << s << ", N = " << n << ", group " << j / 2 << ", cell "
                            << c;
    }
  }
}

TEST(PaddedJitteredPoints, EveryGroupIsStratified) {
  expect_groups_stratified(2, 64);
  expect_groups_stratified(5, 256);
  expect_groups_stratified(6, 100);
  expect_groups_stratified(3, 81);
}

// N = k² in s ≥ 2, as the planner maps N (point_count::perfect_square): a non-square N would
// need a kx × ky grid, 1 × N for prime N, which is not the stratification the rate assumes. The
// message names the nearest squares.
TEST(PaddedJitteredPoints, RejectsNonSquareNInTwoOrMoreDimensions) {
  for (const std::size_t s : {2u, 3u, 4u}) {
    try {
      padded_jittered_points(s, 96, 1, 1);
      ADD_FAILURE() << "N = 96 accepted in s = " << s;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("81 = 9² or 100 = 10²"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(padded_jittered_points(2, 13, 1, 1), std::invalid_argument);
  EXPECT_EQ(padded_jittered_points(2, 100, 1, 1).grid_columns(), 10u);
  EXPECT_EQ(padded_jittered_points(2, 100, 1, 1).grid_rows(), 10u);
  EXPECT_TRUE(padded_jittered_points::is_valid_size(2, 1));
  EXPECT_FALSE(padded_jittered_points::is_valid_size(5, 2));
}

// In 1D the one group is N strata of width 1/N: any N.
TEST(PaddedJitteredPoints, AcceptsAnyNInOneDimension) {
  EXPECT_TRUE(padded_jittered_points::is_valid_size(1, 13));
  expect_groups_stratified(1, 13);
  expect_groups_stratified(1, 96);
}

// Groups are associated at random: the strata of group 0 and group 1 of the same point do not
// follow each other (for the identity they would agree for all N points).
TEST(PaddedJitteredPoints, GroupsAreShuffledAgainstEachOther) {
  const std::uint64_t n = 1024;
  const padded_jittered_points p(4, n, 1, 1);
  std::vector<double> x(4 * n);
  p.generate(0, x);
  int same = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    same += std::uint64_t(x[4 * i] * 32) == std::uint64_t(x[4 * i + 2] * 32) &&
            std::uint64_t(x[4 * i + 1] * 32) == std::uint64_t(x[4 * i + 3] * 32);
  }
  // A random permutation has Poisson(1) fixed points; P(≥ 10) < 1.2e-7.
  EXPECT_LT(same, 10);
}

}  // namespace
