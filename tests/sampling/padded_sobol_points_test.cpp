// Tests of padded_sobol_points.hpp: every pair a (0, m, 2)-net for every randomization, the first
// pair the Sobol' set's first two coordinates, the pairs associated at random, uniform points.
#include "quadmc/sampling/padded_sobol_points.hpp"

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

// Each point is uniform: point 5's coordinate 3 over 4096 streams
// (test_support::expect_uniform_over_streams states the bound).
TYPED_TEST(PaddedSobol, EachPointIsUniform) {
  std::vector<double> x(4);
  test_support::expect_uniform_over_streams([&](std::uint64_t r) {
    padded_sobol_points<TypeParam>(4, 8, 5, r).generate(5, x);
    return x[3];
  });
}

}  // namespace
