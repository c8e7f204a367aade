// Builders for convergence series in tests (analysis and report layers): a series as the runner
// makes it, with the method's theory beside it, and cells of hand-made repetitions.
#pragma once

#include "quadmc/analysis/convergence_table.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace quadmc::test {

inline convergence_series series_of(std::string integrand, std::size_t s, std::string method,
                                    smoothness regularity, double reference,
                                    theoretical_rate theory) {
  convergence_series series;
  series.integrand = std::move(integrand);
  series.s = s;
  series.method = std::move(method);
  series.regularity = regularity;
  series.reference = reference;
  series.theory = std::move(theory);
  return series;
}

inline repetition_result repetition(double value, double std_error, std::uint64_t evaluations,
                                    double seconds) {
  repetition_result r;
  r.value = value;
  r.std_error = std_error;
  r.evaluations = evaluations;
  r.seconds = seconds;
  return r;
}

inline convergence_cell cell_at(std::uint64_t n, std::vector<repetition_result> repetitions,
                                std::uint64_t per_axis = 0,
                                double envelope = std::numeric_limits<double>::quiet_NaN()) {
  convergence_cell cell;
  cell.n = n;
  cell.repetitions = std::move(repetitions);
  cell.per_axis = per_axis;
  cell.error_envelope = envelope;
  return cell;
}

// The rates the tests' series stand for: a composite rule of order r, and σ/√N.
inline theoretical_rate rule_theory(int order, smoothness regularity, std::size_t s = 1) {
  return composite_rule_rate(order, {regularity, s});
}
inline theoretical_rate monte_carlo_theory(smoothness regularity, std::size_t s = 1) {
  return root_n_rate({regularity, s}, "σ/√N", "docs/theory.md#plain-monte-carlo");
}

}  // namespace quadmc::test
