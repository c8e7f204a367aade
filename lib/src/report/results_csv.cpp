// convergence.csv and slopes.csv: writers and readers; the column contract is in results_csv.hpp.
#include "quadmc/report/results_csv.hpp"

#include "quadmc/analysis/slope_verdict.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/report/csv.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>

namespace quadmc {
namespace {

// Shortest text that reads back to the same double; empty for NaN.
std::string number(double x) {
  return std::isnan(x) ? std::string() : fmt::format("{}", x);
}

std::vector<std::string> header_of(std::span<const std::string_view> contract,
                                   std::span<const std::string_view> added) {
  std::vector<std::string> header(contract.begin(), contract.end());
  header.insert(header.end(), added.begin(), added.end());
  return header;
}

// Reads field `name` of row `r` of a table with error messages naming file, line and column.
class record_reader {
 public:
  record_reader(const csv_table& table, std::size_t r) : table_(table), r_(r) {}

  const std::string& text(std::string_view name) const {
    return table_.rows[r_][table_.column(name)];
  }
  double real(std::string_view name) const {
    const std::string& t = text(name);
    if (t.empty()) return std::numeric_limits<double>::quiet_NaN();
    double value = 0.0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || end != t.data() + t.size()) fail(name, t, "a number");
    return value;
  }
  // A number that is finite or empty (NaN): ±inf and "nan" are no value a writer of ours gives.
  double finite_or_empty(std::string_view name) const {
    const double value = real(name);
    if (!text(name).empty() && !std::isfinite(value)) {
      fail(name, text(name), "a finite number or an empty field");
    }
    return value;
  }
  std::uint64_t count(std::string_view name) const {
    const std::string& t = text(name);
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || ec != std::errc() || end != t.data() + t.size()) {
      fail(name, t, "a non-negative integer");
    }
    return value;
  }

  [[noreturn]] void fail(std::string_view name, const std::string& t,
                         std::string_view expected) const {
    // Data row r is record r + 2 of the file (the header is record 1).
    throw invalid_argument(fmt::format("{}: record {}, column '{}' = '{}': expected {}",
                                       table_.source, r_ + 2, name, t, expected));
  }
  std::size_t record() const noexcept { return r_ + 2; }

 private:
  const csv_table& table_;
  std::size_t r_;
};

void require_columns(const csv_table& table, std::span<const std::string_view> columns) {
  for (std::string_view name : columns) table.column(name);  // throws naming file and column
}

}  // namespace

std::string convergence_csv_text(std::string_view scene,
                                 std::span<const convergence_table> tables) {
  std::string out = csv_line(header_of(convergence_csv_columns, convergence_csv_added_columns));
  for (const convergence_table& t : tables) {
    for (const convergence_row& row : t.rows) {
      const cell_statistics& c = row.stats;
      const std::vector<std::string> fields = {std::string(scene),
                                               t.integrand,
                                               fmt::format("{}", t.s),
                                               t.method,
                                               fmt::format("{}", row.n),
                                               fmt::format("{}", c.evaluations),
                                               fmt::format("{}", c.repetitions),
                                               fmt::format("{:.17g}", t.reference),
                                               number(c.estimate_mean),
                                               number(c.rmse),
                                               number(c.mean_abs_error),
                                               number(c.std_error_of_rmse),
                                               number(c.coverage_95),
                                               number(c.seconds),
                                               number(c.evals_per_second),
                                               row.floor ? "1" : "0",
                                               to_string(t.regularity),
                                               number(row.envelope),
                                               number(row.tolerance),
                                               number(c.error_estimate),
                                               number(c.estimate_covers),
                                               number(c.estimate_covers_3x),
                                               number(c.chi2_per_dof),
                                               number(c.q_value),
                                               number(c.replicate_std_error),
                                               number(c.l2_star_discrepancy),
                                               number(c.centered_discrepancy),
                                               number(c.wraparound_discrepancy),
                                               number(row.predicted_error),
                                               number(row.prediction_ratio),
                                               number(row.local_slope),
                                               number(row.rounding_level),
                                               number(row.timing.seconds_per_estimate),
                                               number(row.timing.spread),
                                               fmt::format("{}", row.timing.estimates),
                                               number(c.reached),
                                               fmt::format("{}", row.ensemble.instances),
                                               number(row.ensemble.mse_mean),
                                               number(row.ensemble.mse_ci95_low),
                                               number(row.ensemble.mse_ci95_high),
                                               number(row.ensemble.mse_median),
                                               number(row.ensemble.mse_worst)};
      out += csv_line(fields);
    }
  }
  return out;
}

