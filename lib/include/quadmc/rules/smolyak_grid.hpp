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
// How it generates (no grid is stored; memory O(s·L) beyond the 1D tables):
//  - nodes are the tuples of 1D ids (id_1, …, id_s) with Σ birth(id_j) ≤ L, in lexicographic
//    order, last axis fastest. count[j][r], the number of tuples of axes j…s−1 with levels summing
//    to ≤ r (an s × (L + 1) table), decodes an index into its tuple in O(s·L) once per batch; the
//    batch then walks like an odometer;
//  - the truncated products P_j = Π_{i<j} A_i are kept per axis and recomputed only when axis j
//    moves (O(L²) at a carry), so a node costs the R + 1 multiply-adds of its last axis and the
//    copy of its coordinates: most nodes have R = 0 or 1. The factors d_l(x) and C(t) are read
//    from the 1D rule's by-node tables (nested_rule.hpp: a node's weights and differences from
//    its birth on, contiguous, the differences computed once per process), and a point's s − 1
//    leading coordinates are copied with a length fixed at compile time; both because runs along
//    the last axis are short (2 to 4 nodes on average at s = 4 to 8), so the per-run and
//    per-point overheads, not the arithmetic, set the speed (measured with callgrind on the Genz
//    Gaussian: bench/rules_bench.cpp, equal_n);
//  - the weights are a pure function of the node (every product is formed from the same factors
//    in the same order, wherever a batch starts), so the sum is bitwise the same on any thread
//    count;
//  - mapped(map) writes box coordinates directly, the fast path of weighted_point_set.hpp.
// Memory bound: the tables count[s][L + 1] (8 bytes each) and, per batch, s·(L + 1) doubles of
// products; the 1D rule's tables are shared (nested_rule.hpp). At s = 16, L = 6: 1.7 KiB per grid
// for 2.6·10⁵ nodes.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/rules/nested_rule.hpp"
#include "quadmc/rules/weighted_point_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
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

  // Nodes in [0, 1]^s and their weights (the weighted_point_set contract).
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    walk(
        first, nodes, weights, [this](std::size_t, std::size_t id) { return rule_->node(id); },
        [this](std::size_t id) { return rule_->node(id); });
  }

  class on_box {
   public:
    on_box(const smolyak_grid& grid, const cube_to_box& map) : grid_(&grid), map_(map) {
      require(map_.dimension() == grid.s_, "box dimension", map_.dimension(),
              fmt::format("the grid's dimension {}", grid.s_));
      const std::size_t last = grid.s_ - 1;
      const auto n = static_cast<std::size_t>(grid.rule_->count(grid.level_));
      last_coordinate_.resize(n);
      for (std::size_t id = 0; id < n; ++id)
        last_coordinate_[id] = map_(last, grid.rule_->node(id));
    }
    void generate(std::uint64_t first, std::span<double> x, std::span<double> weights) const {
      grid_->walk(
          first, x, weights,
          [this](std::size_t j, std::size_t id) { return map_(j, grid_->rule_->node(id)); },
          [this](std::size_t id) { return last_coordinate_[id]; });
    }

   private:
    const smolyak_grid* grid_;
    cube_to_box map_;
    std::vector<double> last_coordinate_;
  };
  // The same points in the box of `map`, bitwise what generate() and map.apply() give. Refers to
  // this grid, which must outlive it.
  on_box mapped(const cube_to_box& map) const { return on_box(*this, map); }

  // Σ|w_i| over the grid (1 for positive weights; larger with signed ones: the factor by which
  // rounding errors in f are amplified, weighted_point_set.hpp), by one pass over the weights.
  double absolute_weight_sum() const;

 private:
  // count_[j·(L + 1) + r]: tuples of axes j…s−1 whose birth levels sum to ≤ r.
  std::uint64_t tuples(std::size_t j, unsigned r) const noexcept {
    return j == s_ ? 1 : count_[j * (level_ + 1) + r];
  }

  template <class Coordinate, class Last>
  void walk(std::uint64_t first, std::span<double> x, std::span<double> weights,
            const Coordinate& coordinate, const Last& last_coordinate) const;

  const nested_rule* rule_;
  std::size_t s_;
  unsigned level_;
  std::vector<std::uint64_t> count_;
  std::uint64_t total_ = 0;
};

namespace detail {

// smolyak_grid's walk copies a point's s − 1 leading coordinates with a length fixed at compile
// time for s − 1 < max_fixed_axes (straight-line moves; a loop of variable length is turned into
// a call to memcpy per point by GCC, which cost more than the point's weight); dynamic_axes is
// the loop for larger s.
inline constexpr std::size_t max_fixed_axes = 16;
inline constexpr std::size_t dynamic_axes = std::numeric_limits<std::size_t>::max();

template <std::size_t... J>
void copy_fixed(double* to, const double* from, std::index_sequence<J...>) noexcept {
  ((to[J] = from[J]), ...);
}

// f(std::integral_constant<std::size_t, m>{}) for m < max_fixed_axes, else
// f(std::integral_constant<std::size_t, dynamic_axes>{}): one switch per run of the walk.
template <class F>
void with_leading_axes(std::size_t m, const F& f) {
  [&]<std::size_t... M>(std::index_sequence<M...>) {
    const bool fixed =
        ((m == M ? (f(std::integral_constant<std::size_t, M>{}), true) : false) || ...);
    if (!fixed) f(std::integral_constant<std::size_t, dynamic_axes>{});
  }
  (std::make_index_sequence<max_fixed_axes>{});
}

}  // namespace detail

