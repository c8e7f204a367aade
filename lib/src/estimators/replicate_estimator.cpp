#include "quadmc/estimators/replicate_estimator.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"

#include <fmt/format.h>

#include <boost/math/distributions/binomial.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace quadmc {

std::string_view to_string(replicate_estimator e) noexcept {
  return e == replicate_estimator::median ? "median" : "mean";
}

mean_and_deviation replicate_mean_and_sd(std::span<const double> values) {
  const std::size_t k = values.size();
  require(k >= 2, "replicate_count", k, "k ≥ 2 randomizations for a mean and its error bar");
  const double mean = pairwise_sum(values) / static_cast<double>(k);
  double m2 = 0.0;
  for (const double x : values) m2 += (x - mean) * (x - mean);
  return {mean, std::sqrt(m2 / static_cast<double>(k - 1))};
}

double median_interval_coverage(std::size_t k, std::size_t l) {
  require(k >= 1, "k", k, "at least one value");
  require(l >= 1 && 2 * l <= k + 1, "l", l,
          fmt::format("a rank 1 ≤ l ≤ (k + 1)/2 = {}", (k + 1) / 2));
  const boost::math::binomial_distribution<double> law(static_cast<double>(k), 0.5);
  return 1.0 - 2.0 * boost::math::cdf(law, static_cast<double>(l - 1));
}

std::size_t median_interval_rank(std::size_t k, double level) {
  require(level > 0.0 && level < 1.0, "level", level, "a probability 0 < level < 1");
  std::size_t best = 0;
  for (std::size_t l = 1; 2 * l <= k + 1; ++l) {
    if (median_interval_coverage(k, l) < level) break;  // coverage falls as l grows
    best = l;
  }
  require(best > 0, "k", k,
          fmt::format("enough values for an order-statistic interval of probability ≥ {}", level));
  return best;
}

combined_replicates combine_replicates(std::span<const double> values, replicate_estimator how) {
  const std::size_t k = values.size();
  combined_replicates out;
  if (how == replicate_estimator::mean) {
    const mean_and_deviation spread = replicate_mean_and_sd(values);
    out.value = spread.mean;
    out.std_error = spread.sd / std::sqrt(static_cast<double>(k));
    out.error_estimate = out.std_error;
    return out;
  }
  require(k >= 3 && k % 2 == 1, "replicate_count", k,
          "an odd k ≥ 3 for a median (the middle one of the values)");
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t middle = (k - 1) / 2;  // x_((k+1)/2), 0-based
  out.value = sorted[middle];
  // erf(1/√2): the probability of ±1σ of a normal law.
  const std::size_t l = median_interval_rank(k, std::erf(1.0 / std::sqrt(2.0)));
  out.error_estimate = std::max(out.value - sorted[l - 1], sorted[k - l] - out.value);
  out.std_error = std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace quadmc
