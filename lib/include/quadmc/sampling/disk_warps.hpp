// Points in the unit disk from two uniforms (docs/theory.md#inversion; [Ramamoorthi 2009, §3.1.3];
// [Pharr et al. 2016, §13.6.2]).
//
//  - uniform_disk_warp: r = √U₁, θ = 2πU₂. The area element is r dr dθ, so P(r) = r² and
//    inversion gives r = √U₁; density 1/π with respect to area. Use it for area lights shaped
//    like disks, lens samples, or as the first step of cosine-weighted hemisphere sampling.
//  - naive_disk_warp: r = U₁, θ = 2πU₂. DELIBERATELY WRONG, kept so that a plot and a test can
//    show the clumping at the centre [Ramamoorthi 2009, §3.1.3] warns of: its true density is
//    1/(2πr), not the 1/π its pdf() claims, so an estimator using it is biased. Never estimate
//    with it.
// Neither preserves stratification perfectly (the concentric map of [Shirley & Chiu 1997] does
// better); the polar map is the one of [Ramamoorthi 2009] and enough for the convergence study.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>

namespace quadmc {

class uniform_disk_warp {
 public:
  std::size_t input_dimension() const noexcept { return 2; }
  std::size_t output_dimension() const noexcept { return 2; }
  void sample(std::span<const double> u, std::span<double> x) const noexcept {
    const double r = std::sqrt(u[0]);
    const double theta = 2.0 * std::numbers::pi * u[1];
    x[0] = r * std::cos(theta);
    x[1] = r * std::sin(theta);
  }
  double pdf(std::span<const double> x) const noexcept {
    return x[0] * x[0] + x[1] * x[1] <= 1.0 ? std::numbers::inv_pi : 0.0;
  }
};

class naive_disk_warp {
 public:
  std::size_t input_dimension() const noexcept { return 2; }
  std::size_t output_dimension() const noexcept { return 2; }
  void sample(std::span<const double> u, std::span<double> x) const noexcept {
    const double r = u[0];  // WRONG on purpose: should be √U₁
    const double theta = 2.0 * std::numbers::pi * u[1];
    x[0] = r * std::cos(theta);
    x[1] = r * std::sin(theta);
  }
  // The density the naive warp is wrongly believed to have (uniform); the truth is 1/(2πr).
  double pdf(std::span<const double> x) const noexcept {
    return x[0] * x[0] + x[1] * x[1] <= 1.0 ? std::numbers::inv_pi : 0.0;
  }
};

}  // namespace quadmc
