// Plain Monte Carlo over any point set: F = vol(box)·(1/N)Σ f(a + (b − a)∘Uᵢ)
// (docs/theory.md#the-monte-carlo-estimator).
//
// Use it with independent_points for the textbook estimator (error σ/√N,
// docs/theory.md#plain-monte-carlo), or with jittered / unjittered / padded / Latin hypercube
// points for the same average over a better spread point set; the error estimate follows the point
// set (point_set.hpp, variance_kind). Not for integrands on unbounded domains (map them to a box
// first, or use importance sampling).
#pragma once

#include "quadmc/estimators/estimate.hpp"
#include "quadmc/estimators/sample_mean.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/sampling/point_set.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace quadmc {

// f's box as the estimators use it: checked against the points' dimension (finite, upper >
// lower on every axis), its volume, and the map of unit-cube points onto it, skipped for the
// unit cube itself (0 + 1·u = u exactly). One definition for every estimator of f's values
// (monte_carlo, periodized_monte_carlo.hpp, sample_values.hpp), so they map alike.
class box_map {
 public:
  box_map(const integrand_info& info, std::size_t s, std::size_t point_dimension)
      : s_(s), lower_(info.domain.lower), width_(s) {
    require(point_dimension == s, "point set dimension", point_dimension,
            "the integrand's dimension " + std::to_string(s));
    const box& domain = info.domain;
    require(domain.dimension() == s, "integrand domain dimension", domain.dimension(),
            "the integrand's dimension " + std::to_string(s));
    for (std::size_t j = 0; j < s; ++j) {
      width_[j] = domain.upper[j] - domain.lower[j];
      require(std::isfinite(width_[j]) && width_[j] > 0.0, "integrand domain width", width_[j],
              "a finite box with upper > lower on every axis");
      unit_ &= lower_[j] == 0.0 && width_[j] == 1.0;
    }
    volume_ = domain.volume();
  }

  double volume() const noexcept { return volume_; }
  // x (row-major points of the unit cube) onto the box, in place.
  void apply(std::span<double> x) const noexcept {
    if (unit_) return;
    for (std::size_t i = 0; i < x.size() / s_; ++i) {
      for (std::size_t j = 0; j < s_; ++j) x[i * s_ + j] = lower_[j] + width_[j] * x[i * s_ + j];
    }
  }

 private:
  std::size_t s_;
  std::vector<double> lower_;
  std::vector<double> width_;
  double volume_ = 1.0;
  bool unit_ = true;
};

template <integrand F, point_set P>
estimate monte_carlo(const F& f, const P& points, unsigned threads = 1) {
  const integrand_info info = f.info();
  const std::size_t s = f.dimension();
  const box_map to_box(info, s, points.dimension());
  const auto values = [&](std::uint64_t, std::span<double> x, std::span<double> y) {
    to_box.apply(x);
    f.evaluate(std::span<const double>(x), y);
    check_finite_batch(info.name, x, y, s);
  };
  estimate e = sample_mean(points, threads, values, info.evaluation_block);
  // F = vol·mean(f): the volume scales the estimate once instead of every sample.
  const double volume = to_box.volume();
  e.value *= volume;
  e.std_error *= volume;
  e.variance *= volume * volume;
  return e;
}

}  // namespace quadmc
