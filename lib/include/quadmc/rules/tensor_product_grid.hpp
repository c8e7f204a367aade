// The tensor product of a 1D node set as a weighted point set (weighted_point_set.hpp): the
// nodes and weights behind every tensor-product rule of this layer, 1D included.
//
// Point p of the grid, p = Σ_j k_j·m^(s−1−j) (last axis fastest), is the node (t_{k_1}, …,
// t_{k_s}) with the weight w_{k_1}⋯w_{k_s} — the product of a 1D rule with m nodes along each of
// the s axes, N = m^s points (the product rules of Davis & Rabinowitz, "Methods of Numerical
// Integration", 2nd ed., ch. 5). Use it through integrate() (tensor_product.hpp), or hand it to
// weighted_sum() directly; not for grids with different rules or node counts per axis (one node
// set serves every axis).
//
// How it generates (the reason integrate() is as fast with it as with a dedicated loop):
//  - the grid is never stored: generate() decodes its first index into a multi-index once per
//    batch and walks on like an odometer, recomputing an axis's coordinate only when that axis
//    moves (the leading axes move once every m points or less often); between two moves the
//    points share their leading coordinates, and each is stored down its column from a register;
//  - the weight is formed left to right, (Π_{j<s−1} w_{k_j})·w_{k_s}, the leading product
//    recomputed from the same factors at every carry, so it does not depend on where a batch
//    starts;
//  - when an axis has at most rule_chunk_points nodes (every grid with s ≥ 2 but the largest), the
//    nodes and weights are tabulated once at construction (each entry is reused m^(s−1) times;
//    the rules' node() and weight() divide), else computed per point — the same functions either
//    way, so the same bits;
//  - mapped(map) is the fast path of weighted_point_set.hpp: for a tabulated grid it tabulates
//    every axis's box coordinates once per call and hands each batch to the row kernel
//    (tensor_product_rows.hpp: whole rows of the last axis, vector code chosen at run time), so
//    a point costs a few register stores and one multiply for its weight, not s multiply-adds;
//    bitwise what generate() followed by map.apply() gives.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/rules/rule.hpp"
#include "quadmc/rules/tensor_product_rows.hpp"
#include "quadmc/rules/weighted_point_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace quadmc {

// m^s, the number of points of an s-dimensional tensor grid with m nodes per axis. Throws
// invalid_argument if it is not representable in 64 bits: checked before each multiplication
// (p > (2^64 − 1)/m ⇔ p·m ≥ 2^64), so the test is exact, not a floating-point estimate.
inline std::uint64_t tensor_grid_size(std::uint64_t nodes_per_axis, std::size_t s) {
  require(s >= 1, "dimension s", s, "at least 1");
  require(nodes_per_axis >= 1, "nodes per axis", nodes_per_axis, "at least 1");
  const std::optional<std::uint64_t> points = checked_power(nodes_per_axis, s);
  if (!points) {
    throw invalid_argument(
        "nodes per axis", quote(nodes_per_axis),
        fmt::format("nodes^s ≤ 2^64 − 1 for s = {}: the grid has too many points to count in "
                    "64 bits (use fewer panels or a Monte Carlo method)",
                    s));
  }
  return *points;
}

template <node_set N>
class tensor_product_grid {
 public:
  // Throws invalid_argument if s = 0 or m^s does not fit in 64 bits (tensor_grid_size).
  tensor_product_grid(N q, std::size_t s)
      : q_(std::move(q)), s_(s), m_(q_.size()), total_(tensor_grid_size(m_, s)) {
    const std::size_t table_size = m_ <= rule_chunk_points ? static_cast<std::size_t>(m_) : 0;
    node_table_.resize(table_size);
    weight_table_.resize(table_size);
    for (std::size_t k = 0; k < table_size; ++k) {
      node_table_[k] = q_.node(k);
      weight_table_[k] = q_.weight(k);
    }
  }

  std::uint64_t size() const noexcept { return total_; }
  std::size_t dimension() const noexcept { return s_; }
  std::uint64_t nodes_per_axis() const noexcept { return m_; }

