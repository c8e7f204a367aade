// Cost model and LPT assignment of a plan's cells to processes (scene/schedule.hpp).
#include "quadmc/scene/schedule.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/scene/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace quadmc {

split_policy parse_split_policy(std::string_view text) {
  if (text == "auto") return split_policy::automatic;
  if (text == "all") return split_policy::all;
  if (text == "none") return split_policy::none;
  throw std::invalid_argument(
      fmt::format("invalid --split-cells = '{}': expected auto, all or none", text));
}

std::string cells_csv(const plan& p, std::span<const cell_placement> placement) {
  std::string out =
      "integrand,instance,s,method,N,tolerance,evaluations,repetitions,shares_chunks,placement\n";
  for (std::size_t i = 0; i < p.cells.size(); ++i) {
    const plan_cell& cell = p.cells[i];
    const bool to_tolerance = !std::isnan(cell.tolerance);
    const cell_placement where = i < placement.size() ? placement[i] : cell_placement{};
    // Scene names are identifiers (scene/parse.hpp), so no field needs quoting.
    out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", p.source.integrands[cell.integrand].name,
                       cell.instance, cell.dimension, p.source.methods[cell.method].label,
                       to_tolerance ? std::string() : std::to_string(cell.nominal_N),
                       to_tolerance ? fmt::format("{}", cell.tolerance) : std::string(),
                       cell.evaluations, cell.repetitions, cell_shares_chunks(p, i) ? 1 : 0,
                       where.split ? std::string("split") : fmt::format("rank {}", where.rank));
  }
  return out;
}

bool cell_shares_chunks(const plan& p, std::size_t index) {
  require(index < p.cells.size(), "cell index", index,
          fmt::format("a cell of the plan (it has {})", p.cells.size()));
  const plan_cell& cell = p.cells[index];
  return p.source.methods[cell.method].configured->shares_chunks_at(cell.control);
}

cost_probes choose_cost_probes(const plan& p) {
  cost_probes out;
  std::vector<std::pair<std::size_t, std::size_t>> keys;  // (integrand, method) per series
  out.series_of.assign(p.cells.size(), 0);
  for (std::size_t i = 0; i < p.cells.size(); ++i) {
    const std::pair key{p.cells[i].integrand, p.cells[i].method};
    auto it = std::find(keys.begin(), keys.end(), key);
    if (it == keys.end()) {
      keys.push_back(key);
      out.smallest.push_back(i);
      out.probe.push_back(i);
      it = std::prev(keys.end());
    }
    const auto s = static_cast<std::size_t>(it - keys.begin());
    out.series_of[i] = s;
    const std::uint64_t n = p.cells[i].evaluations;
    if (n < p.cells[out.smallest[s]].evaluations) out.smallest[s] = i;
    // The probe: the largest cell of at most probe_evaluations, else the smallest cell.
    const std::uint64_t probe_n = p.cells[out.probe[s]].evaluations;
    const bool probe_fits = probe_n <= probe_evaluations;
    if (n <= probe_evaluations ? (!probe_fits || n > probe_n) : (!probe_fits && n < probe_n)) {
      out.probe[s] = i;
    }
  }
  return out;
}

series_cost fit_series_cost(std::uint64_t n0, double t0, std::uint64_t n1, double t1) {
  require(std::isfinite(t0) && t0 >= 0.0, "t0", t0, "a finite time ≥ 0");
  require(std::isfinite(t1) && t1 >= 0.0, "t1", t1, "a finite time ≥ 0");
  const double x0 = static_cast<double>(std::max<std::uint64_t>(n0, 1));
  const double x1 = static_cast<double>(std::max<std::uint64_t>(n1, 1));
  series_cost c;
  c.fixed = x1 > x0 ? t0 : 0.0;
  // A slope lost in the noise (t1 ≤ t0) falls back to the probe's mean per evaluation.
  c.per_evaluation = std::max(x1 > x0 && t1 > t0 ? (t1 - t0) / (x1 - x0) : t1 / x1, 1e-12);
  return c;
}

