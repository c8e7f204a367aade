// Log-log least squares with a Student-t interval; the model and its source are in
// power_law_fit.hpp.
#include "quadmc/analysis/power_law_fit.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace quadmc {

const char* to_string(fit_status status) noexcept {
  switch (status) {
    case fit_status::ok:
      return "ok";
    case fit_status::too_few_points:
      return "too_few_points";
    case fit_status::degenerate_abscissa:
      return "degenerate_abscissa";
  }
  return "?";
}

double power_law_fit::predict(double n) const noexcept {
  return std::exp(intercept + slope * std::log(n));
}

power_law_fit fit_power_law(std::span<const double> n, std::span<const double> error,
                            double confidence) {
  require(n.size() == error.size(), "error.size()", error.size(),
          fmt::format("the size of n ({})", n.size()));
  require(confidence > 0.0 && confidence < 1.0, "confidence", confidence, "a value in (0, 1)");
  for (std::size_t k = 0; k < n.size(); ++k) {
    require(std::isfinite(n[k]) && n[k] > 0.0, fmt::format("n[{}]", k), n[k], "finite and > 0");
    require(std::isfinite(error[k]) && error[k] > 0.0, fmt::format("error[{}]", k), error[k],
            "finite and > 0 (drop exact zeros and rounding-floor points before fitting)");
  }

  power_law_fit fit;
  fit.confidence = confidence;
  fit.points = n.size();
  if (n.size() < 3) {
    fit.status = fit_status::too_few_points;
    return fit;
  }

  const std::size_t count = n.size();
  std::vector<double> x(count), y(count);
  neumaier_sum sx, sy;
  for (std::size_t k = 0; k < count; ++k) {
    x[k] = std::log(n[k]);
    y[k] = std::log(error[k]);
    sx += x[k];
    sy += y[k];
  }
  const double mx = sx.value() / static_cast<double>(count);
  const double my = sy.value() / static_cast<double>(count);
  neumaier_sum sxx, sxy;
  for (std::size_t k = 0; k < count; ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  if (!(sxx.value() > 0.0)) {
    fit.status = fit_status::degenerate_abscissa;
    return fit;
  }
  fit.slope = sxy.value() / sxx.value();
  fit.intercept = my - fit.slope * mx;
  neumaier_sum ssr;
  for (std::size_t k = 0; k < count; ++k) {
    const double residual = y[k] - (fit.intercept + fit.slope * x[k]);
    ssr += residual * residual;
  }
  const double dof = static_cast<double>(count - 2);
  fit.slope_std_error = std::sqrt(ssr.value() / (dof * sxx.value()));
  const double t = boost::math::quantile(boost::math::students_t_distribution<double>(dof),
                                         0.5 * (1.0 + confidence));
  fit.ci_low = fit.slope - t * fit.slope_std_error;
  fit.ci_high = fit.slope + t * fit.slope_std_error;
  fit.status = fit_status::ok;
  return fit;
}

}  // namespace quadmc
