#include "quadmc/sampling/jittered_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

// Index of the stratum holding x (row-major, last axis fastest).
std::uint64_t stratum_of(const double* x, std::size_t s, std::uint64_t k) {
  std::uint64_t c = 0;
  for (std::size_t j = 0; j < s; ++j) c = c * k + static_cast<std::uint64_t>(x[j] * double(k));
  return c;
}

TEST(JitteredPoints, EveryStratumHoldsExactlyOnePoint) {
  for (std::size_t s : {1u, 2u, 3u, 4u}) {
    const std::uint64_t k = s == 1 ? 1000 : (s == 2 ? 32 : (s == 3 ? 10 : 5));
    const std::uint64_t n = *stratum_grid::checked_power(k, s);
    const jittered_points p(s, n, 2, 8);
    std::vector<double> x(n * s);
    p.generate(0, x);
    std::vector<int> hits(n, 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t c = stratum_of(&x[i * s], s, k);
      ASSERT_EQ(c, i) << "s = " << s << ", k = " << k << ": point " << i;
      ++hits[c];
    }
    for (std::uint64_t c = 0; c < n; ++c) ASSERT_EQ(hits[c], 1) << "s = " << s << ", stratum " << c;
  }
}

TEST(JitteredPoints, MPointsPerStratumAreConsecutive) {
  const jittered_points p(stratum_grid(2, 4), 3, 1, 1);
  ASSERT_EQ(p.size(), 48u);
  std::vector<double> x(96);
  p.generate(0, x);
  for (std::uint64_t i = 0; i < 48; ++i) EXPECT_EQ(stratum_of(&x[2 * i], 2, 4), i / 3) << i;
  EXPECT_EQ(p.variance().kind, variance_kind::within_strata);
  EXPECT_EQ(p.variance().group, 3u);
}

TEST(JitteredPoints, OnePointPerStratumUsesStratumDifferences) {
  const jittered_points p(2, 64, 1, 1);
  EXPECT_EQ(p.variance().kind, variance_kind::stratum_differences);
  EXPECT_EQ(p.variance().group, 8u);  // strata per row along the last axis
}

TEST(JitteredPoints, RejectsNThatIsNotKToTheS) {
  try {
    jittered_points(2, 50, 1, 1);
    FAIL() << "N = 50 accepted for s = 2";
  } catch (const invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("N = 50"), std::string::npos) << m;
    EXPECT_NE(m.find("49 = 7^2 or 64 = 8^2"), std::string::npos) << m;
  }
}

TEST(JitteredPoints, RejectsOverflowOfKToTheSTimesM) {
  EXPECT_THROW(jittered_points(stratum_grid(2, 1ULL << 26), 1ULL << 20, 1, 1), invalid_argument);
  EXPECT_THROW(jittered_points(stratum_grid(2, 4), 0, 1, 1), invalid_argument);
}

}  // namespace
