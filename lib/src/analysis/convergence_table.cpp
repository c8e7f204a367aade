// analyse_convergence: cell statistics → floor → fit → prediction → theory → verdict (slope or
// envelope) and its reason → work-precision.
#include "quadmc/analysis/convergence_table.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

namespace quadmc {
namespace {

std::string slope_text(const power_law_fit& fit) {
  return fit.ok() ? fmt::format("{:.3f} [{:.3f}, {:.3f}]", fit.slope, fit.ci_low, fit.ci_high)
                  : std::string("no fit");
}

std::string rate_text(std::optional<double> slope) {
  return slope ? fmt::format("{:.3g}", *slope) : std::string("none");
}

// What the prediction said about the measured cells.
struct prediction_check {
  std::size_t valid = 0;   // cells with a valid prediction
  std::size_t judged = 0;  // of them, judged (not floor, above the rounding margin)
  bool agrees = true;      // every judged cell within the tolerance
  double worst = std::numeric_limits<double>::quiet_NaN();  // judged ratio farthest from 1
  std::uint64_t worst_n = 0;                                // its evaluations
  // The coarse-grid term (error_prediction.hpp): its largest share |coarse|/|predicted| over the
  // valid cells and where, and the last valid cell where it exceeds the end-point terms.
  double coarse_share = 0.0;
  std::uint64_t coarse_share_n = 0;
  std::uint64_t coarse_leads_to = 0;
  bool confirmed() const noexcept { return judged > 0 && agrees; }
};

// d log|P|/d log N between n and 2n panels per axis; nullopt where P(n) is not valid or either
// value is 0 or the grid overflows.
std::optional<double> predicted_local_slope(const error_prediction& p, std::uint64_t n,
                                            double validity) {
  if (n > (std::uint64_t{1} << 62)) return std::nullopt;
  const predicted_cell here = p.at(n);
  const predicted_cell next = p.at(2 * n);
  if (!(here.next_change <= validity) || here.evaluations == 0 || next.evaluations == 0 ||
      next.evaluations <= here.evaluations || here.error == 0.0 || next.error == 0.0 ||
      !std::isfinite(here.error) || !std::isfinite(next.error)) {
    return std::nullopt;
  }
  return std::log(std::abs(next.error) / std::abs(here.error)) /
         std::log(static_cast<double>(next.evaluations) / static_cast<double>(here.evaluations));
}

// Fills each row's predicted error and ratio, and says what they add up to.
prediction_check check_prediction(convergence_table& table, const error_prediction& prediction,
                                  const analysis_options& options, const std::string& where) {
  prediction_check check;
  if (!prediction.at) return check;
  for (convergence_row& row : table.rows) {
    if (row.per_axis == 0) continue;
    const predicted_cell p = prediction.at(row.per_axis);
    require(p.evaluations == row.stats.evaluations, "predicted evaluations", p.evaluations,
            fmt::format("the cell's own {} evaluations (n = {} per axis, {})",
                        row.stats.evaluations, row.per_axis, where));
    if (!(p.next_change <= options.prediction_validity) || !std::isfinite(p.error) ||
        p.error == 0.0) {
      continue;
    }
    ++check.valid;
    const double share = std::abs(p.coarse_grid) / std::abs(p.error);
    if (share > check.coarse_share) {
      check.coarse_share = share;
      check.coarse_share_n = row.stats.evaluations;
    }
    if (std::abs(p.coarse_grid) > std::abs(p.error - p.coarse_grid)) {
      check.coarse_leads_to = row.stats.evaluations;
    }
    row.predicted_error = std::abs(p.error);
    const double measured =
        row.stats.repetitions == 1 ? row.stats.estimate_mean - table.reference : row.stats.rmse;
    row.prediction_ratio =
        row.stats.repetitions == 1 ? measured / p.error : measured / std::abs(p.error);
    row.prediction_judged =
        !row.floor && row.stats.rmse > options.prediction_rounding_margin * row.rounding_level;
    if (!row.prediction_judged) continue;
    ++check.judged;
    const double off = std::abs(row.prediction_ratio - 1.0);
    if (std::isnan(check.worst) || off > std::abs(check.worst - 1.0)) {
      check.worst = row.prediction_ratio;
      check.worst_n = row.stats.evaluations;
    }
    check.agrees = check.agrees && off <= options.prediction_tolerance;
  }
  return check;
}

// The evaluations from which the predicted local slope stays within the verdict tolerance of
// `theory`: the first row from which every later row with a prediction is so, else the first
// doubling of the last row's n beyond the ladder that is (nullopt when none below 2^63).
std::optional<std::uint64_t> asymptotic_start(const convergence_table& table,
                                              const error_prediction& prediction, double theory,
                                              const analysis_options& options) {
  const auto asymptotic = [&](std::uint64_t n) {
    const std::optional<double> local =
        predicted_local_slope(prediction, n, options.prediction_validity);
    return local && std::abs(*local - theory) <= options.verdict_tolerance * std::abs(theory);
  };
  std::optional<std::size_t> start;
  std::uint64_t last_n = 0;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    const convergence_row& row = table.rows[k];
    if (row.per_axis == 0) continue;
    last_n = row.per_axis;
    if (asymptotic(row.per_axis)) {
      if (!start) start = k;
    } else {
      start.reset();
    }
  }
  if (start) return table.rows[*start].stats.evaluations;
  for (std::uint64_t n = last_n; n > 0 && n <= (std::uint64_t{1} << 61);) {
    n *= 2;
    if (asymptotic(n)) return prediction.at(n).evaluations;
  }
  return std::nullopt;
}

// The slope verdict and its reason, with the prediction where one is confirmed.
void judge_series(convergence_table& table, const convergence_series& series,
                  const analysis_options& options, const std::vector<double>& fit_n,
                  const std::vector<double>& fit_error, const std::vector<double>& fit_estimate) {
  const std::string where =
      fmt::format("{} / s = {} / {}", series.integrand, series.s, series.method);
  const std::optional<double> class_slope = series.theory.slope;
  const std::size_t clean = fit_n.size();
  const bool floor_limited = table.floor.reached() && clean < 3;
  const bool reference_floor = table.floor.reached() && table.floor.reference_first &&
                               *table.floor.reference_first == *table.floor.first;
  const std::string floor_text =
      !table.floor.reached() ? std::string()
      : reference_floor
          ? fmt::format("the reference's floor ({} × its uncertainty {:.2g}) from N = {}",
                        options.floor.reference_factor, series.reference_uncertainty,
                        table.rows[*table.floor.first].stats.evaluations)
          : fmt::format("the rounding floor of {} from N = {} (ℓ = {:.2g} there)",
                        series.rounding.describe(),
                        table.rows[*table.floor.first].stats.evaluations,
                        table.rows[*table.floor.first].rounding_level);

  prediction_check check;
  const error_prediction* prediction = series.prediction ? &*series.prediction : nullptr;
  if (prediction) check = check_prediction(table, *prediction, options, where);
  table.predicted_points = check.judged;
  table.worst_prediction_ratio = check.worst;
  // The coarse-grid term is named where it is at least 0.1% of a prediction shown.
  const bool coarse =
      prediction && !prediction->coarse_grid_note.empty() && check.coarse_share >= 1e-3;
  const std::string coarse_text =
      coarse
          ? fmt::format(
                "{} ({:.3g}% of the predicted error at N = {}{})", prediction->coarse_grid_note,
                100.0 * check.coarse_share, check.coarse_share_n,
                check.coarse_leads_to > 0
                    ? fmt::format(", above the end-point terms up to N = {}", check.coarse_leads_to)
                    : std::string())
          : std::string();
  const std::string checked =
      check.judged > 0
          ? fmt::format(
                "Euler–Maclaurin prediction{} within {:.2g}% at {} point{} (worst "
                "measured/predicted {:.4f} at N = {}){}",
                coarse ? " with the coarse-grid term" : "", 100.0 * std::abs(check.worst - 1.0),
                check.judged, check.judged == 1 ? "" : "s", check.worst, check.worst_n,
                coarse ? "; " + coarse_text : std::string())
          : std::string();

  // Every term of the expansion vanishes: exponential convergence, judged by being faster than
  // the class rate (or reaching the floor before three points).
  if (prediction && !prediction->leading_slope) {
    // The point estimate, not the interval: a power law is the wrong model for e^(−cN), so its
    // interval is wide by construction (a bending log-log curve leaves large residuals).
    const bool fast = table.fit.ok() && class_slope &&
                      table.fit.slope < *class_slope * (1.0 + options.verdict_tolerance);
    if (fast || floor_limited) {
      table.theory = {std::nullopt, prediction->note, prediction->source};
      table.verdict = slope_verdict::superconvergent;
      table.verdict_reason = fmt::format(
          "{}: exponential convergence, no finite slope ({})", prediction->note,
          fast ? fmt::format("the fitted {:.3g} is far steeper than the class rate {}",
                             table.fit.slope, rate_text(class_slope))
               : fmt::format("{} point{} before {}", clean, clean == 1 ? "" : "s", floor_text));
      return;
    }
  }

  // The rate to judge against: the first non-vanishing term's once the data confirm it.
  const bool superconvergent = prediction && check.confirmed() && prediction->superconvergent &&
                               prediction->leading_slope.has_value();
  if (superconvergent) {
    table.theory = {prediction->leading_slope, prediction->note, prediction->source};
  }
  const std::optional<double> theory = table.theory.slope;
  if (prediction && check.confirmed() && theory) {
    table.asymptotic_from = asymptotic_start(table, *prediction, *theory, options);
    std::vector<double> n, e;
    for (std::size_t k = 0; k < fit_n.size(); ++k) {
      if (table.asymptotic_from && fit_n[k] >= static_cast<double>(*table.asymptotic_from)) {
        n.push_back(fit_n[k]);
        e.push_back(fit_error[k]);
      }
    }
    table.asymptotic_fit = fit_power_law(n, e, options.confidence);
  }
  const std::uint64_t last_evaluations = table.rows.back().stats.evaluations;
  const std::string from_text =
      table.asymptotic_from
          ? fmt::format("from N = {}{}", *table.asymptotic_from,
                        *table.asymptotic_from > last_evaluations ? " (beyond the ladder)" : "")
          : std::string("not below N = 2^63");
  const std::string asymptotic_text =
      table.asymptotic_fit.ok()
          ? fmt::format("slope fitted from there {}", slope_text(table.asymptotic_fit))
          : std::string("fewer than three points from there");

  if (!table.fit.ok()) {
    if (superconvergent) {
      table.verdict = slope_verdict::superconvergent;
      table.verdict_reason =
          fmt::format("{}; {}; no slope fitted ({} points)", prediction->note, checked, clean);
    } else if (floor_limited) {
      table.verdict = slope_verdict::at_floor;
      table.verdict_reason =
          fmt::format("{} point{} before {}: too few to fit a slope{}", clean,
                      clean == 1 ? "" : "s", floor_text, checked.empty() ? "" : "; " + checked);
    } else if (prediction && check.confirmed() && theory &&
               (!table.asymptotic_from || *table.asymptotic_from > last_evaluations)) {
      table.verdict = slope_verdict::pre_asymptotic;
      table.verdict_reason = fmt::format(
          "{}; the predicted local slope reaches {} ± {:.0f}% {}; no slope fitted ({} "
          "points)",
          checked, rate_text(theory), 100.0 * options.verdict_tolerance, from_text, clean);
    } else {
      table.verdict = slope_verdict::no_fit;
      table.verdict_reason = fmt::format("fewer than three usable points ({}){}", clean,
                                         checked.empty() ? "" : "; " + checked);
    }
    return;
  }
  if (!theory) {
    table.verdict = slope_verdict::no_theory;
    table.verdict_reason = "no finite slope predicted: " + table.theory.note;
    return;
  }
  const slope_verdict slope = judge_slope(table.fit, theory, options.verdict_tolerance);
  if (slope == slope_verdict::agrees) {
    table.verdict = superconvergent ? slope_verdict::superconvergent : slope_verdict::agrees;
    // With a coarse-grid term the whole-ladder slope mixes it with the end-point term's: say
    // from where the latter carries the curve.
    const std::string regime =
        coarse && check.confirmed()
            ? fmt::format("; the predicted local slope reaches {} ± {:.0f}% {}", rate_text(theory),
                          100.0 * options.verdict_tolerance, from_text)
            : std::string();
    table.verdict_reason =
        superconvergent ? fmt::format("{}; {}; the slope agrees with {}{}", prediction->note,
                                      checked, rate_text(theory), regime)
                        : fmt::format("slope within max(CI half-width, {:.0f}%·|theory|) of {}{}{}",
                                      100.0 * options.verdict_tolerance, rate_text(theory),
                                      checked.empty() ? "" : "; " + checked, regime);
    return;
  }
  const bool asymptotic_agrees =
      !table.asymptotic_fit.ok() ||
      judge_slope(table.asymptotic_fit, theory, options.verdict_tolerance) == slope_verdict::agrees;
  if (prediction && check.confirmed() && asymptotic_agrees) {
    table.verdict =
        superconvergent ? slope_verdict::superconvergent : slope_verdict::pre_asymptotic;
    table.verdict_reason = fmt::format(
        "{}{}; the predicted local slope reaches {} ± {:.0f}% {}; {}: the whole-ladder slope {} "
        "measures the cells before it",
        superconvergent ? prediction->note + "; " : std::string(), checked, rate_text(theory),
        100.0 * options.verdict_tolerance, from_text, asymptotic_text, slope_text(table.fit));
    return;
  }
  // A bound with a log factor, N^p·(log N)^q, falls over the fitted range N₁ … N₂ with the
  // local slope p + q·(ln ln N₂ − ln ln N₁)/(ln N₂ − ln N₁): a finite ladder measures that, not p
  // (docs/theory.md#pre-asymptotic-ladders). The bound caps the log factor's power at q, so an
  // error under it falls with a local slope between p (no log factor) and the bound's: a fitted
  // slope that agrees with the bound's local slope, or lies between it and p, is a computed
  // reason; one steeper than p or shallower than the bound's local slope stays a finding.
  if (!prediction && table.theory.log_power > 0.0 && fit_n.size() >= 2 &&
      *std::min_element(fit_n.begin(), fit_n.end()) > 1.0) {
    const double n1 = *std::min_element(fit_n.begin(), fit_n.end());
    const double n2 = *std::max_element(fit_n.begin(), fit_n.end());
    const double local = *theory + table.theory.log_power *
                                       (std::log(std::log(n2)) - std::log(std::log(n1))) /
                                       (std::log(n2) - std::log(n1));
    const bool at_bound =
        judge_slope(table.fit, local, options.verdict_tolerance) == slope_verdict::agrees;
    const bool between = table.fit.slope >= *theory && table.fit.slope <= local;
    if (at_bound || between) {
      table.verdict = slope_verdict::pre_asymptotic;
      table.verdict_reason =
          fmt::format(
              "the bound N^{:.3g}·(log N)^{:.3g} falls with the local slope {:.3f} over the "
              "fitted N = {:.0f} … {:.0f}, and the slope {} ",
              *theory, table.theory.log_power, local, n1, n2, slope_text(table.fit)) +
          (at_bound ? fmt::format("agrees with it within max(CI half-width, {:.0f}%): its log "
                                  "factor, not another rate",
                                  100.0 * options.verdict_tolerance)
                    : fmt::format("lies between it and {:.3g}: a log factor of power at most "
                                  "{:.3g}, as the bound allows, not another rate",
                                  *theory, table.theory.log_power));
      return;
    }
  }
  // An adaptive Monte Carlo method (VEGAS, MISER) reports σ̂_N/√N with the σ̂ of the density or
  // strata it has adapted so far, and that σ̂ falls while it adapts: over a finite ladder its
  // error falls faster (or, while a grid is still wrong, slower) than N^(−1/2), which holds only
  // once σ̂ has settled (docs/theory.md#adaptive-monte-carlo-ladders). The slope of the estimate it
  // reports, fitted over the same N, is then the computed reason; a measured slope that does not
  // agree with it stays a finding.
  if (table.theory.adaptive && fit_estimate.size() == fit_n.size() &&
      std::all_of(fit_estimate.begin(), fit_estimate.end(),
                  [](double e) { return std::isfinite(e) && e > 0.0; })) {
    const power_law_fit reported = fit_power_law(fit_n, fit_estimate, options.confidence);
    if (reported.ok() && judge_slope(table.fit, reported.slope, options.verdict_tolerance) ==
                             slope_verdict::agrees) {
      const double first_sigma = fit_estimate.front() * std::sqrt(fit_n.front());
      const double last_sigma = fit_estimate.back() * std::sqrt(fit_n.back());
      table.verdict = slope_verdict::pre_asymptotic;
      table.verdict_reason = fmt::format(
          "adapting: the error σ̂/√N it reports falls with slope {:.3f} over the fitted N = {:.0f} "
          "… {:.0f} (its per-evaluation σ̂ from {:.3g} to {:.3g}), and the slope {} agrees with "
          "it within max(CI half-width, {:.0f}%): its variance changes while it adapts, not "
          "another rate",
          reported.slope, fit_n.front(), fit_n.back(), first_sigma, last_sigma,
          slope_text(table.fit), 100.0 * options.verdict_tolerance);
      return;
    }
  }
  table.verdict = slope;
  std::string why;
  if (!prediction) {
    why = "no error prediction for this method and integrand";
  } else if (!prediction->leading_slope) {
    why = prediction->note + ", yet the ladder is not faster than the class rate";
  } else if (check.judged == 0) {
    why = fmt::format(
        "the Euler–Maclaurin prediction is valid at {} point{} but judged at none "
        "(floor or rounding)",
        check.valid, check.valid == 1 ? "" : "s");
  } else if (!check.agrees) {
    why = fmt::format("the Euler–Maclaurin prediction is off: measured/predicted {:.4g} at N = {}",
                      check.worst, check.worst_n);
  } else {
    why = fmt::format("{}, but the slope {} of the asymptotic part does not agree either", checked,
                      asymptotic_text);
  }
  table.verdict_reason = fmt::format("finding, no computed reason: slope {} against theory {}; {}",
                                     slope_text(table.fit), rate_text(theory), why);
}

}  // namespace

