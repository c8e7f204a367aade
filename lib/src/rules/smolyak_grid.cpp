// The count table, the choice of the block and the weight sum of smolyak_grid.hpp.
#include "quadmc/rules/smolyak_grid.hpp"

namespace quadmc {
namespace {

// count[j·(L + 1) + r] for j = s − 1 … 0 (the recursion of smolyak_grid.hpp), or nullopt when a
// count does not fit in 64 bits.
std::optional<std::vector<std::uint64_t>> count_table(const nested_rule& rule, std::size_t s,
                                                      unsigned level) {
  require(s >= 1, "dimension s", s, "at least 1");
  require(level <= rule.max_level(), "sparse grid level L", level,
          fmt::format("at most {}, the largest level of the {} tables", rule.max_level(),
                      to_string(rule.kind())));
  const std::size_t width = level + 1;
  std::vector<std::uint64_t> table(s * width);
  for (std::size_t j = s; j-- > 0;) {
    for (unsigned r = 0; r <= level; ++r) {
      std::uint64_t total = 0;
      for (unsigned b = 0; b <= r; ++b) {
        const std::uint64_t after = j + 1 == s ? 1 : table[(j + 1) * width + (r - b)];
        std::uint64_t term = 0;
        if (__builtin_mul_overflow(rule.new_count(b), after, &term) ||
            __builtin_add_overflow(total, term, &total)) {
          return std::nullopt;
        }
      }
      table[j * width + r] = total;
    }
  }
  return table;
}

}  // namespace

std::optional<std::uint64_t> smolyak_point_count(const nested_rule& rule, std::size_t s,
                                                 unsigned level) {
  const auto table = count_table(rule, s, level);
  if (!table) return std::nullopt;
  return (*table)[level];  // j = 0, r = L
}

smolyak_grid::smolyak_grid(const nested_rule& rule, std::size_t s, unsigned level)
    : rule_(&rule), s_(s), level_(level) {
  auto table = count_table(rule, s, level);
  if (!table) {
    throw invalid_argument("sparse grid level L", quote(level),
                           fmt::format("a grid whose node count fits in 64 bits in s = {}", s));
  }
  count_ = std::move(*table);
  total_ = count_[level];
  static_assert(max_levels > 16, "nested_rule_max_level is at most 16");
  // d: the largest of 2 and 3 with d ≤ s that keeps the block within the cap. d = s makes the
  // whole grid one block (s = 2, 3 at small levels): one row, a straight run over the table.
  for (std::size_t d = 2; d <= 3; ++d) {
    if (d <= s && tuples(s - d, level) <= smolyak_block::block_nodes_cap) block_axes_ = d;
  }
  if (block_axes_ >= 2) {
    block_ = &smolyak_block_table(rule.kind(), block_axes_);
    if (block_->level() < level) {  // N_d is increasing in the level, so this cannot happen
      throw invalid_argument("sparse grid level L", quote(level),
                             fmt::format("at most the block table's level {}", block_->level()));
    }
  }
}

double smolyak_grid::absolute_weight_sum() const {
  neumaier_sum sum;
  constexpr std::size_t batch = 256;
  std::vector<double> x(batch * s_), w(batch);
  for (std::uint64_t first = 0; first < total_; first += batch) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(batch, total_ - first));
    generate(first, std::span<double>(x.data(), n * s_), std::span<double>(w.data(), n));
    for (std::size_t i = 0; i < n; ++i) sum.add(std::abs(w[i]));
  }
  return sum.value();
}

}  // namespace quadmc
