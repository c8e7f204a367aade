// The results README page; layout and file-name contract in markdown_report.hpp.
#include "quadmc/report/markdown_report.hpp"

#include "quadmc/analysis/estimate_reliability.hpp"
#include "quadmc/report/answer_first.hpp"
#include "quadmc/report/time_to_error_table.hpp"
#include "quadmc/report/who_leads.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace quadmc {
namespace {

// A table cell: '|' would end the cell, a line break the row.
std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n' || c == '\r') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

std::string sci(double x) {
  return std::isnan(x) ? "—" : fmt::format("{:.3e}", x);
}
std::string short_number(double x) {
  return std::isnan(x) ? "—" : fmt::format("{:.3g}", x);
}

std::string slope_text(const power_law_fit& fit) {
  if (!fit.ok()) return fmt::format("no fit ({})", to_string(fit.status));
  return fmt::format("{:.3f} ± {:.3f}", fit.slope, fit.half_width());
}

std::string theory_text(const theoretical_rate& theory) {
  return theory.slope ? fmt::format("{:.3f}", *theory.slope) : std::string("—");
}

// The stable time of one estimate and its spread (analysis/cell_timing.hpp): "1.2e-05 (±4%)",
// "0.31 (timed once)", "—" for a cell that was not timed.
std::string timing_text(const cell_timing& t) {
  if (!t.timed()) return "—";
  if (t.timed_once()) return fmt::format("{:.3g} (timed once)", t.seconds_per_estimate);
  return fmt::format("{:.3g} (spread {:.0f}%)", t.seconds_per_estimate, 100.0 * t.spread);
}

std::string time_to_error_text(const time_to_error& t) {
  switch (t.status) {
    case target_status::reached:
      return fmt::format("{:.3g}", *t.seconds);
    case target_status::reached_at_first_point:
      return fmt::format("≤ {:.3g}", *t.seconds);
    case target_status::not_reached:
      return "not reached";
  }
  return "?";
}

// The tolerance table's "reached" column: ✅ when every repetition's own estimate got to the
// target, else ❌ with how many did.
std::string reached_text(const cell_statistics& c) {
  if (std::isnan(c.reached)) return "—";
  if (c.reached >= 1.0) return "✅";
  const auto repetitions = static_cast<double>(c.repetitions);
  return fmt::format("❌ {} of {}", std::llround(c.reached * repetitions), c.repetitions);
}

void append_method_table(std::string& out, const convergence_table& t) {
  out += fmt::format("### {}\n\n", cell(t.method));
  const bool deterministic = !t.rows.empty() && t.rows.front().stats.repetitions == 1;
  const bool enveloped = t.has_envelope();
  // An envelope series: the verdict is about the bound, the slope only stands beside it.
  const std::string verdict =
      enveloped ? fmt::format("; verdict {} (largest error/envelope {})", to_string(t.verdict),
                              short_number(t.envelope_ratio))
                : fmt::format(": {}", to_string(t.verdict));
  out += fmt::format(
      "Slope {} (theory {}{}); {}; attainable accuracy {}.\n\n", slope_text(t.fit),
      theory_text(t.theory), verdict,
      t.floor.reached()
          ? fmt::format("rounding floor from N = {} ({} points, level ≈ {})",
                        t.rows[*t.floor.first].n, t.floor_points(), sci(t.floor.floor_level))
          : std::string("no rounding floor reached"),
      sci(t.floor.attainable_accuracy));
  if (!t.verdict_reason.empty()) out += fmt::format("Why: {}.\n\n", cell(t.verdict_reason));
  // The method's own error estimate, where it has one (Monte Carlo's σ̂/√N, Romberg's last
  // difference): a column beside the true error, so a reader sees how far to trust it.
  const bool estimated = std::any_of(t.rows.begin(), t.rows.end(), [](const convergence_row& r) {
    return !std::isnan(r.stats.error_estimate);
  });
  const bool to_tolerance = !t.rows.empty() && !std::isnan(t.rows.front().tolerance);
  // The Euler–Maclaurin prediction beside the measured error, where the rule has one.
  const bool predicted = std::any_of(t.rows.begin(), t.rows.end(), [](const convergence_row& r) {
    return !std::isnan(r.predicted_error);
  });
  // The L2 discrepancies of a quasi-Monte Carlo cell's points beside its error (computed for
  // small N only, sampling/discrepancy.hpp), so the page shows both without the CSV.
  const bool discrepant = std::any_of(t.rows.begin(), t.rows.end(), [](const convergence_row& r) {
    return !std::isnan(r.stats.l2_star_discrepancy) || !std::isnan(r.stats.centered_discrepancy) ||
           !std::isnan(r.stats.wraparound_discrepancy);
  });
  if (discrepant) {
    out +=
        "Discrepancies: the root mean square over the repetitions of the L2-star (Warnock's "
        "formula), centered and wrap-around L2 discrepancy of each cell's points; — where N is "
        "too large to compute them (O(N²·s)).\n\n";
  }
  out += fmt::format(
      "| {} | evaluations | {} |{}{}{}{}{} std error | coverage 95% | time (s) | s per estimate | "
      "evals/s | floor |\n",
      to_tolerance ? "tolerance" : "N", deterministic ? "\\|error\\|" : "RMSE",
      to_tolerance ? " reached |" : "",
      discrepant ? " L2-star discrepancy | centered discrepancy | wrap-around discrepancy |" : "",
      predicted ? " predicted | measured/predicted |" : "", estimated ? " error estimate |" : "",
      enveloped ? " envelope |" : "");
  out += fmt::format("|---:|---:|---:|{}{}{}{}{}---:|---:|---:|---:|---:|:---:|\n",
                     to_tolerance ? ":---:|" : "", discrepant ? "---:|---:|---:|" : "",
                     predicted ? "---:|---:|" : "", estimated ? "---:|" : "",
                     enveloped ? "---:|" : "");
  for (const convergence_row& row : t.rows) {
    const cell_statistics& c = row.stats;
    out += fmt::format(
        "| {} | {} | {} |{}{}{}{}{} {} | {} | {} | {} | {} | {} |\n",
        to_tolerance ? sci(row.tolerance) : fmt::format("{}", row.n), c.evaluations, sci(c.rmse),
        to_tolerance ? fmt::format(" {} |", reached_text(c)) : "",
        discrepant ? fmt::format(" {} | {} | {} |", sci(c.l2_star_discrepancy),
                                 sci(c.centered_discrepancy), sci(c.wraparound_discrepancy))
                   : "",
        predicted ? fmt::format(" {} | {} |", sci(row.predicted_error),
                                std::isnan(row.prediction_ratio)
                                    ? std::string("—")
                                    : fmt::format("{:.4f}{}", row.prediction_ratio,
                                                  row.prediction_judged ? "" : " (not judged)"))
                  : "",
        estimated ? fmt::format(" {} |", sci(c.error_estimate)) : "",
        enveloped ? fmt::format(" {} |", sci(row.envelope)) : "", sci(c.std_error_of_rmse),
        std::isnan(c.coverage_95) ? "—" : fmt::format("{:.2f}", c.coverage_95),
        short_number(c.seconds), timing_text(row.timing), short_number(c.evals_per_second),
        row.floor ? "▼" : "");
  }
  out += '\n';
}

// Where a scene runs cells to a tolerance, one line says whether every one got there, and each
// that did not (its own error estimate still above the target when its budget or level cap ran
// out) is listed with what it spent: a row of the tolerance table alone would read as an answer.
// "Effective dimensions": one row per integrand in s ≥ 2 (in 1D there is nothing to split), the
// exact d_T and d_S where f is a product of one-variable factors
// (functions/effective_dimension.hpp), else their pick-freeze estimates with intervals
// (functions/effective_dimension_estimate.hpp), labelled as such. Empty when every integrand is
// one-dimensional.
std::string effective_dimension_section(std::span<const effective_dimension_row> rows) {
  const auto interval = [](const estimated_share& e) {
    return fmt::format("{:.3f} [{:.3f}, {:.3f}]", e.value, e.low, e.high);
  };
  std::string body;
  for (const effective_dimension_row& row : rows) {
    if (row.s < 2) continue;
    const std::string instance =
        row.instances > 1 ? fmt::format(" (instance 0 of the ensemble of {})", row.instances) : "";
    if (row.exact) {
      const effective_dimensions& e = *row.exact;
      body += fmt::format(
          "| {} | {} | {} | {} | {:.3f} | {:.3f} | exact: a product of one-variable factors{} |\n",
          cell(row.integrand), row.s, e.truncation, e.superposition, e.truncation_shares[0],
          e.superposition_shares[0], instance);
    } else if (row.estimated) {
      const effective_dimension_estimate& e = *row.estimated;
      const std::string truncation =
          e.truncation_low == e.truncation_high
              ? fmt::format("{}", e.truncation)
              : fmt::format("{} [{}, {}]", e.truncation, e.truncation_low, e.truncation_high);
      std::string superposition = "—", order_one = "—", how;
      if (e.first_order) {
        superposition = e.superposition_high == 1  ? "1"
                        : e.superposition_low == 2 ? "≥ 2"
                                                   : "1 or ≥ 2";
        order_one = interval(*e.first_order);
        how = fmt::format("; mean dimension {}, order 1 from the first {} rows",
                          interval(*e.mean_dimension), e.first_order_samples);
      } else {
        how = "; order 1 not estimated (64 rows of s² coordinates above its budget)";
      }
      body += fmt::format(
          "| {} | {} | {} | {} | {} | {} | estimated: pick-freeze, {} rows, {} evaluations, {:g} % "
          "intervals{}{} |\n",
          cell(row.integrand), row.s, truncation, superposition, interval(e.first_coordinate),
          order_one, e.samples, e.evaluations, 100.0 * e.confidence, how, instance);
    } else if (!row.not_estimated.empty()) {
      body += fmt::format(
          "| {} | {} | — | — | — | — | not computed: not a product of one-variable factors, and "
          "the integrand failed while it was sampled for an estimate: {}{} |\n",
          cell(row.integrand), row.s, cell(row.not_estimated), instance);
    } else {
      body += fmt::format(
          "| {} | {} | — | — | — | — | not computed: not a product of one-variable factors, and "
          "its sampled variance is 0 or a sampled value not finite{} |\n",
          cell(row.integrand), row.s, instance);
    }
  }
  if (body.empty()) return {};
  return "## Effective dimensions\n\n"
         "How much of each integrand's variance σ² its first coordinates and its low-order "
         "interactions carry (ANOVA, docs/theory.md#effective-dimension): the truncation "
         "dimension d_T is the fewest leading coordinates whose subsets carry 99 % of σ², the "
         "superposition dimension d_S the lowest interaction order that does. Where both are "
         "small beside s, quasi-Monte Carlo's points, whose low-dimensional projections are the "
         "most even, beat Monte Carlo's; where d_T = s with d_S = 1, only their one-dimensional "
         "projections matter. Exact where f is a product of one-variable factors; otherwise "
         "estimated by pick-freeze (docs/theory.md#estimated-effective-dimension), with d_T's "
         "interval from those of the shares and d_S = 1 only where the share of order 1 is above "
         "99 % with its whole interval (the mean dimension Σ|u|σ²_u/σ² beside it).\n\n"
         "| integrand | s | d_T | d_S | share of x₁ | share of order 1 | how |\n"
         "|---|---|---|---|---|---|---|\n" +
         body + "\n";
}

// Ensembles (ensemble_statistics.hpp), per series at its largest N: the mean of the instances'
// MSE with its 95% interval, the median and the worst instance, and the slope of the mean MSE
// (twice the fitted RMSE slope: RMSE² = mean MSE). Empty when no series pools instances.
std::string ensemble_section(std::span<const convergence_table> tables) {
  std::string body;
  for (const convergence_table& t : tables) {
    if (t.rows.empty() || t.rows.back().ensemble.instances <= 1) continue;
    const convergence_row& r = t.rows.back();
    const ensemble_statistics& e = r.ensemble;
    const std::string slope = std::isnan(t.fit.slope)
                                  ? std::string("–")
                                  : fmt::format("{:.2f} [{:.2f}, {:.2f}]", 2 * t.fit.slope,
                                                2 * t.fit.ci_low, 2 * t.fit.ci_high);
    body += fmt::format("| {} | {} | {} | {} | {} | {} [{}, {}] | {} | {} | {:.1f} | {} |\n",
                        cell(t.integrand), t.s, cell(t.method), r.stats.evaluations, e.instances,
                        sci(e.mse_mean), sci(e.mse_ci95_low), sci(e.mse_ci95_high),
                        sci(e.mse_median), sci(e.mse_worst), e.mse_worst / e.mse_median, slope);
  }
  if (body.empty()) return {};
  return "## Ensembles\n\n"
         "Per series at its largest N, over the instances of the ensemble (each instance its own "
         "random integrand, docs/theory.md#random-ensembles): the mean squared error with its 95% "
         "Student interval, the median and the worst instance, the worst over the median, and the "
         "slope of the mean MSE against N with its 95% interval (twice the RMSE slope of the "
         "slope table). Per cell: columns `mse_mean` … `mse_worst` of `convergence.csv`.\n\n"
         "| integrand | s | method | N | instances | MSE mean [95% CI] | median | worst | "
         "worst/median | MSE slope |\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n" +
         body + "\n";
}

std::string targets_not_reached(std::span<const convergence_table> tables) {
  bool any_tolerance = false;
  std::string list;
  std::size_t missed = 0;
  for (const convergence_table& t : tables) {
    for (const convergence_row& row : t.rows) {
      if (std::isnan(row.stats.reached)) continue;
      any_tolerance = true;
      if (row.stats.reached >= 1.0) continue;
      missed += 1;
      const auto repetitions = static_cast<double>(row.stats.repetitions);
      const bool one = row.stats.repetitions == 1;
      const long long stopped = std::llround((1.0 - row.stats.reached) * repetitions);
      // A relative tolerance is a fraction of |I|: the estimate is set beside it on that scale.
      const std::string relative =
          t.relative_tolerance && t.reference != 0.0
              ? fmt::format(" = {} of |I|", sci(row.stats.error_estimate / std::abs(t.reference)))
              : "";
      list += fmt::format(
          "- {} (s = {}), {}, {}tolerance {}: {} of {} {} stopped with {} above the target ({} "
          "evaluations{}, error estimate {}{})\n",
          cell(t.integrand), t.s, cell(t.method), t.relative_tolerance ? "relative " : "",
          sci(row.tolerance), stopped, row.stats.repetitions, one ? "repetition" : "repetitions",
          stopped == 1 ? "its error estimate" : "their error estimates", row.stats.evaluations,
          one ? "" : " on average", sci(row.stats.error_estimate), relative);
    }
  }
  if (!any_tolerance) return "";
  if (missed == 0) {
    return "## Targets not reached\n\nNone: every cell run to a tolerance stopped with its own "
           "error estimate at or below the target.\n\n";
  }
  const bool one = missed == 1;
  const char* its = one ? "its" : "their";
  return fmt::format(
      "## Targets not reached\n\n{} {} run to a tolerance spent {} budget (or reached {} level "
      "cap) with {} own error estimate still above the target; {} row in the tables below is "
      "where it stopped, not an answer at that tolerance:\n\n{}\n",
      missed, one ? "cell" : "cells", its, its, its, one ? "its" : "each one's", list);
}

// "Who leads at equal N" (who_leads.hpp): per family, a table of s × the ladder's N.
void append_leaders(std::string& out, std::span<const family_leaders> families) {
  std::string body;
  for (const family_leaders& f : families) {
    body += fmt::format("### {}\n\n| s |", cell(f.family));
    for (const std::uint64_t n : f.ladder) body += fmt::format(" N = {} |", n);
    body += "\n|---:|";
    for (std::size_t k = 0; k < f.ladder.size(); ++k) body += "---|";
    body += '\n';
    for (const leaders_row& r : f.rows) {
      body += fmt::format("| {} |", r.s);
      for (std::size_t k = 0; k < f.ladder.size(); ++k) {
        const std::optional<leader>& c = r.cells[k];
        if (!c) {
          body += " — |";
          continue;
        }
        body += fmt::format(" {} ({}", cell(c->method), sci(c->error));
        if (c->at_n != f.ladder[k]) body += fmt::format(" at N = {}", c->at_n);
        body += ") |";
      }
      body += '\n';
    }
    body += '\n';
  }
  if (body.empty()) return;
  out += "## Who leads at equal N\n\n";
  out +=
      "Per integrand family (its name without the `_s<s>` of a `dimensions` list) and dimension: "
      "at each N of the ladder, the method with the smallest error (RMSE over the repetitions, "
      "|error| for a rule) among those that spend at most N evaluations, with that error. Each "
      "method competes with its cell of the largest N' ≤ N (\"at N = N'\" when N' < N: a rule "
      "whose grid for N is the one it ran for N', or a method skipped at N). — where fewer than "
      "two methods compete or none ran N itself.\n\n";
  out += body;
}

}  // namespace

