// Comparison of two results folders; the regression rule is in compare.hpp.
#include "quadmc/report/compare.hpp"

#include "quadmc/analysis/slope_verdict.hpp"
#include "quadmc/analysis/work_precision.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/report/results_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace quadmc {
namespace {

using series_key = std::tuple<std::string, std::size_t, std::string>;  // integrand, s, method

std::optional<double> fitted(const slope_record& r) {
  return std::isnan(r.slope) ? std::nullopt : std::optional<double>(r.slope);
}

double half_width(const slope_record& r) {
  return std::isnan(r.ci_low) ? 0.0 : 0.5 * (r.ci_high - r.ci_low);
}

std::map<series_key, std::vector<convergence_record>> by_series(
    std::vector<convergence_record> rows) {
  std::map<series_key, std::vector<convergence_record>> out;
  for (convergence_record& r : rows) {
    out[{r.integrand, r.s, r.method}].push_back(std::move(r));
  }
  for (auto& [key, list] : out) {
    std::sort(list.begin(), list.end(),
              [](const convergence_record& x, const convergence_record& y) {
                // Sized cells by N; cells run to a tolerance (N = 0) by decreasing tolerance.
                return x.n != y.n ? x.n < y.n : x.tolerance > y.tolerance;
              });
  }
  return out;
}

std::vector<time_to_error> times_of(const std::vector<convergence_record>& rows) {
  std::vector<double> seconds, errors;
  for (const convergence_record& r : rows) {
    seconds.push_back(r.time_per_estimate());
    errors.push_back(r.rmse);
  }
  return work_precision(seconds, errors);
}

std::string series_name(const slope_comparison& c) {
  return fmt::format("{} (s = {}) {}", c.integrand, c.s, c.method);
}

// The reason line of compare_result: counts, and the first series of each kind.
std::string outcome_reason(const compare_result& r) {
  const auto first = [&](auto&& predicate) {
    const auto it = std::find_if(r.slopes.begin(), r.slopes.end(), predicate);
    return it == r.slopes.end() ? std::string() : series_name(*it);
  };
  std::vector<std::string> parts;
  if (r.regressions > 0) {
    parts.push_back(fmt::format("{} regression{} (first: {})", r.regressions,
                                r.regressions == 1 ? "" : "s",
                                first([](const slope_comparison& c) { return c.regression; })));
  }
  if (r.missing_in_b > 0) {
    parts.push_back(
        fmt::format("{} series of A missing in B (first: {})", r.missing_in_b,
                    first([](const slope_comparison& c) { return c.status == "missing in B"; })));
  }
  if (r.lost_fits > 0) {
    parts.push_back(
        fmt::format("{} series fitted in A without a fit in B (first: {})", r.lost_fits,
                    first([](const slope_comparison& c) { return c.status == "no fit in B"; })));
  }
  if (r.compared == 0) parts.push_back("no series is fitted in both A and B");
  std::string out;
  for (const std::string& part : parts) out += (out.empty() ? "" : "; ") + part;
  return out;
}

std::string optional_number(const std::optional<double>& x, const char* format_spec) {
  return x ? fmt::format(fmt::runtime(format_spec), *x) : std::string("—");
}

}  // namespace

