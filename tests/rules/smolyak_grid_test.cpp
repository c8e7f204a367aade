// smolyak_grid: the Smolyak sparse grid as a weighted point set — point counts, the weights
// against the combination technique built independently, exactness for total degree ≤ 2L + 1
// [Novak & Ritter 1996], thread and batch independence, distinct nodes in the cube, the fast
// path, the weights bit for bit those of the surplus formula on the by-level tables, and Σ|w|
// with the rounding floor it implies.
#include "quadmc/rules/smolyak_grid.hpp"

#include "quadmc/rules/weighted_sum.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <span>
#include <utility>
#include <vector>

namespace {

using namespace quadmc;

constexpr double eps = std::numeric_limits<double>::epsilon();

const nested_rule& cc() {
  return nested_rule_table(nested_rule_kind::clenshaw_curtis);
}

struct grid_points {
  std::vector<double> x;
  std::vector<double> w;
};

grid_points all_points(const smolyak_grid& g) {
  grid_points p;
  p.x.resize(g.size() * g.dimension());
  p.w.resize(g.size());
  g.generate(0, p.x, p.w);
  return p;
}

// The combination technique, independently of the grid's surplus form: A(L, s) =
// Σ_{L−s+1 ≤ |l| ≤ L} (−1)^(L−|l|)·C(s − 1, L − |l|)·U^(l_1) ⊗ … ⊗ U^(l_s) (the combination
// form of the Smolyak rule, docs/theory.md#smolyak-construction), weights merged per node.
std::map<std::vector<std::size_t>, double> combination_technique(const nested_rule& rule,
                                                                 std::size_t s, unsigned L) {
  std::map<std::vector<std::size_t>, double> weight;
  std::vector<unsigned> l(s, 0);
  auto binomial = [](unsigned n, unsigned k) {
    double c = 1.0;
    for (unsigned i = 1; i <= k; ++i) c = c * (n - k + i) / i;
    return c;
  };
  while (true) {
    unsigned total = 0;
    for (unsigned v : l) total += v;
    if (total <= L && total + s >= L + 1) {
      const unsigned q = L - total;
      const double coefficient = (q % 2 == 0 ? 1.0 : -1.0) * binomial(s - 1, q);
      std::vector<std::size_t> id(s, 0);
      while (true) {
        double w = coefficient;
        for (std::size_t j = 0; j < s; ++j) w *= rule.weight(l[j], id[j]);
        weight[id] += w;
        std::size_t j = s;
        while (j-- > 0) {
          if (++id[j] < rule.count(l[j])) break;
          id[j] = 0;
        }
        if (j == static_cast<std::size_t>(-1)) break;
      }
    }
    std::size_t j = s;
    while (j-- > 0) {
      if (++l[j] <= L) break;
      l[j] = 0;
    }
    if (j == static_cast<std::size_t>(-1)) break;
  }
  return weight;
}

TEST(SmolyakGrid, ClenshawCurtisCountsInTwoDimensionsAreThePublishedOnes) {
  // The Clenshaw–Curtis counts of [Gerstner & Griebel 1998] and [Novak & Ritter 1996]: 1, 5,
  // 13, 29, 65, 145.
  const std::uint64_t published[] = {1, 5, 13, 29, 65, 145, 321, 705, 1537};
  for (unsigned L = 0; L < std::size(published); ++L) {
    EXPECT_EQ(smolyak_point_count(cc(), 2, L), published[L]) << "L = " << L;
    EXPECT_EQ(smolyak_grid(cc(), 2, L).size(), published[L]);
  }
  // One axis: the 1D rule itself.
  for (unsigned L = 0; L <= cc().max_level(); ++L) {
    EXPECT_EQ(smolyak_point_count(cc(), 1, L), cc().count(L));
  }
}

TEST(SmolyakGrid, NodesAndWeightsAreThoseOfTheCombinationTechnique) {
  for (const nested_rule_kind kind :
       {nested_rule_kind::clenshaw_curtis, nested_rule_kind::gauss_patterson,
        nested_rule_kind::trapezoid}) {
    const nested_rule& rule = nested_rule_table(kind);
    for (std::size_t s = 1; s <= 4; ++s) {
      for (unsigned L = 0; L <= std::min(rule.max_level(), 5u); ++L) {
        const auto reference = combination_technique(rule, s, L);
        const smolyak_grid g(rule, s, L);
        ASSERT_EQ(g.size(), reference.size()) << to_string(kind) << " s " << s << " L " << L;
        const grid_points p = all_points(g);
        double scale = 0.0;
        for (const auto& [id, w] : reference) scale += std::abs(w);
        std::map<std::vector<double>, double> by_node;
        for (const auto& [id, w] : reference) {
          std::vector<double> t;
          for (const std::size_t i : id) t.push_back(rule.node(i));
          by_node[t] = w;
        }
        for (std::size_t i = 0; i < g.size(); ++i) {
          const std::vector<double> t(p.x.begin() + i * s, p.x.begin() + (i + 1) * s);
          const auto it = by_node.find(t);
          ASSERT_NE(it, by_node.end()) << to_string(kind) << " s " << s << " L " << L << " i " << i;
          // Both are sums of ≤ 3^s·L products of weights ≤ 1: 64ε of Σ|w| covers their rounding.
          EXPECT_NEAR(p.w[i], it->second, 64 * eps * scale)
              << to_string(kind) << " s " << s << " L " << L << " i " << i;
        }
      }
    }
  }
}

TEST(SmolyakGrid, NodesAreDistinctAndInTheCube) {
  for (const auto& [s, L] : std::vector<std::pair<std::size_t, unsigned>>{{2, 8}, {5, 5}, {8, 4}}) {
    const smolyak_grid g(cc(), s, L);
    const grid_points p = all_points(g);
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < g.size(); ++i) {
      rows.emplace_back(p.x.begin() + i * s, p.x.begin() + (i + 1) * s);
      for (const double t : rows.back()) EXPECT_TRUE(t >= 0.0 && t <= 1.0);
    }
    std::sort(rows.begin(), rows.end());
    EXPECT_EQ(std::adjacent_find(rows.begin(), rows.end()), rows.end()) << s << " " << L;
  }
}