  // Nodes in [0, 1]^s and their product weights (the weighted_point_set contract).
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    if (tabulated()) {
      const auto node = [this](std::size_t, std::uint64_t k) { return node_table_[k]; };
      walk<true>(first, nodes, weights, node, [this](std::uint64_t k) { return node_table_[k]; });
    } else {
      const auto node = [this](std::size_t, std::uint64_t k) { return q_.node(k); };
      walk<false>(first, nodes, weights, node, [this](std::uint64_t k) { return q_.node(k); });
    }
  }

  // The same points in the box of `map`: x_j = map(j, t_j), bitwise what generate() followed by
  // map.apply() gives. Refers to this grid, which must outlive it.
  class on_box {
   public:
    on_box(const tensor_product_grid& grid, const cube_to_box& map) : grid_(&grid), map_(map) {
      require(map_.dimension() == grid.s_, "box dimension", map_.dimension(),
              fmt::format("the grid's dimension {}", grid.s_));
      // Every axis's box coordinates, the last axis's m at the end: the row kernel's tables, s·m
      // values (≤ N, since m^s ≥ s·m for m ≥ 2; ≤ 64 for m = 1), built once per call. The same
      // map(j, t_k) as the walk computes per carry, so the same bits.
      if (!grid.tabulated()) return;
      const std::size_t m = grid.node_table_.size();
      const std::size_t axes = grid.s_ <= detail::tensor_row_max_axes ? grid.s_ : 1;
      const std::size_t first_axis = grid.s_ - axes;
      axis_coordinate_.resize(axes * m);
      for (std::size_t j = 0; j < axes; ++j) {
        for (std::size_t k = 0; k < m; ++k) {
          axis_coordinate_[j * m + k] = map_(first_axis + j, grid.node_table_[k]);
        }
      }
    }

    void generate(std::uint64_t first, std::span<double> x, std::span<double> weights) const {
      const tensor_product_grid& g = *grid_;
      if (g.tabulated() && g.s_ <= detail::tensor_row_max_axes) {
        require_weighted_batch(g.s_, g.total_, first, x, weights);
        if (weights.empty()) return;
        const detail::tensor_row_tables tables{g.s_, g.m_, axis_coordinate_.data(),
                                               g.weight_table_.data()};
        detail::tensor_rows(tables, first, weights.size(), x.data(), weights.data());
      } else if (g.tabulated()) {  // m = 1: the one point
        const auto coordinate = [this, &g](std::size_t j, std::uint64_t k) {
          return map_(j, g.node_table_[k]);
        };
        g.template walk<true>(first, x, weights, coordinate,
                              [this](std::uint64_t) { return axis_coordinate_.front(); });
      } else {
        const auto coordinate = [this, &g](std::size_t j, std::uint64_t k) {
          return map_(j, g.q_.node(k));
        };
        const std::size_t last = g.s_ - 1;
        g.template walk<false>(first, x, weights, coordinate, [this, &g, last](std::uint64_t k) {
          return map_(last, g.q_.node(k));
        });
      }
    }

   private:
    const tensor_product_grid* grid_;
    cube_to_box map_;
    // Tabulated grids: axis j's box coordinate of node k at [j·m + k] (s ≤ tensor_row_max_axes),
    // else the last axis's only (m = 1).
    std::vector<double> axis_coordinate_;
  };

  on_box mapped(const cube_to_box& map) const { return on_box(*this, map); }

 private:
  // With m ≥ 2 nodes per axis, m^s < 2^64 forces s ≤ 63, so the odometer's per-axis state fits in
  // arrays of this size on the stack; a larger s means m = 1 and a single point.
  static constexpr std::size_t max_axes = detail::tensor_row_max_axes;

  bool tabulated() const noexcept { return !node_table_.empty(); }

  template <bool Tabulated>
  double weight(std::uint64_t k) const noexcept {
    if constexpr (Tabulated) {
      return weight_table_[k];
    } else {
      return q_.weight(k);
    }
  }

  // The odometer. coordinate(j, k) is axis j's coordinate for node k (j < s − 1), last(k) the last
  // axis's; both are called only here, so unit and box coordinates share one walk.
  template <bool Tabulated, class Coordinate, class Last>
  void walk(std::uint64_t first, std::span<double> x, std::span<double> weights,
            const Coordinate& coordinate, const Last& last_coordinate) const {
    require_weighted_batch(s_, total_, first, x, weights);
    const std::size_t count = weights.size();
    const std::size_t s = s_;
    const std::size_t last = s - 1;
    if (count == 0) return;
    if (s > max_axes) {  // m = 1: the one point (0, …, 0) of the grid
      double w = 1.0;
      for (std::size_t j = 0; j < last; ++j) {
        x[j] = coordinate(j, 0);
        w *= weight<Tabulated>(0);
      }
      // GCC 12 at -O3, inlining this into a caller whose s it knows to be small, warns that
      // x[last] (last ≥ 64 here) is outside that caller's array, on this branch that such an s
      // never takes (require_weighted_batch checked x.size() ≥ s above): a false positive of the
      // kind GCC's manual warns -Warray-bounds gives on unreachable code.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
      x[last] = last_coordinate(0);
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
      weights[0] = w * weight<Tabulated>(0);
      return;
    }
    const std::uint64_t m = m_;
    std::array<std::uint64_t, max_axes> index;
    std::array<double, max_axes> axis_coordinate;
    std::array<double, max_axes> axis_weight;
    auto place = [&](std::size_t j) {
      axis_coordinate[j] = coordinate(j, index[j]);
      axis_weight[j] = weight<Tabulated>(index[j]);
    };
    std::uint64_t rest = first;
    for (std::size_t j = s; j-- > 0;) {
      index[j] = rest % m;
      rest /= m;
      if (j < last) place(j);
    }
    auto leading_weight = [&] {
      double w = 1.0;
      for (std::size_t j = 0; j < last; ++j) w *= axis_weight[j];
      return w;
    };
    double w_leading = leading_weight();
    std::uint64_t k = index[last];  // the last axis's index
    // The batch in runs of points that share their leading coordinates (at most m − k, then m
    // points): per run the last axis's coordinates and weights, then each leading coordinate
    // stored down its column from a register. (A per-point copy of the s − 1 leading values from
    // a local array is what GCC 12 turns into an inlined `rep movsq` per point, 4× slower.)
    for (std::size_t i = 0; i < count;) {
      const auto run = static_cast<std::size_t>(std::min<std::uint64_t>(m - k, count - i));
      double* row = x.data() + i * s;
      for (std::size_t r = 0; r < run; ++r) {
        row[r * s + last] = last_coordinate(k + r);
        weights[i + r] = w_leading * weight<Tabulated>(k + r);
      }
      for (std::size_t j = 0; j < last; ++j) {
        const double c = axis_coordinate[j];
        for (std::size_t r = 0; r < run; ++r) row[r * s + j] = c;
      }
      i += run;
      k += run;
      if (k == m) {  // carry into the leading axes
        k = 0;
        for (std::size_t j = last; j-- > 0;) {
          if (++index[j] < m) {
            place(j);
            break;
          }
          index[j] = 0;
          place(j);
        }
        w_leading = leading_weight();
      }
    }
  }

  N q_;
  std::size_t s_;
  std::uint64_t m_;
  std::uint64_t total_;
  std::vector<double> node_table_;
  std::vector<double> weight_table_;
};

}  // namespace quadmc