std::vector<series_cost> time_series_costs(const plan& p, const cost_probes& probes,
                                           const run_context& context) {
  using clock = std::chrono::steady_clock;
  const auto seconds_of = [&](std::size_t i) {
    const int timings = p.cells[i].evaluations <= probe_evaluations ? 3 : 1;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < timings; ++k) {
      const auto t0 = clock::now();
      (void)run_cell_repetitions(p, i, 0, 1, context, 0.0);
      best = std::min(best, std::chrono::duration<double>(clock::now() - t0).count());
    }
    return best;
  };
  std::vector<series_cost> cost(probes.smallest.size());
  for (std::size_t s = 0; s < cost.size(); ++s) {
    try {
      const std::size_t small = probes.smallest[s];
      const std::size_t probe = probes.probe[s];
      const double t0 = seconds_of(small);
      const double t1 = probe == small ? t0 : seconds_of(probe);
      cost[s] = fit_series_cost(p.cells[small].evaluations, t0, p.cells[probe].evaluations, t1);
    } catch (const std::exception&) {
      cost[s] = series_cost{};
    }
  }
  return cost;
}

std::vector<double> cell_costs(const plan& p, const cost_probes& probes,
                               std::span<const series_cost> series) {
  require(probes.series_of.size() == p.cells.size(), "probes.series_of", probes.series_of.size(),
          fmt::format("one series per cell of the plan ({})", p.cells.size()));
  std::vector<double> cost(p.cells.size());
  for (std::size_t i = 0; i < p.cells.size(); ++i) {
    if (probes.series_of[i] >= series.size()) {
      throw invalid_argument(
          "series", fmt::format("{} costs", series.size()),
          fmt::format("a cost for series {} of cell {}", probes.series_of[i], i));
    }
    const series_cost& c = series[probes.series_of[i]];
    cost[i] = static_cast<double>(p.cells[i].repetitions) *
              (c.fixed + static_cast<double>(p.cells[i].evaluations) * c.per_evaluation);
  }
  return cost;
}

std::vector<cell_placement> assign_cells(std::span<const double> cost,
                                         const std::vector<bool>& shares_chunks, unsigned processes,
                                         split_policy policy) {
  require(processes >= 1, "processes", processes, "at least 1");
  require(shares_chunks.size() == cost.size(), "shares_chunks", shares_chunks.size(),
          fmt::format("one flag per cell ({})", cost.size()));
  for (std::size_t i = 0; i < cost.size(); ++i) {
    if (!(std::isfinite(cost[i]) && cost[i] >= 0.0)) {
      throw invalid_argument(fmt::format("cost[{}]", i), fmt::format("{}", cost[i]),
                             "a finite cost ≥ 0");
    }
  }
  const double total = std::accumulate(cost.begin(), cost.end(), 0.0);
  const double split_above = total / (4.0 * static_cast<double>(processes));
  std::vector<cell_placement> placement(cost.size());
  std::vector<std::size_t> whole;
  for (std::size_t i = 0; i < cost.size(); ++i) {
    const bool split = policy == split_policy::all || (policy == split_policy::automatic &&
                                                       cost[i] > split_above && shares_chunks[i]);
    placement[i].split = split;
    if (!split) whole.push_back(i);
  }
  // Largest first; equal costs keep plan order (stable), and min_element takes the lowest rank
  // among equally loaded ones.
  std::stable_sort(whole.begin(), whole.end(),
                   [&](std::size_t x, std::size_t y) { return cost[x] > cost[y]; });
  std::vector<double> load(processes, 0.0);
  for (const std::size_t i : whole) {
    const auto least =
        static_cast<unsigned>(std::min_element(load.begin(), load.end()) - load.begin());
    load[least] += cost[i];
    placement[i].rank = least;
  }
  return placement;
}

}  // namespace quadmc
