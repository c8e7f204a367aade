// smolyak_grid: the Smolyak sparse grid as a weighted point set — point counts, the weights
// against the combination technique built independently, exactness for total degree ≤ 2L + 1
// [Novak & Ritter 1996], thread and batch independence, distinct nodes in the cube, the fast
// path, the weights bit for bit those of the documented block formula on the by-level tables,
// their agreement with the previous walk's within a derived rounding bound, and Σ|w| with the
// rounding floor it implies.
#include "quadmc/rules/smolyak_grid.hpp"

#include "clenshaw_curtis_table.hpp"
#include "quadmc/rules/weighted_sum.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <utility>
#include <vector>

namespace {

using namespace quadmc;

using quadmc::test_support::eps;

using quadmc::testing::cc;

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
  for (const auto& c : cases) {
    // Named copies, not a structured binding: the lambdas below use s, and clang 14 (the sanitize
    // build's compiler) cannot capture structured bindings yet.
    const std::size_t s = c.first;
    const unsigned L = c.second;
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

// The leading product P = Π_{j<m} A_j truncated to degree ≤ budget (smolyak_grid.hpp), from the
// by-level tables alone: P_{j+1}[t] = Σ_{k ≤ t} P_j[t − k]·(weight(b + k) − weight(b + k − 1)),
// summed from zero in ascending k, in double. Returns the budget left for the axes after m.
unsigned leading_product(const nested_rule& rule, const std::vector<std::size_t>& id, std::size_t m,
                         unsigned L, std::vector<double>& product) {
  product.assign(L + 1, 0.0);
  product[0] = 1.0;
  unsigned budget = L;
  for (std::size_t j = 0; j < m; ++j) {
    const unsigned b = rule.birth(id[j]);
    const unsigned rest = budget - b;
    std::vector<double> next(L + 1, 0.0);
    for (unsigned t = 0; t <= rest; ++t) {
      double sum = 0.0;
      for (unsigned k = 0; k <= t; ++k) {
        const double previous = k > 0 ? rule.weight(b + k - 1, id[j]) : 0.0;
        sum += product[t - k] * (rule.weight(b + k, id[j]) - previous);
      }
      next[t] = sum;
    }
    product = next;
    budget = rest;
  }
  return budget;
}

// The weight of the previous walk, which multiplied out all s axes in double: P over the s − 1
// leading axes, then w(x) = Σ_{u ≤ R} P[u]·C(R − u), C(t) the last node's weight in U^(b + t).
// For d = 1 (s ≤ 2) the grid's weights are still these, bit for bit.
double previous_walk_weight(const nested_rule& rule, const std::vector<std::size_t>& id,
                            unsigned L) {
  std::vector<double> product;
  const std::size_t s = id.size();
  const unsigned budget = leading_product(rule, id, s - 1, L, product);
  const std::size_t node = id[s - 1];
  const unsigned b = rule.birth(node);
  const unsigned R = budget - b;
  double w = 0.0;
  for (unsigned u = 0; u <= R; ++u) w += product[u] * rule.weight(b + R - u, node);
  return w;
}

// T_l of the block node with ids `block` (smolyak_block.hpp), rebuilt from the by-level tables in
// the order the header documents: δ_c[k] = w(b_c + k) − w(b_c + k − 1) in long double, the
// product's coefficients summed from zero in ascending k, the partial sums in ascending v, each
// rounded once. Returns T_l for l = t … L at [l] (NaN below the node's shell t).
std::vector<double> block_table_weights(const nested_rule& rule,
                                        const std::vector<std::size_t>& block, unsigned L) {
  unsigned t = 0;
  for (const std::size_t i : block) t += rule.birth(i);
  const unsigned degree = L - t;
  std::vector<long double> coefficient(degree + 1, 0.0L), next(degree + 1), delta(degree + 1);
  coefficient[0] = 1.0L;
  for (const std::size_t i : block) {
    const unsigned b = rule.birth(i);
    for (unsigned k = 0; k <= degree; ++k) {
      const long double below = k == 0 ? 0.0L : static_cast<long double>(rule.weight(b + k - 1, i));
      delta[k] = static_cast<long double>(rule.weight(b + k, i)) - below;
    }
    for (unsigned v = 0; v <= degree; ++v) {
      long double sum = 0.0L;
      for (unsigned k = 0; k <= v; ++k) sum += coefficient[v - k] * delta[k];
      next[v] = sum;
    }
    coefficient = next;
  }
  std::vector<double> T(L + 1, std::numeric_limits<double>::quiet_NaN());
  long double partial = 0.0L;
  for (unsigned v = 0; v <= degree; ++v) {
    partial += coefficient[v];
    T[t + v] = static_cast<double>(partial);
  }
  return T;
}

// The grid's documented weight for a block of the last d axes (smolyak_grid.hpp): w = 0.0 +
// P[0]·T_r + P[1]·T_(r−1) + …, u ascending, over the u with T_(r−u) defined and P[u] ≠ 0. For
// d = 1, T_l is the 1D weight of level l.
double block_walk_weight(const nested_rule& rule, const std::vector<std::size_t>& id, unsigned L,
                         std::size_t d) {
  std::vector<double> product;
  const std::size_t m = id.size() - d;
  const unsigned r = leading_product(rule, id, m, L, product);
  const std::vector<std::size_t> block(id.begin() + static_cast<std::ptrdiff_t>(m), id.end());
  std::vector<double> T(L + 1, std::numeric_limits<double>::quiet_NaN());
  if (d == 1) {
    for (unsigned l = rule.birth(block[0]); l <= L; ++l) T[l] = rule.weight(l, block[0]);
  } else {
    T = block_table_weights(rule, block, L);
  }
  double w = 0.0 + product[0] * T[r];
  for (unsigned u = 1; u <= r; ++u) {
    if (std::isnan(T[r - u])) break;
    if (product[u] != 0.0) w += product[u] * T[r - u];
  }
  return w;
}

// |w|(x) = Σ_{k ≥ b, |k|₁ ≤ L} Π_j |d_{k_j}(x_j)|: the sum of the magnitudes of the terms every
// evaluation order adds (the exact differences of the tables' weights, in long double).
long double absolute_terms(const nested_rule& rule, const std::vector<std::size_t>& id,
                           unsigned L) {
  unsigned t = 0;
  for (const std::size_t i : id) t += rule.birth(i);
  const unsigned degree = L - t;
  std::vector<long double> coefficient(degree + 1, 0.0L), next(degree + 1);
  coefficient[0] = 1.0L;
  for (const std::size_t i : id) {
    const unsigned b = rule.birth(i);
    for (unsigned v = 0; v <= degree; ++v) {
      long double sum = 0.0L;
      for (unsigned k = 0; k <= v; ++k) {
        const long double below =
            k == 0 ? 0.0L : static_cast<long double>(rule.weight(b + k - 1, i));
        sum +=
            coefficient[v - k] * std::abs(static_cast<long double>(rule.weight(b + k, i)) - below);
      }
      next[v] = sum;
    }
    coefficient = next;
  }
  long double total = 0.0L;
  for (const long double c : coefficient) total += c;
  return total;
}

// The block size d the header documents: the largest of 2 and 3 with d ≤ s and N_d(L) ≤ the cap
// (d = s: the whole grid is the block).
std::size_t documented_block_axes(const nested_rule& rule, std::size_t s, unsigned L) {
  std::size_t d = 1;
  for (std::size_t c = 2; c <= 3; ++c) {
    const auto n = smolyak_point_count(rule, c, L);
    if (c <= s && n && *n <= smolyak_block::block_nodes_cap) d = c;
  }
  return d;
}

// Each point's ids (via its coordinates), checked to be a node of the grid.
std::vector<std::vector<std::size_t>> ids_of(const nested_rule& rule, const smolyak_grid& g,
                                             const grid_points& p) {
  std::map<double, std::size_t> id_of;  // a node's coordinate → its id
  for (std::size_t id = 0; id < rule.count(rule.max_level()); ++id) id_of[rule.node(id)] = id;
  const std::size_t s = g.dimension();
  std::vector<std::vector<std::size_t>> ids;
  for (std::uint64_t i = 0; i < g.size(); ++i) {
    std::vector<std::size_t> id(s);
    unsigned births = 0;
    for (std::size_t j = 0; j < s; ++j) {
      const auto it = id_of.find(p.x[i * s + j]);
      EXPECT_NE(it, id_of.end()) << "s " << s << " point " << i << " axis " << j;
      if (it == id_of.end()) return {};
      id[j] = it->second;
      births += rule.birth(id[j]);
    }
    EXPECT_LE(births, g.level()) << "s " << s << " point " << i;
    ids.push_back(std::move(id));
  }
  return ids;
}

// The weights are the documented block formula bit for bit — the leading product in double, the
// block's T tables in long double rounded once, u ascending — for every d the grid picks (1 for
// s = 1 and for s = 2 beyond the block's cap, where they are also the previous walk's weights bit
// for bit; 2 and 3 above, and d = s, the whole grid one block, for s = 2, 3 at small levels: then
// a weight is T_L itself), in every dimension the copy is specialised for and beyond (s = 17,
// 20: the loop); each node comes once. Reversing a product order, or summing the block's terms
// in double, fails it.
TEST(SmolyakGrid, WeightsAreTheSurplusFormulaBitForBitAndEachNodeComesOnce) {
  for (const nested_rule_kind kind :
       {nested_rule_kind::clenshaw_curtis, nested_rule_kind::gauss_patterson,
        nested_rule_kind::trapezoid}) {
    const nested_rule& rule = nested_rule_table(kind);
    std::set<std::size_t> block_axes_seen;
    std::set<std::size_t> whole_grid_blocks_seen;  // the s with d = s
    for (const auto& [s, L] : {std::pair<std::size_t, unsigned>{1, 7},
                               {2, 6},
                               {2, 12},
                               {3, 5},
                               {3, 7},
                               {3, 10},
                               {4, 6},
                               {5, 4},
                               {8, 4},
                               {16, 2},
                               {17, 2},
                               {20, 2}}) {
      if (L > rule.max_level()) continue;  // s = 2, L = 12: beyond Gauss–Patterson's tables
      const smolyak_grid g(rule, s, L);
      ASSERT_EQ(g.block_axes(), documented_block_axes(rule, s, L)) << s << " " << L;
      block_axes_seen.insert(g.block_axes());
      if (g.block_axes() == s) whole_grid_blocks_seen.insert(s);
      const grid_points p = all_points(g);
      const auto ids = ids_of(rule, g, p);
      ASSERT_EQ(ids.size(), g.size());
      std::map<std::vector<std::size_t>, int> visits;
      for (std::uint64_t i = 0; i < g.size(); ++i) {
        const double expected = block_walk_weight(rule, ids[i], L, g.block_axes());
        ASSERT_EQ(std::bit_cast<std::uint64_t>(p.w[i]), std::bit_cast<std::uint64_t>(expected))
            << to_string(kind) << " s " << s << " L " << L << " point " << i;
        if (g.block_axes() == 1) {
          ASSERT_EQ(std::bit_cast<std::uint64_t>(p.w[i]),
                    std::bit_cast<std::uint64_t>(previous_walk_weight(rule, ids[i], L)))
              << to_string(kind) << " s " << s << " L " << L << " point " << i;
        }
        ++visits[ids[i]];
      }
      // Every tuple visited once, and as many tuples as the grid has nodes.
      for (const auto& [tuple, n] : visits) ASSERT_EQ(n, 1) << to_string(kind) << " s " << s;
      EXPECT_EQ(visits.size(), g.size()) << to_string(kind) << " s " << s;
    }
    EXPECT_EQ(block_axes_seen, (std::set<std::size_t>{1, 2, 3})) << to_string(kind);
    EXPECT_EQ(whole_grid_blocks_seen, (std::set<std::size_t>{1, 2, 3})) << to_string(kind);
  }
}

// A weighted point set of given nodes and weights (the previous walk's, in its order: the
// lexicographic order of the s ids), so that the kernel sums them as it summed that walk.
struct listed_points {
  std::size_t s;
  std::vector<double> x;
  std::vector<double> w;
  std::uint64_t size() const { return w.size(); }
  std::size_t dimension() const { return s; }
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    std::copy_n(x.begin() + static_cast<std::ptrdiff_t>(first * s), nodes.size(), nodes.begin());
    std::copy_n(w.begin() + static_cast<std::ptrdiff_t>(first), weights.size(), weights.begin());
  }
};

// The Genz Gaussian of the benchmark (a = 1/√s·…, u = 0.5) with the scalar std::exp, so that f
// at a node has the same bits wherever in a batch the node falls.
struct scalar_gaussian {
  std::size_t s;
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      double v = 0.0;
      for (std::size_t j = 0; j < s; ++j) {
        const double a = 1.0 + 0.25 * static_cast<double>(j);
        v += a * a * (x[i * s + j] - 0.5) * (x[i * s + j] - 0.5);
      }
      y[i] = std::exp(-v);
    }
  }
  integrand_info info() const {
    integrand_info i;
    i.name = "scalar_gaussian";
    i.domain = box::unit(s);
    return i;
  }
};