std::string plot_stem(std::string_view integrand) {
  std::string out;
  for (const char c : integrand) {
    const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '_' || c == '.' || c == '-';
    if (kept) {
      out += c;
    } else {
      out += fmt::format("~{:02X}", static_cast<unsigned char>(c));
    }
  }
  return out;
}

namespace {
// The integrand part of both plot names (the rule in markdown_report.hpp).
std::string plot_name(std::string_view integrand, std::size_t s) {
  const std::string stem = plot_stem(integrand);
  return stem.ends_with(fmt::format("_s{}", s)) ? stem : fmt::format("{}_s={}", stem, s);
}
}  // namespace

std::string convergence_plot_file(std::string_view integrand, std::size_t s) {
  return "error_" + plot_name(integrand, s) + ".svg";
}

std::string work_precision_plot_file(std::string_view integrand, std::size_t s) {
  return "work_precision_" + plot_name(integrand, s) + ".svg";
}

std::string render_results_markdown(const run_info& info,
                                    std::span<const convergence_table> tables) {
  std::string out = fmt::format("# Results: {}\n\n", info.scene);
  // The scene's own words first, as Markdown (it is the author's text): what the run is for.
  const std::string_view description = trimmed(info.description);
  if (!description.empty()) out += fmt::format("{}\n\n", description);
  // The answer first (answer_first.hpp): five lines at most, from the same "Who leads" tables as
  // the section further down, before the metadata, so that a reader sees it on the first screen.
  // A quotation, so that its list does not run into the metadata list below it.
  const std::vector<family_leaders> leaders = who_leads(tables);
  for (const std::string& line : answer_first_lines(tables, leaders, info.plots)) {
    out += fmt::format("> - {}\n", line);
  }
  out += '\n';
  out += fmt::format("- seed: {}\n", info.seed);
  out += fmt::format(
      "- rng: {} (the methods' random streams; docs/theory.md#counter-based-generators)\n",
      info.build.rng);
  out += info.threads_allowed != 0 && info.threads_allowed != info.threads
             ? fmt::format("- threads: {} used ({} allowed; no cell had work for more)\n",
                           info.threads, info.threads_allowed)
             : fmt::format("- threads: {}\n", info.threads);
  if (info.ranks > 1) {
    out += fmt::format(
        "- processes: {} MPI ranks × the threads above each (cells assigned by "
        "planned cost, large cells split by chunks; every column but the timing "
        "is what one process writes)\n",
        info.ranks);
  }
  if (!info.machine.empty()) out += fmt::format("- machine: {}\n", info.machine);
  // What made the page, as `quadmc --version` says it and meta.csv records it.
  if (!info.build.version.empty()) {
    out += fmt::format("- quadmc: {}, commit {}\n", info.build.version,
                       info.build.commit.empty() ? "unknown" : info.build.commit);
  }
  if (!info.build.compiler.empty()) out += fmt::format("- compiler: {}\n", info.build.compiler);
  if (!info.build.simd_levels_available.empty()) {
    out += fmt::format("- SIMD levels available: {}\n",
                       fmt::join(info.build.simd_levels_available, ", "));
  }
  out += fmt::format("- run time: {:.3g} s\n\n", info.run_seconds);
  out +=
      "Slopes are of the RMSE over repetitions (|error| for a deterministic rule, which runs "
      "once per N) against N = total integrand evaluations, fitted by least squares in log-log "
      "with a 95% Student-t interval; rounding-floor points (▼) are excluded. A slope *agrees* "
      "when |slope − theory| ≤ max(CI half-width, 0.1·|theory|). A deterministic rule on a jump "
      "it can bound (step, Genz discontinuous, a 1D disk or half-space) is judged against its "
      "a-priori error envelope instead, the jump term K·|J|·h plus the smooth part, since where "
      "the jump falls in its panel, not n alone, sets the error: *within_envelope* when every "
      "non-floor point is under it (the slope is shown beside it, not judged), *above_envelope* "
      "when one is not — a bug, no discretisation explains it. Where a rule's Euler–Maclaurin "
      "expansion predicts its error (f with known end-point derivatives), the prediction stands "
      "beside every cell and explains slopes the class rate does not: *superconvergent* (a "
      "leading term vanishes; the theory column is the order of the first one that does not), "
      "*pre_asymptotic* (the predicted curve matches the points, and its local slope reaches the "
      "asymptotic one only from the N the reason gives); *at_floor* when the rounding floor of "
      "the evaluation precision and the accumulator comes before three points could be fitted. "
      "*steeper* and *shallower* remain only where no computed reason explains the slope: they "
      "are findings, listed first.";
  out += info.csv ? " Data: `convergence.csv`, `slopes.csv`.\n\n"
                  : " (No CSV files: the scene's [output] turns csv off.)\n\n";
  out +=
      "Times: `time (s)` is the wall time of a cell's repetitions; `s per estimate` is its "
      "stable timing, apart from the statistics: repetition 1's call repeated in batches until "
      "the scene's `timing_min_seconds` had passed, the median over batches of seconds per call, "
      "with the spread (max − min)/median of the batches; a call that alone took the minimum is "
      "timed once. Work-precision figures use `s per estimate`.\n\n";
  if (!info.references.empty()) {
    // Not folded: every error of these integrands depends on the reference, so the reader sees
    // which ones before any table (docs/theory.md#references-without-a-closed-form).
    out +=
        "References without a closed form: the errors of these integrands are measured from a "
        "given or computed reference (not a family's exact value, where it has one); errors below "
        "10 times its uncertainty are floor points, not fitted.\n\n";
    for (const std::string& r : info.references) out += fmt::format("- {}\n", r);
    out += "\n";
  }
  if (!info.skipped.empty()) {
    // Folded: a ladder in s = 8 skips dozens of repeated grids, and the list would push the
    // slope table off the first screen. GitHub renders <details> with Markdown inside.
    out += fmt::format(
        "<details><summary>Skipped by the plan: {} {} (click for the reasons)</summary>\n\n",
        info.skipped.size(), info.skipped.size() == 1 ? "cell" : "cells");
    for (const std::string& s : info.skipped) out += fmt::format("- {}\n", s);
    out += "\n</details>\n\n";
  }

  // Findings first: a slope no computed reason explains, or a point above its bound.
  out += "## Findings\n\n";
  bool finding = false;
  for (const convergence_table& t : tables) {
    if (t.verdict != slope_verdict::steeper && t.verdict != slope_verdict::shallower &&
        t.verdict != slope_verdict::above_envelope) {
      continue;
    }
    finding = true;
    out += fmt::format("- **{} (s = {}), {}**: {} — {}\n", cell(t.integrand), t.s, cell(t.method),
                       to_string(t.verdict), cell(t.verdict_reason));
  }
  out += finding ? "\n"
                 : "None: every verdict has a computed reason (the slope table's last column).\n\n";
  out += targets_not_reached(tables);

  out += effective_dimension_section(info.effective_dimensions);

  out += "## Slopes\n\n";
  out += "| integrand | s | method | slope ± 95% CI | theory | verdict | points (floor) | why |\n";
  out += "|---|---:|---|---:|---:|---|---:|---|\n";
  for (const convergence_table& t : tables) {
    out +=
        fmt::format("| {} | {} | {} | {} | {} | {} | {} ({}) | {} |\n", cell(t.integrand), t.s,
                    cell(t.method), slope_text(t.fit), theory_text(t.theory), to_string(t.verdict),
                    t.points_used(), t.floor_points(), cell(t.verdict_reason));
  }
  out += '\n';
  out += ensemble_section(tables);

  // The floor rule of rounding_floor.hpp, per series: the smallest error reached before rounding
  // took over, absolute and relative to |I|, and where the floor began (reported as each method's
  // attainable accuracy: docs/design.md#accuracy-targets, docs/theory.md#rounding-floor).
  out += "## Attainable accuracy\n\n";
  out +=
      "Smallest error before the rounding floor (rounding_floor.hpp), absolute and relative to "
      "the reference; the floor starts at the N shown, its points are excluded from the slope.\n\n";
  out +=
      "| integrand | s | method | attainable accuracy | relative | floor from N | floor level |\n";
  out += "|---|---:|---|---:|---:|---:|---:|\n";
  for (const convergence_table& t : tables) {
    const double relative = t.reference != 0.0 ? t.floor.attainable_accuracy / std::abs(t.reference)
                                               : std::numeric_limits<double>::quiet_NaN();
    out += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} |\n", cell(t.integrand), t.s, cell(t.method),
        sci(t.floor.attainable_accuracy), t.reference != 0.0 ? sci(relative) : std::string("–"),
        t.floor.reached() ? fmt::format("{}", t.rows[*t.floor.first].n) : std::string("none"),
        t.floor.reached() ? sci(t.floor.floor_level) : std::string("–"));
  }
  out += '\n';

  // How often each method's own error estimate held (estimate_reliability.hpp), where any has one.
  const std::vector<estimate_reliability> reliability = summarise_estimate_reliability(tables);
  if (!reliability.empty()) {
    out += "## Error-estimate reliability\n\n";
    out +=
        "For every method that reports its own error estimate ê, per smoothness class and pooled "
        "over integrands and cells: the fraction of estimates (cells × repetitions) whose true "
        "|error| was at most ê and at most 3ê, the largest RMSE/ê of a cell (ê as the root mean "
        "square over its repetitions) and the mean χ²/dof of the iterations (VEGAS). A 1σ "
        "estimate (Monte Carlo's σ̂/√N, VEGAS's σ̂) that is honest covers ≈ 0.68 at 1× and ≈ 0.997 "
        "at 3×; a bound (Romberg's last difference, Genz–Malik's |Q₇ − Q₅|) should cover every "
        "estimate.";
    out += info.csv
               ? " Column `estimate_covers` (`_3x`) of `convergence.csv` holds it per cell.\n\n"
               : "\n\n";
    out +=
        "| method | class | series | cells | estimates | \\|error\\| ≤ ê | ≤ 3ê | worst RMSE/ê | "
        "χ²/dof |\n";
    out += "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const estimate_reliability& r : reliability) {
      out += fmt::format("| {} | {} | {} | {} | {} | {:.3f} | {:.3f} | {} | {} |\n", cell(r.method),
                         to_string(r.regularity), r.series, r.cells, r.estimates, r.covered,
                         r.covered_3x, short_number(r.worst_ratio), short_number(r.chi2_per_dof));
    }
    out += '\n';
  }

  // Scenes that run methods to tolerances beside peers: who gets there first
  // (time_to_error_table.hpp).
  out += time_to_error_markdown(tables, info.paired_timing, info.ranks, info.csv);

  append_leaders(out, leaders);

  // Groups in order of first appearance.
  std::vector<std::pair<std::string, std::size_t>> groups;
  for (const convergence_table& t : tables) {
    const std::pair<std::string, std::size_t> key{t.integrand, t.s};
    if (std::find(groups.begin(), groups.end(), key) == groups.end()) groups.push_back(key);
  }
  for (const auto& [integrand, s] : groups) {
    out += fmt::format("## {} (s = {})\n\n", cell(integrand), s);
    if (info.plots) {
      out += fmt::format("![error against N]({})\n\n", convergence_plot_file(integrand, s));
      out += fmt::format("![work-precision]({})\n\n", work_precision_plot_file(integrand, s));
    }
    std::vector<double> targets;
    for (const convergence_table& t : tables) {
      if (t.integrand != integrand || t.s != s) continue;
      append_method_table(out, t);
      if (targets.empty()) {
        for (const time_to_error& e : t.work_precision) targets.push_back(e.target);
      }
    }
    out += "### Work-precision: seconds per estimate to reach an error\n\n| method |";
    for (double target : targets) out += fmt::format(" {:.0e} |", target);
    out += "\n|---|";
    for (std::size_t k = 0; k < targets.size(); ++k) out += "---:|";
    out += '\n';
    for (const convergence_table& t : tables) {
      if (t.integrand != integrand || t.s != s) continue;
      out += fmt::format("| {} |", cell(t.method));
      for (const time_to_error& e : t.work_precision) {
        out += fmt::format(" {} |", time_to_error_text(e));
      }
      out += '\n';
    }
    out += '\n';
  }
  return out;
}

}  // namespace quadmc
