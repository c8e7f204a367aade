// Tests of padded_sobol_points.hpp: every pair a (0, m, 2)-net for every randomization, the first
// pair the Sobol' set's first two coordinates, the pairs associated at random, uniform points.
#include "quadmc/sampling/padded_sobol_points.hpp"

#include "sampling/elementary_intervals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using namespace quadmc;
using test_support::is_interval_net;
using test_support::is_pair_net;

static_assert(point_set<padded_sobol_points<owen_scramble>>);

template <class R>
class PaddedSobol : public ::testing::Test {};
using randomizations =
    ::testing::Types<owen_scramble, fast_owen_scramble, linear_matrix_scramble, digital_shift>;
TYPED_TEST_SUITE(PaddedSobol, randomizations);

// Each randomization keeps the net of its pair (sobol_points_test.cpp: they map elementary
// intervals to elementary intervals), so in s = 5 pairs (0, 1) and (2, 3) are (0, m, 2)-nets and
// coordinate 4 a (0, m, 1)-net, for m = 4 … 10; coordinates 0 and 2 are not (a random matching of
// two (0, 8, 1)-nets fills the 16 × 16 boxes once each with probability (16!)^32/256! < 1e-80).
TYPED_TEST(PaddedSobol, EveryPairIsANetAndPairsAreShuffled) {
  for (const unsigned m : {4u, 8u, 10u}) {
    const padded_sobol_points<TypeParam> p(5, std::uint64_t{1} << m, 7, 3);
    std::vector<double> x(p.size() * 5);
    p.generate(0, x);
    EXPECT_TRUE(is_pair_net(x, 5, 0, 1, 0, m)) << "m = " << m;
    EXPECT_TRUE(is_pair_net(x, 5, 2, 3, 0, m)) << "m = " << m;
    EXPECT_TRUE(is_interval_net(x, 5, 4, 0, m)) << "m = " << m;
    if (m == 8) {
      EXPECT_FALSE(is_pair_net(x, 5, 0, 2, 0, m));
    }
  }
}

// Owen's, Burley's and the digital shift's keys are per dimension: the first pair is the Sobol'
// set's first two coordinates, bit for bit (the linear scramble's keys depend on s).
TEST(PaddedSobol, FirstPairIsTheSobolSetsFirstTwoCoordinates) {
  const padded_sobol_points<owen_scramble> padded(4, 256, 9, 1);
  const sobol_points<owen_scramble> sobol(4, 256, 9, 1);
  std::vector<double> a(256 * 4), b(256 * 4);
  padded.generate(0, a);
  sobol.generate(0, b);
  for (std::size_t i = 0; i < 256; ++i) {
    ASSERT_EQ(a[i * 4], b[i * 4]) << "point " << i;
    ASSERT_EQ(a[i * 4 + 1], b[i * 4 + 1]) << "point " << i;
  }
}

// Each point is uniform: over 4096 streams, point 5's coordinate 3 in 16 equal bins is within
// 4.9 standard deviations of 256 in each (binomial, p = 1/16, sd = 15.5: a false alarm of 1e-6
// per bin, 1.6e-5 for the 16).
TYPED_TEST(PaddedSobol, EachPointIsUniform) {
  std::vector<int> bins(16, 0);
  std::vector<double> x(4);
  for (std::uint64_t r = 0; r < 4096; ++r) {
    const padded_sobol_points<TypeParam> p(4, 8, 5, r);
    p.generate(5, x);
    ++bins[static_cast<std::size_t>(x[3] * 16)];
  }
  const double sd = std::sqrt(4096.0 * (1.0 / 16) * (15.0 / 16));
  for (int b = 0; b < 16; ++b) EXPECT_NEAR(bins[b], 256.0, 4.9 * sd) << "bin " << b;
}

}  // namespace
