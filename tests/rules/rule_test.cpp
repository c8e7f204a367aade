// The rule concept: every rule satisfies it, and every node set is a proper rule on [0, 1]
// (nodes ascending inside [0, 1], positive weights summing to 1, the documented node count).
#include "quadmc/rules/rule.hpp"

#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/rectangle_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

namespace {

static_assert(quadmc::rule<quadmc::midpoint_rule>);
static_assert(quadmc::rule<quadmc::trapezoid_rule>);
static_assert(quadmc::rule<quadmc::simpson_rule>);
static_assert(quadmc::rule<quadmc::left_rectangle_rule>);
static_assert(quadmc::rule<quadmc::right_rectangle_rule>);
static_assert(quadmc::rule<quadmc::gauss_legendre_rule>);
static_assert(!quadmc::rule<double>);

// Weights summed in order: n ≤ 64 terms each ≤ 1 with relative rounding ≤ 2ε (one division,
// one multiplication), so |Σw − 1| ≤ (2 + n)ε·1; we assert (n + 4)ε.
template <class R>
void expect_proper_node_set(const R& rule, std::uint64_t n, std::uint64_t expected_size) {
  const auto q = rule.nodes(n);
  ASSERT_EQ(q.size(), expected_size) << rule.name() << " n = " << n;
  double sum = 0.0;
  double previous = -1.0;
  for (std::uint64_t k = 0; k < q.size(); ++k) {
    const double t = q.node(k);
    const double w = q.weight(k);
    EXPECT_GE(t, 0.0) << rule.name() << " n = " << n << " k = " << k;
    EXPECT_LE(t, 1.0) << rule.name() << " n = " << n << " k = " << k;
    EXPECT_GT(t, previous) << rule.name() << " n = " << n << " k = " << k;
    EXPECT_GT(w, 0.0) << rule.name() << " n = " << n << " k = " << k;
    previous = t;
    sum += w;
  }
  constexpr double eps = std::numeric_limits<double>::epsilon();
  EXPECT_NEAR(sum, 1.0, (static_cast<double>(q.size()) + 4.0) * eps) << rule.name() << " n = " << n;
}

TEST(Rule, NodeSetsAreRulesOnTheUnitInterval) {
  for (std::uint64_t n : {2U, 4U, 6U, 10U, 64U}) {
    expect_proper_node_set(quadmc::midpoint_rule{}, n, n);
    expect_proper_node_set(quadmc::trapezoid_rule{}, n, n + 1);
    expect_proper_node_set(quadmc::simpson_rule{}, n, n + 1);
    expect_proper_node_set(quadmc::left_rectangle_rule{}, n, n);
    expect_proper_node_set(quadmc::right_rectangle_rule{}, n, n);
    for (unsigned m : quadmc::gauss_legendre_rule::supported_points) {
      expect_proper_node_set(quadmc::gauss_legendre_rule(m), n, m * n);
    }
  }
}

TEST(Rule, EndNodesAreExact) {
  // Division k/n (not k·(1/n)) puts the end nodes exactly on 0 and 1: 49·(1/49) ≠ 1 in double.
  const std::uint64_t n = 49;
  EXPECT_EQ(quadmc::trapezoid_rule{}.nodes(n).node(n), 1.0);
  EXPECT_EQ(quadmc::simpson_rule{}.nodes(50).node(50), 1.0);
  EXPECT_EQ(quadmc::right_rectangle_rule{}.nodes(n).node(n - 1), 1.0);
  EXPECT_EQ(quadmc::left_rectangle_rule{}.nodes(n).node(0), 0.0);
}

TEST(Rule, OrdersAndNames) {
  EXPECT_EQ(quadmc::left_rectangle_rule{}.order(), 1);
  EXPECT_EQ(quadmc::right_rectangle_rule{}.order(), 1);
  EXPECT_EQ(quadmc::midpoint_rule{}.order(), 2);
  EXPECT_EQ(quadmc::trapezoid_rule{}.order(), 2);
  EXPECT_EQ(quadmc::simpson_rule{}.order(), 4);
  EXPECT_EQ(quadmc::gauss_legendre_rule(5).order(), 10);
  // Display names for messages (the scene names of the methods are the registry's).
  EXPECT_EQ(std::string(quadmc::gauss_legendre_rule(5).name()), "composite Gauss–Legendre m = 5");
  EXPECT_EQ(std::string(quadmc::left_rectangle_rule{}.name()), "composite left rectangle");
  EXPECT_EQ(std::string(quadmc::simpson_rule{}.name()), "composite Simpson");
}

}  // namespace
