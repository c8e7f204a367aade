// Rounding-floor detection; the rule and why it is built that way are in rounding_floor.hpp.
#include "quadmc/analysis/rounding_floor.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace quadmc {

double rounding_model::relative_level(double n) const noexcept {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  constexpr double eps_extended = std::numeric_limits<long double>::epsilon();
  double sum = eps;
  switch (accumulator) {
    case summation::pairwise:
      sum = eps * std::max(1.0, std::log2(n));
      break;
    case summation::neumaier:
      sum = eps;
      break;
    case summation::naive:
      sum = eps * std::max(1.0, std::sqrt(n));
      break;
    case summation::long_double:
      sum = eps_extended * std::max(1.0, std::sqrt(n));
      break;
  }
  return std::max(epsilon_of(precision), sum);
}

std::string rounding_model::describe() const {
  return fmt::format("{} evaluation, {} sum", to_string(precision), to_string(accumulator));
}

double rounding_level(double n, double scale, const rounding_floor_options& options) {
  return rounding_level(n, scale, rounding_model{}, options);
}

double rounding_level(double n, double scale, const rounding_model& model,
                      const rounding_floor_options& options) {
  return options.kappa * scale * model.relative_level(n);
}

rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     double scale, const rounding_floor_options& options) {
  return detect_rounding_floor(n, error, scale, rounding_model{}, options);
}

rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     double scale, const rounding_model& model,
                                     const rounding_floor_options& options) {
  require(std::isfinite(scale) && scale >= 0.0, "scale", scale, "finite and >= 0");
  const std::vector<double> scales(n.size(), scale);
  return detect_rounding_floor(n, error, scales, model, options);
}

rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     std::span<const double> scales,
                                     const rounding_floor_options& options) {
  return detect_rounding_floor(n, error, scales, rounding_model{}, options);
}

rounding_floor detect_rounding_floor(std::span<const double> n, std::span<const double> error,
                                     std::span<const double> scales, const rounding_model& model,
                                     const rounding_floor_options& options) {
  require(n.size() == error.size(), "error.size()", error.size(),
          fmt::format("the size of n ({})", n.size()));
  require(scales.size() == n.size(), "scales.size()", scales.size(),
          fmt::format("the size of n ({})", n.size()));
  for (std::size_t k = 0; k < scales.size(); ++k) {
    require(std::isfinite(scales[k]) && scales[k] >= 0.0, fmt::format("scales[{}]", k), scales[k],
            "finite and >= 0");
  }
  require(std::isfinite(options.kappa) && options.kappa > 0.0, "kappa", options.kappa,
          "finite and > 0");
  require(std::isfinite(options.band) && options.band >= 1.0, "band", options.band,
          "finite and >= 1");
  require(std::isfinite(options.stall_factor) && options.stall_factor > 1.0, "stall_factor",
          options.stall_factor, "finite and > 1");
  require(options.stall_window >= 1, "stall_window", options.stall_window, ">= 1");
  for (std::size_t k = 0; k < n.size(); ++k) {
    require(std::isfinite(n[k]) && n[k] > 0.0, fmt::format("n[{}]", k), n[k], "finite and > 0");
    require(k == 0 || n[k] > n[k - 1], fmt::format("n[{}]", k), n[k],
            "strictly increasing N along the ladder");
    require(std::isfinite(error[k]) && error[k] >= 0.0, fmt::format("error[{}]", k), error[k],
            "finite and >= 0");
  }

  rounding_floor out;
  const std::size_t count = n.size();
  out.flags.assign(count, false);
  for (std::size_t k = 0; k < count && !out.first; ++k) {
    const double level = rounding_level(n[k], scales[k], model, options);
    const bool at_floor = error[k] <= level;
    const std::size_t window_end = std::min(count, k + 1 + options.stall_window);
    const double next_best =
        k + 1 < count ? *std::min_element(error.begin() + static_cast<std::ptrdiff_t>(k + 1),
                                          error.begin() + static_cast<std::ptrdiff_t>(window_end))
                      : 0.0;
    const bool stalled = k + 1 < count && error[k] <= options.band * level &&
                         next_best > error[k] / options.stall_factor;
    if (at_floor || stalled) out.first = k;
  }

  if (out.first) {
    for (std::size_t k = *out.first; k < count; ++k) out.flags[k] = true;
    std::vector<double> floor_errors(error.begin() + static_cast<std::ptrdiff_t>(*out.first),
                                     error.end());
    std::sort(floor_errors.begin(), floor_errors.end());
    const std::size_t m = floor_errors.size();
    out.floor_level =
        m % 2 == 1 ? floor_errors[m / 2] : 0.5 * (floor_errors[m / 2 - 1] + floor_errors[m / 2]);
  }
  const std::size_t clean_end = out.first.value_or(count);
  if (clean_end > 0) {
    out.attainable_accuracy =
        *std::min_element(error.begin(), error.begin() + static_cast<std::ptrdiff_t>(clean_end));
  } else if (count > 0) {
    out.attainable_accuracy = *std::min_element(error.begin(), error.end());
  }
  return out;
}

void add_reference_floor(rounding_floor& floor, std::span<const double> error, double uncertainty,
                         double factor) {
  require(std::isfinite(uncertainty) && uncertainty >= 0.0, "uncertainty", uncertainty,
          "finite and >= 0");
  require(std::isfinite(factor) && factor > 0.0, "factor", factor, "finite and > 0");
  require(error.size() == floor.flags.size(), "error.size()", error.size(),
          fmt::format("the size of the floor's flags ({})", floor.flags.size()));
  if (uncertainty == 0.0) return;
  const double level = factor * uncertainty;
  for (std::size_t k = 0; k < error.size(); ++k) {
    if (error[k] < level) {
      floor.reference_first = k;
      break;
    }
  }
  if (!floor.reference_first) return;
  if (floor.first && *floor.first <= *floor.reference_first) return;
  const std::size_t first = *floor.reference_first;
  floor.first = first;
  for (std::size_t k = first; k < error.size(); ++k) floor.flags[k] = true;
  std::vector<double> floor_errors(error.begin() + static_cast<std::ptrdiff_t>(first), error.end());
  std::sort(floor_errors.begin(), floor_errors.end());
  const std::size_t m = floor_errors.size();
  floor.floor_level =
      m % 2 == 1 ? floor_errors[m / 2] : 0.5 * (floor_errors[m / 2 - 1] + floor_errors[m / 2]);
  floor.attainable_accuracy =
      first > 0
          ? *std::min_element(error.begin(), error.begin() + static_cast<std::ptrdiff_t>(first))
          : *std::min_element(error.begin(), error.end());
}

}  // namespace quadmc
