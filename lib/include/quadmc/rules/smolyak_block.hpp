// The block of a Smolyak grid's last d axes (smolyak_grid.hpp): the d-dimensional Smolyak grid of
// a nested rule (nested_rule.hpp) at every level up to a cap, tabulated once per process, so
// that a grid in s dimensions walks rows of a whole block instead of runs of its last axis.
//
// What it holds, for d = 2 or 3:
//  - the block's nodes in shell order: total birth level 0, then 1, …; within a shell the birth
//    tuples, and within a tuple the ids, in lexicographic order. So the d-dimensional grid of
//    level l is the first count(l) nodes, for every l ≤ level();
//  - T_l[i], the weight of node i in the d-dimensional grid of level l [Gerstner & Griebel 1998],
//    for i < count(l): with b its birth levels (|b|₁ = t ≤ l) and δ_c[m] = w(b_c + m) − w(b_c +
//    m − 1) the differences of its c-th id on the by-level tables (w(b − 1) = 0), T_(t+v) is the
//    sum of the coefficients of degree ≤ v of Π_c Σ_m δ_c[m]·z^m
//    (docs/theory.md#smolyak-construction). Formed in long double — each coefficient summed from
//    zero in ascending m, the partial sums in ascending v — and rounded to double once, so a T is
//    within about one ulp of the exact sum on the tables' weights
//    (tests/rules/smolyak_grid_test.cpp rebuilds it in this order, bit for bit). T_l of a grid of
//    lower level is the same prefix, the same bits: a grid's weights do not depend on how far the
//    table was built.
// Use it through smolyak_grid, which also takes it as the whole grid when s = d and the level
// is tabulated (smolyak_grid.hpp); not a weighted point set of its own.
//
// Memory: count(level()) ≤ block_nodes_cap = 16384 nodes, d coordinates each, and Σ_l count(l)
// weights (< 2.5·count(level()) for the three rule families), at most 0.6 MB per table; one table
// per rule family and d, built on first use: 1.1 MB for Clenshaw–Curtis (d = 2 to level 11, d = 3
// to level 9). Built in O(count·d·level²) flops, milliseconds, once per process.
#pragma once

#include "quadmc/rules/nested_rule.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace quadmc {

class smolyak_block {
 public:
  // A block has at most this many nodes at its top level.
  static constexpr std::uint64_t block_nodes_cap = 16384;

  // The block of `rule` with d ≥ 2 axes to the largest level ≤ rule.max_level() whose grid has
  // at most block_nodes_cap nodes. Throws invalid_argument for d < 2.
  smolyak_block(const nested_rule& rule, std::size_t d);

  std::size_t axes() const noexcept { return d_; }
  // The largest level tabulated.
  unsigned level() const noexcept { return static_cast<unsigned>(count_.size() - 1); }
  // N_d(l): the nodes of the d-dimensional grid of level l ≤ level().
  std::uint64_t count(unsigned l) const noexcept { return count_[l]; }
  // Unit coordinates, d per node, in shell order.
  const double* nodes() const noexcept { return nodes_.data(); }
  // T_l: count(l) weights, l ≤ level().
  const double* weights(unsigned l) const noexcept { return weights_.data() + offset_[l]; }

 private:
  std::size_t d_;
  std::vector<std::uint64_t> count_;
  std::vector<std::size_t> offset_;
  std::vector<double> weights_;
  std::vector<double> nodes_;
};

// The process's block of `kind` with d ∈ {2, 3} axes, built on first use (thread-safe) and kept.
// Throws invalid_argument for another d.
const smolyak_block& smolyak_block_table(nested_rule_kind kind, std::size_t d);

}  // namespace quadmc
