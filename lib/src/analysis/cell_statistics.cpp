// Cell statistics from repetitions; definitions and sources in cell_statistics.hpp.
#include "quadmc/analysis/cell_statistics.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/normal_quantile.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/core/welford.hpp"

#include <cmath>
#include <string>

namespace quadmc {

cell_statistics compute_cell_statistics(std::span<const repetition_result> repetitions,
                                        double reference) {
  require(!repetitions.empty(), "repetitions", repetitions.size(), "at least one repetition");
  require_finite(reference, "reference");
  for (std::size_t r = 0; r < repetitions.size(); ++r) {
    const repetition_result& rep = repetitions[r];
    const std::string where = fmt::format("repetitions[{}]", r);
    require(std::isfinite(rep.value), where + ".value", rep.value, "a finite estimate");
    require(std::isfinite(rep.seconds) && rep.seconds >= 0.0, where + ".seconds", rep.seconds,
            "a finite time >= 0");
    require(std::isnan(rep.std_error) || (std::isfinite(rep.std_error) && rep.std_error >= 0.0),
            where + ".std_error", rep.std_error, "NaN (none) or a finite value >= 0");
  }

  const double count = static_cast<double>(repetitions.size());
  constexpr double z = normal_quantile_975();
  neumaier_sum value_sum, squared_error_sum, abs_error_sum, seconds_sum;
  welford squared_error_spread;
  std::uint64_t evaluations = 0;
  std::size_t covered = 0;
  bool every_rep_has_std_error = true;
  for (const repetition_result& rep : repetitions) {
    const double error = rep.value - reference;
    value_sum += rep.value;
    squared_error_sum += error * error;
    abs_error_sum += std::abs(error);
    seconds_sum += rep.seconds;
    squared_error_spread.add(error * error);
    evaluations += rep.evaluations;
    if (std::isnan(rep.std_error)) {
      every_rep_has_std_error = false;
    } else if (std::abs(error) <= z * rep.std_error) {
      ++covered;
    }
  }

  cell_statistics out;
  out.repetitions = repetitions.size();
  out.total_evaluations = evaluations;
  out.evaluations =
      static_cast<std::uint64_t>(std::llround(static_cast<double>(evaluations) / count));
  out.estimate_mean = value_sum.value() / count;
  const double mse = squared_error_sum.value() / count;
  out.rmse = std::sqrt(mse);
  out.mean_abs_error = abs_error_sum.value() / count;
  if (repetitions.size() >= 2) {
    if (out.rmse == 0.0) {
      out.std_error_of_rmse = 0.0;  // every error is exactly 0: no spread at all
    } else {
      // Welford's variance has divisor R − 1; se(MSE) = sd(e²)/√R.
      const double se_mse = std::sqrt(squared_error_spread.variance() / count);
      out.std_error_of_rmse = se_mse / (2.0 * out.rmse);
    }
  }
  if (every_rep_has_std_error) out.coverage_95 = static_cast<double>(covered) / count;
  out.seconds = seconds_sum.value();
  if (out.seconds > 0.0) out.evals_per_second = static_cast<double>(evaluations) / out.seconds;
  return out;
}

}  // namespace quadmc
