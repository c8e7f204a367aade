#include "quadmc/sampling/jittered_points.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
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

// One point per stratum, s ≤ 8, runs a vector kernel chosen at run time (whole rows of the last
// axis in registers): at every level this CPU has, each coordinate must be bit for bit the
// documented formula min((cell_j + u)·fl(1/k), largest_below_one), with cell_j from integer
// division and u = uniform i·s + j of the stream, rebuilt here point by point. Rows shorter and
// longer than a register (k = 1, 2, 3, 5, 6, 7, 40), batches that start and end inside a row,
// and a batch through the last stratum.
TEST(JitteredPoints, RowKernelIsTheScalarFormulaAtEverySimdLevel) {
  const simd_level saved = active_simd_level();
  for (const simd_level level : available_simd_levels()) {
    set_simd_level(level);
    for (std::size_t s = 1; s <= 9; ++s) {
      for (const std::uint64_t k : {1u, 2u, 3u, 5u, 6u, 7u, 40u}) {
        const auto strata = stratum_grid::checked_power(k, s, std::uint64_t{1} << 22);
        if (!strata) continue;
        const std::uint64_t n = *strata;
        const jittered_points p(s, n, 9, k + 100 * s);
        const random_stream rng(9, k + 100 * s);
        const double inv_k = 1.0 / static_cast<double>(k);
        for (const std::uint64_t first : {std::uint64_t{0}, n / 3, n > 300 ? n - 300 : 0}) {
          // 259 = 256 + 3: a whole batch of the kernel and a tail, or to the end of the set.
          const std::uint64_t count = std::min<std::uint64_t>(259, n - first);
          std::vector<double> x(count * s);
          p.generate(first, x);
          for (std::uint64_t i = 0; i < count; ++i) {
            std::uint64_t c = first + i;
            for (std::size_t j = s; j-- > 0;) {
              const std::uint64_t cell = c % k;
              c /= k;
              const double u = rng.uniform((first + i) * s + j);
              const double expected =
                  std::min((static_cast<double>(cell) + u) * inv_k, largest_below_one);
              ASSERT_EQ(std::bit_cast<std::uint64_t>(x[i * s + j]),
                        std::bit_cast<std::uint64_t>(expected))
                  << "level " << to_string(level) << ", s = " << s << ", k = " << k << ", point "
                  << first + i << ", axis " << j;
            }
          }
        }
      }
    }
  }
  set_simd_level(saved);
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
