// Time to error by log-log interpolation; the model is in work_precision.hpp.
#include "quadmc/analysis/work_precision.hpp"

#include "quadmc/core/errors.hpp"

#include <cmath>

namespace quadmc {

std::vector<time_to_error> work_precision(std::span<const double> seconds,
                                          std::span<const double> error,
                                          std::span<const double> targets) {
  require(seconds.size() == error.size(), "error.size()", error.size(),
          fmt::format("the size of seconds ({})", seconds.size()));
  for (std::size_t k = 0; k < seconds.size(); ++k) {
    require(std::isfinite(seconds[k]) && seconds[k] >= 0.0, fmt::format("seconds[{}]", k),
            seconds[k], "finite and >= 0");
    require(std::isfinite(error[k]) && error[k] >= 0.0, fmt::format("error[{}]", k), error[k],
            "finite and >= 0");
  }
  std::vector<time_to_error> out;
  out.reserve(targets.size());
  for (double target : targets) {
    require(std::isfinite(target) && target > 0.0, "target", target, "finite and > 0");
    time_to_error entry;
    entry.target = target;
    for (std::size_t k = 0; k < error.size(); ++k) {
      if (error[k] > target) continue;
      if (k == 0) {
        entry.status = target_status::reached_at_first_point;
        entry.seconds = seconds[0];
        break;
      }
      const double e1 = error[k - 1], e2 = error[k], t1 = seconds[k - 1], t2 = seconds[k];
      // e1 > target ≥ e2 ≥ 0; an exact-zero e2 leaves no logarithm: take t2.
      double t = t2;
      if (e2 > 0.0) {
        const double fraction = (std::log(target) - std::log(e1)) / (std::log(e2) - std::log(e1));
        t = (t1 > 0.0 && t2 > 0.0)
                ? std::exp(std::log(t1) + fraction * (std::log(t2) - std::log(t1)))
                : t1 + fraction * (t2 - t1);
      }
      entry.status = target_status::reached;
      entry.seconds = t;
      break;
    }
    out.push_back(entry);
  }
  return out;
}

}  // namespace quadmc
