// tensor_product_grid: the product nodes and weights of a 1D rule as a weighted point set, and
// integrate() over it giving the bits of the summation order it has always had.
#include "quadmc/rules/tensor_product_grid.hpp"

#include "quadmc/functions/catalogue.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/rectangle_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "reference_weighted_sum.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

using quadmc::test_support::bits;

// Point p of the tensor grid of q in s dimensions, straight from the definition: the base-m
// digits of p (last axis fastest), t_j = node(k_j), w = w_{k_1}·…·w_{k_s} multiplied left to
// right.
template <class Q>
void tensor_point(const Q& q, std::size_t s, std::uint64_t p, std::span<double> t, double& w) {
  const std::uint64_t m = q.size();
  std::vector<std::uint64_t> k(s);
  for (std::size_t j = s; j-- > 0;) {
    k[j] = p % m;
    p /= m;
  }
  w = 1.0;
  for (std::size_t j = 0; j < s; ++j) {
    t[j] = q.node(k[j]);
    w *= q.weight(k[j]);
  }
}

// f(x) = exp(Σ x_j)/(1 + x_1²) on a box: scalar, smooth, different on every axis.
struct smooth_integrand {
  box domain;
  std::size_t dimension() const { return domain.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = dimension();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < s; ++j) sum += x[i * s + j];
      y[i] = std::exp(sum) / (1.0 + x[i * s] * x[i * s]);
    }
  }
  integrand_info info() const {
    integrand_info i;
    i.name = "smooth";
    i.domain = domain;
    return i;
  }
};

box shifted_box(std::size_t s) {
  box b;
  for (std::size_t j = 0; j < s; ++j) {
    b.lower.push_back(-0.75 + 0.25 * static_cast<double>(j));
    b.upper.push_back(1.5 + 0.5 * static_cast<double>(j));
  }
  return b;
}

using quadmc::testing::all_accumulators;

