#include "quadmc/sampling/latin_hypercube_points.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using namespace quadmc;

// Along every axis, each of the N rows [r/N, (r+1)/N) holds exactly one point, for any N.
TEST(LatinHypercubePoints, ExactlyOnePointPerRowInEveryDimension) {
  for (std::uint64_t n : {1ULL, 2ULL, 7ULL, 100ULL, 1000ULL, 4097ULL}) {
    for (std::size_t s : {1u, 3u, 8u}) {
      const latin_hypercube_points p(s, n, 13, n + s);
      std::vector<double> x(n * s);
      p.generate(0, x);
      for (std::size_t j = 0; j < s; ++j) {
        std::vector<int> hits(n, 0);
        for (std::uint64_t i = 0; i < n; ++i) ++hits[std::uint64_t(x[i * s + j] * double(n))];
        for (std::uint64_t r = 0; r < n; ++r) {
          ASSERT_EQ(hits[r], 1) << "N = " << n << ", s = " << s << ", axis " << j << ", row " << r;
        }
      }
    }
  }
}

// Different axes use different permutations: the rows of axis 0 and axis 1 of the same point
// agree for about one point in a random pair of permutations (Poisson(1)); P(≥ 10) < 1.2e-7.
TEST(LatinHypercubePoints, AxesArePermutedIndependently) {
  const std::uint64_t n = 1000;
  const latin_hypercube_points p(2, n, 1, 1);
  std::vector<double> x(2 * n);
  p.generate(0, x);
  int same = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    same += std::uint64_t(x[2 * i] * double(n)) == std::uint64_t(x[2 * i + 1] * double(n));
  }
  EXPECT_LT(same, 10);
}

}  // namespace
