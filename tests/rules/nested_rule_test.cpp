// nested_rule: the Clenshaw–Curtis, Gauss–Patterson and periodic trapezoid tables — node counts,
// nesting, weights (against quadrule's independent Clenshaw–Curtis code), degree of exactness,
// and the by-node tables of weights and differences against the by-level ones.
#include "quadmc/rules/nested_rule.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

extern "C" {
#include <quadrule.h>
}

namespace {

using namespace quadmc;

using quadmc::test_support::eps;
constexpr nested_rule_kind all_kinds[] = {nested_rule_kind::clenshaw_curtis,
                                          nested_rule_kind::gauss_patterson,
                                          nested_rule_kind::trapezoid};

// Σ_i w_i·f(t_i) for the rule of level l, compensated-free: the rules have ≤ 65536 nodes and
// positive weights, so the naive sum errs by ≤ n·ε·Σ|w f| — the bounds below allow for it.
template <class F>
double apply(const nested_rule& rule, unsigned l, F f) {
  double sum = 0.0;
  for (std::size_t id = 0; id < rule.count(l); ++id) sum += rule.weight(l, id) * f(rule.node(id));
  return sum;
}

TEST(NestedRule, CountsPerLevelAreThePublishedSequences) {
  const nested_rule& cc = nested_rule_table(nested_rule_kind::clenshaw_curtis);
  const nested_rule& gp = nested_rule_table(nested_rule_kind::gauss_patterson);
  const nested_rule& tr = nested_rule_table(nested_rule_kind::trapezoid);
  EXPECT_EQ(cc.max_level(), 14u);
  EXPECT_EQ(gp.max_level(), 7u);
  EXPECT_EQ(tr.max_level(), 16u);
  EXPECT_EQ(cc.count(0), 1u);
  for (unsigned l = 1; l <= cc.max_level(); ++l) EXPECT_EQ(cc.count(l), (1u << l) + 1) << l;
  for (unsigned l = 0; l <= gp.max_level(); ++l) EXPECT_EQ(gp.count(l), (2u << l) - 1) << l;
  for (unsigned l = 0; l <= tr.max_level(); ++l) EXPECT_EQ(tr.count(l), 1u << l) << l;
}

TEST(NestedRule, NodesAreDistinctInTheCubeAndBornInOrder) {
  for (const nested_rule_kind kind : all_kinds) {
    const nested_rule& rule = nested_rule_table(kind);
    const std::size_t n = rule.count(rule.max_level());
    std::vector<double> nodes;
    for (std::size_t id = 0; id < n; ++id) {
      const double t = rule.node(id);
      EXPECT_TRUE(t >= 0.0 && t <= 1.0) << to_string(kind) << " id " << id << ": " << t;
      nodes.push_back(t);
      const unsigned b = rule.birth(id);
      EXPECT_LT(id, rule.count(b));
      if (b > 0) {
        EXPECT_GE(id, rule.count(b - 1));
      }
    }
    std::sort(nodes.begin(), nodes.end());
    EXPECT_EQ(std::adjacent_find(nodes.begin(), nodes.end()), nodes.end()) << to_string(kind);
  }
}

TEST(NestedRule, ClenshawCurtisWeightsAgreeWithQuadruleAndAreSymmetric) {
  // quadrule's clenshaw_curtis_compute is an independent code (its own cosine sums on
  // [−1, 1]); both sides are sorted by node, t = (1 + x)/2.
  const nested_rule& cc = nested_rule_table(nested_rule_kind::clenshaw_curtis);
  for (unsigned l = 1; l <= 10; ++l) {
    const int order = (1 << l) + 1;
    std::vector<double> x(order), w(order);
    clenshaw_curtis_compute(order, x.data(), w.data());
    std::vector<std::pair<double, double>> theirs;  // quadrule lists x = cos(kπ/n), decreasing
    for (int i = 0; i < order; ++i) theirs.emplace_back(0.5 * (1.0 + x[i]), 0.5 * w[i]);
    std::sort(theirs.begin(), theirs.end());
    std::vector<std::pair<double, double>> ours;
    for (std::size_t id = 0; id < cc.count(l); ++id)
      ours.emplace_back(cc.node(id), cc.weight(l, id));
    std::sort(ours.begin(), ours.end());
    for (int i = 0; i < order; ++i) {
      EXPECT_NEAR(ours[i].first, theirs[i].first, 4 * eps) << "level " << l << " node " << i;
      // Weights are ≥ 1/(n² − 1) and computed by sums of O(n) terms of size ≤ 1: a few ulp of
      // 1/n each way, 64ε/n in all.
      EXPECT_NEAR(ours[i].second, theirs[i].second, 64 * eps / order)
          << "level " << l << " weight " << i;
      EXPECT_EQ(ours[i].second, ours[order - 1 - i].second) << "level " << l << " symmetry " << i;
    }
  }
}

TEST(NestedRule, WeightsArePositiveAndSumToOne) {
  for (const nested_rule_kind kind : all_kinds) {
    const nested_rule& rule = nested_rule_table(kind);
    for (unsigned l = 0; l <= rule.max_level(); ++l) {
      double sum = 0.0;
      for (const double w : rule.weights(l)) {
        EXPECT_GT(w, 0.0);
        sum += w;
      }
      const auto n = static_cast<double>(rule.count(l));
      EXPECT_NEAR(sum, 1.0, n * eps) << to_string(kind) << " level " << l;
    }
  }
}

// ∫₀¹ (2t − 1)^d dt = 1/(d + 1) for even d, 0 for odd d: monomials centred on the interval keep
// the values O(1) at high degree, so exactness is seen to a few ulp.
double centred_moment(unsigned d) {
  return d % 2 == 0 ? 1.0 / (d + 1.0) : 0.0;
}

TEST(NestedRule, DegreeOfExactnessIsAttainedAndSharp) {
  for (const nested_rule_kind kind :
       {nested_rule_kind::clenshaw_curtis, nested_rule_kind::gauss_patterson}) {
    const nested_rule& rule = nested_rule_table(kind);
    for (unsigned l = 0; l <= std::min(rule.max_level(), 7u); ++l) {
      const unsigned degree = rule.degree(l);
      for (unsigned d = 0; d <= degree + 2; ++d) {
        const double q = apply(rule, l, [d](double t) { return std::pow(2.0 * t - 1.0, d); });
        const double error = std::abs(q - centred_moment(d));
        const double allowed = 8.0 * static_cast<double>(rule.count(l)) * eps;
        if (d <= degree) {
          EXPECT_LE(error, allowed) << to_string(kind) << " level " << l << " degree " << d;
        } else if (d % 2 == 0 && l <= 3) {
          // The first even degree past the rule's: not exact (odd ones vanish by symmetry). At
          // higher levels (2t − 1)^d is negligible but near the ends and the rule's error is
          // below any clear threshold.
          EXPECT_GT(error, 1e3 * allowed) << to_string(kind) << " level " << l << " degree " << d;
        }
      }
    }
  }
}

TEST(NestedRule, PeriodicTrapezoidIsExactForTrigonometricPolynomialsBelowItsNodeCount) {
  const nested_rule& rule = nested_rule_table(nested_rule_kind::trapezoid);
  for (unsigned l = 0; l <= 8; ++l) {
    const std::uint64_t n = rule.count(l);
    for (std::uint64_t k = 1; k <= n; ++k) {
      const double q = apply(rule, l, [k](double t) {
        return std::cos(2.0 * std::numbers::pi * static_cast<double>(k) * t);
      });
      // ∫cos(2πkt) = 0 for k ≥ 1; the rule gives 0 for k < n, and 1 at k = n (aliasing).
      EXPECT_NEAR(q, k < n ? 0.0 : 1.0, 8.0 * static_cast<double>(n) * eps) << l << " " << k;
    }
  }
}

TEST(NestedRule, NamesRoundTrip) {
  for (const nested_rule_kind kind : all_kinds) {
    EXPECT_EQ(parse_nested_rule_kind(to_string(kind)), kind);
  }
  EXPECT_FALSE(parse_nested_rule_kind("gauss_legendre").has_value());
}

// The by-node tables are the by-level weights and their differences bit for bit (the walk of
// smolyak_grid.hpp reads them in place of the subtraction it made at every visit), and the
// differences telescope: Σ_{m ≤ l − b} d_(b+m) = weight(l, id), to the rounding of the l − b + 1
// additions (each at most ε·Σ|d|/2: Higham, "Accuracy and Stability of Numerical Algorithms",
// 2nd ed., §4.2; the bound below is (l − b + 1)·ε·Σ|d|).
TEST(NestedRule, ByNodeTablesAreTheByLevelWeightsAndTheirDifferences) {
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  for (const nested_rule_kind kind : all_kinds) {
    const nested_rule& rule = nested_rule_table(kind);
    const unsigned top = rule.max_level();
    for (std::size_t id = 0; id < rule.count(top); ++id) {
      const unsigned b = rule.birth(id);
      const double* w = rule.weights_from_birth(id);
      const double* d = rule.differences_from_birth(id);
      ASSERT_EQ(bits(d[0]), bits(rule.weight(b, id))) << to_string(kind) << " id " << id;
      double sum = 0.0, magnitude = 0.0;
      for (unsigned l = b; l <= top; ++l) {
        const unsigned m = l - b;
        ASSERT_EQ(bits(w[m]), bits(rule.weight(l, id))) << to_string(kind) << " id " << id;
        if (m > 0) {
          ASSERT_EQ(bits(d[m]), bits(rule.weight(l, id) - rule.weight(l - 1, id)))
              << to_string(kind) << " id " << id << " level " << l;
        }
        sum += d[m];
        magnitude += std::abs(d[m]);
        ASSERT_LE(std::abs(sum - rule.weight(l, id)), (m + 1) * eps * magnitude)
            << to_string(kind) << " id " << id << " level " << l;
        // The by-birth table holds the same bits, contiguous over the nodes born at b.
        const std::size_t k = id - (b == 0 ? 0 : static_cast<std::size_t>(rule.count(b - 1)));
        ASSERT_EQ(bits(rule.differences_by_birth(b, m)[k]), bits(d[m]))
            << to_string(kind) << " id " << id << " level " << l;
      }
    }
  }
}

}  // namespace
