// Time for a method to reach an absolute error ε, read off its work-precision ladder.
//
// Use it on ladder points (evaluations, seconds, error) of one method on one integrand. The
// answer is the time at which the error falls below ε and stays below for every larger N of the
// ladder (a lucky sign change of the error at one N is not "reached"), interpolated linearly in
// log(seconds) against log(error) between the last point above ε and the first point of that
// tail: for a power law error ∝ time^−r that interpolation is exact. If the smallest point is
// already below ε the answer is "≤ its time"; if no tail stays below ε, "not reached" within the
// ladder (no extrapolation: the ladder says what was measured).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace quadmc::peers {

struct ladder_point {
  double evaluations = 0.0;
  double seconds = 0.0;
  double error = 0.0;  // |value − exact|, or the RMS over repetitions for random methods
};

struct time_to_accuracy {
  enum class status { reached, at_most, not_reached } outcome = status::not_reached;
  double seconds = 0.0;  // interpolated time (reached) or the smallest point's time (at_most)
};

inline time_to_accuracy time_to_reach(std::vector<ladder_point> points, double epsilon) {
  std::sort(points.begin(), points.end(), [](const ladder_point& a, const ladder_point& b) {
    return a.evaluations < b.evaluations;
  });
  std::size_t first = points.size();  // start of the tail that stays ≤ ε
  for (std::size_t k = points.size(); k-- > 0;) {
    if (points[k].error <= epsilon) {
      first = k;
    } else {
      break;
    }
  }
  if (first == points.size()) return {};
  if (first == 0) return {time_to_accuracy::status::at_most, points[0].seconds};
  const ladder_point& above = points[first - 1];
  const ladder_point& below = points[first];
  // An error of exactly 0 (an exact rule) would put log(0) in the formula: floor it far below ε.
  const double e0 = std::log(above.error);
  const double e1 = std::log(std::max(below.error, epsilon * 1e-6));
  const double t0 = std::log(above.seconds);
  const double t1 = std::log(below.seconds);
  const double fraction = (e0 - std::log(epsilon)) / (e0 - e1);
  return {time_to_accuracy::status::reached, std::exp(t0 + fraction * (t1 - t0))};
}

}  // namespace quadmc::peers