std::string slopes_csv_text(std::string_view scene, std::span<const convergence_table> tables) {
  std::string out = csv_line(header_of(slopes_csv_columns, slopes_csv_added_columns));
  for (const convergence_table& t : tables) {
    const double theory = t.theory.slope.value_or(std::numeric_limits<double>::quiet_NaN());
    const std::vector<std::string> fields = {
        std::string(scene),
        t.integrand,
        fmt::format("{}", t.s),
        t.method,
        number(t.fit.slope),
        number(t.fit.ci_low),
        number(t.fit.ci_high),
        number(theory),
        to_string(t.verdict),
        fmt::format("{}", t.points_used()),
        fmt::format("{}", t.floor_points()),
        to_string(t.regularity),
        to_string(t.fit.status),
        number(t.floor.attainable_accuracy),
        t.theory.note,
        number(t.envelope_ratio),
        t.verdict_reason,
        number(t.class_theory.slope.value_or(std::numeric_limits<double>::quiet_NaN())),
        t.asymptotic_from ? fmt::format("{}", *t.asymptotic_from) : std::string(),
        number(t.asymptotic_fit.slope),
        fmt::format("{}", t.predicted_points),
        number(t.worst_prediction_ratio),
        t.rounding.describe()};
    out += csv_line(fields);
  }
  return out;
}

std::vector<convergence_record> read_convergence_csv(const std::filesystem::path& file) {
  const csv_table table = read_csv_file(file);
  require_columns(table, convergence_csv_columns);
  const bool has_floor = table.has_column("floor");
  const bool has_envelope = table.has_column("envelope");
  const bool has_tolerance = table.has_column("tolerance");
  const bool has_error_estimate = table.has_column("error_estimate");
  // Columns added after error_estimate: read when present, NaN for an older file.
  auto optional_real = [&](const record_reader& f, std::string_view column) {
    return table.has_column(column) ? f.real(column) : std::numeric_limits<double>::quiet_NaN();
  };
  const bool has_predicted_error = table.has_column("predicted_error");
  const bool has_prediction_ratio = table.has_column("prediction_ratio");
  std::vector<convergence_record> out;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const record_reader f(table, r);
    convergence_record rec;
    rec.scene = f.text("scene");
    rec.integrand = f.text("integrand");
    rec.s = f.count("s");
    rec.method = f.text("method");
    rec.n = f.count("N");
    rec.evaluations = f.count("evaluations");
    rec.repetitions = f.count("repetitions");
    // "nan" or "inf" in these is no figure a run writes (it writes NaN as an empty field): refused
    // here, naming file, record and column, not later where the row is no longer known.
    rec.reference = f.finite_or_empty("reference");
    rec.estimate_mean = f.finite_or_empty("estimate_mean");
    rec.rmse = f.finite_or_empty("rmse");
    rec.mean_abs_error = f.finite_or_empty("mean_abs_error");
    rec.std_error_of_rmse = f.real("std_error_of_rmse");
    rec.coverage_95 = f.real("coverage_95");
    rec.seconds = f.real("seconds");
    rec.evals_per_second = f.real("evals_per_second");
    rec.floor = has_floor && f.text("floor") == "1";
    if (has_envelope) rec.envelope = f.real("envelope");
    if (has_tolerance) rec.tolerance = f.real("tolerance");
    if (has_error_estimate) rec.error_estimate = f.real("error_estimate");
    rec.estimate_covers = optional_real(f, "estimate_covers");
    rec.estimate_covers_3x = optional_real(f, "estimate_covers_3x");
    rec.chi2_per_dof = optional_real(f, "chi2_per_dof");
    rec.q_value = optional_real(f, "q_value");
    for (const auto& [column, field] :
         {std::pair{"replicate_std_error", &convergence_record::replicate_std_error},
          std::pair{"l2_star_discrepancy", &convergence_record::l2_star_discrepancy},
          std::pair{"centered_discrepancy", &convergence_record::centered_discrepancy},
          std::pair{"wraparound_discrepancy", &convergence_record::wraparound_discrepancy}}) {
      if (table.has_column(column)) rec.*field = f.real(column);
    }
    if (has_predicted_error) rec.predicted_error = f.real("predicted_error");
    if (has_prediction_ratio) rec.prediction_ratio = f.real("prediction_ratio");
    rec.seconds_per_estimate = optional_real(f, "seconds_per_estimate");
    rec.seconds_spread = optional_real(f, "seconds_spread");
    if (table.has_column("timed_estimates")) rec.timed_estimates = f.count("timed_estimates");
    rec.reached = optional_real(f, "reached");
    out.push_back(std::move(rec));
  }
  return out;
}

