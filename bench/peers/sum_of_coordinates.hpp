// f(x) = x₁ + … + x_s on [0,1]^s, ∫ = s/2: the cheapest integrand there is, used by the peers
// benchmark to expose what a method costs apart from the integrand (random numbers, summation,
// bookkeeping). Variance of one sample: s/12 (each xⱼ is uniform, independent).
//
// Use it to measure overhead per evaluation. Not for convergence studies: it is linear, so every
// tensor rule of order ≥ 2 and hcubature integrate it exactly, and jittered points only see the
// rounding.
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <cstddef>
#include <span>

namespace quadmc::peers {

class sum_of_coordinates {
 public:
  explicit sum_of_coordinates(std::size_t s) : s_(s) { require(s >= 1, "dimension s", s, "s ≥ 1"); }
  std::size_t dimension() const noexcept { return s_; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      double t = 0.0;
      for (std::size_t j = 0; j < s_; ++j) t += x[i * s_ + j];
      y[i] = t;
    }
  }
  integrand_info info() const {
    integrand_info info{.name = "sum_of_coordinates",
                        .formula = "x₁ + … + x_s",
                        .domain = box::unit(s_),
                        .exact = 0.5 * static_cast<double>(s_),
                        .reference = "closed form s/2",
                        .regularity = smoothness::analytic};
    info.derivative_bound = {static_cast<double>(s_), 1.0, 0.0, 0.0, 0.0};
    return info;
  }

 private:
  std::size_t s_;
};

}  // namespace quadmc::peers