// Σ_i w_i Π_j (2x_ij − 1)^α_j against its exact value Π_j m(α_j), m the centred moment
// (1/(α + 1) for even α, 0 for odd): every monomial of total degree ≤ 2L + 1.
TEST(SmolyakGrid, ClenshawCurtisIsExactForTotalDegreeTwoLPlusOne) {
  const std::vector<std::pair<std::size_t, unsigned>> cases = {{2, 6}, {3, 5}, {4, 5}, {5, 4},
                                                               {6, 4}, {7, 3}, {8, 3}};
  for (const auto& [s, L] : cases) {
    const smolyak_grid g(cc(), s, L);
    const grid_points p = all_points(g);
    const unsigned degree = 2 * L + 1;
    double abs_weights = 0.0;
    for (const double w : p.w) abs_weights += std::abs(w);
    // powers[(i·s + j)·(degree + 3) + a] = (2x_ij − 1)^a, to degree 2L + 2 for the sharpness check.
    const unsigned width = degree + 2;
    std::vector<double> powers(g.size() * s * width);
    for (std::size_t i = 0; i < g.size() * s; ++i) {
      double v = 1.0;
      for (unsigned a = 0; a < width; ++a) {
        powers[i * width + a] = v;
        v *= 2.0 * p.x[i] - 1.0;
      }
    }
    auto error_of = [&](const std::vector<unsigned>& alpha) {
      neumaier_sum q;
      for (std::size_t i = 0; i < g.size(); ++i) {
        double f = p.w[i];
        for (std::size_t j = 0; j < s; ++j) f *= powers[(i * s + j) * width + alpha[j]];
        q.add(f);
      }
      double exact = 1.0;
      for (const unsigned a : alpha) exact *= a % 2 == 0 ? 1.0 / (a + 1.0) : 0.0;
      return std::abs(q.value() - exact);
    };
    // Every |f| ≤ 1 at the nodes, so rounding in the weights and the products costs at most a
    // few ulp of Σ|w|: 16ε·Σ|w| ("to a few ulp" of the sum's own scale).
    const double allowed = 16 * eps * abs_weights;
    std::vector<unsigned> alpha(s, 0);
    std::size_t monomials = 0;
    double worst = 0.0;
    while (true) {
      unsigned total = 0;
      for (unsigned a : alpha) total += a;
      if (total <= degree) {
        worst = std::max(worst, error_of(alpha));
        ++monomials;
      }
      std::size_t j = s;
      while (j-- > 0) {
        if (++alpha[j] <= degree) break;
        alpha[j] = 0;
      }
      if (j == static_cast<std::size_t>(-1)) break;
    }
    EXPECT_LE(worst, allowed) << "s " << s << " L " << L << " (" << monomials << " monomials)";
    // Sharp: Π_{j ≤ L} (2x_j − 1)², degree 2L + 2, needs L + 1 axes at level ≥ 1, which no term
    // of the grid has.
    if (s >= L + 1) {
      std::vector<unsigned> beyond(s, 0);
      for (std::size_t j = 0; j <= L; ++j) beyond[j] = 2;
      EXPECT_GT(error_of(beyond), 1e6 * allowed) << "s " << s << " L " << L;
    }
  }
}

