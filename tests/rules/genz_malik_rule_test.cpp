#include "quadmc/rules/genz_malik_rule.hpp"

#include "quadmc/core/rng.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <set>
#include <span>
#include <vector>

namespace {

using quadmc::test_support::eps;

// A polynomial Σ_m c_m Π_j x_j^{k_mj} with its exact integral over a box.
struct polynomial {
  std::vector<double> coefficient;
  std::vector<std::vector<int>> exponents;  // one row of s exponents per monomial

  double operator()(std::span<const double> x) const {
    double sum = 0.0;
    for (std::size_t m = 0; m < coefficient.size(); ++m) {
      double term = coefficient[m];
      for (std::size_t j = 0; j < x.size(); ++j) term *= std::pow(x[j], exponents[m][j]);
      sum += term;
    }
    return sum;
  }
  // Σ_m |c_m Π x_j^k|: the scale of the value's rounding error.
  double magnitude(std::span<const double> x) const {
    double sum = 0.0;
    for (std::size_t m = 0; m < coefficient.size(); ++m) {
      double term = std::abs(coefficient[m]);
      for (std::size_t j = 0; j < x.size(); ++j) term *= std::abs(std::pow(x[j], exponents[m][j]));
      sum += term;
    }
    return sum;
  }
  // ∫ over Π[a_j, b_j], and Σ_m |c_m Π ∫x^k| (the scale of its rounding).
  std::pair<double, double> integral(std::span<const double> a, std::span<const double> b) const {
    double sum = 0.0;
    double scale = 0.0;
    for (std::size_t m = 0; m < coefficient.size(); ++m) {
      double term = coefficient[m];
      for (std::size_t j = 0; j < a.size(); ++j) {
        const int k = exponents[m][j];
        term *= (std::pow(b[j], k + 1) - std::pow(a[j], k + 1)) / (k + 1);
      }
      sum += term;
      scale += std::abs(term);
    }
    return {sum, scale};
  }
};

// Every monomial of total degree exactly `degree` spread over random axes, plus lower ones, with
// coefficients in [−1, 1): a polynomial of that degree.
polynomial random_polynomial(std::size_t s, int degree, std::uint64_t seed) {
  const quadmc::random_stream rng(seed, 7);
  std::uint64_t index = 0;
  polynomial p;
  for (int d = 0; d <= degree; ++d) {
    for (int copy = 0; copy < 4; ++copy) {
      std::vector<int> k(s, 0);
      for (int i = 0; i < d; ++i) {
        ++k[static_cast<std::size_t>(rng.uniform(index++) * static_cast<double>(s))];
      }
      p.exponents.push_back(k);
      p.coefficient.push_back(2.0 * rng.uniform(index++) - 1.0);
    }
  }
  return p;
}

struct region_result {
  double q7 = 0.0;
  double q5 = 0.0;
  double exact = 0.0;
  double tolerance = 0.0;
};

// The rule on the box Π[a_j, b_j] for polynomial p. The tolerance is rounding, derived: each value
// has a relative error ≤ (8 + m)ε·Σ|monomials| (a product of ≤ 8 factors, a sum of m terms), the
// weighted sum adds (⌈log₂ n⌉ + 8)ε·Σ|w f| (pairwise sums, Higham §4.2, plus the few products),
// amplified by Σ|w| ≥ 1 because w₁ and w₃ are negative; the exact integral's own rounding is
// (2s + m + 8)ε·Σ|terms|. Twice their sum leaves room for the first-order bounds' higher terms.
region_result integrate_on_box(const quadmc::genz_malik_rule& rule, const polynomial& p,
                               std::span<const double> a, std::span<const double> b) {
  const std::size_t s = rule.dimension();
  std::vector<double> centre(s), half(s), x(s);
  double volume = 1.0;
  for (std::size_t j = 0; j < s; ++j) {
    centre[j] = 0.5 * (a[j] + b[j]);
    half[j] = 0.5 * (b[j] - a[j]);
    volume *= b[j] - a[j];
  }
  std::vector<double> f(rule.points());
  double largest = 0.0;
  for (std::uint64_t i = 0; i < rule.points(); ++i) {
    rule.node(i, centre, half, x);
    f[i] = p(x);
    largest = std::max(largest, p.magnitude(x));
  }
  region_result out;
  out.q7 = rule.combine(f, volume).value;
  out.q5 = rule.embedded_value(f, volume);
  const auto [exact, scale] = p.integral(a, b);
  out.exact = exact;
  const double m = static_cast<double>(p.coefficient.size());
  const double log_n = std::ceil(std::log2(static_cast<double>(rule.points())));
  out.tolerance =
      2.0 * ((8.0 + m + log_n + 8.0) * eps * volume * largest * rule.absolute_weight_sum() +
             (2.0 * static_cast<double>(s) + m + 8.0) * eps * scale);
  return out;
}

std::vector<double> random_box_corner(std::size_t s, std::uint64_t seed, double shift) {
  const quadmc::random_stream rng(seed, 11);
  std::vector<double> out(s);
  for (std::size_t j = 0; j < s; ++j) out[j] = shift + rng.uniform(j);
  return out;
}

// The 2^s + 2s² + 2s + 1 nodes are distinct, inside the box, and as many as points() says.
TEST(GenzMalikRule, HasTwoToTheSPlusTwoSSquaredPlusTwoSPlusOneDistinctNodes) {
  for (std::size_t s = 2; s <= 10; ++s) {
    const quadmc::genz_malik_rule rule(s);
    const std::uint64_t expected = (std::uint64_t{1} << s) + 2 * s * s + 2 * s + 1;
    EXPECT_EQ(rule.points(), expected) << "s = " << s;
    EXPECT_EQ(quadmc::genz_malik_rule::points_for(s), expected);
    const std::vector<double> centre(s, 0.0), half(s, 1.0);
    std::set<std::vector<double>> nodes;
    std::vector<double> x(s);
    for (std::uint64_t i = 0; i < rule.points(); ++i) {
      rule.node(i, centre, half, x);
      for (double v : x) {
        EXPECT_LT(std::abs(v), 1.0) << "s = " << s << ", node " << i;
      }
      nodes.insert(x);
    }
    EXPECT_EQ(nodes.size(), expected) << "s = " << s;
  }
}

// Degree 7 for the rule and 5 for the embedded one, on random polynomials over random boxes in
// s = 2…10; and not one degree more: x₀⁸ (x₀⁶ for the embedded rule) is integrated with an error
// far above rounding, so the degrees claimed are the true ones.
TEST(GenzMalikRule, IsExactForDegreeSevenAndItsEmbeddedRuleForDegreeFive) {
  for (std::size_t s = 2; s <= 10; ++s) {
    const quadmc::genz_malik_rule rule(s);
    for (std::uint64_t trial = 0; trial < 3; ++trial) {
      const std::vector<double> a = random_box_corner(s, 100 * s + trial, -1.0);
      std::vector<double> b = random_box_corner(s, 200 * s + trial, 0.0);
      for (std::size_t j = 0; j < s; ++j) b[j] += 0.5;  // b_j > a_j
      const region_result r7 =
          integrate_on_box(rule, random_polynomial(s, 7, 10 * s + trial), a, b);
      EXPECT_LE(std::abs(r7.q7 - r7.exact), r7.tolerance)
          << "degree 7, s = " << s << ", trial " << trial << ": " << r7.q7 << " vs " << r7.exact;
      const region_result r5 =
          integrate_on_box(rule, random_polynomial(s, 5, 30 * s + trial), a, b);
      EXPECT_LE(std::abs(r5.q5 - r5.exact), r5.tolerance)
          << "degree 5, s = " << s << ", trial " << trial << ": " << r5.q5 << " vs " << r5.exact;
      EXPECT_LE(std::abs(r5.q7 - r5.exact), r5.tolerance) << "degree 5 by the degree-7 rule";
    }
    std::vector<int> eighth(s, 0), sixth(s, 0);
    eighth[0] = 8;
    sixth[0] = 6;
    const std::vector<double> lo(s, -1.0), hi(s, 1.0);
    const region_result r8 = integrate_on_box(rule, polynomial{{1.0}, {eighth}}, lo, hi);
    EXPECT_GT(std::abs(r8.q7 - r8.exact), 1e6 * r8.tolerance) << "x0^8 exact at s = " << s;
    const region_result r6 = integrate_on_box(rule, polynomial{{1.0}, {sixth}}, lo, hi);
    EXPECT_GT(std::abs(r6.q5 - r6.exact), 1e6 * r6.tolerance) << "x0^6 exact for Q5, s = " << s;
  }
}

// The error estimate is |Q₇ − Q₅|, and the split axis is the one along which f bends most: for
// f = x_k⁴ (fourth difference only along k) it is k.
TEST(GenzMalikRule, SplitsAlongTheAxisOfLargestFourthDifference) {
  for (std::size_t s = 2; s <= 6; ++s) {
    const quadmc::genz_malik_rule rule(s);
    const std::vector<double> centre(s, 0.5), half(s, 0.5);
    for (std::size_t k = 0; k < s; ++k) {
      std::vector<double> f(rule.points()), x(s);
      for (std::uint64_t i = 0; i < rule.points(); ++i) {
        rule.node(i, centre, half, x);
        f[i] = std::pow(x[k] - 0.5, 4) + 0.1 * x[(k + 1) % s];  // the linear part bends nowhere
      }
      const quadmc::genz_malik_estimate e = rule.combine(f, 1.0);
      EXPECT_EQ(e.split_axis, k) << "s = " << s;
      EXPECT_EQ(e.error, std::abs(e.value - rule.embedded_value(f, 1.0)));
    }
  }
}

// nodes() writes runs of nodes in bulk (rows repeated, vertices by aligned blocks, a kernel per
// s ≤ 4); every run, wherever it starts and ends, must hold exactly node()'s doubles: a batch of
// adaptive_cubature.hpp can cut a region anywhere, and the results are bitwise those of node().
TEST(GenzMalikRule, NodesOfAnyRunAreBitwiseTheNodesOneByOne) {
  for (std::size_t s : {2u, 3u, 4u, 5u, 6u, 8u, 11u}) {
    const quadmc::genz_malik_rule rule(s);
    const std::uint64_t points = rule.points();
    const std::vector<double> centre = random_box_corner(s, 500 + s, -0.5);
    std::vector<double> half = random_box_corner(s, 600 + s, 0.0);
    for (double& h : half) h += 1e-3;
    std::vector<double> expected(points * s);
    for (std::uint64_t i = 0; i < points; ++i) {
      rule.node(i, centre, half, std::span<double>(expected.data() + i * s, s));
    }
    for (std::uint64_t run : {1ul, 2ul, 3ul, 5ul, 7ul, 16ul, 17ul, 100ul, 256ul, points}) {
      // Runs of `run` nodes from an offset, so that they start inside an axis's or a pair's four
      // nodes and at unaligned vertices.
      for (std::uint64_t offset : {0ul, 1ul, 2ul, 3ul}) {
        std::vector<double> got(points * s, -7.0);
        for (std::uint64_t first = 0; first < points;) {
          const std::uint64_t count = std::min(first == 0 ? offset + 1 : run, points - first);
          rule.nodes(first, static_cast<std::size_t>(count), centre, half, got.data() + first * s);
          first += count;
        }
        for (std::uint64_t k = 0; k < points * s; ++k) {
          ASSERT_EQ(std::bit_cast<std::uint64_t>(got[k]), std::bit_cast<std::uint64_t>(expected[k]))
              << "s = " << s << ", runs of " << run << " after " << offset + 1 << ", node " << k / s
              << ", coordinate " << k % s;
        }
      }
    }
  }
}

TEST(GenzMalikRule, RefusesDimensionsItIsNotBuiltFor) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] { quadmc::genz_malik_rule rule(1); }, "between 2 and 40"));
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] { quadmc::genz_malik_rule rule(41); }, "between 2 and 40"));
}

}  // namespace