convergence_table analyse_convergence(const convergence_series& series,
                                      const analysis_options& options) {
  require(!series.cells.empty(), "cells", series.cells.size(),
          fmt::format("at least one cell for {} / {}", series.integrand, series.method));
  require(series.s >= 1, "s", series.s,
          fmt::format("a dimension >= 1 for {} / {}", series.integrand, series.method));
  convergence_table table;
  table.integrand = series.integrand;
  table.s = series.s;
  table.method = series.method;
  table.regularity = series.regularity;
  table.relative_tolerance = series.relative_tolerance;
  table.reference = series.reference;
  table.reference_uncertainty = series.reference_uncertainty;
  table.theory = series.theory;

  // Sized cells in increasing N; cells run to a tolerance in decreasing tolerance, the order in
  // which a convergent method spends more.
  const bool to_tolerance = !std::isnan(series.cells.front().tolerance);
  std::vector<const convergence_cell*> cells;
  for (const convergence_cell& cell : series.cells) {
    require(std::isnan(cell.tolerance) != to_tolerance, "tolerance", cell.tolerance,
            fmt::format("cells of one kind in a series, all sized or all run to a tolerance ({} / "
                        "s = {} / {})",
                        series.integrand, series.s, series.method));
    cells.push_back(&cell);
  }
  std::stable_sort(cells.begin(), cells.end(),
                   [&](const convergence_cell* a, const convergence_cell* b) {
                     return to_tolerance ? a->tolerance > b->tolerance : a->n < b->n;
                   });

  for (const convergence_cell* cell : cells) {
    const std::string where =
        to_tolerance ? fmt::format("cell tolerance = {} of {} / s = {} / {}", cell->tolerance,
                                   series.integrand, series.s, series.method)
                     : fmt::format("cell N = {} of {} / s = {} / {}", cell->n, series.integrand,
                                   series.s, series.method);
    if (to_tolerance) {
      require(table.rows.empty() || cell->tolerance != table.rows.back().tolerance, "tolerance",
              cell->tolerance, "distinct tolerances in a series (" + where + ")");
    } else {
      require(table.rows.empty() || cell->n != table.rows.back().n, "N", cell->n,
              "distinct N in a series (" + where + ")");
    }
    require(std::isnan(cell->error_envelope) || cell->error_envelope >= 0.0, "error_envelope",
            cell->error_envelope, "a bound >= 0 on |error|, or NaN for none (" + where + ")");
    require(std::isnan(cell->error_envelope) == std::isnan(series.cells.front().error_envelope),
            "error_envelope", cell->error_envelope,
            "an envelope on every cell of the series or on none (" + where + ")");
    convergence_row row;
    row.n = cell->n;
    row.tolerance = cell->tolerance;
    row.per_axis = cell->per_axis;
    row.envelope = cell->error_envelope;
    row.timing = cell->timing;
    try {
      row.stats = compute_cell_statistics(cell->repetitions, series.reference, series.errors);
      if (cell->instances > 1) {
        row.ensemble =
            compute_ensemble_statistics(cell->repetitions, series.reference, cell->instances);
      }
    } catch (const invalid_argument& e) {
      throw invalid_argument(fmt::format("{}: {}", where, e.what()));
    }
    // Equal counts are one computation reached twice (a tolerance met at the same level, a
    // budget not spent); fewer is a ladder out of order.
    require(table.rows.empty() || row.stats.evaluations >= table.rows.back().stats.evaluations,
            "evaluations", row.stats.evaluations,
            fmt::format("at least the evaluations of the previous {} ({})",
                        to_tolerance ? "(looser) tolerance" : "N of the ladder", where));
    table.rows.push_back(row);
  }

  // The ladder the floor rule, the fit and the work-precision table see: one point per distinct
  // evaluation count, the first row that spent it (fixed-size cells are distinct already: the
  // plan skips a repeated grid; a budget or tolerance cell may stop where a smaller one did).
  std::vector<std::size_t> ladder;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    if (ladder.empty() ||
        table.rows[k].stats.evaluations != table.rows[ladder.back()].stats.evaluations) {
      ladder.push_back(k);
    }
  }
  std::vector<double> evaluations, errors, seconds, amplification;
  double largest_error = 0.0;
  for (const std::size_t k : ladder) {
    const convergence_row& row = table.rows[k];
    evaluations.push_back(static_cast<double>(row.stats.evaluations));
    errors.push_back(row.stats.rmse);
    seconds.push_back(row.seconds_per_estimate());
    largest_error = std::max(largest_error, row.stats.rmse);
    // A rule with weights of both signs amplifies rounding by Σ|w| (cell_statistics.hpp).
    const double w = row.stats.absolute_weight_sum;
    amplification.push_back(std::isnan(w) ? 1.0 : std::max(1.0, w));
  }
  const double scale = series.reference != 0.0 ? std::abs(series.reference) : largest_error;
  std::vector<double> scales;
  for (const double a : amplification) scales.push_back(scale * a);
  // The floor, fit and work-precision steps name their inputs by position ("error[0]"); the
  // series they came from goes in front, so a failure says which integrand and method.
  const auto in_series = [&](auto&& step) {
    try {
      return step();
    } catch (const invalid_argument& e) {
      throw invalid_argument(
          fmt::format("{} / s = {} / {}: {}", series.integrand, series.s, series.method, e.what()));
    }
  };
  table.rounding = series.rounding;
  table.class_theory = series.theory;
  table.floor = in_series([&] {
    rounding_floor floor =
        detect_rounding_floor(evaluations, errors, scales, series.rounding, options.floor);
    // A reference known to ± u cannot measure an error near u: such points are not fitted
    // (docs/theory.md#references-without-a-closed-form).
    add_reference_floor(floor, errors, series.reference_uncertainty,
                        options.floor.reference_factor);
    return floor;
  });

  // A row shares the floor flag of the ladder point that spent its evaluations; the table's
  // floor is then stated per row, like everything else in it.
  std::vector<double> fit_n, fit_error, fit_estimate;  // fit_estimate: the method's own claims
  std::vector<bool> row_flags(table.rows.size(), false);
  for (std::size_t p = 0; p < ladder.size(); ++p) {
    const std::size_t end = p + 1 < ladder.size() ? ladder[p + 1] : table.rows.size();
    for (std::size_t k = ladder[p]; k < end; ++k) {
      table.rows[k].floor = table.floor.flags[p];
      row_flags[k] = table.floor.flags[p];
      table.rows[k].rounding_level =
          rounding_level(evaluations[p], scales[p], series.rounding, options.floor);
    }
    if (p > 0 && errors[p] > 0.0 && errors[p - 1] > 0.0) {
      table.rows[ladder[p]].local_slope =
          std::log(errors[p] / errors[p - 1]) / std::log(evaluations[p] / evaluations[p - 1]);
    }
    if (!table.floor.flags[p]) {
      fit_n.push_back(evaluations[p]);
      fit_error.push_back(errors[p]);
      fit_estimate.push_back(table.rows[ladder[p]].stats.error_estimate);
    }
  }
  if (table.floor.first) table.floor.first = ladder[*table.floor.first];
  if (table.floor.reference_first) {
    table.floor.reference_first = ladder[*table.floor.reference_first];
  }
  table.floor.flags = std::move(row_flags);
  table.fit = in_series([&] { return fit_power_law(fit_n, fit_error, options.confidence); });
  if (table.has_envelope()) {
    std::vector<double> judged_error, allowed;
    for (const convergence_row& row : table.rows) {
      if (row.floor) continue;
      const double error = row.stats.rmse;
      const auto n = static_cast<double>(row.stats.evaluations);
      judged_error.push_back(error);
      const double w = row.stats.absolute_weight_sum;
      allowed.push_back(row.envelope +
                        rounding_level(n, scale * (std::isnan(w) ? 1.0 : std::max(1.0, w)),
                                       series.rounding, options.floor));
      const double ratio =
          row.envelope > 0.0 ? error / row.envelope : std::numeric_limits<double>::infinity();
      table.envelope_ratio =
          std::isnan(table.envelope_ratio) ? ratio : std::max(table.envelope_ratio, ratio);
    }
    table.verdict = judge_envelope(judged_error, allowed);
    table.verdict_reason =
        table.verdict == slope_verdict::within_envelope
            ? fmt::format(
                  "every non-floor point is under its a-priori error envelope (largest "
                  "error/envelope {:.3g}); the slope of a jump ladder is not a rate",
                  table.envelope_ratio)
        : table.verdict == slope_verdict::above_envelope
            ? fmt::format(
                  "a point is above its a-priori error envelope (largest error/envelope "
                  "{:.3g}): no discretisation explains that, a bug",
                  table.envelope_ratio)
            : std::string("no point to judge against the envelope");
  } else {
    judge_series(table, series, options, fit_n, fit_error, fit_estimate);
  }
  table.work_precision =
      in_series([&] { return work_precision(seconds, errors, options.error_targets); });
  return table;
}

}  // namespace quadmc