TEST(SmolyakGrid, WeightsSumToOne) {
  for (const nested_rule_kind kind :
       {nested_rule_kind::clenshaw_curtis, nested_rule_kind::gauss_patterson,
        nested_rule_kind::trapezoid}) {
    for (std::size_t s = 2; s <= 8; ++s) {
      for (unsigned L = 0; L <= 4; ++L) {
        const smolyak_grid g(nested_rule_table(kind), s, L);
        const grid_points p = all_points(g);
        neumaier_sum sum;
        double abs_sum = 0.0;
        for (const double w : p.w) {
          sum.add(w);
          abs_sum += std::abs(w);
        }
        EXPECT_NEAR(sum.value(), 1.0, 16 * eps * abs_sum)
            << to_string(kind) << " s " << s << " L " << L;
      }
    }
  }
}

// The weight of the surplus form, w(x) = Σ_{u ≤ R} P[u]·C(R − u) (smolyak_grid.hpp), computed
// here from the by-level tables alone, in the order the header documents: P_{j+1}[t] =
// Σ_{m ≤ t} P_j[t − m]·(weight(b + m) − weight(b + m − 1)) for the leading axes, then the last
// axis. The walk reads the by-node tables and copies coordinates by fixed-length moves; this
// pins that its weights are this formula bit for bit, in every dimension the copy is specialised
// for and beyond (s = 17: the loop), and that each node is visited once.
double surplus_weight(const nested_rule& rule, const std::vector<std::size_t>& id, unsigned L) {
  const std::size_t s = id.size();
  std::vector<double> product(L + 1, 0.0);
  product[0] = 1.0;
  unsigned budget = L;
  for (std::size_t j = 0; j + 1 < s; ++j) {
    const unsigned b = rule.birth(id[j]);
    const unsigned rest = budget - b;
    std::vector<double> next(L + 1, 0.0);
    for (unsigned t = 0; t <= rest; ++t) {
      double sum = 0.0;
      for (unsigned m = 0; m <= t; ++m) {
        const double previous = m > 0 ? rule.weight(b + m - 1, id[j]) : 0.0;
        sum += product[t - m] * (rule.weight(b + m, id[j]) - previous);
      }
      next[t] = sum;
    }
    product = next;
    budget = rest;
  }
  const std::size_t node = id[s - 1];
  const unsigned b = rule.birth(node);
  const unsigned R = budget - b;
  double w = 0.0;
  for (unsigned u = 0; u <= R; ++u) w += product[u] * rule.weight(b + R - u, node);
  return w;
}