// integrate(f, rule, n, threads, accumulate) against reference_weighted_sum over the grid's
// points from tensor_point, for every accumulator and 1, 2, 3, 8 threads. Cases with more than
// 450 000 points are skipped to keep the test short.
template <class F, class R>
void expect_reference_bits(const F& f, const R& rule, std::uint64_t n, const std::string& label) {
  const std::size_t s = f.dimension();
  const auto q = rule.nodes(n);
  const std::uint64_t total = tensor_grid_size(q.size(), s);
  if (total > 450'000) return;
  const auto point_at = [&q, s](std::uint64_t p, std::span<double> t, double& w) {
    tensor_point(q, s, p, t, w);
  };
  for (const summation accumulate : all_accumulators) {
    const double expected = quadmc::testing::reference_weighted_sum(f, total, point_at, accumulate);
    for (const unsigned threads : {1U, 2U, 3U, 8U}) {
      const rule_result r = integrate(f, rule, n, threads, accumulate);
      EXPECT_EQ(bits(r.value), bits(expected))
          << label << " " << rule.name() << " s = " << s << " n = " << n << " "
          << to_string(accumulate) << " threads = " << threads << ": " << r.value
          << " vs reference " << expected;
      EXPECT_EQ(r.evaluations, total);
    }
  }
}

template <class F>
void expect_reference_bits_for_every_rule(const F& f, std::uint64_t n, const std::string& label) {
  expect_reference_bits(f, rectangle_rule<rectangle_side::left>{}, n, label);
  expect_reference_bits(f, rectangle_rule<rectangle_side::right>{}, n, label);
  expect_reference_bits(f, midpoint_rule{}, n, label);
  expect_reference_bits(f, trapezoid_rule{}, n, label);
  expect_reference_bits(f, simpson_rule{}, n + n % 2, label);
  expect_reference_bits(f, gauss_legendre_rule(2), n, label);
  expect_reference_bits(f, gauss_legendre_rule(5), n, label);
}

// The sizes cover one point per axis, grids smaller than a batch, partial last batches and
// chunks, several chunks (s = 1, n = 40 000: 40 001 to 200 000 points), and axes with more than
// 2^14 nodes, whose nodes are computed per point instead of tabulated (s = 1, n = 40 000).
TEST(TensorProductGrid, IntegrateGivesTheBitsOfTheReferenceSummationOrder) {
  const std::vector<std::vector<std::uint64_t>> panels = {
      {1, 2, 6, 40000}, {2, 130}, {2, 30}, {4, 12}};
  for (std::size_t s = 1; s <= 4; ++s) {
    const smooth_integrand f{shifted_box(s)};
    integrand_params p;
    p.dimension = s;
    p.seed = 17;
    const any_integrand genz = make_integrand("genz_oscillatory", p);
    for (const std::uint64_t n : panels[s - 1]) {
      expect_reference_bits_for_every_rule(f, n, "smooth");
      expect_reference_bits_for_every_rule(genz, n, "genz_oscillatory");
    }
  }
}

// m = 1 leaves one point for any s; past s = 64 the grid takes its single-point path. (A box
// around 0, so that exp(Σ x_j) stays finite in 100 dimensions.)
TEST(TensorProductGrid, OneNodePerAxisInManyDimensions) {
  for (const std::size_t s : {63U, 64U, 65U, 100U}) {
    box around_zero;
    for (std::size_t j = 0; j < s; ++j) {
      around_zero.lower.push_back(-0.5);
      around_zero.upper.push_back(0.5 + 0.001 * static_cast<double>(j));
    }
    const smooth_integrand f{around_zero};
    expect_reference_bits(f, midpoint_rule{}, 1, "smooth");
    const tensor_product_grid grid(midpoint_rule{}.nodes(1), s);
    std::vector<double> t(s);
    double w = 0.0;
    grid.generate(0, t, std::span<double>(&w, 1));
    for (const double v : t) EXPECT_EQ(v, 0.5);
    EXPECT_EQ(w, 1.0);
  }
}

// generate() decodes each batch's first index on its own, so any cut of [0, N) into batches gives
// the points of the definition.
template <class R>
void expect_points_of_the_definition(const R& rule, std::uint64_t n, std::size_t s) {
  const auto q = rule.nodes(n);
  const tensor_product_grid grid(q, s);
  ASSERT_EQ(grid.size(), tensor_grid_size(q.size(), s));
  ASSERT_EQ(grid.dimension(), s);
  ASSERT_EQ(grid.nodes_per_axis(), q.size());
  std::vector<double> t(s);
  std::uint64_t first = 0;
  for (const std::size_t step : {1U, 7U, 256U, 3U, 1000U, 2U}) {
    if (first >= grid.size()) break;
    const std::size_t count =
        static_cast<std::size_t>(std::min<std::uint64_t>(step, grid.size() - first));
    std::vector<double> nodes(count * s);
    std::vector<double> weights(count);
    grid.generate(first, nodes, weights);
    for (std::size_t i = 0; i < count; ++i) {
      double w = 0.0;
      tensor_point(q, s, first + i, t, w);
      for (std::size_t j = 0; j < s; ++j) {
        ASSERT_EQ(bits(nodes[i * s + j]), bits(t[j]))
            << rule.name() << " s = " << s << " point " << first + i << " axis " << j;
      }
      ASSERT_EQ(bits(weights[i]), bits(w)) << rule.name() << " s = " << s << " point " << first + i;
    }
    first += count * 37;  // skip ahead: batches start anywhere, carries included
  }
}

TEST(TensorProductGrid, AnyBatchCutGivesThePointsOfTheDefinition) {
  for (const std::size_t s : {1U, 2U, 3U, 5U}) {
    expect_points_of_the_definition(trapezoid_rule{}, 6, s);
    expect_points_of_the_definition(simpson_rule{}, 4, s);
    expect_points_of_the_definition(gauss_legendre_rule(3), 2, s);
  }
  // 20 000 midpoint nodes per axis: more than 2^14, so computed per point rather than tabulated.
  expect_points_of_the_definition(midpoint_rule{}, 20000, 1);
  expect_points_of_the_definition(midpoint_rule{}, 20000, 2);
}

// The fast path: mapped(map) writes map(j, t_j) directly, bitwise what generate() and
// cube_to_box::apply give, tabulated or not.
template <class R>
void expect_mapped_equals_generate_then_map(const R& rule, std::uint64_t n, std::size_t s,
                                            std::uint64_t first, std::size_t count) {
  const tensor_product_grid grid(rule.nodes(n), s);
  const cube_to_box map(shifted_box(s));
  const auto on_box = grid.mapped(map);
  std::vector<double> unit(count * s), x(count * s), w_unit(count), w_box(count);
  grid.generate(first, unit, w_unit);
  map.apply(unit);
  on_box.generate(first, x, w_box);
  for (std::size_t i = 0; i < count * s; ++i) {
    ASSERT_EQ(bits(x[i]), bits(unit[i])) << rule.name() << " s = " << s << " entry " << i;
  }
  for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(bits(w_box[i]), bits(w_unit[i]));
}

TEST(TensorProductGrid, MappedGeneratorEqualsGenerateThenMap) {
  expect_mapped_equals_generate_then_map(simpson_rule{}, 10, 3, 100, 500);
  expect_mapped_equals_generate_then_map(gauss_legendre_rule(4), 3, 2, 5, 100);
  expect_mapped_equals_generate_then_map(trapezoid_rule{}, 4, 1, 0, 5);
  expect_mapped_equals_generate_then_map(midpoint_rule{}, 1, 70, 0, 1);
  expect_mapped_equals_generate_then_map(midpoint_rule{}, 20000, 1, 19000, 1000);  // per point
  expect_mapped_equals_generate_then_map(midpoint_rule{}, 20000, 2, 19990, 300);   // carries
}

TEST(TensorProductGrid, RejectsBadInput) {
  using quadmc::testing::throws_with;
  const tensor_product_grid grid(simpson_rule{}.nodes(2), 2);  // 9 points
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] { (void)tensor_product_grid(trapezoid_rule{}.nodes(65535), 4); },
      "invalid nodes per axis = 65536: expected nodes^s ≤ 2^64 − 1 for s = 4"));
  EXPECT_TRUE(
      throws_with<invalid_argument>([] { (void)tensor_product_grid(midpoint_rule{}.nodes(3), 0); },
                                    "invalid dimension s = 0: expected at least 1"));
  std::vector<double> nodes(10);
  std::vector<double> weights(5);
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { grid.generate(5, nodes, weights); },
      "invalid batch first point = 5: expected a batch of 5 points inside [0, N) with N = 9"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { grid.generate(0, std::span<double>(nodes).first(9), weights); },
      "invalid batch nodes size = 9: expected weights size × dimension = 5 × 2 = 10"));
  EXPECT_TRUE(
      throws_with<invalid_argument>([&] { (void)grid.mapped(cube_to_box(box::unit(3))); },
                                    "invalid box dimension = 3: expected the grid's dimension 2"));
}

}  // namespace
