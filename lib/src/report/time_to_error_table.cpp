// The time-to-error table and time_to_error_pairs.csv; what each figure means is in
// time_to_error_table.hpp and analysis/time_to_error_cells.hpp.
#include "quadmc/report/time_to_error_table.hpp"

#include "quadmc/report/csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadmc {
namespace {

std::string seconds_text(double x) {
  return fmt::format("{:.3g}", x);
}

std::string entry_text(const time_to_error_entry& e) {
  if (!e.ran) return "—";
  if (!e.reached) return "not reached";
  return fmt::format("{} s, {}", seconds_text(e.seconds), e.evaluations);
}

// The ratio a cell shows, as its figure and what qualifies it (empty for none): the paired
// median with its spread over the rounds, else the ratio of the two single timings.
std::pair<std::string, std::string> ratio_parts(const time_to_error_cell& c) {
  if (c.paired) {
    return {fmt::format("{:.3g}", c.paired->median),
            fmt::format("{:.3g}–{:.3g} over {} alternating runs", c.paired->min, c.paired->max,
                        c.paired->rounds())};
  }
  if (std::isnan(c.ratio)) return {"—", ""};
  if (std::isinf(c.ratio)) return {"∞", "quadmc not reached"};
  return {fmt::format("{:.3g}", c.ratio), ""};
}

// "0.998 (0.97–1.02 over 5 alternating runs)", "∞ (quadmc not reached)", "0.5"; `where`, when
// given, joins the parenthesis.
std::string ratio_text(const time_to_error_cell& c, std::string_view where = {}) {
  const auto [figure, detail] = ratio_parts(c);
  if (detail.empty() && where.empty()) return figure;
  if (detail.empty() || where.empty()) return fmt::format("{} ({}{})", figure, detail, where);
  return fmt::format("{} ({}; {})", figure, detail, where);
}

// How the ratios were measured, after the table's general explanation.
std::string paired_timing_text(std::span<const time_to_error_cell> cells,
                               const paired_timing_outcome& paired, unsigned ranks, bool csv) {
  const bool any_both =
      std::any_of(cells.begin(), cells.end(), [](const auto& c) { return c.has_both(); });
  if (!any_both) return {};
  if (!paired.ran()) {
    return " The ratios compare the two cells' single stable timings, each measured at its own "
           "moment of the run (no paired timing ran: `budget.paired_timing_rounds = 0` turns it "
           "off).";
  }
  std::string out = fmt::format(
      " Ratios: where both sides reach the target, quadmc's best and the best peer were timed "
      "again after the cells had run{}, alternately — quadmc, peer, quadmc, peer, … — {} rounds "
      "of one stable timing of each cell's call (`budget.paired_timing_rounds`), so that the "
      "machine's load at one moment weighs on both sides alike; the ratio shown is the median of "
      "the per-round ratios quadmc / peer, with their smallest and largest ({}the paired "
      "timing took {:.3g} s). The method columns and the best columns' seconds are the cells' "
      "own stable timings from the run.",
      ranks > 1 ? ", on MPI rank 0 while the other ranks waited idle" : "", paired.rounds,
      csv ? fmt::format("every round in `{}`; ", time_to_error_pairs_csv_file) : std::string(),
      paired.seconds);
  return out;
}

}  // namespace

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

std::string time_to_error_markdown(std::span<const convergence_table> tables,
                                   const paired_timing_outcome& paired, unsigned ranks, bool csv) {
  std::vector<time_to_error_cell> cells = time_to_error_cells(tables);
  if (cells.empty()) return {};
  attach_pairs(cells, paired.pairs);
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
      "the scene is planned, outside every timed call.";
  out += paired_timing_text(cells, paired, ranks, csv);
  out += "\n\n";
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
    out += fmt::format(" {} | {} | {} |\n", best(c.best_quadmc), best(c.best_peer), ratio_text(c));
  }
  const time_to_error_summary sum = summarise_time_to_error(cells);
  const bool any_paired =
      std::any_of(cells.begin(), cells.end(), [](const auto& c) { return c.paired.has_value(); });
  out += '\n';
  out += fmt::format(
      "- analytic cells where quadmc's best is at most the best peer's time (or no peer reaches "
      "the target){}: {} of {}{}\n",
      any_paired ? ", by the median of the alternating runs where paired" : "", sum.analytic_met,
      sum.analytic_cells,
      sum.analytic_cells > 0
          ? fmt::format(" ({:.0f}%)", 100.0 * static_cast<double>(sum.analytic_met) /
                                          static_cast<double>(sum.analytic_cells))
          : std::string());
  if (sum.worst_cell) {
    const time_to_error_cell& w = cells[*sum.worst_cell];
    out += fmt::format(
        "- worst ratio among the {} cells a peer reaches: {}\n", sum.peer_cells,
        ratio_text(w, fmt::format("{}, s = {}, tolerance {:g}", w.family, w.s, w.tolerance)));
  } else {
    out += "- no peer reaches any target\n";
  }
  for (const std::string& why : paired.not_paired) {
    out += fmt::format("- not paired, single timings: {}\n", why);
  }
  out += '\n';
  return out;
}

std::string time_to_error_pairs_csv_text(std::string_view scene,
                                         std::span<const time_to_error_pair> pairs) {
  std::string out =
      "scene,family,integrand,s,tolerance,tolerance_kind,quadmc_method,quadmc_N,"
      "quadmc_evaluations,peer_method,peer_N,peer_evaluations,rounds,ratio_median,ratio_min,"
      "ratio_max,quadmc_seconds_median,peer_seconds_median,ratios,quadmc_seconds,peer_seconds\n";
  // Shortest text that reads back to the same double, as results_csv.cpp writes numbers.
  auto joined = [](const std::vector<double>& values) {
    return fmt::format("{}", fmt::join(values, ";"));
  };
  for (const time_to_error_pair& p : pairs) {
    const paired_ratio r = summarise_pair(p);
    const std::vector<std::string> fields = {std::string(scene),
                                             p.family,
                                             p.integrand,
                                             fmt::format("{}", p.s),
                                             fmt::format("{}", p.tolerance),
                                             p.relative ? "relative" : "absolute",
                                             p.quadmc_method,
                                             fmt::format("{}", p.quadmc_n),
                                             fmt::format("{}", p.quadmc_evaluations),
                                             p.peer_method,
                                             fmt::format("{}", p.peer_n),
                                             fmt::format("{}", p.peer_evaluations),
                                             fmt::format("{}", r.rounds()),
                                             fmt::format("{}", r.median),
                                             fmt::format("{}", r.min),
                                             fmt::format("{}", r.max),
                                             fmt::format("{}", r.quadmc_median_seconds),
                                             fmt::format("{}", r.peer_median_seconds),
                                             joined(r.ratios),
                                             joined(p.quadmc_seconds),
                                             joined(p.peer_seconds)};
    out += csv_line(fields);
  }
  return out;
}

}  // namespace quadmc
