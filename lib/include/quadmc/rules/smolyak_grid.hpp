// The isotropic Smolyak sparse grid of a nested 1D rule (nested_rule.hpp) as a weighted point set
// (weighted_point_set.hpp): every distinct node once, weights of both signs with the combination
// coefficients folded in.
//
// Use it for smooth integrands in moderate to high dimension (docs/theory.md#sparse-grids): with
// level L (Novak & Ritter's q = s + L) it costs O(2^L·L^(s−1)) nodes instead of the tensor
// product's 2^(Ls), and is exact for total degree ≤ 2L + 1 with Clenshaw–Curtis [Novak & Ritter
// 1996]. Not for integrands with jumps or kinks off the coordinate planes (they have no mixed
// smoothness, and the signed weights amplify the error: docs/theory.md#sparse-grid-rates), nor for
// an integrand that cannot be evaluated on the boundary when the rule has end nodes
// (Clenshaw–Curtis, trapezoid): use gauss_patterson there.
//
// The construction [Smolyak 1963], in the hierarchical-surplus form of [Gerstner & Griebel 1998]:
// with Δ_l = U^l − U^(l−1) (U^(−1) = 0) and 0-based levels,
//   A(L, s) = Σ_{|k|₁ ≤ L} Δ_{k_1} ⊗ … ⊗ Δ_{k_s}.
// The rules are nested, so a node x = (x_1, …, x_s) is born at the levels b_j = birth(x_j), it is
// in the grid iff |b|₁ ≤ L, and its weight collects every term that holds it:
//   w(x) = Σ_{k ≥ b, |k|₁ ≤ L} Π_j d_{k_j}(x_j),   d_l(x) = weight of x in U^l − weight in U^(l−1).
// With a_j(m) = d_{b_j + m}(x_j) this is Σ_{|m|₁ ≤ R} Π_j a_j(m_j), R = L − |b|₁: the sum of the
// coefficients of degree ≤ R of the polynomial Π_j A_j(z), A_j(z) = Σ_m a_j(m)·z^m. So
//   w(x) = Σ_{u ≤ R} P[u]·C(R − u),
// P = Π_{j<s} A_j truncated to degree R (the leading axes' product) and C(t) = Σ_{m ≤ t} a_s(m)
// = the weight of x_s in U^(b_s + t) (a telescoping sum: a table lookup, no differences).
//
// How it generates (no grid is stored; memory O(s·L) plus one table of the last axes, below):
//  - the last d ∈ {1, 2, 3} axes form a block: the d-dimensional Smolyak grid of level r is the
//    set of the last d ids of the nodes whose leading s − d ids leave a budget r = L − Σ birth.
//    Its nodes are tabulated once per process in shell order (smolyak_block.hpp), so the block
//    of level r is the first N_d(r) entries of the block of level L, together with
//      T_l[i] = the weight of block node i in the d-dimensional grid of level l, i < N_d(l).
//    For d = 1 the block is the 1D rule itself and T_l its weights of level l (nested_rule.hpp:
//    ids are in birth order);
//  - a node's weight is then w = Σ_{u ≤ r} P[u]·T_{r−u}[i], P = Π_{j<s−d} A_j truncated to degree
//    r (the leading axes' product): for the block nodes of one leading tuple — a row of N_d(r)
//    consecutive indices — the weights are r + 1 passes of a multiply-add over contiguous
//    prefixes of the T tables, the leading s − d coordinates are the same for the whole row, and
//    the last d come from the block's coordinate table. Rows average 91 points at s = 4, L = 9
//    (d = 3) and 11.8 at s = 8, L = 8 (d = 3), against runs of 3.3 and 2.1 along the last axis
//    alone, which is what pays: a row's fixed cost (the carry into the leading axes, which
//    recomputes their products) was the larger part of a point's cost;
//  - d is the largest of 2 and 3 with d ≤ s and N_d(L) ≤ smolyak_block::block_nodes_cap (16384)
//    nodes, else 1 (so rows stay in cache); the tables are the process's (smolyak_block.hpp), not
//    the grid's, and a call maps the block's N_d(L)·d coordinates to the box once. With d = s
//    (s = 2 to L = 11, s = 3 to L = 9 for Clenshaw–Curtis) the whole grid is one block and one
//    row: P = 1, so a weight is T_L[i] itself (1.0·T, bit for bit) and the walk is a straight
//    copy of the table's prefix — no leading axis, no carry;
//  - with one leading axis (s = d + 1: s = 2 above the cap, s = 3 at L ≥ 10, s = 4 to L = 9 for
//    Clenshaw–Curtis) the grid is walked by birth groups: for b = 0 … L, the new_count(b) ids
//    born at level b on the first axis times the N_d(L − b) block nodes. Rows over the block
//    (one id, its block row) are short where the ids are many — at s = 2 half the first axis's
//    ids are born at level L and hold one point each (rows of 8 points on average at L = 13,
//    which made the walk 0.71× tensor Simpson's throughput) — so a group with more ids than
//    block nodes goes the other way: one row per block node q over the group's ids, w_k =
//    Σ_u T_(r−u)[q]·d_(b+u)[k], the differences read contiguously by birth level
//    (nested_rule::differences_by_birth). The products are those of the rows over the block
//    (P = d_(b+u) exactly with one leading axis), added in the same ascending u, so the weights
//    are the same bits either way; only the order of the nodes in the grid differs. The first
//    axis's coordinates are copied from one run (mapped once per call on a box), and a row's
//    terms are summed in one pass (detail::combined_row). Measured (callgrind instructions per
//    evaluation, Genz Gaussian, equal N, one thread: bench/tools/rules_callgrind.cpp), against
//    tensor Simpson: s = 2, L = 11 (one block) 74.9 vs 78.1, L = 13 72.8 vs 74.1; s = 3, L = 9
//    (one block) 89.3 vs 97.2, L = 10 83.1 vs 91.5; s = 4, L = 9 93.4 vs 111.5 (the row walk
//    before: 109.1, 102.9, 97.8, 93.4, 99.1);
//  - otherwise nodes are the tuples of 1D ids (leading ids, block node) in lexicographic order of
//    the leading ids, the block in shell order. count[j][r], the number of tuples of axes j…s−1
//    with levels summing to ≤ r (an s × (L + 1) table; count[s − d][r] = N_d(r)), decodes an index
//    into its tuple in O(s·L) once per batch; the batch then walks like an odometer (a birth
//    group's offset decodes the same way, by the group sizes);
//  - the truncated products P_j = Π_{i<j} A_i are kept per leading axis and recomputed only when
//    axis j moves (O(L²) at a carry), from the 1D rule's by-node difference tables
//    (nested_rule.hpp), in double; the block's T_l are sums over d axes formed in long double
//    and rounded once (smolyak_block.hpp), so a weight is within a few ulp of Σ|terms| of the exact
//    surplus sum (tests/rules/smolyak_grid_test.cpp derives the bound and checks it against the sum
//    of the previous walk, which multiplied out all s axes in double);
//  - the weights are a pure function of the node (every product is formed from the same factors
//    in the same order, wherever a batch starts), so the sum is bitwise the same on any thread
//    count;
//  - mapped(map) writes box coordinates directly, the fast path of weighted_point_set.hpp (the
//    block's coordinates mapped once per call, a leading coordinate when its axis moves).
// Memory bound: the tables count[s][L + 1] (8 bytes each), per call the block's mapped
// coordinates (≤ 16384·d doubles; the whole grid when d = s, so at most 16384 nodes) and with
// one leading axis its count(L) mapped coordinates (the 1D rule of level L: ≤ 16385 doubles for
// Clenshaw–Curtis, 65536 for the trapezoid), per batch s·(L + 1) doubles of products; the 1D
// rule's tables and the blocks are the process's (nested_rule.hpp, smolyak_block.hpp, ≤ 1.1 MB
// each per rule family). None of it grows with N beyond the 1D rule of level L. At s = 16, L =
// 6: 1.7 KiB of counts and a block of 1073 nodes (d = 3) for 2.1·10⁶ nodes.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/rules/nested_rule.hpp"
#include "quadmc/rules/smolyak_block.hpp"
#include "quadmc/rules/weighted_point_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace quadmc {

