// How often a method's own error estimate held: per (method, smoothness class), pooled over the
// cells of every integrand of that class, the fraction of repetitions whose true |error| was at
// most the claimed error ê (and at most 3ê), with the mean χ²/dof where the method reports one.
//
// Use it for the reliability table of a results page (report/markdown_report.hpp) or any study
// of whether a method's error bars can be trusted. Not a verdict on the estimate: a 1σ claim
// (Monte Carlo's σ̂/√N, VEGAS's σ̂) covers ≈ 68% at 1× and ≈ 99.7% at 3× when it is honest, while a
// bound (an a-priori bound, an embedded rule's |Q₇ − Q₅|, Romberg's last difference) should cover
// every cell; the reader compares the fraction with what the method claims. Methods without an
// own estimate (ê NaN in any repetition of a cell) do not appear.
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/core/smoothness.hpp"

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

struct estimate_reliability {
  std::string method;  // the series' display name
  smoothness regularity = smoothness::analytic;
  std::size_t series = 0;     // (integrand, s) series pooled
  std::size_t cells = 0;      // cells with an estimate in every repetition
  std::size_t estimates = 0;  // repetitions of those cells
  double covered = 0.0;       // fraction of estimates with |error| ≤ ê
  double covered_3x = 0.0;    // fraction with |error| ≤ 3ê
  double worst_ratio = 0.0;   // largest |error|/ê over the cells' RMSE/error_estimate
  double chi2_per_dof = std::numeric_limits<double>::quiet_NaN();  // mean over cells; NaN: none
};

// One entry per (method, smoothness) in order of first appearance among the tables; an entry
// only where at least one cell has an estimate. The fractions weigh every repetition equally
// (Σ covers·R / Σ R).
std::vector<estimate_reliability> summarise_estimate_reliability(
    std::span<const convergence_table> tables);

}  // namespace quadmc
