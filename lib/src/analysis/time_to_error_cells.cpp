// Who reaches each target first, and the paired record of the winners; what each figure means is
// in time_to_error_cells.hpp.
#include "quadmc/analysis/time_to_error_cells.hpp"

#include "quadmc/core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadmc {
namespace {

std::string family_of(std::string_view integrand, std::size_t s) {
  const std::string suffix = fmt::format("_s{}", s);
  if (integrand.size() > suffix.size() && integrand.ends_with(suffix)) {
    return std::string(integrand.substr(0, integrand.size() - suffix.size()));
  }
  return std::string(integrand);
}

bool has_tolerance_rows(const convergence_table& t) {
  return !t.rows.empty() && !std::isnan(t.rows.front().tolerance);
}

// What method table t (tables[index]) needs to reach `target` (absolute), for the cell run to
// (tolerance, relative) where t runs to tolerances: the winning-cell choice of the header.
time_to_error_entry entry_of(const convergence_table& t, std::size_t index, double tolerance,
                             bool relative, double target) {
  time_to_error_entry e;
  e.method = t.method;
  e.peer = is_peer_method(t.method);
  e.table = index;
  auto take = [&](std::size_t row) {
    e.reached = true;
    e.seconds = t.rows[row].seconds_per_estimate();
    e.evaluations = t.rows[row].stats.evaluations;
    e.row = row;
  };
  if (has_tolerance_rows(t)) {
    if (t.relative_tolerance != relative) return e;
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
      if (t.rows[k].tolerance != tolerance) continue;
      e.ran = true;
      if (t.rows[k].stats.rmse <= target) take(k);
    }
    return e;
  }
  e.ran = !t.rows.empty();
  for (std::size_t k = 0; k < t.rows.size(); ++k) {  // in increasing N
    if (t.rows[k].stats.rmse <= target) {
      take(k);
      break;
    }
  }
  return e;
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

bool is_peer_method(std::string_view method) {
  return method.starts_with("peer_");
}

std::vector<time_to_error_cell> time_to_error_cells(std::span<const convergence_table> tables) {
  const bool any_tolerance = std::any_of(tables.begin(), tables.end(), has_tolerance_rows);
  const bool any_peer = std::any_of(tables.begin(), tables.end(), [](const convergence_table& t) {
    return is_peer_method(t.method);
  });
  std::vector<time_to_error_cell> out;
  if (!any_tolerance || !any_peer) return out;

  std::vector<std::pair<std::string, std::size_t>> groups;
  for (const convergence_table& t : tables) {
    const std::pair<std::string, std::size_t> key{t.integrand, t.s};
    if (std::find(groups.begin(), groups.end(), key) == groups.end()) groups.push_back(key);
  }
  for (const auto& [integrand, s] : groups) {
    std::vector<std::size_t> members;              // indices into tables
    std::vector<std::pair<double, bool>> targets;  // (tolerance, relative)
    for (std::size_t k = 0; k < tables.size(); ++k) {
      const convergence_table& t = tables[k];
      if (t.integrand != integrand || t.s != s) continue;
      members.push_back(k);
      if (!has_tolerance_rows(t)) continue;
      for (const convergence_row& row : t.rows) {
        const std::pair<double, bool> key{row.tolerance, t.relative_tolerance};
        if (std::find(targets.begin(), targets.end(), key) == targets.end()) {
          targets.push_back(key);
        }
      }
    }
    const convergence_table& first = tables[members.front()];
    for (const auto& [tolerance, relative] : targets) {
      time_to_error_cell c;
      c.family = family_of(integrand, s);
      c.integrand = integrand;
      c.s = s;
      c.tolerance = tolerance;
      c.relative = relative;
      c.regularity = first.regularity;
      c.target = relative ? tolerance * std::abs(first.reference) : tolerance;
      for (const std::size_t k : members) {
        c.methods.push_back(entry_of(tables[k], k, tolerance, relative, c.target));
      }
      // The fastest of each side; a tie goes to the method listed first.
      for (std::size_t k = 0; k < c.methods.size(); ++k) {
        const time_to_error_entry& e = c.methods[k];
        if (!e.reached) continue;
        std::optional<std::size_t>& best = e.peer ? c.best_peer : c.best_quadmc;
        if (!best || e.seconds < c.methods[*best].seconds) best = k;
      }
      if (c.best_peer) {
        const double peer = c.methods[*c.best_peer].seconds;
        c.ratio = !c.best_quadmc ? std::numeric_limits<double>::infinity()
                  : peer > 0.0   ? c.methods[*c.best_quadmc].seconds / peer
                                 : std::numeric_limits<double>::quiet_NaN();
      }
      out.push_back(std::move(c));
    }
  }
  return out;
}

paired_ratio summarise_pair(const time_to_error_pair& pair) {
  const std::size_t n = pair.quadmc_seconds.size();
  const std::string what = fmt::format("{} × {}, s = {}, tolerance {}", pair.quadmc_method,
                                       pair.peer_method, pair.s, pair.tolerance);
  require(n > 0, "rounds of " + what, n, "at least one");
  require(pair.peer_seconds.size() == n, "peer rounds of " + what, pair.peer_seconds.size(),
          fmt::format("as many as quadmc's ({})", n));
  paired_ratio out;
  for (std::size_t i = 0; i < n; ++i) {
    const double q = pair.quadmc_seconds[i];
    const double p = pair.peer_seconds[i];
    require(std::isfinite(q) && q > 0.0,
            fmt::format("quadmc seconds of round {} of {}", i + 1, what), q, "finite and > 0");
    require(std::isfinite(p) && p > 0.0, fmt::format("peer seconds of round {} of {}", i + 1, what),
            p, "finite and > 0");
    out.ratios.push_back(q / p);
  }
  out.median = median_of(out.ratios);
  const auto [low, high] = std::minmax_element(out.ratios.begin(), out.ratios.end());
  out.min = *low;
  out.max = *high;
  out.quadmc_median_seconds = median_of(pair.quadmc_seconds);
  out.peer_median_seconds = median_of(pair.peer_seconds);
  return out;
}

bool pairs_cell(const time_to_error_pair& pair, const time_to_error_cell& cell) {
  return cell.has_both() && pair.integrand == cell.integrand && pair.s == cell.s &&
         pair.tolerance == cell.tolerance && pair.relative == cell.relative &&
         pair.quadmc_method == cell.methods[*cell.best_quadmc].method &&
         pair.peer_method == cell.methods[*cell.best_peer].method;
}

void attach_pairs(std::span<time_to_error_cell> cells, std::span<const time_to_error_pair> pairs) {
  for (time_to_error_cell& c : cells) {
    const auto it = std::find_if(pairs.begin(), pairs.end(),
                                 [&](const time_to_error_pair& p) { return pairs_cell(p, c); });
    if (it == pairs.end()) continue;
    c.paired = summarise_pair(*it);
    c.ratio = c.paired->median;
  }
}

}  // namespace quadmc
