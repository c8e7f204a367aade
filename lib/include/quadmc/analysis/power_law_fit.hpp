// Convergence slope: ordinary least squares of log(error) against log(N), with a Student-t
// confidence interval for the slope.
//
// Use it for the fitted rate of a convergence ladder (error ≈ C·N^slope). Not for exponentially
// converging rules (Gauss–Legendre, Romberg on analytic f): log(error) is then not linear in
// log(N) and the slope depends on the ladder; the theory table says "no finite slope" there.
// Exclude rounding-floor points first (rounding_floor.hpp): the fit assumes one power law.
//
// Model: y_k = a + b·x_k + ε_k, x = ln N, y = ln error, ε_k i.i.d. N(0, σ²). Then
//   b̂ = Sxy/Sxx, se(b̂) = √(SSR/((n − 2)·Sxx)), CI = b̂ ± t_{n−2, (1+c)/2}·se(b̂)
// (Draper & Smith, Applied Regression Analysis, 3rd ed., §1.4). The interval is exact for
// lognormal noise on the error; RMSE of R repetitions is close to that for moderate R. Sums use
// centred data (two passes) and compensated summation so a 1e-12-accurate slope survives.
#pragma once

#include <cstddef>
#include <limits>
#include <span>

namespace quadmc {

enum class fit_status {
  ok,
  too_few_points,       // fewer than 3 points: no degree of freedom left for the interval
  degenerate_abscissa,  // every N equal: the slope is undefined
};

const char* to_string(fit_status status) noexcept;

struct power_law_fit {
  fit_status status = fit_status::too_few_points;
  double slope = std::numeric_limits<double>::quiet_NaN();
  double intercept = std::numeric_limits<double>::quiet_NaN();  // ln C
  double slope_std_error = std::numeric_limits<double>::quiet_NaN();
  double ci_low = std::numeric_limits<double>::quiet_NaN();
  double ci_high = std::numeric_limits<double>::quiet_NaN();
  double confidence = 0.95;
  std::size_t points = 0;

  bool ok() const noexcept { return status == fit_status::ok; }
  double half_width() const noexcept { return 0.5 * (ci_high - ci_low); }
  // The fitted error at N: C·N^slope.
  double predict(double n) const noexcept;
};

// Fits error ≈ C·N^slope. Returns a non-ok status (never throws) for < 3 points or all-equal N.
// Throws invalid_argument when the spans differ in length, an N or error is not finite and > 0
// (filter exact zeros and floor points before), or confidence is not in (0, 1).
power_law_fit fit_power_law(std::span<const double> n, std::span<const double> error,
                            double confidence = 0.95);

}  // namespace quadmc