// The number of nodes of the level-L Smolyak grid of `rule` in s dimensions, N(L, s) =
// Σ_{|b|₁ ≤ L} Π_j new_count(b_j), exact; nullopt if it does not fit in 64 bits. For
// Clenshaw–Curtis in s = 2: 1, 5, 13, 29, 65, 145, … Throws invalid_argument for s = 0 or L above
// the rule's max_level.
std::optional<std::uint64_t> smolyak_point_count(const nested_rule& rule, std::size_t s,
                                                 unsigned level);

class smolyak_grid {
 public:
  // The grid of level L in s dimensions on the process's tables of `rule`. Throws
  // invalid_argument for s = 0, a level above the rule's max_level, or a count beyond 64 bits.
  smolyak_grid(const nested_rule& rule, std::size_t s, unsigned level);

  std::uint64_t size() const noexcept { return total_; }
  std::size_t dimension() const noexcept { return s_; }
  unsigned level() const noexcept { return level_; }
  const nested_rule& rule() const noexcept { return *rule_; }
  // d, the number of trailing axes tabulated as one block (1, 2 or 3; see "How it generates").
  std::size_t block_axes() const noexcept { return block_axes_; }

  // Nodes in [0, 1]^s and their weights (the weighted_point_set contract).
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    walk(
        first, nodes, weights, [this](std::size_t, std::size_t id) { return rule_->node(id); },
        block_nodes(), rule_->nodes().data());
  }

  class on_box {
   public:
    on_box(const smolyak_grid& grid, const cube_to_box& map) : grid_(&grid), map_(map) {
      require(map_.dimension() == grid.s_, "box dimension", map_.dimension(),
              fmt::format("the grid's dimension {}", grid.s_));
      const std::size_t d = grid.block_axes_;
      const std::size_t leading = grid.s_ - d;
      const auto n = static_cast<std::size_t>(grid.block_count(grid.level_));
      const double* unit = grid.block_nodes();
      // On unit block axes the map is the identity bit for bit (0 + 1·t = t for the nodes, all
      // ≥ +0), so the process's table serves as it is; else the block's n·d coordinates are
      // mapped once per call, an axis at a time (no zero fill first: every entry is written).
      bool identity = true;
      for (std::size_t c = 0; c < d; ++c) {
        identity = identity && map_.lower[leading + c] == 0.0 && map_.width[leading + c] == 1.0;
      }
      if (identity) {
        block_coordinate_ = unit;
      } else {
        mapped_block_ = std::make_unique_for_overwrite<double[]>(n * d);
        for (std::size_t c = 0; c < d; ++c) {
          const double a = map_.lower[leading + c];
          const double w = map_.width[leading + c];
          double* out = mapped_block_.get() + c;
          const double* in = unit + c;
          for (std::size_t i = 0; i < n; ++i) out[i * d] = a + w * in[i * d];
        }
        block_coordinate_ = mapped_block_.get();
      }
      // With one leading axis (birth groups), its count(L) coordinates too, when not unit: the
      // rows over the first axis then copy them from one contiguous run.
      first_axis_ = grid.rule_->nodes().data();
      if (leading == 1 && !(map_.lower[0] == 0.0 && map_.width[0] == 1.0)) {
        const auto m = static_cast<std::size_t>(grid.rule_->count(grid.level_));
        mapped_first_ = std::make_unique_for_overwrite<double[]>(m);
        for (std::size_t i = 0; i < m; ++i) mapped_first_[i] = map_(0, first_axis_[i]);
        first_axis_ = mapped_first_.get();
      }
    }
    void generate(std::uint64_t first, std::span<double> x, std::span<double> weights) const {
      grid_->walk(
          first, x, weights,
          [this](std::size_t j, std::size_t id) { return map_(j, grid_->rule_->node(id)); },
          block_coordinate_, first_axis_);
    }

   private:
    const smolyak_grid* grid_;
    cube_to_box map_;
    std::unique_ptr<double[]> mapped_block_;  // unless the block's axes are unit
    const double* block_coordinate_ = nullptr;
    std::unique_ptr<double[]> mapped_first_;  // one leading axis, not unit
    const double* first_axis_ = nullptr;
  };
  // The same points in the box of `map`, bitwise what generate() and map.apply() give. Refers to
  // this grid, which must outlive it.
  on_box mapped(const cube_to_box& map) const { return on_box(*this, map); }

  // Σ|w_i| over the grid (1 for positive weights; larger with signed ones: the factor by which
  // rounding errors in f are amplified, weighted_point_set.hpp), by one pass over the weights.
  double absolute_weight_sum() const;

 private:
  // The largest level of any nested rule is below this (nested_rule_max_level: 16 at most), so a
  // batch keeps its pointers to the T tables on the stack.
  static constexpr unsigned max_levels = 32;

  // count_[j·(L + 1) + r]: tuples of axes j…s−1 whose birth levels sum to ≤ r.
  std::uint64_t tuples(std::size_t j, unsigned r) const noexcept {
    return j == s_ ? 1 : count_[j * (level_ + 1) + r];
  }
  // N_d(r): the nodes of the block of level r.
  std::uint64_t block_count(unsigned r) const noexcept { return tuples(s_ - block_axes_, r); }
  // The block's unit coordinates, d per node, in block order.
  const double* block_nodes() const noexcept {
    return block_ == nullptr ? rule_->nodes().data() : block_->nodes();
  }
  // T_l: the block's weights in the d-dimensional grid of level l, N_d(l) values.
  const double* block_weights(unsigned l) const noexcept {
    return block_ == nullptr ? rule_->weights(l).data() : block_->weights(l);
  }

  template <class Coordinate>
  void walk(std::uint64_t first, std::span<double> x, std::span<double> weights,
            const Coordinate& coordinate, const double* block_coordinate,
            const double* first_axis) const {
    // One leading axis (s = d + 1): by birth groups; none or more: by rows.
    const bool groups = s_ == block_axes_ + 1;
    switch (block_axes_) {
      case 1:
        if (groups) {
          walk_groups<1>(first, x, weights, coordinate, block_coordinate, first_axis);
        } else {
          walk_rows<1>(first, x, weights, coordinate, block_coordinate);
        }
        break;
      case 2:
        if (groups) {
          walk_groups<2>(first, x, weights, coordinate, block_coordinate, first_axis);
        } else {
          walk_rows<2>(first, x, weights, coordinate, block_coordinate);
        }
        break;
      default:
        if (groups) {
          walk_groups<3>(first, x, weights, coordinate, block_coordinate, first_axis);
        } else {
          walk_rows<3>(first, x, weights, coordinate, block_coordinate);
        }
        break;
    }
  }
  template <std::size_t D, class Coordinate>
  void walk_rows(std::uint64_t first, std::span<double> x, std::span<double> weights,
                 const Coordinate& coordinate, const double* block_coordinate) const;
  template <std::size_t D, class Coordinate>
  void walk_groups(std::uint64_t first, std::span<double> x, std::span<double> weights,
                   const Coordinate& coordinate, const double* block_coordinate,
                   const double* first_axis) const;

  const nested_rule* rule_;
  std::size_t s_;
  unsigned level_;
  std::vector<std::uint64_t> count_;
  std::uint64_t total_ = 0;
  std::size_t block_axes_ = 1;
  const smolyak_block* block_ = nullptr;  // the process's table for d ≥ 2
};

