// Who leads a table of competing rows (report/table_leaders.hpp).
#include "quadmc/report/table_leaders.hpp"

#include "quadmc/core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace quadmc {
namespace {

std::string column(const scored_table& t, std::size_t k) {
  return fmt::format("{} = {}", t.column_label, t.columns[k]);
}

}  // namespace

std::vector<std::optional<std::size_t>> column_winners(const scored_table& t) {
  if (t.values.size() != t.rows.size()) {
    throw invalid_argument("scored_table.values", fmt::format("{} rows", t.values.size()),
                           fmt::format("one per row name ({})", t.rows.size()));
  }
  std::vector<std::optional<std::size_t>> winners(t.columns.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.values[r].size() != t.columns.size()) {
      throw invalid_argument(fmt::format("scored_table.values[{}]", r),
                             fmt::format("{} values", t.values[r].size()),
                             fmt::format("one per column ({})", t.columns.size()));
    }
    for (std::size_t k = 0; k < t.columns.size(); ++k) {
      const std::optional<double>& v = t.values[r][k];
      // Strictly smaller: a tie stays with the row listed first.
      if (v && (!winners[k] || *v < *t.values[*winners[k]][k])) winners[k] = r;
    }
  }
  return winners;
}

std::string leaders_phrase(const scored_table& t, std::string_view baseline) {
  const std::vector<std::optional<std::size_t>> winners = column_winners(t);
  std::vector<std::size_t> decided;  // the columns with a winner
  for (std::size_t k = 0; k < winners.size(); ++k) {
    if (winners[k]) decided.push_back(k);
  }
  if (decided.empty()) return "no figures";
  const std::size_t last = decided.back();
  const std::size_t leader = *winners[last];
  std::size_t first = decided.size() - 1;
  while (first > 0 && *winners[decided[first - 1]] == leader) --first;
  if (decided.size() > 1 && first == decided.size() - 1) {
    // The last two columns have different winners: no steady leader.
    return fmt::format("no steady leader (`{}` at {}, `{}` at {})",
                       t.rows[*winners[decided[first - 1]]], column(t, decided[first - 1]),
                       t.rows[leader], column(t, last));
  }
  const double value = *t.values[leader][last];
  std::string text = fmt::format("`{}` leads {}", t.rows[leader],
                                 decided.size() == 1 ? fmt::format("at {}", column(t, last))
                                 : first == 0        ? fmt::format("at every {}", t.column_label)
                                              : fmt::format("from {}", column(t, decided[first])));
  text += fmt::format(" ({:.4g} at {}", value, column(t, last));
  const auto base = std::find(t.rows.begin(), t.rows.end(), baseline);
  if (!baseline.empty() && base != t.rows.end()) {
    const auto b = static_cast<std::size_t>(base - t.rows.begin());
    if (b != leader && t.values[b][last] && *t.values[b][last] > value && value > 0.0) {
      text += fmt::format(", {:.3g}× below `{}`'s {:.4g}", *t.values[b][last] / value, baseline,
                          *t.values[b][last]);
    }
  }
  return text + ")";
}

}  // namespace quadmc
