// The tables of smolyak_block.hpp.
#include "quadmc/rules/smolyak_block.hpp"

#include "quadmc/core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <mutex>

namespace quadmc {

smolyak_block::smolyak_block(const nested_rule& rule, std::size_t d) : d_(d) {
  require(d >= 2, "sparse grid block axes d", d, "at least 2");
  // N_c(l) for c = 1 … d by N_c(l) = Σ_b new_count(b)·N_(c−1)(l − b), N_0 = 1, up to the cap.
  std::vector<std::uint64_t> previous;
  for (unsigned l = 0; l <= rule.max_level(); ++l) previous.push_back(rule.count(l));
  for (std::size_t c = 2; c <= d; ++c) {
    std::vector<std::uint64_t> next;
    for (unsigned l = 0; l < previous.size(); ++l) {
      std::uint64_t total = 0;
      for (unsigned b = 0; b <= l; ++b) total += rule.new_count(b) * previous[l - b];
      if (total > block_nodes_cap) break;
      next.push_back(total);
    }
    previous = std::move(next);
  }
  count_ = std::move(previous);  // level 0 has one node, so never empty
  const unsigned top = level();
  const auto n = static_cast<std::size_t>(count_[top]);

  // The ids of the nodes, d per node, in shell order.
  std::vector<std::size_t> ids;
  ids.reserve(n * d);
  std::vector<unsigned> birth(d);
  std::vector<std::size_t> id(d);
  auto first_new = [&rule](unsigned b) -> std::size_t {
    return b == 0 ? 0 : static_cast<std::size_t>(rule.count(b - 1));
  };
  // Every id tuple with the births in `birth`, lexicographic.
  auto emit_ids = [&] {
    for (std::size_t c = 0; c < d; ++c) id[c] = first_new(birth[c]);
    while (true) {
      ids.insert(ids.end(), id.begin(), id.end());
      std::size_t c = d;
      while (c-- > 0) {
        if (++id[c] < rule.count(birth[c])) break;
        id[c] = first_new(birth[c]);
      }
      if (c == static_cast<std::size_t>(-1)) return;
    }
  };
  // Every birth tuple with |b|₁ = t, lexicographic.
  auto births_of_shell = [&](auto& self, std::size_t c, unsigned rest) -> void {
    if (c + 1 == d) {
      birth[c] = rest;
      emit_ids();
      return;
    }
    for (unsigned b = 0; b <= rest; ++b) {
      birth[c] = b;
      self(self, c + 1, rest - b);
    }
  };
  for (unsigned t = 0; t <= top; ++t) {
    births_of_shell(births_of_shell, 0, t);
    if (ids.size() != count_[t] * d) {
      throw invalid_argument("sparse grid block shell", quote(t),
                             fmt::format("{} nodes up to it, the count's", count_[t]));
    }
  }

  nodes_.resize(n * d);
  for (std::size_t i = 0; i < n * d; ++i) nodes_[i] = rule.node(ids[i]);
  offset_.resize(top + 1);
  std::size_t offset = 0;
  for (unsigned l = 0; l <= top; ++l) {
    offset_[l] = offset;
    offset += static_cast<std::size_t>(count_[l]);
  }
  weights_.assign(offset, 0.0);

  std::vector<long double> coefficient(top + 1), next(top + 1), delta(top + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t* node = ids.data() + i * d;
    unsigned t = 0;
    for (std::size_t c = 0; c < d; ++c) t += rule.birth(node[c]);
    const unsigned degree = top - t;
    std::fill(coefficient.begin(), coefficient.end(), 0.0L);
    coefficient[0] = 1.0L;
    for (std::size_t c = 0; c < d; ++c) {
      const unsigned b = rule.birth(node[c]);
      for (unsigned m = 0; m <= degree; ++m) {
        const long double below =
            m == 0 ? 0.0L : static_cast<long double>(rule.weight(b + m - 1, node[c]));
        delta[m] = static_cast<long double>(rule.weight(b + m, node[c])) - below;
      }
      for (unsigned v = 0; v <= degree; ++v) {
        long double sum = 0.0L;
        for (unsigned m = 0; m <= v; ++m) sum += coefficient[v - m] * delta[m];
        next[v] = sum;
      }
      std::copy(next.begin(), next.begin() + degree + 1, coefficient.begin());
    }
    long double partial = 0.0L;
    for (unsigned v = 0; v <= degree; ++v) {
      partial += coefficient[v];
      weights_[offset_[t + v] + i] = static_cast<double>(partial);
    }
  }
}

const smolyak_block& smolyak_block_table(nested_rule_kind kind, std::size_t d) {
  require(d == 2 || d == 3, "sparse grid block axes d", d, "2 or 3");
  // One slot per family and d, each built once: a grid of another family or d does not pay for
  // it, and the tables never move once built.
  static std::array<std::once_flag, 6> built;
  static std::array<std::vector<smolyak_block>, 6> blocks;  // one element once built
  const std::size_t slot = static_cast<std::size_t>(kind) * 2 + (d - 2);
  std::call_once(built[slot], [&] { blocks[slot].emplace_back(nested_rule_table(kind), d); });
  return blocks[slot].front();
}

}  // namespace quadmc
