#include "quadmc/sampling/latin_hypercube_points.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/sampling/random_permutation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
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

// AVX2 and AVX-512 run the permutations and the placement fused, lane by lane in the batch's
// layout; scalar and SSE2 run the per-axis loop (and AVX2 does for n > 2^31). At every level this
// CPU has, each coordinate must be bit for bit the documented min((π_j(i) + u)·fl(1/N),
// largest_below_one), with π_j rebuilt here from its key (random_permutation::operator()) and u =
// uniform i·s + j of the stream: for s whose lanes fill registers exactly and not (1…9, 12, 16),
// N that walks, never walks, is AVX2's largest (2^31) or above, and batches with a tail shorter
// than a block.
TEST(LatinHypercubePoints, FusedKernelIsThePerAxisFormulaAtEverySimdLevel) {
  const simd_level saved = active_simd_level();
  for (const simd_level level : available_simd_levels()) {
    set_simd_level(level);
    for (const std::size_t s : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u, 9u, 12u, 16u}) {
      for (const std::uint64_t n :
           {std::uint64_t{1}, std::uint64_t{7}, std::uint64_t{1000}, std::uint64_t{4096},
            std::uint64_t{100003}, std::uint64_t{1} << 31, (std::uint64_t{1} << 31) + 1,
            (std::uint64_t{1} << 33) + 5}) {
        const latin_hypercube_points p(s, n, 21, n + s);
        const random_stream rng(21, n + s);
        std::vector<random_permutation> axes;
        for (std::size_t j = 0; j < s; ++j) {
          axes.emplace_back(n, rng.bits(std::numeric_limits<std::uint64_t>::max() - j));
        }
        const double inv_n = 1.0 / static_cast<double>(n);
        for (const std::uint64_t first : {std::uint64_t{0}, n / 3, n > 300 ? n - 300 : 0}) {
          const std::uint64_t count = std::min<std::uint64_t>(259, n - first);  // 256 + 3
          std::vector<double> x(count * s);
          p.generate(first, x);
          for (std::uint64_t i = 0; i < count; ++i) {
            for (std::size_t j = 0; j < s; ++j) {
              const double u = rng.uniform((first + i) * s + j);
              const auto row = static_cast<double>(axes[j](first + i));
              const double expected = std::min((row + u) * inv_n, largest_below_one);
              ASSERT_EQ(std::bit_cast<std::uint64_t>(x[i * s + j]),
                        std::bit_cast<std::uint64_t>(expected))
                  << "level " << to_string(level) << ", s = " << s << ", N = " << n << ", point "
                  << first + i << ", axis " << j;
            }
          }
        }
      }
    }
  }
  set_simd_level(saved);
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
