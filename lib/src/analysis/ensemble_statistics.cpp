// The ensemble statistics of ensemble_statistics.hpp.
#include "quadmc/analysis/ensemble_statistics.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace quadmc {

ensemble_statistics compute_ensemble_statistics(std::span<const repetition_result> repetitions,
                                                double reference, std::size_t instances) {
  require(!repetitions.empty(), "repetitions", repetitions.size(), "at least one repetition");
  require(instances >= 1 && repetitions.size() % instances == 0, "instances", instances,
          "a count ≥ 1 that divides the repetitions (R per instance)");
  require(std::isfinite(reference), "reference", reference, "a finite reference");
  const std::size_t per = repetitions.size() / instances;
  std::vector<double> mse(instances);
  for (std::size_t k = 0; k < instances; ++k) {
    neumaier_sum squares;
    for (std::size_t r = 0; r < per; ++r) {
      const double v = repetitions[k * per + r].value;
      require(std::isfinite(v), "repetition value", v, "a finite estimate");
      squares.add((v - reference) * (v - reference));
    }
    mse[k] = squares.value() / static_cast<double>(per);
  }
  ensemble_statistics out;
  out.instances = instances;
  neumaier_sum total;
  for (const double m : mse) total.add(m);
  out.mse_mean = total.value() / static_cast<double>(instances);
  out.mse_worst = *std::max_element(mse.begin(), mse.end());
  std::vector<double> sorted = mse;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t half = instances / 2;
  out.mse_median = instances % 2 == 1 ? sorted[half] : 0.5 * (sorted[half - 1] + sorted[half]);
  if (instances >= 2) {
    neumaier_sum spread;
    for (const double m : mse) spread.add((m - out.mse_mean) * (m - out.mse_mean));
    const double k = static_cast<double>(instances);
    const double standard_error = std::sqrt(spread.value() / (k - 1.0) / k);
    const double t = boost::math::quantile(boost::math::students_t(k - 1.0), 0.975);
    out.mse_ci95_low = std::max(0.0, out.mse_mean - t * standard_error);
    out.mse_ci95_high = out.mse_mean + t * standard_error;
  }
  return out;
}

}  // namespace quadmc