TEST(SmolyakGrid, WeightsAreTheSurplusFormulaBitForBitAndEachNodeComesOnce) {
  for (const nested_rule_kind kind :
       {nested_rule_kind::clenshaw_curtis, nested_rule_kind::gauss_patterson,
        nested_rule_kind::trapezoid}) {
    const nested_rule& rule = nested_rule_table(kind);
    std::map<double, std::size_t> id_of;  // a node's coordinate → its id
    for (std::size_t id = 0; id < rule.count(rule.max_level()); ++id) id_of[rule.node(id)] = id;
    for (const auto& [s, L] : {std::pair<std::size_t, unsigned>{1, 7},
                               {2, 6},
                               {3, 5},
                               {5, 4},
                               {8, 4},
                               {16, 2},
                               {17, 2}}) {
      const smolyak_grid g(rule, s, L);
      const grid_points p = all_points(g);
      std::map<std::vector<std::size_t>, int> visits;
      for (std::uint64_t i = 0; i < g.size(); ++i) {
        std::vector<std::size_t> id(s);
        unsigned births = 0;
        for (std::size_t j = 0; j < s; ++j) {
          const auto it = id_of.find(p.x[i * s + j]);
          ASSERT_NE(it, id_of.end()) << "s " << s << " point " << i << " axis " << j;
          id[j] = it->second;
          births += rule.birth(id[j]);
        }
        ASSERT_LE(births, L) << "s " << s << " point " << i;
        ASSERT_EQ(std::bit_cast<std::uint64_t>(p.w[i]),
                  std::bit_cast<std::uint64_t>(surplus_weight(rule, id, L)))
            << to_string(kind) << " s " << s << " L " << L << " point " << i;
        ++visits[id];
      }
      // Every tuple visited once, and as many tuples as the grid has nodes.
      for (const auto& [tuple, n] : visits) ASSERT_EQ(n, 1) << to_string(kind) << " s " << s;
      EXPECT_EQ(visits.size(), g.size()) << to_string(kind) << " s " << s;
    }
  }
}

TEST(SmolyakGrid, AnyBatchStartGivesTheSameNodesAndWeights) {
  const smolyak_grid g(cc(), 4, 6);
  const grid_points p = all_points(g);
  std::vector<double> x(4), w(1);
  for (std::uint64_t i = 0; i < g.size(); ++i) {
    g.generate(i, x, w);
    for (std::size_t j = 0; j < 4; ++j) ASSERT_EQ(x[j], p.x[i * 4 + j]) << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(w[0]), std::bit_cast<std::uint64_t>(p.w[i])) << i;
  }
}

struct product_exp {
  std::size_t s;
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      double v = 0.0;
      for (std::size_t j = 0; j < s; ++j) v += x[i * s + j] * (0.5 + 0.1 * j);
      y[i] = std::exp(v);
    }
  }
  integrand_info info() const {
    integrand_info i;
    i.name = "product_exp";
    i.domain = box{std::vector<double>(s, -1.0), std::vector<double>(s, 2.0)};
    return i;
  }
};

TEST(SmolyakGrid, SumIsBitwiseTheSameForAnyThreadCountAndThroughTheFastPath) {
  const smolyak_grid g(cc(), 4, 10);  // several chunks of 2^14 points
  ASSERT_GT(g.size(), 3u * 16384u);
  const product_exp f{4};
  const double one = weighted_sum(f, g, 1).value;
  for (const unsigned threads : {2u, 3u, 8u}) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(weighted_sum(f, g, threads).value),
              std::bit_cast<std::uint64_t>(one))
        << threads;
  }
  // mapped() writes box coordinates: bitwise what generate() and the kernel's map give.
  const cube_to_box map(f.info().domain);
  const auto on_box = g.mapped(map);
  std::vector<double> x1(256 * 4), w1(256), x2(256 * 4), w2(256);
  for (std::uint64_t first = 0; first + 256 <= g.size(); first += 7919) {
    g.generate(first, x1, w1);
    map.apply(x1);
    on_box.generate(first, x2, w2);
    ASSERT_EQ(x1, x2) << first;
    ASSERT_EQ(w1, w2) << first;
  }
}

