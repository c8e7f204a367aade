// Nested one-dimensional rules on [0, 1]: a sequence of rules U^0, U^1, …, U^Lmax whose node sets
// grow by inclusion, X^0 ⊂ X^1 ⊂ …, tabulated once per process. The building block of the sparse
// grids (smolyak_grid.hpp, dimension_adaptive_sparse_grid.hpp): nesting is what lets a Smolyak
// grid evaluate each distinct node once.
//
// Use nested_rule_table(kind) for the three families the sparse grids offer:
//  - clenshaw_curtis: 1, 3, 5, 9, …, 2^l + 1 nodes (l ≥ 1), the Chebyshev extrema
//    t_k = sin²(kπ/(2n)), n = 2^l, the node count of the nested sequence of [Novak & Ritter 1996]
//    and [Gerstner & Griebel 1998]; weights by the exact cosine sum of [Waldvogel 2006, eq. 2.4]
//    (the explicit form of the Clenshaw–Curtis weights; Trefethen's clenshaw_curtis code in
//    [Trefethen 2008] computes the same sum). Level l integrates polynomials of degree n exactly
//    (n + 1 nodes, n even, symmetric), so the rule of level l has degree ≥ 2l + 1 … the bound
//    Smolyak's exactness needs (docs/theory.md#smolyak-construction).
//  - gauss_patterson: 1, 3, 7, …, 2^(l+1) − 1 nodes, Patterson's nested extensions of the
//    3-point Gauss rule [Patterson 1968], degree 3·2^l − 1 (l ≥ 1); nodes and weights from
//    Burkardt's quadrule library (Debian libquadrule-dev, [quadrule]), which tabulates them up
//    to 255 nodes (level 7). Every weight is positive.
//  - trapezoid: 1, 2, 4, …, 2^l nodes k/2^l with equal weights 2^−l, the trapezoid rule of a
//    periodic integrand on one period (f(0) = f(1), so the end nodes are one node): exponentially
//    convergent on periodic analytic f [Trefethen & Weideman 2014], only O(n^−2) otherwise.
// Not for the composite rules of tensor_product.hpp (those are not nested in this sense).
//
// Node ids are in birth order: the nodes of level l are ids [0, count(l)), the new ones of level
// l are [count(l − 1), count(l)). A node's coordinate and its weight in every level that holds it
// are table lookups, by level or by node (weights_from_birth, differences_from_birth) or by
// birth level (differences_by_birth). Memory: Σ_l count(l) weights, < 2·count(Lmax) + Lmax for
// these families (count doubles per level), held four times (by level; by node; the differences
// by node and by birth level), plus count(Lmax) nodes — 16385 nodes and 4 × about 33 000 weights
// (1.1 MB) for Clenshaw–Curtis at level 14, the largest tabulated (its cosine sums cost O(n²) once
// per process, ~0.1 s at n = 2^14).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace quadmc {

enum class nested_rule_kind { clenshaw_curtis, gauss_patterson, trapezoid };

std::string_view to_string(nested_rule_kind kind) noexcept;
std::optional<nested_rule_kind> parse_nested_rule_kind(std::string_view name) noexcept;

class nested_rule {
 public:
  // The tables of `kind` up to level max_level(kind) (the constructor of nested_rule_table).
  // Throws invalid_argument if a level's nodes are not those of the level above (nesting is
  // checked, not assumed: quadrule's Patterson tables are matched value for value).
  explicit nested_rule(nested_rule_kind kind);

  nested_rule_kind kind() const noexcept { return kind_; }
  unsigned max_level() const noexcept { return static_cast<unsigned>(count_.size() - 1); }
  // Nodes of level l (cumulative): count(l) ≥ count(l − 1) + 1.
  std::uint64_t count(unsigned level) const noexcept { return count_[level]; }
  // Nodes new at level l: count(l) − count(l − 1), count(−1) = 0.
  std::uint64_t new_count(unsigned level) const noexcept {
    return level == 0 ? count_[0] : count_[level] - count_[level - 1];
  }
  // The level at which node id first appears.
  unsigned birth(std::size_t id) const noexcept { return birth_[id]; }
  double node(std::size_t id) const noexcept { return nodes_[id]; }
  // Every node by id, count(max_level()) values: the nodes of level l are the first count(l).
  std::span<const double> nodes() const noexcept { return nodes_; }
  // Weight of node id in the rule of level l ≥ birth(id) (weights refer to [0, 1], Σ = 1).
  double weight(unsigned level, std::size_t id) const noexcept {
    return weights_[weight_offset_[level] + id];
  }
  // The weights of level l, by node id: count(l) values.
  std::span<const double> weights(unsigned level) const noexcept {
    return {weights_.data() + weight_offset_[level], static_cast<std::size_t>(count_[level])};
  }
  // Degree of polynomial exactness of the rule of level l.
  unsigned degree(unsigned level) const noexcept;

  // The same weights by node: for m = 0 … max_level() − birth(id),
  //   weights_from_birth(id)[m] = weight(birth(id) + m, id),
  //   differences_from_birth(id)[m] = d_(birth + m)(id) = weight(birth + m, id) − weight(birth + m
  //   − 1, id), with d_birth(id) = weight(birth, id) (the node is in no rule below its birth),
  // the factors of the hierarchical-surplus (Δ_l = U^l − U^(l−1)) form of a Smolyak grid
  // [Gerstner & Griebel 1998]. Contiguous per node, so a sparse grid's walk reads a node's factors
  // from one place instead of one table per level; the differences are the subtractions it would
  // otherwise repeat at every visit of the node, made once per process (the same operation on the
  // same operands, so the same bits).
  const double* weights_from_birth(std::size_t id) const noexcept {
    return by_node_weights_.data() + by_node_offset_[id];
  }
  const double* differences_from_birth(std::size_t id) const noexcept {
    return by_node_differences_.data() + by_node_offset_[id];
  }
  // The same differences by birth level: for the nodes born at level b (ids count(b − 1) + k,
  // k < new_count(b)) and m ≤ max_level() − b, differences_by_birth(b, m)[k] =
  // differences_from_birth(count(b − 1) + k)[m], contiguous in k (bit for bit the same values):
  // a Smolyak walk whose rows run along the first axis's new nodes reads them in a stream.
  const double* differences_by_birth(unsigned birth, unsigned m) const noexcept {
    return by_birth_differences_.data() + by_birth_offset_[birth] +
           m * static_cast<std::size_t>(new_count(birth));
  }

 private:
  void add_level(std::span<const double> nodes_in_birth_order, std::span<const double> weights);

  nested_rule_kind kind_;
  std::vector<std::uint64_t> count_;
  std::vector<unsigned> birth_;
  std::vector<double> nodes_;
  std::vector<std::size_t> weight_offset_;
  std::vector<double> weights_;
  std::vector<std::size_t> by_node_offset_;
  std::vector<double> by_node_weights_;
  std::vector<double> by_node_differences_;
  std::vector<std::size_t> by_birth_offset_;
  std::vector<double> by_birth_differences_;
};

// The tables of each kind, built on first use (thread-safe) and kept for the process.
const nested_rule& nested_rule_table(nested_rule_kind kind);

// max_level of each kind: 14 for Clenshaw–Curtis (16385 nodes), 7 for Gauss–Patterson (255,
// quadrule's largest table), 16 for the trapezoid (65536 nodes).
unsigned nested_rule_max_level(nested_rule_kind kind) noexcept;

}  // namespace quadmc
