// Indicator functions of regions of [0,1]^s with exact volumes: the discontinuous integrands of
// geometric Monte Carlo (the "area of a disk" experiment of every Monte Carlo course).
//
//   disk_indicator  1 if ‖x − c‖ ≤ r   volume π^{s/2} r^s / Γ(s/2 + 1)   (inside the cube; a
//                                      disk in 2D, a ball otherwise: one name in every s)
//   half_space  1 if Σ wᵢxᵢ ≤ t, wᵢ ≠ 0  volume Σ_{v∈{0,1}^s} (−1)^{|v|} (t' − |w|·v)₊^s /
//   (s!·Π|wᵢ|)
//                                      with t' = t + Σ_(wᵢ<0) |wᵢ| (each axis of a negative weight
//                                      reflected, x ↦ 1 − x, which keeps the volume)
//
// The half-space volume is the cube-slice formula (Barrow & Smith, "Spline notation applied to a
// volume problem", Amer. Math. Monthly 86, 1979), an alternating sum over the 2^s vertices:
// computed in 50-digit arithmetic with a rounding bound (inclusion_exclusion.hpp) and rejected
// above 1e-10 relative (50-digit arithmetic: trustworthy for every s ≤ 20 it accepts). In 2D with w
// = (1, 1) it is the triangle/pentagon below the line x₁ + x₂ = t.
//
// Use the ball for a curved boundary (infinite Hardy–Krause variation: Koksma–Hlawka says
// nothing, docs/theory.md#curved-boundaries), the half-space for a flat but oblique one; Genz's
// discontinuous family has only axis-parallel jumps. Not for smooth-integrand rates: both jump.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/integrand.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

namespace quadmc {

class disk_indicator {
 public:
  // The ball must lie inside [0,1]^s (cⱼ − r ≥ 0 and cⱼ + r ≤ 1) so its volume is the formula.
  disk_indicator(std::vector<double> center, double radius)
      : center_(std::move(center)), radius_(radius) {
    require(!center_.empty(), "center", center_.size(),
            "a non-empty vector (its length is the dimension s ≥ 1)");
    require(std::isfinite(radius_) && radius_ > 0.0, "r", radius_, "a finite radius r > 0");
    for (double c : center_) {
      require(std::isfinite(c) && c - radius_ >= 0.0 && c + radius_ <= 1.0, "center", c,
              fmt::format("a ball inside [0,1]^s: r ≤ cⱼ ≤ 1 − r with r = {}", radius_));
    }
    r2_ = radius_ * radius_;
    // The volume falls fast with s (r ≤ 1/2: below 1e-308 from s ≈ 340 on, where Γ(s/2 + 1)
    // also overflows): a reference that is 0 or subnormal has no relative error left to measure.
    const double volume = ball_volume(center_.size(), radius_);
    require(volume >= std::numeric_limits<double>::min(), "r", radius_,
            fmt::format("a radius whose ball in s = {} has a normal double volume (it is {:.3g})",
                        center_.size(), volume));
  }
  std::size_t dimension() const noexcept { return center_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    const std::size_t s = center_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double d2 = 0.0;
      for (std::size_t j = 0; j < s; ++j) {
        const double d = x[i * s + j] - center_[j];
        d2 += d * d;
      }
      y[i] = d2 <= r2_ ? 1.0 : 0.0;
    }
  }
  // π^{s/2} r^s / Γ(s/2 + 1).
  static double ball_volume(std::size_t s, double r) {
    const double h = 0.5 * static_cast<double>(s);
    return std::pow(std::numbers::pi, h) * std::pow(r, static_cast<double>(s)) /
           std::tgamma(h + 1.0);
  }
  integrand_info info() const {
    integrand_info info{.name = "disk_indicator",
                        .formula = "1 if ‖x − c‖ ≤ r else 0",
                        .domain = box::unit(center_.size()),
                        .exact = ball_volume(center_.size(), radius_),
                        .reference = "closed form π^{s/2} r^s / Γ(s/2 + 1)",
                        .regularity = smoothness::discontinuous};
    info.derivative_bound[0] = 1.0;
    // In 1D the ball is the interval [c − r, c + r]: jumps of size 1 at its ends, unless an end
    // is an end of [0, 1] (f is 1 up to it there: no jump). f(c ± r) = 1, the inner limit.
    if (center_.size() == 1) {
      piecewise_smooth_factor factor;
      if (center_[0] - radius_ > 0.0) factor.jumps.push_back({center_[0] - radius_, 1.0});
      if (center_[0] + radius_ < 1.0) factor.jumps.push_back({center_[0] + radius_, 1.0});
      factor.derivative_bound = {1.0, 0.0, 0.0, 0.0, 0.0};
      factor.integral = info.exact;
      info.separable_factors.push_back(std::move(factor));
    }
    return info;
  }
  const std::vector<double>& center() const noexcept { return center_; }
  double radius() const noexcept { return radius_; }

 private:
  std::vector<double> center_;
  double radius_, r2_;
};

class half_space_indicator {
 public:
  static constexpr std::size_t max_dimension = 20;  // the closed form sums 2^s terms
  static constexpr double max_relative_error = 1e-10;

  // The plane must cut the cube: Σ_(wᵢ<0) wᵢ < t < Σ_(wᵢ>0) wᵢ (0 < t < Σw for positive w).
  //
  // The region {Σ wᵢxᵢ ≤ t} does not change when w and t are multiplied by the same c > 0, so
  // both are divided by c = 2^⌊log₂ max wᵢ⌋ first, which is exact (a power of two): the largest
  // weight becomes [1, 2), Σw and the closed form's s!·Π wᵢ stay finite whatever the scale of
  // the input (w = (1e308, 1e308) has Σw = inf in double), and evaluate() compares the scaled sum,
  // whose rounding is the unscaled one's. A weight that the division would make subnormal (more
  // than 2^1021 below the largest) is refused.
  half_space_indicator(std::vector<double> w, double t);  // lib/src/functions/indicators.cpp
  std::size_t dimension() const noexcept { return w_.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    const std::size_t s = w_.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double p = 0.0;
      for (std::size_t j = 0; j < s; ++j) p += w_[j] * x[i * s + j];
      y[i] = p <= t_ ? 1.0 : 0.0;
    }
  }
  integrand_info info() const {
    integrand_info info{
        .name = "half_space",
        .formula = "1 if Σ wᵢxᵢ ≤ t else 0",
        .domain = box::unit(w_.size()),
        .exact = exact_,
        .reference = fmt::format("closed form Σ_v (−1)^|v| (t − w·v)₊^s/(s!·Π wᵢ) (Barrow & "
                                 "Smith 1979), 50 digits, relative rounding bound {:.2g}",
                                 error_bound_),
        .regularity = smoothness::discontinuous};
    info.derivative_bound[0] = 1.0;
    // In 1D, 1{w·x ≤ t} with the plane inside is a jump of size 1 at t/w (f(t/w) = 1, the left
    // limit for w > 0, the right one for w < 0;
    // where fl(w·x) switches differs from t/w by rounding only, and the envelopes do not depend
    // on where the jump is).
    if (w_.size() == 1) {
      piecewise_smooth_factor factor;
      factor.jumps.push_back({t_ / w_[0], 1.0});
      factor.derivative_bound = {1.0, 0.0, 0.0, 0.0, 0.0};
      factor.integral = exact_;
      info.separable_factors.push_back(std::move(factor));
    }
    return info;
  }
  double relative_error_bound() const noexcept { return error_bound_; }

 private:
  std::vector<double> w_;
  double t_, exact_, error_bound_;
};

}  // namespace quadmc