compare_result compare_results(const std::filesystem::path& a, const std::filesystem::path& b,
                               double tolerance) {
  require(std::isfinite(tolerance) && tolerance >= 0.0, "tolerance", tolerance, "finite and >= 0");
  compare_result result;
  result.a = a;
  result.b = b;
  result.tolerance = tolerance;

  std::map<series_key, slope_record> slopes_a, slopes_b;
  std::vector<series_key> order;  // A's order first, then what only B has
  for (slope_record& r : read_slopes_csv(a / "slopes.csv")) {
    series_key key{r.integrand, r.s, r.method};
    order.push_back(key);
    slopes_a.emplace(key, std::move(r));
  }
  for (slope_record& r : read_slopes_csv(b / "slopes.csv")) {
    series_key key{r.integrand, r.s, r.method};
    if (!slopes_a.count(key)) order.push_back(key);
    slopes_b.emplace(key, std::move(r));
  }

  for (const series_key& key : order) {
    slope_comparison c;
    std::tie(c.integrand, c.s, c.method) = key;
    const auto ia = slopes_a.find(key);
    const auto ib = slopes_b.find(key);
    if (ia != slopes_a.end()) {
      c.slope_a = fitted(ia->second);
      c.half_width_a = half_width(ia->second);
      if (!std::isnan(ia->second.theory)) c.theory = ia->second.theory;
    }
    if (ib != slopes_b.end()) {
      c.slope_b = fitted(ib->second);
      c.half_width_b = half_width(ib->second);
      if (!c.theory && !std::isnan(ib->second.theory)) c.theory = ib->second.theory;
    }
    c.allowed = std::max(tolerance, std::hypot(c.half_width_a, c.half_width_b));
    // An envelope verdict in B (slope_verdict.hpp) decides for itself: above its a-priori bound
    // is a regression whatever the slope did; within it, the slope of a jump ladder is not a
    // rate (it depends on where the jump falls in each grid), so a moved slope is reported only.
    const std::string verdict_b = ib != slopes_b.end() ? ib->second.verdict : std::string();
    const bool envelope_b = verdict_b == to_string(slope_verdict::within_envelope) ||
                            verdict_b == to_string(slope_verdict::above_envelope);
    if (verdict_b == to_string(slope_verdict::above_envelope)) {
      c.regression = true;
      c.status = "above envelope in B";
    } else if (ia == slopes_a.end()) {
      c.status = "missing in A";
    } else if (ib == slopes_b.end()) {
      c.status = "missing in B";
      ++result.missing_in_b;
    } else if (!c.slope_a) {
      c.status = "no fit in A";
    } else if (!c.slope_b) {
      c.status = "no fit in B";
      ++result.lost_fits;
    } else {
      ++result.compared;
      const double loss = *c.slope_b - *c.slope_a;  // > 0: B converges more slowly
      if (envelope_b) {
        c.status = std::abs(loss) > c.allowed ? "slope moved, within envelope in B" : "ok";
      } else {
        c.regression = loss > c.allowed;
        c.status = c.regression ? "regression" : (loss < -c.allowed ? "steeper in B" : "ok");
      }
    }
    if (c.regression) ++result.regressions;
    result.slopes.push_back(std::move(c));
  }
  result.regression = result.regressions > 0;
  result.outcome = result.regression ? compare_outcome::regression
                   : result.missing_in_b > 0 || result.lost_fits > 0 || result.compared == 0
                       ? compare_outcome::incomparable
                       : compare_outcome::no_regression;
  result.reason = result.outcome == compare_outcome::no_regression ? "" : outcome_reason(result);

  const auto rows_a = by_series(read_convergence_csv(a / "convergence.csv"));
  const auto rows_b = by_series(read_convergence_csv(b / "convergence.csv"));
  for (const auto& [key, list_a] : rows_a) {
    const auto it = rows_b.find(key);
    if (it == rows_b.end()) continue;
    const auto& list_b = it->second;
    for (const convergence_record& ra : list_a) {
      const auto rb = std::find_if(list_b.begin(), list_b.end(), [&](const convergence_record& r) {
        return r.n == ra.n && (r.tolerance == ra.tolerance ||
                               (std::isnan(r.tolerance) && std::isnan(ra.tolerance)));
      });
      if (rb == list_b.end()) continue;
      error_comparison e{
          std::get<0>(key),
          std::get<1>(key),
          std::get<2>(key),
          ra.n,
          ra.rmse,
          rb->rmse,
          ra.rmse > 0.0 ? rb->rmse / ra.rmse : std::numeric_limits<double>::quiet_NaN()};
      result.errors.push_back(std::move(e));
    }
    const auto times_a = times_of(list_a);
    const auto times_b = times_of(list_b);
    for (std::size_t k = 0; k < times_a.size(); ++k) {
      time_comparison t{std::get<0>(key),   std::get<1>(key),   std::get<2>(key), times_a[k].target,
                        times_a[k].seconds, times_b[k].seconds, std::nullopt};
      if (t.seconds_a && t.seconds_b && *t.seconds_a > 0.0) t.ratio = *t.seconds_b / *t.seconds_a;
      result.times.push_back(std::move(t));
    }
  }
  return result;
}