namespace detail {

// smolyak_grid's rows copy a point's s − d leading coordinates with a length fixed at compile
// time for s − d < max_fixed_axes (straight-line moves from registers; a loop of variable length
// is turned into a call to memcpy per point by GCC, which cost more than the point's weight);
// dynamic_axes is the loop for larger s.
inline constexpr std::size_t max_fixed_axes = 16;
inline constexpr std::size_t dynamic_axes = std::numeric_limits<std::size_t>::max();

// f(std::integral_constant<std::size_t, m>{}) for m < max_fixed_axes, else
// f(std::integral_constant<std::size_t, dynamic_axes>{}): one switch per row of the walk.
template <class F>
void with_leading_axes(std::size_t m, const F& f) {
  [&]<std::size_t... M>(std::index_sequence<M...>) {
    const bool fixed =
        ((m == M ? (f(std::integral_constant<std::size_t, M>{}), true) : false) || ...);
    if (!fixed) f(std::integral_constant<std::size_t, dynamic_axes>{});
  }
  (std::make_index_sequence<max_fixed_axes>{});
}

// out[q] = a·in[q] (Add = false) or out[q] += a·in[q] (Add = true) for q < n, two lanes at a
// time by the compilers' vector extension: the same IEEE operations per element, so the same bits
// as the scalar loop, which GCC's -O2 does not vectorize (a row's weights are such passes).
template <bool Add>
inline void scaled_row(double* out, double a, const double* in, std::size_t n) noexcept {
  using pair = double __attribute__((vector_size(16)));
  const pair a2 = {a, a};
  std::size_t q = 0;
#pragma GCC unroll 2
  for (; q + 2 <= n; q += 2) {
    pair x;
    std::memcpy(&x, in + q, sizeof x);
    pair y = a2 * x;
    if constexpr (Add) {
      pair o;
      std::memcpy(&o, out + q, sizeof o);
      y = o + y;
    }
    std::memcpy(out + q, &y, sizeof y);
  }
  if (q < n) out[q] = Add ? out[q] + a * in[q] : a * in[q];
}

// out[q] = c[0]·in[0][q] + c[1]·in[1][q] + … + c[T−1]·in[T−1][q] for q < n, added left to right:
// the same IEEE operations per element as scaled_row<false> with a = c[0] and T − 1 passes of
// scaled_row<true> (a·x = x·a), so the same bits, with out stored once instead of T times.
template <std::size_t T>
inline void combined_row(double* out, const double* c, const double* const* in,
                         std::size_t n) noexcept {
  using pair = double __attribute__((vector_size(16)));
  std::array<pair, T> c2;
  for (std::size_t t = 0; t < T; ++t) c2[t] = pair{c[t], c[t]};
  std::size_t q = 0;
#pragma GCC unroll 2
  for (; q + 2 <= n; q += 2) {
    pair x;
    std::memcpy(&x, in[0] + q, sizeof x);
    pair y = c2[0] * x;
    for (std::size_t t = 1; t < T; ++t) {
      std::memcpy(&x, in[t] + q, sizeof x);
      y = y + c2[t] * x;
    }
    std::memcpy(out + q, &y, sizeof y);
  }
  if (q < n) {
    double y = c[0] * in[0][q];
    for (std::size_t t = 1; t < T; ++t) y = y + c[t] * in[t][q];
    out[q] = y;
  }
}

}  // namespace detail

