// Work-precision: the time a method needs to reach an error target, read off its convergence
// ladder.
//
// Use it for the work-precision table and for comparing the cost of methods at equal accuracy
// (report/compare.hpp's time-to-error ratio). Not a prediction past the ladder: a target the
// ladder never reached is "not reached", never extrapolated.
//
// Between two ladder points (t₁, e₁) and (t₂, e₂) with e₁ > target ≥ e₂, the time is interpolated
// linearly in log t against log e (a power law between neighbours, the same model the slope fit
// uses). The first point with e ≤ target is the crossing (errors of a jump or of Monte Carlo are
// not monotone; the first crossing is what a user stepping up N would see). When the first point
// already meets the target, its time is an upper bound (reached_at_first_point). A zero time
// (below clock resolution) interpolates linearly in t instead.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace quadmc {

inline constexpr std::array<double, 7> default_error_targets = {1e-2, 1e-3, 1e-4, 1e-5,
                                                                1e-6, 1e-7, 1e-8};

enum class target_status { reached, reached_at_first_point, not_reached };

struct time_to_error {
  double target = 0.0;
  target_status status = target_status::not_reached;
  std::optional<double> seconds;  // empty when not reached
};

// seconds[k], error[k]: ladder point k in increasing N. Throws invalid_argument on size mismatch,
// negative or non-finite times or errors, or targets not finite and > 0.
std::vector<time_to_error> work_precision(std::span<const double> seconds,
                                          std::span<const double> error,
                                          std::span<const double> targets = default_error_targets);

}  // namespace quadmc
