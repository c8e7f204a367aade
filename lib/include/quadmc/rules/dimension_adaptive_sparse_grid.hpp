// The dimension-adaptive sparse grid of [Gerstner & Griebel 2003]: a Smolyak-type rule
// Q_I = Σ_{k ∈ I} Δ_{k_1} ⊗ … ⊗ Δ_{k_s} over a downward-closed set I of level multi-indices that
// grows where the integrand's surpluses |Δ_k f| are largest, with its own error estimate.
//
// Use it when the dimensions matter unequally (a Genz family with unequal a_i, an integrand of low
// effective dimension) or when a tolerance rather than a size is given; on the nested rules of
// nested_rule.hpp (Clenshaw–Curtis or Gauss–Patterson). Not for integrands with jumps or kinks:
// the surplus then does not decay monotonically and the estimate can stop early
// (docs/theory.md#dimension-adaptive-sparse-grid); and not when a fixed, reproducible node set is
// wanted (smolyak_grid.hpp).
//
// The algorithm ([Gerstner & Griebel 2003, §3], with their weight w = 1: the indicator is the
// surplus alone):
//   the old set O = ∅, the active set A = {0}; η = Σ_{k ∈ A} |Δ_k f|;
//   repeat: take the k ∈ A with the largest |Δ_k f| (ties: the earlier index), move it to O, and
//   add to A every forward neighbour k + e_j whose backward neighbours k + e_j − e_i are all in O
//   (admissible, so I = O ∪ A stays downward closed), computing its surplus;
//   until η ≤ the tolerance (checked once the centre 0 is in O), or the next step's new nodes
//   would exceed the budget, or A is empty.
// The estimate is Q = Σ_{k ∈ O ∪ A} Δ_k f and its error estimate η (the surpluses not yet
// refined: the next terms of the series) plus the rounding of Q, 4ε·Σ|w_i f_i|. An index that
// cannot grow along an axis because the rule's tables end there keeps its surplus in η. η is a
// heuristic, not a bound: it misses the terms beyond the active front, which on a product of
// slowly decaying factors in s ≥ 4 (Genz's product peak) can be many times η.
//
// Evaluations: because the rules are nested, Δ_k f needs f on the full tensor grid of k, but only
// the block of nodes new in k (the tensor product of the new 1D nodes of each k_j) is evaluated;
// the others were evaluated with the blocks b ≤ k, which I holds. So N = distinct nodes. f is
// evaluated block by block in batches of ≤ 256 points; every value is kept (8 bytes) with the
// node's weight in Q_I (8 bytes): memory O(N), which is why the method caps N
// (adaptive_sparse_grid_max_evaluations). Each weight is accumulated as the surpluses are formed,
// so Σ|w| of the rule that ran is known (the rounding scale of weighted_point_set.hpp).
// Serial and deterministic: the same bits for any thread count.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/rules/nested_rule.hpp"
#include "quadmc/rules/weighted_point_set.hpp"
#include "quadmc/rules/weighted_sum.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace quadmc {

// What one run may keep: 2^22 evaluations are 64 MiB of values and weights.
inline constexpr std::uint64_t adaptive_sparse_grid_max_evaluations = std::uint64_t{1} << 22;

struct adaptive_sparse_grid_options {
  std::uint64_t max_evaluations = 1u << 16;  // the budget; at most the cap above
  // Stop when η ≤ max(absolute_tolerance, relative_tolerance·|Q|) (both 0: run to the budget).
  double absolute_tolerance = 0.0;
  double relative_tolerance = 0.0;
};

struct adaptive_sparse_grid_result {
  double value = 0.0;
  // vol·(η + 4ε·Σ|w_i f_i|): the active surpluses and the rounding of the sum
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t evaluations = 0;
  double absolute_weight_sum = 1.0;  // Σ|w| of the final rule (unit cube)
  std::size_t indices = 0;           // |O ∪ A|
  bool converged = false;            // stopped on the tolerance, not the budget
};