template <std::size_t D, class Coordinate>
void smolyak_grid::walk_rows(std::uint64_t first, std::span<double> x, std::span<double> weights,
                             const Coordinate& coordinate, const double* block_coordinate) const {
  require_weighted_batch(s_, total_, first, x, weights);
  const std::size_t count = weights.size();
  if (count == 0) return;
  const std::size_t s = s_;
  const std::size_t lead = s - D;  // the leading axes, 0 … s − d − 1
  const unsigned L = level_;
  const std::size_t width = L + 1;
  const nested_rule& rule = *rule_;

  // Per leading axis j: its id, the budget r_j = L − Σ_{i<j} birth(id_i), its coordinate, and the
  // truncated product P_{j+1} = P_j·A_j (degree ≤ r_j − birth(id_j)); P_0 = 1; budget[lead] is
  // the block's level. Two allocations per batch, never per point.
  std::vector<std::size_t> state(2 * lead + 1);
  std::size_t* id = state.data();
  std::size_t* budget = state.data() + lead;
  std::vector<double> values(lead + (lead + 1) * width, 0.0);
  double* axis_coordinate = values.data();
  double* product = values.data() + lead;
  product[0] = 1.0;
  budget[0] = L;
  // The T tables and the block sizes N_d(l), looked up once per batch.
  std::array<const double*, max_levels> table{};
  std::array<std::size_t, max_levels> block_size{};
  for (unsigned l = 0; l <= L; ++l) {
    table[l] = block_weights(l);
    block_size[l] = static_cast<std::size_t>(block_count(l));
  }

  // P_{j+1} from P_j and axis j's node: P_{j+1}[t] = Σ_{u+m=t} P_j[u]·d_{b+m}(id), t ≤ r_{j+1},
  // the differences d read from the node's contiguous table (nested_rule.hpp).
  auto place = [&](std::size_t j) {
    const std::size_t node = id[j];
    const std::size_t rest = budget[j] - rule.birth(node);
    budget[j + 1] = rest;
    axis_coordinate[j] = coordinate(j, node);
    const double* d = rule.differences_from_birth(node);
    const double* in = product + j * width;
    double* out = product + (j + 1) * width;
    // The sum from zero with its first term peeled (0.0 + x keeps its bits, as in the weights
    // below): most calls have rest ≤ 2, so the loop's overhead is what counts.
    for (std::size_t t = 0; t <= rest; ++t) {
      double sum = 0.0 + in[t] * d[0];
      for (std::size_t m = 1; m <= t; ++m) sum += in[t - m] * d[m];
      out[t] = sum;
    }
  };
  // Decode `first`: at leading axis j with budget r, the ids of birth level b hold new_count(b)
  // blocks of tuples(j + 1, r − b) tuples each; what remains is the index in the block.
  std::uint64_t rest = first;
  for (std::size_t j = 0; j < lead; ++j) {
    const auto r = static_cast<unsigned>(budget[j]);
    std::size_t base = 0;
    for (unsigned b = 0; b <= r; ++b) {
      const std::uint64_t per_id = tuples(j + 1, r - b);
      const std::uint64_t block = rule.new_count(b) * per_id;
      if (rest < block) {
        id[j] = base + static_cast<std::size_t>(rest / per_id);
        rest %= per_id;
        break;
      }
      rest -= block;
      base += static_cast<std::size_t>(rule.new_count(b));
    }
    place(j);
  }

  // The batch in rows: block nodes k … N_d(r) − 1 of the current leading tuple (r = its
  // budget), then a carry into the leading axes. A row's weights are r + 1 passes over prefixes
  // of the T tables, w_i = P[0]·T_r[i] + P[1]·T_(r−1)[i] + … (u ascending; a term with T_(r−u)
  // shorter than i is absent, one with P[u] = 0 is skipped). These are the bits of the sum from
  // zero, 0.0 + P[0]·T_r[i] + …: P[0] > 0 (a product of weights at birth levels, all positive
  // in the three families) and no T is −0 (a long double sum from zero, or a 1D weight > 0), so
  // no w is −0, and adding ±0 to it leaves its bits. Its points are written row-major, the
  // leading coordinates from registers (a length fixed at compile time for s − d <
  // max_fixed_axes), the last d from the block's table. The loops are unrolled by 4 (GCC's -O2
  // does not vectorize them): their control was a third of a point's cost (callgrind).
  auto emit_row = [&](auto leading_axes, std::size_t i, std::size_t k, std::size_t run) {
    constexpr std::size_t M = decltype(leading_axes)::value;
    const auto r = static_cast<unsigned>(budget[lead]);
    const double* p = product + lead * width;
    double* w_out = weights.data() + i;
    double* point = x.data() + i * s;
    const double* block = block_coordinate + k * D;
    detail::scaled_row<false>(w_out, p[0], table[r] + k, run);
    // The points, after the first term of each weight.
    if constexpr (M == detail::dynamic_axes) {
      for (std::size_t q = 0; q < run; ++q, point += s, block += D) {
        for (std::size_t j = 0; j < lead; ++j) point[j] = axis_coordinate[j];
        for (std::size_t c = 0; c < D; ++c) point[lead + c] = block[c];
      }
    } else {
      // A local copy, so the compiler can keep it in registers (axis_coordinate could alias x),
      // and fixed-length copies, which it turns into a few vector moves.
      std::array<double, M + 1> leading{};
      for (std::size_t j = 0; j < M; ++j) leading[j] = axis_coordinate[j];
#pragma GCC unroll 4
      for (std::size_t q = 0; q < run; ++q, point += s, block += D) {
        std::memcpy(point, leading.data(), M * sizeof(double));
        std::memcpy(point + M, block, D * sizeof(double));
      }
    }
    for (unsigned u = 1; u <= r; ++u) {
      const std::size_t size = block_size[r - u];
      if (size <= k) break;  // the sizes fall with u
      const double pu = p[u];
      if (pu == 0.0) continue;
      const std::size_t n = std::min(size - k, run);
      detail::scaled_row<true>(w_out, pu, table[r - u] + k, n);
    }
  };
  std::size_t k = static_cast<std::size_t>(rest);
  for (std::size_t i = 0; i < count;) {
    const std::size_t end = block_size[budget[lead]];
    const std::size_t run = std::min<std::size_t>(end - k, count - i);
    detail::with_leading_axes(lead, [&](auto M) { emit_row(M, i, k, run); });
    i += run;
    k += run;
    if (k == end && i < count) {
      // Carry: the rightmost leading axis whose next id still fits its budget moves; the axes
      // after it restart at id 0 (birth 0 always fits). With no leading axis (d = s) the block
      // is the whole grid and this is never reached.
      std::size_t j = lead;
      while (j-- > 0) {
        if (id[j] + 1 < rule.count(static_cast<unsigned>(budget[j]))) break;
      }
      // j wraps past 0 only at the grid's end, which the batch check excludes.
      ++id[j];
      place(j);
      for (std::size_t t = j + 1; t < lead; ++t) {
        id[t] = 0;
        place(t);
      }
      k = 0;
    }
  }
}