template <class Coordinate, class Last>
void smolyak_grid::walk(std::uint64_t first, std::span<double> x, std::span<double> weights,
                        const Coordinate& coordinate, const Last& last_coordinate) const {
  require_weighted_batch(s_, total_, first, x, weights);
  const std::size_t count = weights.size();
  if (count == 0) return;
  const std::size_t s = s_;
  const std::size_t last = s - 1;
  const unsigned L = level_;
  const std::size_t width = L + 1;
  const nested_rule& rule = *rule_;

  // Per axis j: its id, the budget r_j = L − Σ_{i<j} birth(id_i), its coordinate, and the
  // truncated product P_{j+1} = P_j·A_j (degree ≤ r_j − birth(id_j)); P_0 = 1. Two allocations
  // per batch, never per point.
  std::vector<std::size_t> state(2 * s + 1);
  std::size_t* id = state.data();
  std::size_t* budget = state.data() + s;
  std::vector<double> values(s + (s + 1) * width, 0.0);
  double* axis_coordinate = values.data();
  double* product = values.data() + s;
  product[0] = 1.0;
  budget[0] = L;

  // P_{j+1} from P_j and axis j's node: P_{j+1}[t] = Σ_{u+m=t} P_j[u]·d_{b+m}(id), t ≤ r_{j+1},
  // the differences d read from the node's contiguous table (nested_rule.hpp).
  auto place = [&](std::size_t j) {
    const std::size_t node = id[j];
    const std::size_t rest = budget[j] - rule.birth(node);
    budget[j + 1] = rest;
    if (j < last) axis_coordinate[j] = coordinate(j, node);
    const double* d = rule.differences_from_birth(node);
    const double* in = product + j * width;
    double* out = product + (j + 1) * width;
    // The sum from zero with its first term peeled (0.0 + x keeps its bits, as in the last
    // axis's weights below): most calls have rest ≤ 2, so the loop's overhead is what counts.
    for (std::size_t t = 0; t <= rest; ++t) {
      double sum = 0.0 + in[t] * d[0];
      for (std::size_t m = 1; m <= t; ++m) sum += in[t - m] * d[m];
      out[t] = sum;
    }
  };
  // Decode `first`: at axis j with budget r, the ids of birth level b hold new_count(b) blocks of
  // tuples(j + 1, r − b) tuples each.
  std::uint64_t rest = first;
  for (std::size_t j = 0; j < s; ++j) {
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
    if (j < last) place(j);  // the last axis's budget is set by place(last − 1)
  }

  // The batch in runs along the last axis (its ids 0 … count(r_last) − 1 for the current leading
  // ids), then a carry into the leading axes. Runs are short (2 to 4 points on average at s = 4 to
  // 8: most leading tuples use up most of the budget), so a point is written row by row — its
  // s − 1 leading coordinates copied from axis_coordinate, then the last one — and not column by
  // column per run as in tensor_product_grid.hpp, whose loop overhead per column was paid for
  // every 2 points here. The copy has a length fixed at compile time for s ≤ max_fixed_axes (a
  // few vector moves; a variable length is a call to memcpy per point, which cost more than the
  // point's weight), chosen once per run.
  auto emit_run = [&](auto leading_axes, std::size_t i, std::size_t k, std::size_t run) {
    constexpr std::size_t M = decltype(leading_axes)::value;
    const std::size_t r = budget[last];
    const double* leading = product + last * width;
    double* row = x.data() + i * s;
    double* w_out = weights.data() + i;
    for (std::size_t q = 0; q < run; ++q) {
      const std::size_t node = k + q;
      const std::size_t R = r - rule.birth(node);
      // Σ_{u ≤ R} P[u]·C(R − u), C(t) = weight of the node in U^(b + t), summed from u = 0 as
      // the sum w = 0 + …: 0.0 + the first term keeps the bits of a sum that starts at zero.
      const double* c = rule.weights_from_birth(node);
      double w = 0.0 + leading[0] * c[R];
      for (std::size_t u = 1; u <= R; ++u) w += leading[u] * c[R - u];
      w_out[q] = w;
      double* point = row + q * s;
      if constexpr (M == detail::dynamic_axes) {
        for (std::size_t j = 0; j < last; ++j) point[j] = axis_coordinate[j];
      } else {
        detail::copy_fixed(point, axis_coordinate, std::make_index_sequence<M>{});
      }
      point[last] = last_coordinate(node);
    }
  };
  std::size_t k = id[last];
  for (std::size_t i = 0; i < count;) {
    const std::size_t r = budget[last];
    const auto end = static_cast<std::size_t>(rule.count(static_cast<unsigned>(r)));
    const std::size_t run = std::min<std::size_t>(end - k, count - i);
    detail::with_leading_axes(last, [&](auto M) { emit_run(M, i, k, run); });
    i += run;
    k += run;
    if (k == end && i < count) {
      // Carry: the rightmost leading axis whose next id still fits its budget moves; the axes
      // after it restart at id 0 (birth 0 always fits).
      std::size_t j = last;
      while (j-- > 0) {
        if (id[j] + 1 < rule.count(static_cast<unsigned>(budget[j]))) break;
      }
      // j wraps past 0 only at the grid's end, which the batch check excludes.
      ++id[j];
      place(j);
      for (std::size_t t = j + 1; t < last; ++t) {
        id[t] = 0;
        place(t);
      }
      k = 0;
    }
  }
}

}  // namespace quadmc
