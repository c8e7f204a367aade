// The weighted-point-set contract (weighted_point_set.hpp): which types model it, the map of the
// unit cube onto a box, the batch checks, and the properties every set must have — nodes in
// [0, 1]^s, finite weights summing to 1, points independent of how [0, N) is cut into batches.
#include "quadmc/rules/weighted_point_set.hpp"

#include "hand_built_rules.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product_grid.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace {

using namespace quadmc;
using quadmc::testing::extrapolated_midpoint;
using quadmc::testing::fibonacci_lattice;

static_assert(weighted_point_set<tensor_product_grid<simpson_rule::node_set>>);
static_assert(box_mapped_point_set<tensor_product_grid<simpson_rule::node_set>>);
static_assert(weighted_point_set<extrapolated_midpoint>);
static_assert(!box_mapped_point_set<extrapolated_midpoint>);
static_assert(weighted_point_set<fibonacci_lattice>);
static_assert(!weighted_point_set<simpson_rule::node_set>);  // a 1D node set is not a point set

using quadmc::test_support::eps;

// The unit cube's corners go to the box's corners; the widths of these boxes and the sums below
// are exact in binary, so the map is exact too.
TEST(CubeToBox, MapsTheUnitCubeOntoTheBox) {
  const cube_to_box map(box{{-1.5, 2.0, 1e8}, {0.25, 3.0, 1e8 + 1.0}});
  ASSERT_EQ(map.dimension(), 3U);
  EXPECT_EQ(map.width[0], 1.75);
  EXPECT_EQ(map.width[1], 1.0);
  EXPECT_EQ(map.width[2], 1.0);
  for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(map(j, 0.0), map.lower[j]);
  EXPECT_EQ(map(0, 1.0), 0.25);
  EXPECT_EQ(map(1, 0.5), 2.5);
  EXPECT_EQ(map(2, 1.0), 1e8 + 1.0);
}

// apply() maps a row-major batch in place with the same formula, one axis at a time: the same bits
// as the per-coordinate operator().
TEST(CubeToBox, ApplyEqualsThePerCoordinateMap) {
  const cube_to_box map(box{{-1.5, 2.0, -7.0}, {0.25, 3.0, 11.0}});
  std::vector<double> nodes(3 * 100);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    nodes[i] = std::fmod(0.618033988749895 * static_cast<double>(i), 1.0);
  }
  const std::vector<double> unit = nodes;
  map.apply(nodes);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(nodes[i]),
              std::bit_cast<std::uint64_t>(map(i % 3, unit[i])))
        << "entry " << i;
  }
}

TEST(RequireWeightedBatch, AcceptsWholeBatchesInsideTheSet) {
  std::vector<double> nodes(6);
  std::vector<double> weights(3);
  EXPECT_NO_THROW(require_weighted_batch(2, 10, 7, nodes, weights));  // points 7, 8, 9
  EXPECT_NO_THROW(require_weighted_batch(2, 10, 10, {}, {}));         // empty, at the end
}

TEST(RequireWeightedBatch, RejectsMismatchedSizesAndBatchesOutsideTheSet) {
  using quadmc::testing::throws_with;
  std::vector<double> nodes(7);
  std::vector<double> weights(3);
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { require_weighted_batch(2, 10, 0, nodes, weights); },
      "invalid batch nodes size = 7: expected weights size × dimension = 3 × 2 = 6"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { require_weighted_batch(2, 10, 0, std::span<double>(nodes).first(4), weights); },
      "invalid batch nodes size = 4: expected weights size × dimension = 3 × 2 = 6"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { require_weighted_batch(2, 10, 8, std::span<double>(nodes).first(6), weights); },
      "invalid batch first point = 8: expected a batch of 3 points inside [0, N) with N = 10"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { require_weighted_batch(1, 10, 11, {}, {}); },
      "invalid batch first point = 11: expected a batch of 0 points inside [0, N) with N = 10"));
  // The hand-built sets check through it as well.
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { extrapolated_midpoint(2).generate(4, std::span<double>(nodes).first(3), weights); },
      "invalid batch first point = 4: expected a batch of 3 points inside [0, N) with N = 6"));
}