template <std::size_t D, class Coordinate>
void smolyak_grid::walk_groups(std::uint64_t first, std::span<double> x, std::span<double> weights,
                               const Coordinate& coordinate, const double* block_coordinate,
                               const double* first_axis) const {
  require_weighted_batch(s_, total_, first, x, weights);
  const std::size_t count = weights.size();
  if (count == 0) return;
  constexpr std::size_t s = D + 1;
  const unsigned L = level_;
  const nested_rule& rule = *rule_;
  std::array<const double*, max_levels> table{};
  std::array<std::size_t, max_levels> block_size{};
  for (unsigned l = 0; l <= L; ++l) {
    table[l] = block_weights(l);
    block_size[l] = static_cast<std::size_t>(block_count(l));
  }
  // The group of `first`: birth b of the first axis, n0 = new_count(b) ids times N_d(L − b)
  // block nodes each.
  unsigned b = 0;
  std::uint64_t rest = first;
  while (true) {
    const std::uint64_t group = rule.new_count(b) * block_size[L - b];
    if (rest < group) break;
    rest -= group;
    ++b;
  }
  for (std::size_t i = 0; i < count; ++b, rest = 0) {
    const unsigned r = L - b;
    const auto n0 = static_cast<std::size_t>(rule.new_count(b));
    const std::size_t m = block_size[r];
    const std::size_t first_id = b == 0 ? 0 : static_cast<std::size_t>(rule.count(b - 1));
    if (n0 <= m) {
      // Rows over the block: the first axis's id first_id + k fixed, the block nodes q … in
      // shell order; P[u] = d_(b+u)(id), so these are walk_rows' bits (its P_1 is exactly d).
      auto k = static_cast<std::size_t>(rest / m);
      auto q = static_cast<std::size_t>(rest % m);
      for (; i < count && k < n0; ++k, q = 0) {
        const std::size_t id = first_id + k;
        const std::size_t run = std::min(m - q, count - i);
        const double* p = rule.differences_from_birth(id);
        double* w_out = weights.data() + i;
        detail::scaled_row<false>(w_out, p[0], table[r] + q, run);
        const double leading = coordinate(0, id);
        double* point = x.data() + i * s;
        const double* block = block_coordinate + q * D;
#pragma GCC unroll 4
        for (std::size_t c = 0; c < run; ++c, point += s, block += D) {
          point[0] = leading;
          std::memcpy(point + 1, block, D * sizeof(double));
        }
        for (unsigned u = 1; u <= r; ++u) {
          const std::size_t size = block_size[r - u];
          if (size <= q) break;
          if (p[u] == 0.0) continue;
          detail::scaled_row<true>(w_out, p[u], table[r - u] + q, std::min(size - q, run));
        }
        i += run;
      }
    } else {
      // Rows over the first axis (more new ids than block nodes: the high birth levels, where
      // the rows over the block would be a few points long): block node q fixed, ids first_id
      // + k …, w_k = Σ_u T_(r−u)[q]·d_(b+u)[k] in ascending u over the u with q < N_d(r − u) —
      // the same products (a·b = b·a) added in the same order as the rows over the block; the
      // zero products those skip add ±0 to a weight that is never −0 (walk_rows), so the bits
      // are the same.
      auto q = static_cast<std::size_t>(rest / n0);
      auto k = static_cast<std::size_t>(rest % n0);
      for (; i < count && q < m; ++q, k = 0) {
        const std::size_t run = std::min(n0 - k, count - i);
        double* w_out = weights.data() + i;
        // The terms u = 0 … with q < N_d(r − u): most block nodes have one to three (a node born
        // at level t has r − t + 1), summed in one pass.
        unsigned terms = 1;
        while (terms <= r && q < block_size[r - terms]) ++terms;
        std::array<double, max_levels> c;
        std::array<const double*, max_levels> in;
        for (unsigned u = 0; u < terms; ++u) {
          c[u] = table[r - u][q];
          in[u] = rule.differences_by_birth(b, u) + k;
        }
        switch (terms) {
          case 1:
            detail::combined_row<1>(w_out, c.data(), in.data(), run);
            break;
          case 2:
            detail::combined_row<2>(w_out, c.data(), in.data(), run);
            break;
          case 3:
            detail::combined_row<3>(w_out, c.data(), in.data(), run);
            break;
          default:
            detail::combined_row<4>(w_out, c.data(), in.data(), run);
            for (unsigned u = 4; u < terms; ++u) {
              detail::scaled_row<true>(w_out, c[u], in[u], run);
            }
            break;
        }
        std::array<double, D> block{};
        std::memcpy(block.data(), block_coordinate + q * D, D * sizeof(double));
        double* point = x.data() + i * s;
        const double* leading = first_axis + first_id + k;
#pragma GCC unroll 4
        for (std::size_t c = 0; c < run; ++c, point += s) {
          point[0] = leading[c];
          std::memcpy(point + 1, block.data(), D * sizeof(double));
        }
        i += run;
      }
    }
  }
}

}  // namespace quadmc