// A slopes.csv row is checked as it is read, so that `compare` (and anything else reading it)
// never judges from a malformed row: a duplicated series (only the first was read, so a regressed
// copy appended after it passed), ci_low > ci_high (a negative half-width widened the allowed
// difference), ±inf or NaN written out, an unknown verdict, a slope where fit_status says no fit
// was made. Each is an invalid_argument naming the file, the record and the column.
std::vector<slope_record> read_slopes_csv(const std::filesystem::path& file) {
  const csv_table table = read_csv_file(file);
  require_columns(table, slopes_csv_columns);
  const bool has_fit_status = table.has_column("fit_status");
  std::map<std::tuple<std::string, std::string, std::size_t, std::string>, std::size_t> seen;
  std::vector<slope_record> out;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const record_reader f(table, r);
    slope_record rec;
    rec.scene = f.text("scene");
    rec.integrand = f.text("integrand");
    rec.s = f.count("s");
    rec.method = f.text("method");
    rec.slope = f.finite_or_empty("slope");
    rec.ci_low = f.finite_or_empty("ci_low");
    rec.ci_high = f.finite_or_empty("ci_high");
    rec.theory = f.finite_or_empty("theory");
    rec.verdict = f.text("verdict");
    rec.points_used = f.count("points_used");
    rec.floor_points = f.count("floor_points");
    if (table.has_column("envelope_ratio")) rec.envelope_ratio = f.real("envelope_ratio");
    if (table.has_column("verdict_reason")) rec.verdict_reason = f.text("verdict_reason");
    if (table.has_column("class_theory")) rec.class_theory = f.real("class_theory");

    try {
      (void)parse_slope_verdict(rec.verdict);
    } catch (const invalid_argument&) {
      f.fail("verdict", rec.verdict, "a verdict quadmc writes (agrees, steeper, shallower, …)");
    }
    if (std::isnan(rec.ci_low) != std::isnan(rec.ci_high)) {
      f.fail(std::isnan(rec.ci_low) ? "ci_low" : "ci_high", "",
             "both ends of the interval or neither");
    }
    if (rec.ci_low > rec.ci_high) {
      f.fail("ci_low", f.text("ci_low"), fmt::format("at most ci_high = {}", f.text("ci_high")));
    }
    if (!std::isnan(rec.ci_low) && std::isnan(rec.slope)) {
      f.fail("slope", "", "a slope where the row has an interval");
    }
    if (has_fit_status && f.text("fit_status") != "ok" && !std::isnan(rec.slope)) {
      f.fail("slope", f.text("slope"),
             fmt::format("an empty field: fit_status = '{}' says no fit was made",
                         f.text("fit_status")));
    }
    const auto [at, fresh] =
        seen.emplace(std::tuple{rec.scene, rec.integrand, rec.s, rec.method}, f.record());
    if (!fresh) {
      f.fail("method", rec.method,
             fmt::format("one row per series: record {} has the same scene, integrand, s and "
                         "method",
                         at->second));
    }
    out.push_back(std::move(rec));
  }
  return out;
}

}  // namespace quadmc