// The block walk changed the order of the arithmetic (s ≥ 3, and s = 2 at the levels where the
// whole grid is one block): each weight now sums the block's terms in long double and the leading
// product's in double (none when d = s), and the nodes of a row come in shell order; with one
// leading axis the nodes come in birth groups (s = 2, L = 13: the weights are the previous walk's
// bits, only the order of the sum differs). Both it and
// the previous walk evaluate w(x) = Σ_k Π_j d_{k_j}(x_j) with at most n = s·(L + 2) roundings on
// each term's path (per axis one difference, one product and ≤ L additions; the block's long double
// part costs < 1 double rounding), so each is within γ_n·|w|(x) of the exact sum [Higham 2002,
// §3.1], |w|(x) = Σ_k Π_j |d_{k_j}(x_j)|, and they differ by at most 2γ_n·|w|(x). The kernel's sums
// then add ≤ γ_12·Σ|w_i f_i| each (the product w·f, pairwise over 256 terms, Neumaier across
// batches: weighted_point_set.hpp), so
//   |Q_new − Q_prev| ≤ Σ_i 2γ_n·|w|(x_i)·|f_i| + γ_12·(Σ|w_new,i f_i| + Σ|w_prev,i f_i|).
// Checked per weight and for the sum, on the levels of the benchmark's equal-N comparison.
TEST(SmolyakGrid, BlockWalkAgreesWithThePreviousWalkWithinTheRoundingBound) {
  const auto gamma = [](double n) { return n * eps / (1.0 - n * eps); };
  for (const auto& [s, L] : std::vector<std::pair<std::size_t, unsigned>>{
           {2, 11}, {2, 13}, {3, 9}, {3, 10}, {4, 9}, {5, 6}, {8, 5}, {16, 3}}) {
    const smolyak_grid g(cc(), s, L);
    const grid_points p = all_points(g);
    const auto ids = ids_of(cc(), g, p);
    ASSERT_EQ(ids.size(), g.size());
    const double n_roundings = static_cast<double>(s * (L + 2));
    // The previous walk's points in its order: the ids sorted lexicographically.
    std::vector<std::size_t> order(g.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
    listed_points previous{s, std::vector<double>(g.size() * s), std::vector<double>(g.size())};
    const scalar_gaussian f{s};
    std::vector<double> y(g.size());
    f.evaluate(p.x, y);
    long double bound = 0.0L;
    double worst_weight_ratio = 0.0;
    for (std::size_t k = 0; k < order.size(); ++k) {
      const std::size_t i = order[k];
      const double w_previous = previous_walk_weight(cc(), ids[i], L);
      const long double terms = absolute_terms(cc(), ids[i], L);
      const double allowed = static_cast<double>(2 * gamma(n_roundings) * terms);
      const double difference = std::abs(p.w[i] - w_previous);
      ASSERT_LE(difference, allowed) << "s " << s << " L " << L << " point " << i;
      worst_weight_ratio = std::max(worst_weight_ratio, difference / allowed);
      std::copy_n(p.x.begin() + static_cast<std::ptrdiff_t>(i * s), s,
                  previous.x.begin() + static_cast<std::ptrdiff_t>(k * s));
      previous.w[k] = w_previous;
      const long double fy = std::abs(static_cast<long double>(y[i]));
      bound += 2 * gamma(n_roundings) * terms * fy;
      bound += gamma(12) * (std::abs(p.w[i]) + std::abs(w_previous)) * fy;
    }
    const double q_new = weighted_sum(f, g, 1).value;
    const double q_previous = weighted_sum(f, previous, 1).value;
    const double difference = std::abs(q_new - q_previous);
    EXPECT_LE(difference, static_cast<double>(bound)) << "s " << s << " L " << L;
    std::cout << fmt::format(
        "s {:2} L {} d {}: N {:7}, |Q_new − Q_prev| = {:.3g} (bound {:.3g}), worst weight "
        "difference {:.3g} of its bound\n",
        s, L, g.block_axes(), g.size(), difference, static_cast<double>(bound), worst_weight_ratio);
  }
}

// One point at a time, from every index, and batches of 97 from every 7th index: the points of
// one whole-grid batch, for each walk — birth groups (s = d + 1: s = 4, L = 6 and s = 3, L = 10
// with d = 3 and 2, s = 2, L = 12 with d = 1, where both row directions occur), rows (s = 5,
// L = 6; s = 3, L = 12 with d = 1) and the whole grid as one block (s = 2, L = 6).
TEST(SmolyakGrid, AnyBatchStartGivesTheSameNodesAndWeights) {
  for (const auto& [s, L] : std::vector<std::pair<std::size_t, unsigned>>{
           {4, 6}, {3, 10}, {2, 12}, {5, 6}, {3, 12}, {2, 6}}) {
    const smolyak_grid g(cc(), s, L);
    const grid_points p = all_points(g);
    std::vector<double> x(97 * s), w(97);
    for (std::uint64_t i = 0; i < g.size(); ++i) {
      const std::size_t n = (i % 7 == 0) ? std::min<std::uint64_t>(97, g.size() - i) : 1;
      g.generate(i, std::span<double>(x.data(), n * s), std::span<double>(w.data(), n));
      for (std::size_t q = 0; q < n; ++q) {
        for (std::size_t j = 0; j < s; ++j) {
          ASSERT_EQ(x[q * s + j], p.x[(i + q) * s + j]) << "s " << s << " L " << L << " " << i;
        }
        ASSERT_EQ(std::bit_cast<std::uint64_t>(w[q]), std::bit_cast<std::uint64_t>(p.w[i + q]))
            << "s " << s << " L " << L << " " << i;
      }
    }
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
  // The whole grid one block (d = s): s = 2 at L = 11, s = 3 at L = 9, each the largest level
  // within the block's cap; and s = 2 at L = 13, beyond it (d = 1, several chunks).
  const smolyak_grid whole2(cc(), 2, 11);
  const smolyak_grid whole3(cc(), 3, 9);
  const smolyak_grid rows2(cc(), 2, 13);
  ASSERT_EQ(whole2.block_axes(), 2u);
  ASSERT_EQ(whole3.block_axes(), 3u);
  ASSERT_EQ(rows2.block_axes(), 1u);
  for (const smolyak_grid* grid : {&g, &whole2, &whole3, &rows2}) {
    const product_exp f{grid->dimension()};
    const double one = weighted_sum(f, *grid, 1).value;
    for (const unsigned threads : {2u, 3u, 8u}) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(weighted_sum(f, *grid, threads).value),
                std::bit_cast<std::uint64_t>(one))
          << "s " << grid->dimension() << " threads " << threads;
    }
  }
  // mapped() writes box coordinates: bitwise what generate() and the kernel's map give, for a
  // block of 2 and of 3 axes (d = 2 here, 3 at s = 5, L = 6), for whole-grid blocks and for d = 1,
  // on a box (the block's coordinates mapped per call) and on the unit cube (the process's table
  // used as it is).
  const smolyak_grid g3(cc(), 5, 6);
  ASSERT_EQ(g.block_axes(), 2u);
  ASSERT_EQ(g3.block_axes(), 3u);
  for (const smolyak_grid* grid : {&g, &g3, &whole2, &whole3, &rows2}) {
    const std::size_t s = grid->dimension();
    for (const box& domain :
         {box{std::vector<double>(s, -1.0), std::vector<double>(s, 2.0)}, box::unit(s)}) {
      const cube_to_box map(domain);
      const auto on_box = grid->mapped(map);
      std::vector<double> x1(256 * s), w1(256), x2(256 * s), w2(256);
      for (std::uint64_t first = 0; first + 256 <= grid->size(); first += 997) {
        grid->generate(first, x1, w1);
        map.apply(x1);
        on_box.generate(first, x2, w2);
        ASSERT_EQ(x1, x2) << "s " << s << " first " << first;
        ASSERT_EQ(w1, w2) << "s " << s << " first " << first;
      }
    }
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
