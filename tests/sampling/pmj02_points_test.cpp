// Tests of pmj02_points.hpp: the (0,2)-sequence property (every aligned block of 2^m points a
// (0, m, 2)-net), the stratification of every prefix's 1D projections, the partner offsets
// against the Sobol' digits they are solved from, padding, and uniformity of a point.
#include "quadmc/sampling/pmj02_points.hpp"

#include "quadmc/sampling/sobol_points.hpp"
#include "sampling/elementary_intervals.hpp"
#include "sampling/uniform_bins.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using namespace quadmc;
using test_support::is_interval_net;
using test_support::is_pair_net;

static_assert(point_set<pmj02_points>);

std::vector<double> points_of(const pmj02_points& p) {
  std::vector<double> x(p.size() * p.dimension());
  p.generate(0, x);
  return x;
}

// Every prefix of 2^m points and every aligned block of 2^m is a (0, m, 2)-net, for m up to 13
// and three seeds: in s = 2 from the table alone (it holds the whole set), and in s = 64, whose
// table holds the first 2^17/64 = 2^11 points, through the chains of the later ones (the first
// pair; the last one, whose sequence indices are shuffled, as a whole).
TEST(Pmj02Points, EveryAlignedBlockOfTwoToTheMPointsIsANet) {
  constexpr unsigned top = 13;
  for (const std::size_t s : {2u, 64u}) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      const pmj02_points p(s, std::uint64_t{1} << top, seed, 4);
      const std::vector<double> x = points_of(p);
      for (unsigned m = 0; m <= top; ++m) {
        const std::uint64_t block = std::uint64_t{1} << m;
        for (std::uint64_t first = 0; first < p.size(); first += block) {
          ASSERT_TRUE(is_pair_net(x, s, 0, 1, first, m))
              << "s = " << s << ", seed " << seed << ", block of 2^" << m << " at " << first;
        }
      }
      // A later pair follows its sequence at shuffled indices: the whole set is its net.
      EXPECT_TRUE(is_pair_net(x, s, s - 2, s - 1, 0, top)) << "s = " << s << ", seed " << seed;
    }
  }
}

// Any prefix of n points, 2^k < n ≤ 2^(k+1), is stratified in each 1D projection as
// [Christensen et al. 2018] prove: at most one point per interval of 2^−(k+1) and at least one
// per interval of 2^−k.
TEST(Pmj02Points, EveryPrefixIsStratifiedInEachCoordinate) {
  const pmj02_points p(2, 1024, 7, 1);
  const std::vector<double> x = points_of(p);
  for (std::uint64_t n = 2; n <= p.size(); ++n) {
    const int k = std::bit_width(n - 1) - 1;  // 2^k < n ≤ 2^(k+1)
    for (std::size_t c = 0; c < 2; ++c) {
      std::vector<int> fine(std::size_t{2} << k, 0);
      std::vector<int> coarse(std::size_t{1} << k, 0);
      for (std::uint64_t i = 0; i < n; ++i) {
        ++fine[static_cast<std::size_t>(std::ldexp(x[i * 2 + c], k + 1))];
        ++coarse[static_cast<std::size_t>(std::ldexp(x[i * 2 + c], k))];
      }
      for (const int f : fine) ASSERT_LE(f, 1) << "n = " << n << ", coordinate " << c;
      for (const int h : coarse) ASSERT_GE(h, 1) << "n = " << n << ", coordinate " << c;
    }
  }
}

// The offsets solve C_k·a_k = column k's first k digits: point 2^k + i of the unrandomized
// Sobol' sequence (natural order) shares its first k digits with point i ⊕ a_k, in both
// coordinates, for every level and a spread of i.
TEST(Pmj02Points, PartnersShareTheirFirstDigitsInTheSobolSequence) {
  const sobol_matrices c(2);
  const pmj02_partners& a = pmj02_partner_offsets();
  const auto digits = [&](std::size_t j, std::uint64_t index) {
    std::uint32_t v = 0;
    for (unsigned b = 0; b < 32; ++b) {
      if (((index >> b) & 1u) != 0) v ^= c.columns(j)[b];
    }
    return v;
  };
  for (unsigned k = 1; k < 32; ++k) {
    EXPECT_EQ(a.x[k], 0u) << "van der Corput's partner is i itself";
    for (const std::uint64_t i : {std::uint64_t{0}, std::uint64_t{1}, (std::uint64_t{1} << k) - 1,
                                  (std::uint64_t{1} << k) / 3}) {
      for (std::size_t j = 0; j < 2; ++j) {
        const std::uint64_t partner = i ^ (j == 0 ? a.x[k] : a.y[k]);
        ASSERT_LT(partner, std::uint64_t{1} << k);
        EXPECT_EQ(digits(j, (std::uint64_t{1} << k) + i) >> (32 - k),
                  digits(j, partner) >> (32 - k))
            << "level " << k << ", i = " << i << ", coordinate " << j;
      }
    }
  }
}

// Padding: in s = 5 every pair (0, 1), (2, 3) is a (0, m, 2)-net and coordinate 4 a (0, m, 1)-net;
// the pairs are associated at random, so coordinates 0 and 2 are not a net (a random matching of
// two (0, 8, 1)-nets fills the 16 × 16 boxes once each with probability (16!)^32/256! < 1e-80).
TEST(Pmj02Points, EveryPairIsANetAndPairsAreShuffled) {
  const pmj02_points p(5, 256, 11, 2);
  const std::vector<double> x = points_of(p);
  EXPECT_TRUE(is_pair_net(x, 5, 0, 1, 0, 8));
  EXPECT_TRUE(is_pair_net(x, 5, 2, 3, 0, 8));
  EXPECT_TRUE(is_interval_net(x, 5, 4, 0, 8));
  EXPECT_FALSE(is_pair_net(x, 5, 0, 2, 0, 8));
}

// Each point is uniform (a nested uniform scramble in distribution, [Helmer et al. 2021]): point
// 13's y (level 3, a chain of three partners) over 4096 streams
// (test_support::expect_uniform_over_streams states the bound).
TEST(Pmj02Points, EachPointIsUniform) {
  std::vector<double> x(2);
  test_support::expect_uniform_over_streams([&](std::uint64_t r) {
    pmj02_points(2, 16, 5, r).generate(13, x);
    return x[1];
  });
}

TEST(Pmj02Points, RejectsMoreThanThirtyTwoLevels) {
  EXPECT_THROW(pmj02_points(1, (std::uint64_t{1} << 32) + 1, 1, 1), invalid_argument);
  EXPECT_NO_THROW(pmj02_points(1, std::uint64_t{1} << 20, 1, 1));
}

}  // namespace
