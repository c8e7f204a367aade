// Pooled coverage of the methods' own error estimates; definitions in estimate_reliability.hpp.
#include "quadmc/analysis/estimate_reliability.hpp"

#include "quadmc/core/summation.hpp"

#include <algorithm>
#include <cmath>

namespace quadmc {

std::vector<estimate_reliability> summarise_estimate_reliability(
    std::span<const convergence_table> tables) {
  struct sums {
    estimate_reliability entry;
    neumaier_sum covered, covered_3x, chi2;
    std::size_t chi2_cells = 0;
  };
  std::vector<sums> groups;
  for (const convergence_table& t : tables) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const sums& g) {
      return g.entry.method == t.method && g.entry.regularity == t.regularity;
    });
    bool counted_series = false;
    for (const convergence_row& row : t.rows) {
      const cell_statistics& c = row.stats;
      if (std::isnan(c.estimate_covers)) continue;
      if (it == groups.end()) {
        groups.push_back({});
        it = groups.end() - 1;
        it->entry.method = t.method;
        it->entry.regularity = t.regularity;
      }
      if (!counted_series) {
        ++it->entry.series;
        counted_series = true;
      }
      const double r = static_cast<double>(c.repetitions);
      ++it->entry.cells;
      it->entry.estimates += c.repetitions;
      it->covered += std::round(c.estimate_covers * r);  // a count: k/R · R
      it->covered_3x += std::round(c.estimate_covers_3x * r);
      // RMSE against the estimates' root mean square: how far the claim fell short at worst (an
      // estimate of exactly 0 against a non-zero error is infinitely short).
      const double ratio = c.rmse == 0.0            ? 0.0
                           : c.error_estimate > 0.0 ? c.rmse / c.error_estimate
                                                    : std::numeric_limits<double>::infinity();
      it->entry.worst_ratio = std::max(it->entry.worst_ratio, ratio);
      if (!std::isnan(c.chi2_per_dof)) {
        it->chi2 += c.chi2_per_dof;
        ++it->chi2_cells;
      }
    }
  }
  std::vector<estimate_reliability> out;
  for (sums& g : groups) {
    const double n = static_cast<double>(g.entry.estimates);
    g.entry.covered = g.covered.value() / n;
    g.entry.covered_3x = g.covered_3x.value() / n;
    if (g.chi2_cells > 0) g.entry.chi2_per_dof = g.chi2.value() / static_cast<double>(g.chi2_cells);
    out.push_back(g.entry);
  }
  return out;
}

}  // namespace quadmc
