// Tests of net_quality.hpp: t-values against sets whose t is known by construction (a scrambled
// Sobol' pair, pmj02 and padded Sobol' pairs: 0; a grid of 2^h × 2^h centres: h; N equal points:
// m), invariance under scrambling, and the minimum distance of grids against the packings'.
#include "quadmc/sampling/net_quality.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/sampling/padded_sobol_points.hpp"
#include "quadmc/sampling/pmj02_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using namespace quadmc;

template <point_set P>
std::vector<double> points_of(const P& p) {
  std::vector<double> x(p.size() * p.dimension());
  p.generate(0, x);
  return x;
}

// A k × k grid of cell centres, k = 2^h: a box of shape 2^−d1 × 2^−d2 holds 2^(m − d1 − d2)
// points when d1, d2 ≤ h and none may when one is above, so the t-value is exactly h = m/2.
std::vector<double> centre_grid(std::size_t k) {
  std::vector<double> x;
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      x.push_back((static_cast<double>(i) + 0.5) / static_cast<double>(k));
      x.push_back((static_cast<double>(j) + 0.5) / static_cast<double>(k));
    }
  }
  return x;
}

TEST(NetQuality, TValuesOfSetsWithAKnownT) {
  for (const unsigned h : {1u, 2u, 4u, 5u}) {
    EXPECT_EQ(net_t_value(centre_grid(std::size_t{1} << h), 2), h) << "h = " << h;
  }
  const std::vector<double> same(2 * 64, 0.25);
  EXPECT_EQ(net_t_value(same, 2), 6u) << "64 equal points: only the whole cube is exact";
  for (const unsigned m : {4u, 8u, 12u}) {
    const std::uint64_t n = std::uint64_t{1} << m;
    EXPECT_EQ(net_t_value(points_of(sobol_points<unrandomized_digits>(2, n, 1, 1)), 2), 0u);
    EXPECT_EQ(net_t_value(points_of(sobol_points<owen_scramble>(2, n, 1, 1)), 2), 0u);
    EXPECT_EQ(net_t_value(points_of(pmj02_points(2, n, 3, 1)), 2), 0u);
  }
}

// Scrambling maps elementary intervals onto elementary intervals of the same shape, so the whole
// Sobol' set's t in s = 3 and 4 is the same under every randomization; it is above 0 (the first
// three Sobol' dimensions are no (0, m, 3)-net) and at most m.
TEST(NetQuality, ScramblingKeepsTheWholeSetsT) {
  for (const std::size_t s : {3u, 4u}) {
    const std::uint64_t n = 1024;
    const auto t = net_t_value(points_of(sobol_points<unrandomized_digits>(s, n, 1, 1)), s);
    ASSERT_TRUE(t.has_value());
    EXPECT_GT(*t, 0u);
    EXPECT_LE(*t, 10u);
    EXPECT_EQ(net_t_value(points_of(sobol_points<owen_scramble>(s, n, 5, 2)), s), t);
    EXPECT_EQ(net_t_value(points_of(sobol_points<linear_matrix_scramble>(s, n, 5, 2)), s), t);
  }
}

// Padded sets: every pair of a pair group is a net (best 0), the pairs across groups are not
// (worst above 0, first found on a cross pair).
TEST(NetQuality, PairwiseTValuesOfPaddedSets) {
  const auto pmj = pairwise_t_values(points_of(pmj02_points(4, 1024, 2, 1)), 4);
  ASSERT_TRUE(pmj.has_value());
  EXPECT_EQ(pmj->best, 0u);
  EXPECT_GT(pmj->worst, 0u);
  EXPECT_NE(pmj->worst_j / 2, pmj->worst_k / 2) << "a cross pair: (0, 1) and (2, 3) are nets";
  const std::vector<double> padded = points_of(padded_sobol_points<owen_scramble>(4, 1024, 2, 1));
  const std::array<std::size_t, 2> second{2, 3};
  EXPECT_EQ(net_t_value(padded, 4, second), 0u);
  EXPECT_FALSE(pairwise_t_values(std::vector<double>(3 * 2, 0.5), 2).has_value()) << "N = 3";
}

// A square grid's nearest neighbours are 1/k apart; N points of the densest packing in 2D (the
// hexagonal one) would be (2/(√3·N))^(1/2) apart, so the ratio is (√3/2)^(1/2). The cubic grid
// against the densest in 3D (face-centred cubic, whose neighbours are 2^(1/6) times the cubic
// grid's spacing at equal density): 2^(−1/6). Evenly spaced points in 1D: exactly 1.
TEST(NetQuality, MinimumDistanceOfGridsAgainstThePackings) {
  EXPECT_NEAR(normalized_min_distance(centre_grid(32), 2), std::sqrt(std::sqrt(3.0) / 2.0), 1e-12);
  std::vector<double> cubic;
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      for (int k = 0; k < 8; ++k)
        cubic.insert(cubic.end(), {(i + 0.5) / 8, (j + 0.5) / 8, (k + 0.5) / 8});
    }
  }
  EXPECT_NEAR(normalized_min_distance(cubic, 3), std::pow(2.0, -1.0 / 6.0), 1e-12);
  std::vector<double> line;
  for (int i = 0; i < 100; ++i) line.push_back((i + 0.5) / 100);
  EXPECT_NEAR(normalized_min_distance(line, 1), 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(normalized_min_distance(std::vector<double>(9 * 4, 0.5), 9)));
}

TEST(NetQuality, BadInputIsNamed) {
  EXPECT_FALSE(net_t_value(std::vector<double>(2 * 48, 0.5), 2).has_value()) << "N = 48";
  EXPECT_THROW(net_t_value(std::vector<double>(2 * 16, 1.0), 2), invalid_argument);
  EXPECT_THROW(net_t_value(std::vector<double>(9 * 16, 0.5), 9), invalid_argument);
  // s = 8 at N = 2^16 would count 65536 points into C(23, 7) = 245157 shapes: refused, not run.
  EXPECT_THROW(net_t_value(std::vector<double>(8 * 65536, 0.5), 8), invalid_argument);
  const std::array<std::size_t, 1> beyond{2};
  EXPECT_THROW(net_t_value(std::vector<double>(2 * 16, 0.5), 2, beyond), invalid_argument);
  EXPECT_THROW(normalized_min_distance(std::vector<double>(5, 0.5), 2), invalid_argument);
}

}  // namespace
