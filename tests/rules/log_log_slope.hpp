// Least-squares slope of log|error| against log N, test-only (the analysis layer owns the real
// convergence fit with its confidence interval; the rule tests must not depend on it).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace quadmc::testing {

// Ordinary least squares slope of y = log|error| on x = log n.
inline double log_log_slope(const std::vector<double>& n, const std::vector<double>& error) {
  const std::size_t k = n.size();
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (std::size_t i = 0; i < k; ++i) {
    mean_x += std::log(n[i]);
    mean_y += std::log(std::abs(error[i]));
  }
  mean_x /= static_cast<double>(k);
  mean_y /= static_cast<double>(k);
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t i = 0; i < k; ++i) {
    const double dx = std::log(n[i]) - mean_x;
    sxy += dx * (std::log(std::abs(error[i])) - mean_y);
    sxx += dx * dx;
  }
  return sxy / sxx;
}

}  // namespace quadmc::testing