// The levels the default scene's "dimension" section uses (Clenshaw–Curtis, N ≤ 2^20): Σ|w|/|Σw|
// and the rounding floor it implies. The compensated sum errs by ≈ 2ε·Σ|w f| and an error δ in
// each f by Σ|w|·δ (weighted_point_set.hpp), so the floor of analysis/rounding_floor.hpp is
// scaled by Σ|w|·|I|, not |I|. Shown for each level; checked on a polynomial the grid integrates
// exactly, whose error is then all rounding: it stays below ℓ(N) = 2ε·Σ|w|·|I|·log₂N.
TEST(SmolyakGrid, AbsoluteWeightSumAndTheRoundingFloorItImplies) {
  std::cout << "   s   L          N     Σ|w|/|Σw|   floor ℓ(N)/|I|\n";
  double largest = 0.0;
  for (const std::size_t s : {2u, 4u, 8u, 16u}) {
    for (unsigned L = 0; L <= cc().max_level(); ++L) {
      const auto n = smolyak_point_count(cc(), s, L);
      if (!n || *n > (1u << 20)) break;
      const smolyak_grid g(cc(), s, L);
      const double ratio = g.absolute_weight_sum();  // Σw = 1
      largest = std::max(largest, ratio);
      const double floor = 2 * eps * ratio * std::max(1.0, std::log2(static_cast<double>(*n)));
      std::cout << fmt::format("{:4} {:3} {:10} {:13.6g} {:16.3g}\n", s, L, *n, ratio, floor);
      EXPECT_GE(ratio, 1.0 - 1e-12);
      // f = 1 + Π_j (2x_j − 1)²·3^(s/2)/2^s-free: a polynomial of degree 2s … use degree ≤ 2L+1.
      struct quadratic {
        std::size_t s;
        std::size_t dimension() const { return s; }
        void evaluate(std::span<const double> x, std::span<double> y) const {
          for (std::size_t i = 0; i < y.size(); ++i) {
            double v = 1.0 / 3.0;
            for (std::size_t j = 0; j < s; ++j)
              v += (2 * x[i * s + j] - 1) * (2 * x[i * s + j] - 1);
            y[i] = v;
          }
        }
        integrand_info info() const {
          integrand_info i;
          i.name = "quadratic";
          i.domain = box::unit(s);
          return i;
        }
      };
      if (L >= 1) {  // degree 2 needs 2L + 1 ≥ 2
        const double exact = 1.0 / 3.0 + static_cast<double>(s) / 3.0;
        const double q = weighted_sum(quadratic{s}, g, 2).value;
        EXPECT_LE(std::abs(q - exact), floor * exact) << "s " << s << " L " << L;
      }
    }
  }
  // The signed weights matter: some level of the section has Σ|w| well above 1.
  EXPECT_GT(largest, 2.0);
}

TEST(SmolyakGrid, RejectsALevelAboveTheTablesAndACountBeyond64Bits) {
  EXPECT_TRUE(quadmc::testing::throws_with<invalid_argument>([] { smolyak_grid(cc(), 2, 15); },
                                                             "at most 14"));
  EXPECT_TRUE(quadmc::testing::throws_with<invalid_argument>([] { smolyak_grid(cc(), 0, 1); },
                                                             "dimension s"));
  EXPECT_FALSE(smolyak_point_count(cc(), 4096, 14).has_value());
  EXPECT_TRUE(quadmc::testing::throws_with<invalid_argument>([] { smolyak_grid(cc(), 4096, 14); },
                                                             "fits in 64 bits"));
}

}  // namespace