std::string render_compare_markdown(const compare_result& r) {
  std::string out = fmt::format("# Compare: A = `{}`, B = `{}`\n\n", r.a.string(), r.b.string());
  switch (r.outcome) {
    case compare_outcome::regression:
      out += fmt::format(
          "**REGRESSION**: {} series of B are shallower than A's by more than "
          "max({}, √(h_A² + h_B²)) or above their error envelope. {}.\n\n",
          r.regressions, r.tolerance, r.reason);
      break;
    case compare_outcome::incomparable:
      out += fmt::format("**INCOMPARABLE**: {}. A gate cannot pass on what it did not compare.\n\n",
                         r.reason);
      break;
    case compare_outcome::no_regression:
      out += fmt::format(
          "No slope regression in {} series (tolerance max({}, √(h_A² + h_B²)), h = 95% CI "
          "half-width).\n\n",
          r.compared, r.tolerance);
      break;
  }
  out += "## Slopes\n\n| integrand | s | method | A | B | B − A | allowed | theory | status |\n";
  out += "|---|---:|---|---:|---:|---:|---:|---:|---|\n";
  for (const slope_comparison& c : r.slopes) {
    const std::optional<double> diff =
        c.slope_a && c.slope_b ? std::optional<double>(*c.slope_b - *c.slope_a) : std::nullopt;
    out += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {:.3f} | {} | {} |\n", c.integrand, c.s, c.method,
        c.slope_a ? fmt::format("{:.3f} ± {:.3f}", *c.slope_a, c.half_width_a) : "—",
        c.slope_b ? fmt::format("{:.3f} ± {:.3f}", *c.slope_b, c.half_width_b) : "—",
        optional_number(diff, "{:+.3f}"), c.allowed, optional_number(c.theory, "{:.3f}"),
        c.regression ? "**regression**" : c.status);
  }

  out += "\n## Error at equal N (RMSE of B / RMSE of A)\n\n";
  out += "| integrand | s | method | points | geometric mean | worst (max) |\n";
  out += "|---|---:|---|---:|---:|---:|\n";
  for (std::size_t i = 0; i < r.errors.size();) {
    std::size_t j = i;
    neumaier_sum log_sum;
    std::size_t count = 0;
    double worst = -std::numeric_limits<double>::infinity();
    while (j < r.errors.size() && r.errors[j].integrand == r.errors[i].integrand &&
           r.errors[j].s == r.errors[i].s && r.errors[j].method == r.errors[i].method) {
      const double ratio = r.errors[j].ratio;
      if (std::isfinite(ratio) && ratio > 0.0) {
        log_sum += std::log(ratio);
        ++count;
        worst = std::max(worst, ratio);
      }
      ++j;
    }
    out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", r.errors[i].integrand, r.errors[i].s,
                       r.errors[i].method, count,
                       count ? fmt::format("{:.3g}", std::exp(log_sum.value() / count)) : "—",
                       count ? fmt::format("{:.3g}", worst) : "—");
    i = j;
  }

  out += "\n## Time to error (seconds per estimate of B / A)\n\n";
  out += "| integrand | s | method | target | A (s) | B (s) | B / A |\n";
  out += "|---|---:|---|---:|---:|---:|---:|\n";
  for (const time_comparison& t : r.times) {
    if (!t.seconds_a && !t.seconds_b) continue;  // neither reached it: nothing to say
    out += fmt::format("| {} | {} | {} | {:.0e} | {} | {} | {} |\n", t.integrand, t.s, t.method,
                       t.target, optional_number(t.seconds_a, "{:.3g}"),
                       optional_number(t.seconds_b, "{:.3g}"), optional_number(t.ratio, "{:.3g}"));
  }
  return out;
}

}  // namespace quadmc
