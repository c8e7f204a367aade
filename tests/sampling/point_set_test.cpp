// Properties every point set must have (point_set.hpp): coordinates in [0,1), determinism
// whatever the batch order, and validation of sizes and batches.
#include "quadmc/sampling/point_set.hpp"

#include "quadmc/sampling/cmj_points.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/padded_jittered_points.hpp"
#include "quadmc/sampling/padded_sobol_points.hpp"
#include "quadmc/sampling/pmj02_points.hpp"
#include "quadmc/sampling/unjittered_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace {

using namespace quadmc;

static_assert(point_set<independent_points>);
static_assert(point_set<jittered_points>);
static_assert(point_set<unjittered_points>);
static_assert(point_set<padded_jittered_points>);
static_assert(point_set<latin_hypercube_points>);

// Every point set takes (s, N, seed, stream); the unjittered one is then the shifted grid. The
// counts below are valid for every set: 1024 = 32² in 2D, 729 = 27² = 9³ in 3D (jittered needs
// k^s, padded jittered and cmj k²; the padded Sobol' class takes any N, its nets need 2^m).
template <class P>
P make(std::size_t s, std::uint64_t n, std::uint64_t seed) {
  return P(s, n, seed, 3);
}

template <class P>
class PointSetProperties : public ::testing::Test {};
using all_point_sets = ::testing::Types<independent_points, jittered_points, unjittered_points,
                                        padded_jittered_points, latin_hypercube_points, cmj_points,
                                        pmj02_points, padded_sobol_points<owen_scramble>>;
TYPED_TEST_SUITE(PointSetProperties, all_point_sets);

TYPED_TEST(PointSetProperties, CoordinatesLieInTheHalfOpenUnitCube) {
  for (std::size_t s : {1u, 2u, 3u}) {
    const std::uint64_t n = s == 1 ? 1000 : (s == 2 ? 1024 : 729);
    const auto p = make<TypeParam>(s, n, 11);
    std::vector<double> x(n * s);
    p.generate(0, x);
    for (std::size_t i = 0; i < x.size(); ++i) {
      ASSERT_GE(x[i], 0.0) << "s = " << s << ", coordinate " << i;
      ASSERT_LT(x[i], 1.0) << "s = " << s << ", coordinate " << i;
    }
  }
}

// Regenerating the points in reversed batches of odd sizes, or one point alone, gives bitwise
// the same values as one big batch (counter-based randomness, permutation by element).
TYPED_TEST(PointSetProperties, BatchOrderDoesNotChangeAnyBit) {
  const std::size_t s = 3;
  const std::uint64_t n = 729;
  const auto p = make<TypeParam>(s, n, 5);
  std::vector<double> whole(n * s);
  p.generate(0, whole);
  std::vector<double> pieces(n * s);
  const std::uint64_t step = 37;
  for (std::uint64_t end = n; end > 0;) {
    const std::uint64_t first = end >= step ? end - step : 0;
    p.generate(first, std::span<double>(pieces).subspan(first * s, (end - first) * s));
    end = first;
  }
  EXPECT_EQ(0, std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(double)));
  std::vector<double> one(s);
  p.generate(617, one);
  for (std::size_t j = 0; j < s; ++j) EXPECT_EQ(one[j], whole[617 * s + j]);
  // The same parameters give the same set; another seed gives another (except unshifted grids).
  const auto again = make<TypeParam>(s, n, 5);
  std::vector<double> twice(n * s);
  again.generate(0, twice);
  EXPECT_EQ(whole, twice);
  const auto other = make<TypeParam>(s, n, 6);
  other.generate(0, twice);
  EXPECT_NE(whole, twice);
}

TYPED_TEST(PointSetProperties, RejectsBatchesOutsideTheSetOrOfPartialPoints) {
  const auto p = make<TypeParam>(2, 16, 1);
  std::vector<double> x(6);
  EXPECT_THROW(p.generate(14, x), invalid_argument);  // points 14, 15, 16: 16 is past the end
  std::vector<double> odd(5);
  EXPECT_THROW(p.generate(0, odd), invalid_argument);
  EXPECT_NO_THROW(p.generate(13, x));
}

TYPED_TEST(PointSetProperties, RejectsZeroPointsAndZeroDimensions) {
  EXPECT_THROW(make<TypeParam>(2, 0, 1), invalid_argument);
  EXPECT_THROW(make<TypeParam>(0, 16, 1), invalid_argument);
}

TEST(PointSetSize, MessagesNameTheParameter) {
  try {
    require_point_set_size(2, 0);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_STREQ(e.what(), "invalid number of points N = 0: expected N ≥ 1");
  }
  try {
    require_point_set_size(0, 5);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_STREQ(e.what(), "invalid dimension s = 0: expected s ≥ 1");
  }
}

}  // namespace
