// A method's prediction of its own error on one integrand, cell by cell: what the analysis
// compares the measured errors with (convergence_table.hpp), and the rate it implies.
//
// Use it when theory gives more than an exponent: a composite rule on an integrand with known
// end-point derivatives has a predicted error curve, the Euler–Maclaurin expansion plus, for f
// with known complex poles, the coarse-grid term (rules/euler_maclaurin.hpp; the method builds
// it, methods/method.hpp: error_prediction). Not for
// bounds (an error envelope bounds, it does not predict: convergence_cell::error_envelope) and not
// for random methods (their error is a random variable; σ/√N is their theory).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>

namespace quadmc {

// The prediction for one grid.
struct predicted_cell {
  std::uint64_t evaluations = 0;  // N of the grid (0: it does not fit in 64 bits)
  double error = std::numeric_limits<double>::quiet_NaN();  // predicted estimate − reference
  // |P₃ − P₂|/|P₂|: how much the next term of the expansion moves the prediction; the analysis
  // trusts it only where this is small (analysis_options::prediction_validity).
  double next_change = std::numeric_limits<double>::infinity();
  // The part of `error` that is no end-point term: the coarse-grid term e^(−2πd/H) of f's
  // complex poles (docs/theory.md#coarse-grid-term); 0 where there is none.
  double coarse_grid = 0.0;
};

struct error_prediction {
  // The slope in N of the leading term (−j/s for an H^j term in s dimensions); nullopt when
  // every term of the expansion vanishes (exponential convergence).
  std::optional<double> leading_slope;
  // A term of the rule's own order vanished on this f (or all did): the leading slope is
  // steeper than the class rate of theoretical_rate.hpp.
  bool superconvergent = false;
  std::string note;  // which end-point terms vanished, and the leading term
  // The coarse-grid term in words (which poles, their distance d, its leading size); empty when
  // f lists no pole.
  std::string coarse_grid_note;
  std::string source;  // docs/theory.md anchor and references
  // The prediction for n panels per axis (the plan cell's per_axis), any valid n of the rule.
  std::function<predicted_cell(std::uint64_t per_axis)> at;
};

}  // namespace quadmc