template <integrand F>
adaptive_sparse_grid_result dimension_adaptive_sparse_grid(
    const F& f, const nested_rule& rule, const adaptive_sparse_grid_options& options) {
  const integrand_info info = detail::checked_integrand_info(f);
  const std::size_t s = info.dimension();
  require(
      options.max_evaluations >= 1 &&
          options.max_evaluations <= adaptive_sparse_grid_max_evaluations,
      "adaptive sparse grid max_evaluations", options.max_evaluations,
      fmt::format("between 1 and {} (every value is kept)", adaptive_sparse_grid_max_evaluations));
  require(options.absolute_tolerance >= 0.0, "absolute_tolerance", options.absolute_tolerance,
          ">= 0");
  require(options.relative_tolerance >= 0.0, "relative_tolerance", options.relative_tolerance,
          ">= 0");
  const cube_to_box map(info.domain);
  const double volume = info.domain.volume();
  const unsigned top = rule.max_level();

  struct index_entry {
    std::size_t offset = 0;  // first value of its block
    std::size_t size = 0;    // nodes new in it
    double surplus = 0.0;    // Δ_k f on the unit cube
    bool old = false;
  };
  std::vector<unsigned char> levels;  // s per index, in creation order
  std::vector<index_entry> entries;
  std::unordered_map<std::string, std::size_t> position;
  std::vector<double> values;  // f at the nodes, block after block
  std::vector<double> weight;  // each node's weight in Q_I
  std::vector<double> x(batch_points * s);
  std::vector<double> y(batch_points);
  std::vector<std::size_t> id(s), lo(s), hi(s);
  std::vector<unsigned> b(s);

  auto key_of = [&](const unsigned char* k) {
    return std::string(reinterpret_cast<const char*>(k), s);
  };
  auto first_id = [&](unsigned l) -> std::size_t { return l == 0 ? 0 : rule.count(l - 1); };
  auto new_nodes = [&](const unsigned char* k) {
    std::uint64_t n = 1;
    for (std::size_t j = 0; j < s; ++j) n *= rule.new_count(k[j]);
    return n;
  };
  // d_l(id): the weight of node id in U^l − U^(l−1).
  auto delta = [&](unsigned l, std::size_t node) {
    const double below = l > 0 && node < rule.count(l - 1) ? rule.weight(l - 1, node) : 0.0;
    return rule.weight(l, node) - below;
  };

  // Evaluates the block of index k (new ids of each level, last axis fastest).
  auto evaluate_block = [&](const unsigned char* k, std::size_t size) {
    const std::size_t offset = values.size();
    values.resize(offset + size);
    weight.resize(offset + size, 0.0);
    for (std::size_t j = 0; j < s; ++j) id[j] = first_id(k[j]);
    std::size_t done = 0;
    while (done < size) {
      const std::size_t count = std::min<std::size_t>(batch_points, size - done);
      for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t j = 0; j < s; ++j) x[i * s + j] = map(j, rule.node(id[j]));
        for (std::size_t j = s; j-- > 0;) {
          if (++id[j] < rule.count(k[j])) break;
          id[j] = first_id(k[j]);
        }
      }
      const std::span<const double> xs(x.data(), count * s);
      const std::span<double> ys(y.data(), count);
      f.evaluate(xs, ys);
      check_finite_batch(info.name, xs, ys, s);
      std::copy(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(count),
                values.begin() + static_cast<std::ptrdiff_t>(offset + done));
      done += count;
    }
    return offset;
  };

  // Δ_k f = Σ_{b ≤ k} Σ_{x ∈ block b} Π_j d_{k_j}(x_j)·f(x); adds each term's factor to its
  // node's weight.
  auto surplus_of = [&](const unsigned char* k) {
    neumaier_sum sum;
    std::fill(b.begin(), b.end(), 0u);
    std::vector<unsigned char> bk(s);
    while (true) {
      for (std::size_t j = 0; j < s; ++j) bk[j] = static_cast<unsigned char>(b[j]);
      const index_entry& e = entries[position.at(key_of(bk.data()))];
      for (std::size_t j = 0; j < s; ++j) {
        lo[j] = first_id(b[j]);
        hi[j] = rule.count(b[j]);
        id[j] = lo[j];
      }
      for (std::size_t i = 0; i < e.size; ++i) {
        double factor = 1.0;
        for (std::size_t j = 0; j < s; ++j) factor *= delta(k[j], id[j]);
        sum.add(factor * values[e.offset + i]);
        weight[e.offset + i] += factor;
        for (std::size_t j = s; j-- > 0;) {
          if (++id[j] < hi[j]) break;
          id[j] = lo[j];
        }
      }
      std::size_t j = s;
      while (j-- > 0) {
        if (++b[j] <= k[j]) break;
        b[j] = 0;
      }
      if (j == static_cast<std::size_t>(-1)) break;
    }
    return sum.value();
  };

  // Adds index k (its block evaluated, its surplus formed) and returns its position.
  auto add_index = [&](const std::vector<unsigned char>& k) {
    index_entry e;
    e.size = static_cast<std::size_t>(new_nodes(k.data()));
    e.offset = evaluate_block(k.data(), e.size);
    const std::size_t at = entries.size();
    levels.insert(levels.end(), k.begin(), k.end());
    entries.push_back(e);
    position.emplace(key_of(k.data()), at);
    entries[at].surplus = surplus_of(k.data());
    return at;
  };

  // The active set by surplus, ties to the earlier index.
  using ranked = std::pair<double, std::size_t>;
  auto lower = [](const ranked& a, const ranked& c) {
    return a.first < c.first || (a.first == c.first && a.second > c.second);
  };
  std::priority_queue<ranked, std::vector<ranked>, decltype(lower)> active(lower);
  neumaier_sum eta;       // Σ |Δ| over the active set and the indices that cannot grow
  neumaier_sum estimate;  // Σ Δ over O ∪ A

  const std::size_t origin = add_index(std::vector<unsigned char>(s, 0));
  active.emplace(std::abs(entries[origin].surplus), origin);
  eta.add(std::abs(entries[origin].surplus));
  estimate.add(entries[origin].surplus);

  adaptive_sparse_grid_result out;
  std::vector<unsigned char> k(s), neighbour(s), back(s);
  std::vector<std::vector<unsigned char>> admissible;
  while (true) {
    const double q = estimate.value();
    const double target =
        std::max(options.absolute_tolerance, options.relative_tolerance * std::abs(q));
    // One value says nothing about how the surpluses decay (a jump or a peak missed by the
    // centre gives η = 0), so the tolerance is checked only once the centre has been refined.
    if (entries[origin].old && eta.value() <= target) {
      out.converged = true;
      break;
    }
    if (active.empty()) break;
    const std::size_t at = active.top().second;
    std::copy_n(levels.begin() + static_cast<std::ptrdiff_t>(at * s), s, k.begin());
    // Its forward neighbours that would be admissible once k is old.
    admissible.clear();
    std::uint64_t cost = 0;
    bool capped = false;
    for (std::size_t j = 0; j < s; ++j) {
      if (k[j] >= top) {
        capped = true;
        continue;
      }
      neighbour = k;
      ++neighbour[j];
      bool ok = true;
      for (std::size_t i = 0; i < s && ok; ++i) {
        if (i == j || neighbour[i] == 0) continue;
        back = neighbour;
        --back[i];
        const auto found = position.find(key_of(back.data()));
        ok = found != position.end() && entries[found->second].old;
      }
      if (!ok) continue;
      admissible.push_back(neighbour);
      cost += new_nodes(neighbour.data());
    }
    if (values.size() + cost > options.max_evaluations) break;  // the budget ends the run
    active.pop();
    entries[at].old = true;
    // k leaves A; its surplus stays in η if an axis cannot be refined past the tables.
    if (!capped) eta.add(-std::abs(entries[at].surplus));
    for (const auto& next : admissible) {
      const std::size_t added = add_index(next);
      const double d = entries[added].surplus;
      active.emplace(std::abs(d), added);
      eta.add(std::abs(d));
      estimate.add(d);
    }
  }
  neumaier_sum abs_weights;
  neumaier_sum abs_terms;
  for (std::size_t i = 0; i < weight.size(); ++i) {
    abs_weights.add(std::abs(weight[i]));
    abs_terms.add(std::abs(weight[i] * values[i]));
  }
  out.value = volume * estimate.value();
  // η plus the rounding of Q itself: values each off by a few ulp, summed with weights of both
  // signs, move Q by up to about 4ε·Σ|w_i f_i| [Higham 2002, §4.3]; η alone falls below that once
  // the surpluses are resolved to rounding.
  const double rounding = 4.0 * std::numeric_limits<double>::epsilon() * abs_terms.value();
  out.error_estimate = volume * (std::max(0.0, eta.value()) + rounding);
  out.evaluations = values.size();
  out.absolute_weight_sum = abs_weights.value();
  out.indices = entries.size();
  return out;
}

}  // namespace quadmc
