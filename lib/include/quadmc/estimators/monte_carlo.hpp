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

template <integrand F, point_set P>
estimate monte_carlo(const F& f, const P& points, unsigned threads = 1) {
  const integrand_info info = f.info();
  const std::size_t s = f.dimension();
  require(points.dimension() == s, "point set dimension", points.dimension(),
          "the integrand's dimension " + std::to_string(s));
  const box& domain = info.domain;
  require(domain.dimension() == s, "integrand domain dimension", domain.dimension(),
          "the integrand's dimension " + std::to_string(s));
  std::vector<double> lower = domain.lower;
  std::vector<double> width(s);
  for (std::size_t j = 0; j < s; ++j) {
    width[j] = domain.upper[j] - domain.lower[j];
    require(std::isfinite(width[j]) && width[j] > 0.0, "integrand domain width", width[j],
            "a finite box with upper > lower on every axis");
  }
  const double volume = domain.volume();
  // The unit cube needs no map (0 + 1·u = u exactly), so its points go straight to f.
  bool unit_box = true;
  for (std::size_t j = 0; j < s; ++j) unit_box &= lower[j] == 0.0 && width[j] == 1.0;
  const auto values = [&](std::uint64_t, std::span<double> x, std::span<double> y) {
    if (!unit_box) {
      for (std::size_t i = 0; i < y.size(); ++i) {
        for (std::size_t j = 0; j < s; ++j) x[i * s + j] = lower[j] + width[j] * x[i * s + j];
      }
    }
    f.evaluate(std::span<const double>(x), y);
    check_finite_batch(info.name, x, y, s);
  };
  estimate e = sample_mean(points, threads, values, info.evaluation_block);
  // F = vol·mean(f): the volume scales the estimate once instead of every sample.
  e.value *= volume;
  e.std_error *= volume;
  e.variance *= volume * volume;
  return e;
}

}  // namespace quadmc
