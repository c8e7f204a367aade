#include "quadmc/sampling/unjittered_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace quadmc;

TEST(UnjitteredPoints, AreTheStratumCentres) {
  const unjittered_points p(2, 16);
  std::vector<double> x(32);
  p.generate(0, x);
  for (std::uint64_t i = 0; i < 16; ++i) {
    EXPECT_EQ(x[2 * i], (double(i / 4) + 0.5) / 4.0) << i;
    EXPECT_EQ(x[2 * i + 1], (double(i % 4) + 0.5) / 4.0) << i;
  }
  EXPECT_EQ(p.variance().kind, variance_kind::not_estimable);
}

// Shifted grid: the centres plus one Δ (uniforms 0, 1 of the stream) modulo 1; every stratum of
// the shifted grid, hence every stratum of the unshifted one as well, holds exactly one point.
TEST(UnjitteredPoints, ShiftedGridMovesEveryPointByTheSameDelta) {
  const unjittered_points p(2, 25, 7, 3);
  const random_stream rng(7, 3);
  std::vector<double> x(50);
  p.generate(0, x);
  std::vector<int> hits(25, 0);
  for (std::uint64_t i = 0; i < 25; ++i) {
    for (std::size_t j = 0; j < 2; ++j) {
      const double centre = (double(j == 0 ? i / 5 : i % 5) + 0.5) / 5.0;
      const double expected = std::fmod(centre + rng.uniform(j), 1.0);
      EXPECT_NEAR(x[2 * i + j], expected, 1e-15) << "point " << i << ", axis " << j;
    }
    ++hits[std::uint64_t(x[2 * i] * 5) * 5 + std::uint64_t(x[2 * i + 1] * 5)];
  }
  for (int h : hits) EXPECT_EQ(h, 1);
}

TEST(UnjitteredPoints, RejectsNThatIsNotKToTheS) {
  EXPECT_THROW(unjittered_points(3, 100), invalid_argument);
}

}  // namespace