// --- Properties of every set -------------------------------------------------------------------

// All N points in one batch.
template <class P>
void generate_all(const P& points, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(points.size() * points.dimension(), 0.0);
  weights.assign(points.size(), 0.0);
  points.generate(0, nodes, weights);
}

// The contract on all N points: nodes in [0, 1]^s, finite weights summing to 1 within
// weight_sum_tolerance, and the same bits whatever batches the points are generated in.
template <class P>
void expect_contract(const P& points, double weight_sum_tolerance) {
  const std::size_t s = points.dimension();
  const std::uint64_t n = points.size();
  std::vector<double> nodes, weights;
  generate_all(points, nodes, weights);
  double sum = 0.0;
  for (std::uint64_t i = 0; i < n; ++i) {
    ASSERT_TRUE(std::isfinite(weights[i])) << "point " << i;
    sum += weights[i];
    for (std::size_t j = 0; j < s; ++j) {
      ASSERT_GE(nodes[i * s + j], 0.0) << "point " << i;
      ASSERT_LE(nodes[i * s + j], 1.0) << "point " << i;
    }
  }
  EXPECT_NEAR(sum, 1.0, weight_sum_tolerance) << "a rule exact for constants";
  // The same points batch by batch, in reverse order and with uneven sizes: same bits.
  std::vector<double> node_batch, weight_batch;
  std::uint64_t end = n;
  std::size_t step = 1;
  while (end > 0) {
    const std::uint64_t count = std::min<std::uint64_t>(step, end);
    const std::uint64_t first = end - count;
    node_batch.assign(count * s, -1.0);
    weight_batch.assign(count, 0.0);
    points.generate(first, node_batch, weight_batch);
    for (std::uint64_t i = 0; i < count; ++i) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(weight_batch[i]),
                std::bit_cast<std::uint64_t>(weights[first + i]))
          << "point " << first + i;
      for (std::size_t j = 0; j < s; ++j) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(node_batch[i * s + j]),
                  std::bit_cast<std::uint64_t>(nodes[(first + i) * s + j]))
            << "point " << first + i << " axis " << j;
      }
    }
    end = first;
    step = step * 3 + 1;
  }
}

// Σw = 1 up to the rounding of N weights each off by ≤ ε/2 relative and of the running sum
// ((N − 1)ε·Σ|w|, Higham §4.2), here bounded by 2Nε·Σ|w|.
TEST(WeightedPointSetContract, TensorGrids) {
  const tensor_product_grid simpson(simpson_rule{}.nodes(6), 3);
  expect_contract(simpson, 2.0 * 343.0 * eps);
  const tensor_product_grid trapezoid(trapezoid_rule{}.nodes(40), 2);
  expect_contract(trapezoid, 2.0 * 1681.0 * eps);
  const tensor_product_grid gauss(gauss_legendre_rule(5).nodes(3), 2);
  expect_contract(gauss, 2.0 * 225.0 * eps);
}

// Weights of both signs: Σ|w| = 4/3 + 1/3 = 5/3.
TEST(WeightedPointSetContract, ExtrapolatedMidpointHasWeightsOfBothSigns) {
  const extrapolated_midpoint points(50);
  expect_contract(points, 2.0 * 150.0 * eps * 5.0 / 3.0);
  std::vector<double> nodes, weights;
  generate_all(points, nodes, weights);
  double positive = 0.0;
  double negative = 0.0;
  for (const double w : weights) (w > 0.0 ? positive : negative) += w;
  EXPECT_NEAR(positive, 4.0 / 3.0, 200.0 * eps);
  EXPECT_NEAR(negative, -1.0 / 3.0, 100.0 * eps);
}

TEST(WeightedPointSetContract, FibonacciLattice) {
  const fibonacci_lattice points(12);  // N = F_12 = 144, generator F_11 = 89
  ASSERT_EQ(points.size(), 144U);
  ASSERT_EQ(points.generator(), 89U);
  expect_contract(points, 2.0 * 144.0 * eps);
}

}  // namespace
