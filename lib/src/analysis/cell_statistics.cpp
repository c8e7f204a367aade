// Cell statistics from repetitions; definitions and sources in cell_statistics.hpp.
#include "quadmc/analysis/cell_statistics.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/normal_quantile.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/core/welford.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace quadmc {
namespace {

// 1, or for x above 2^200 the power of two c with c ≤ x < 2c: x/c < 2 squares (and its square
// squares) without overflow, and dividing by a power of two is exact, so statistics of x/c times
// c are those of x, bit for bit below 2^200.
double squaring_scale(double x) {
  if (!(x > 0x1p200)) return 1.0;
  int exponent = 0;
  (void)std::frexp(x, &exponent);        // 2^(exponent − 1) ≤ x < 2^exponent
  return std::ldexp(1.0, exponent - 1);  // ≤ 2^1023: finite
}

}  // namespace

cell_statistics compute_cell_statistics(std::span<const repetition_result> repetitions,
                                        double reference, error_bars bars) {
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
    require(std::isnan(rep.error_estimate) ||
                (std::isfinite(rep.error_estimate) && rep.error_estimate >= 0.0),
            where + ".error_estimate", rep.error_estimate, "NaN (none) or a finite value >= 0");
    require(std::isnan(rep.target) || (std::isfinite(rep.target) && rep.target >= 0.0),
            where + ".target", rep.target, "NaN (a sized cell) or a finite value >= 0");
    require(std::isnan(rep.target) == std::isnan(repetitions[0].target), where + ".target",
            rep.target,
            std::isnan(repetitions[0].target)
                ? "NaN like repetitions[0]'s (a cell is run to a tolerance or sized, in every "
                  "repetition)"
                : "a value like repetitions[0]'s (a cell is run to a tolerance or sized, in "
                  "every repetition)");
    require(std::isnan(rep.absolute_weight_sum) ||
                (std::isfinite(rep.absolute_weight_sum) && rep.absolute_weight_sum >= 0.0),
            where + ".absolute_weight_sum", rep.absolute_weight_sum,
            "NaN (none) or a finite value >= 0");
    require(std::isnan(rep.chi2_per_dof) ||
                (std::isfinite(rep.chi2_per_dof) && rep.chi2_per_dof >= 0.0),
            where + ".chi2_per_dof", rep.chi2_per_dof, "NaN (none) or a finite value >= 0");
    require(std::isnan(rep.q_value) || (rep.q_value >= 0.0 && rep.q_value <= 1.0),
            where + ".q_value", rep.q_value, "NaN (none) or a probability in [0, 1]");
  }

  // Large errors are divided by a power of two c before they are squared: e² overflows above
  // 1.3e154 and the spread of e² (a sum of e⁴) above 1.2e77, while (e/c)² < 4. Scaling by a power
  // of two is exact and commutes with every rounding, so the statistics are those of the unscaled
  // formulas; errors up to 2^200 ≈ 1.6e60 (e⁴ ≤ 2^800) are left as they are, bit for bit.
  double largest_error = 0.0;
  for (std::size_t r = 0; r < repetitions.size(); ++r) {
    const double error = repetitions[r].value - reference;
    require(std::isfinite(error), fmt::format("repetitions[{}].value − reference", r), error,
            "a finite error (estimate and reference are too far apart for double)");
    largest_error = std::max(largest_error, std::abs(error));
  }
  const double scale = squaring_scale(largest_error);
  const double inverse_scale = 1.0 / scale;  // exact: a power of two ≥ 2^-1023

  const double count = static_cast<double>(repetitions.size());
  constexpr double z = normal_quantile_975();
  neumaier_sum value_sum, squared_error_sum, abs_error_sum, seconds_sum;
  welford squared_error_spread;
  std::uint64_t evaluations = 0;
  std::size_t covered = 0;
  bool every_rep_has_std_error = true;
  for (const repetition_result& rep : repetitions) {
    const double error = rep.value - reference;
    const double scaled = error * inverse_scale;
    value_sum += rep.value;
    squared_error_sum += scaled * scaled;
    abs_error_sum += std::abs(scaled);
    seconds_sum += rep.seconds;
    squared_error_spread.add(scaled * scaled);
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
  const double scaled_mse = squared_error_sum.value() / count;  // MSE / c²
  const double scaled_rmse = std::sqrt(scaled_mse);             // RMSE / c: c² is a power of 4
  out.rmse = scaled_rmse * scale;
  out.mean_abs_error = abs_error_sum.value() / count * scale;
  if (repetitions.size() >= 2) {
    if (scaled_rmse == 0.0) {
      out.std_error_of_rmse = 0.0;  // every error is exactly 0: no spread at all
    } else {
      // Welford's variance has divisor R − 1; se(MSE) = sd(e²)/√R, here both divided by c².
      const double scaled_se_mse = std::sqrt(squared_error_spread.variance() / count);
      out.std_error_of_rmse = scaled_se_mse / (2.0 * scaled_rmse) * scale;
    }
  }
  if (every_rep_has_std_error) out.coverage_95 = static_cast<double>(covered) / count;
  // The estimates' root mean square, scaled like the errors so that it cannot overflow where the
  // RMSE does not.
  neumaier_sum estimate_square_sum;
  double largest_estimate = 0.0;
  for (const repetition_result& rep : repetitions) {
    largest_estimate = std::max(largest_estimate, rep.error_estimate);  // NaN stays out of max
  }
  bool every_rep_has_estimate = true;
  const double estimate_scale = squaring_scale(largest_estimate);
  for (const repetition_result& rep : repetitions) {
    if (std::isnan(rep.error_estimate)) {
      every_rep_has_estimate = false;
      break;
    }
    const double scaled = rep.error_estimate / estimate_scale;
    estimate_square_sum += scaled * scaled;
  }
  if (every_rep_has_estimate) {
    out.error_estimate = std::sqrt(estimate_square_sum.value() / count) * estimate_scale;
    std::size_t within = 0, within_3x = 0;
    for (const repetition_result& rep : repetitions) {
      const double error = std::abs(rep.value - reference);
      if (error <= rep.error_estimate) ++within;
      if (error <= 3.0 * rep.error_estimate) ++within_3x;
    }
    out.estimate_covers = static_cast<double>(within) / count;
    out.estimate_covers_3x = static_cast<double>(within_3x) / count;
  }
  if (!std::isnan(repetitions[0].target)) {
    // NaN ≤ target is false: a repetition without an estimate claims nothing, so reached nothing.
    const auto reached = std::count_if(
        repetitions.begin(), repetitions.end(),
        [](const repetition_result& rep) { return rep.error_estimate <= rep.target; });
    out.reached = static_cast<double>(reached) / count;
  }
  // Means of the iterations' consistency, over repetitions that all report one.
  neumaier_sum chi2_sum, q_sum;
  bool every_rep_has_chi2 = true;
  for (const repetition_result& rep : repetitions) {
    if (std::isnan(rep.chi2_per_dof) || std::isnan(rep.q_value)) {
      every_rep_has_chi2 = false;
      break;
    }
    chi2_sum += rep.chi2_per_dof;
    q_sum += rep.q_value;
  }
  if (every_rep_has_chi2) {
    out.chi2_per_dof = chi2_sum.value() / count;
    out.q_value = q_sum.value() / count;
  }
  for (const repetition_result& rep : repetitions) {
    // std::max keeps its first argument when the second is NaN: start from NaN, take any value.
    if (!std::isnan(rep.absolute_weight_sum)) {
      out.absolute_weight_sum = std::isnan(out.absolute_weight_sum)
                                    ? rep.absolute_weight_sum
                                    : std::max(out.absolute_weight_sum, rep.absolute_weight_sum);
    }
  }
  out.seconds = seconds_sum.value();
  if (out.seconds > 0.0) out.evals_per_second = static_cast<double>(evaluations) / out.seconds;

  // The spread of the values themselves (s_R), in scaled errors so that it cannot overflow.
  if (repetitions.size() >= 2) {
    welford spread;
    for (const repetition_result& rep : repetitions)
      spread.add((rep.value - reference) * inverse_scale);
    const double sd = std::sqrt(spread.variance()) * scale;
    out.replicate_std_error = sd / std::sqrt(count);
    if (bars == error_bars::replicates) {
      out.error_estimate = sd;
      if (repetitions.size() >= 3) {
        // Leave one out: the mean and M₂ of the other R − 1 values by Welford's downdate,
        // m' = (R·m − v)/(R − 1), M₂' = M₂ − (v − m)(v − m').
        const double R = count;
        const double m = spread.mean();
        const double m2 = spread.variance() * (R - 1.0);
        const boost::math::students_t t_law(R - 2.0);
        const double t = boost::math::quantile(t_law, 0.975);
        std::size_t inside = 0;
        for (const repetition_result& rep : repetitions) {
          const double v = (rep.value - reference) * inverse_scale;
          const double m_other = (R * m - v) / (R - 1.0);
          const double m2_other = std::max(0.0, m2 - (v - m) * (v - m_other));
          const double sd_other = std::sqrt(m2_other / (R - 2.0));
          if (std::abs(v) <= t * sd_other) ++inside;
        }
        out.coverage_95 = static_cast<double>(inside) / R;
      } else {
        out.coverage_95 = std::numeric_limits<double>::quiet_NaN();
      }
    }
  }
  // Root mean squares of the point sets' discrepancies (each ≤ a few units: no scaling needed)
  // over the repetitions that measured them: all of a cell's, or an ensemble's first instance's.
  auto root_mean_square = [&](double repetition_result::*field) {
    neumaier_sum sum;
    std::size_t measured = 0;
    for (const repetition_result& rep : repetitions) {
      const double d = rep.*field;
      if (std::isnan(d)) continue;
      sum += d * d;
      ++measured;
    }
    return measured == 0 ? std::numeric_limits<double>::quiet_NaN()
                         : std::sqrt(sum.value() / static_cast<double>(measured));
  };
  out.l2_star_discrepancy = root_mean_square(&repetition_result::l2_star_discrepancy);
  out.centered_discrepancy = root_mean_square(&repetition_result::centered_discrepancy);
  out.wraparound_discrepancy = root_mean_square(&repetition_result::wraparound_discrepancy);
  return out;
}

}  // namespace quadmc
