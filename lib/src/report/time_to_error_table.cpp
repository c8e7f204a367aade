// The time-to-error table; what each figure means is in time_to_error_table.hpp.
#include "quadmc/report/time_to_error_table.hpp"

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

// What method table t needs to reach `target` (absolute), for the cell run to (tolerance,
// relative) where t runs to tolerances.
time_to_error_entry entry_of(const convergence_table& t, double tolerance, bool relative,
                             double target) {
  time_to_error_entry e;
  e.method = t.method;
  e.peer = is_peer_method(t.method);
  auto take = [&](const convergence_row& row) {
    e.reached = true;
    e.seconds = row.seconds_per_estimate();
    e.evaluations = row.stats.evaluations;
  };
  if (has_tolerance_rows(t)) {
    if (t.relative_tolerance != relative) return e;
    for (const convergence_row& row : t.rows) {
      if (row.tolerance != tolerance) continue;
      e.ran = true;
      if (row.stats.rmse <= target) take(row);
    }
    return e;
  }
  e.ran = !t.rows.empty();
  for (const convergence_row& row : t.rows) {  // in increasing N
    if (row.stats.rmse <= target) {
      take(row);
      break;
    }
  }
  return e;
}

std::string seconds_text(double x) {
  return fmt::format("{:.3g}", x);
}

std::string entry_text(const time_to_error_entry& e) {
  if (!e.ran) return "—";
  if (!e.reached) return "not reached";
  return fmt::format("{} s, {}", seconds_text(e.seconds), e.evaluations);
}

std::string ratio_text(double ratio) {
  if (std::isnan(ratio)) return "—";
  if (std::isinf(ratio)) return "∞ (quadmc not reached)";
  return fmt::format("{:.3g}", ratio);
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
    std::vector<const convergence_table*> members;
    std::vector<std::pair<double, bool>> targets;  // (tolerance, relative)
    for (const convergence_table& t : tables) {
      if (t.integrand != integrand || t.s != s) continue;
      members.push_back(&t);
      if (!has_tolerance_rows(t)) continue;
      for (const convergence_row& row : t.rows) {
        const std::pair<double, bool> key{row.tolerance, t.relative_tolerance};
        if (std::find(targets.begin(), targets.end(), key) == targets.end()) {
          targets.push_back(key);
        }
      }
    }
    for (const auto& [tolerance, relative] : targets) {
      time_to_error_cell c;
      c.family = family_of(integrand, s);
      c.integrand = integrand;
      c.s = s;
      c.tolerance = tolerance;
      c.relative = relative;
      c.regularity = members.front()->regularity;
      c.target = relative ? tolerance * std::abs(members.front()->reference) : tolerance;
      for (const convergence_table* t : members) {
        c.methods.push_back(entry_of(*t, tolerance, relative, c.target));
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

time_to_error_summary summarise_time_to_error(std::span<const time_to_error_cell> cells) {
  time_to_error_summary out;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const time_to_error_cell& c = cells[k];
    if (c.regularity == smoothness::analytic && (c.best_quadmc || c.best_peer)) {
      ++out.analytic_cells;
      if (c.best_quadmc && (!c.best_peer || c.ratio <= 1.0)) ++out.analytic_met;
    }
    if (c.best_peer) {
      ++out.peer_cells;
      if (!std::isnan(c.ratio) && (std::isnan(out.worst_ratio) || c.ratio > out.worst_ratio)) {
        out.worst_ratio = c.ratio;
        out.worst_cell = k;
      }
    }
  }
  return out;
}

std::string time_to_error_markdown(std::span<const convergence_table> tables) {
  const std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  if (cells.empty()) return {};
  std::vector<std::string> methods;
  for (const time_to_error_cell& c : cells) {
    for (const time_to_error_entry& e : c.methods) {
      if (std::find(methods.begin(), methods.end(), e.method) == methods.end()) {
        methods.push_back(e.method);
      }
    }
  }
  std::string out = "## Time to error\n\n";
  out +=
      "Per integrand family, s and tolerance: the seconds per estimate and evaluations each "
      "method needs to reach the target error (tolerance·|I| for a relative tolerance). A method "
      "run to the tolerance reaches it when its true error (RMSE over its repetitions) is at "
      "most the target, in the stable time of its whole call; a method on the N ladder at the "
      "smallest N whose RMSE is at most the target, in that cell's time. quadmc's best is its "
      "fastest method that reaches it, the best peer the fastest `peer_*` method; ratio = "
      "quadmc's best / best peer (below 1: quadmc faster). — where a method did not run the "
      "cell. Tables a method builds once per process (the sparse grids' 1D rules) are built when "
      "the scene is planned, outside every timed call.\n\n";
  out += "| family | s | tolerance | target | smoothness |";
  for (const std::string& m : methods) out += fmt::format(" {} |", m);
  out += " quadmc's best | best peer | ratio |\n|---|---:|---:|---:|---|";
  for (std::size_t k = 0; k < methods.size(); ++k) out += "---:|";
  out += "---|---|---:|\n";
  for (const time_to_error_cell& c : cells) {
    out += fmt::format("| {} | {} | {:g}{} | {:.3e} | {} |", c.family, c.s, c.tolerance,
                       c.relative ? " ·\\|I\\|" : "", c.target, to_string(c.regularity));
    for (const std::string& m : methods) {
      const auto it = std::find_if(c.methods.begin(), c.methods.end(),
                                   [&](const time_to_error_entry& e) { return e.method == m; });
      out += fmt::format(" {} |", it == c.methods.end() ? std::string("—") : entry_text(*it));
    }
    auto best = [&](const std::optional<std::size_t>& k) {
      return k ? fmt::format("{} ({} s)", c.methods[*k].method, seconds_text(c.methods[*k].seconds))
               : std::string("not reached");
    };
    out += fmt::format(" {} | {} | {} |\n", best(c.best_quadmc), best(c.best_peer),
                       ratio_text(c.ratio));
  }
  const time_to_error_summary sum = summarise_time_to_error(cells);
  out += '\n';
  out += fmt::format(
      "- analytic cells where quadmc's best is at most the best peer's time (or no peer reaches "
      "the target): {} of {}{}\n",
      sum.analytic_met, sum.analytic_cells,
      sum.analytic_cells > 0
          ? fmt::format(" ({:.0f}%)", 100.0 * static_cast<double>(sum.analytic_met) /
                                          static_cast<double>(sum.analytic_cells))
          : std::string());
  if (sum.worst_cell) {
    const time_to_error_cell& w = cells[*sum.worst_cell];
    out += fmt::format(
        "- worst ratio among the {} cells a peer reaches: {} ({}, s = {}, tolerance {:g})\n",
        sum.peer_cells, ratio_text(sum.worst_ratio), w.family, w.s, w.tolerance);
  } else {
    out += "- no peer reaches any target\n";
  }
  out += '\n';
  return out;
}

}  // namespace quadmc
