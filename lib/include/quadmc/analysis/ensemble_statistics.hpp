// What an ensemble of random integrands says about one cell, as the sampler tests of the
// rendering community report it ([Pilleboue et al. 2015]; docs/theory.md#random-ensembles): the
// mean squared error over the instances with its 95% interval, the median instance and the worst.
//
// Use it for a cell whose repetitions come from K instances of a random family (a scene's
// `ensemble = K`), R repetitions each, in instance order: MSE_k is the mean of e² over instance
// k's repetitions, and
//   mse_mean            Σ MSE_k / K (= rmse², the pooled mean: every instance has R repetitions);
//   mse_ci95_low/high   mse_mean ∓ t(0.975, K − 1)·sd(MSE_k)/√K, Student's interval over the K
//                       independent instances (the low end clipped at 0); NaN for K < 2;
//   mse_median          the median of the MSE_k (the mean of the middle two for even K);
//   mse_worst           the largest MSE_k.
// A worst instance far above the median says a set fails on some orientations or placements
// (an edge aligned with its strata, a disk its pattern aliases); a mean far above the median says
// the same with fewer words. Not for K = 1 (nothing to compare: every field is that MSE, the
// interval NaN).
#pragma once

#include "quadmc/analysis/cell_statistics.hpp"

#include <cstddef>
#include <limits>
#include <span>

namespace quadmc {

struct ensemble_statistics {
  std::size_t instances = 1;
  double mse_mean = std::numeric_limits<double>::quiet_NaN();
  double mse_ci95_low = std::numeric_limits<double>::quiet_NaN();
  double mse_ci95_high = std::numeric_limits<double>::quiet_NaN();
  double mse_median = std::numeric_limits<double>::quiet_NaN();
  double mse_worst = std::numeric_limits<double>::quiet_NaN();
};

// The statistics of `repetitions` (instance k's are [k·R, (k + 1)·R), R = size/instances) against
// `reference`. Throws invalid_argument for no repetitions, instances = 0, a size that is not a
// multiple of it, or a value or reference that is not finite.
ensemble_statistics compute_ensemble_statistics(std::span<const repetition_result> repetitions,
                                                double reference, std::size_t instances);

}  // namespace quadmc
