// Indicator functions of regions of [0,1]^s with exact volumes: the discontinuous integrands of
// geometric Monte Carlo (the "area of a disk" experiment of every Monte Carlo course).
//
//   ball        1 if ‖x − c‖ ≤ r          volume π^{s/2} r^s / Γ(s/2 + 1)   (ball inside the cube)
//   half_space  1 if Σ wᵢxᵢ ≤ t, wᵢ > 0   volume Σ_{v∈{0,1}^s} (−1)^{|v|} (t − w·v)₊^s / (s!·Π wᵢ)
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
#include "quadmc/functions/inclusion_exclusion.hpp"
#include "quadmc/functions/integrand.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

namespace quadmc {

class ball_indicator {
 public:
  // The ball must lie inside [0,1]^s (cⱼ − r ≥ 0 and cⱼ + r ≤ 1) so its volume is the formula.
  ball_indicator(std::vector<double> center, double radius)
      : center_(std::move(center)), radius_(radius) {
    require(!center_.empty(), "center", center_.size(),
            "a non-empty vector (its length is the dimension s ≥ 1)");
    require(std::isfinite(radius_) && radius_ > 0.0, "r", radius_, "a finite radius r > 0");
    for (double c : center_) {
      require(std::isfinite(c) && c - radius_ >= 0.0 && c + radius_ <= 1.0, "center", c,
              fmt::format("a ball inside [0,1]^s: r ≤ cⱼ ≤ 1 − r with r = {}", radius_));
    }
    r2_ = radius_ * radius_;
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

  // The plane must cut the cube: 0 < t < Σw.
  half_space_indicator(std::vector<double> w, double t) : w_(std::move(w)), t_(t) {
    require(!w_.empty(), "w", w_.size(), "a non-empty vector (its length is the dimension s ≥ 1)");
    require(w_.size() <= max_dimension, "dimension", w_.size(),
            "s ≤ 20 (the half-space volume sums 2^s terms)");
    double total = 0.0;
    for (double wi : w_) {
      require(std::isfinite(wi) && wi > 0.0, "w", wi, "finite weights wᵢ > 0");
      total += wi;
    }
    require(std::isfinite(t_) && t_ > 0.0 && t_ < total, "t", t_,
            fmt::format("a plane cutting the cube, 0 < t < Σw = {}", total));
    const std::size_t s = w_.size();
    const wide_float eps = std::numeric_limits<wide_float>::epsilon();
    const wide_float tw = t_;
    const double n = static_cast<double>(s);
    // g(τ) = (t − τ)₊^s. d = t − τ is off by ≤ Δτ + ε·|t − τ|, and the power moves it by
    // ≤ s·(|d| + δ)^{s−1}·δ, plus s roundings of the power itself.
    const vertex_sum sum =
        alternating_vertex_sum(w_, [&](const wide_float& tau, const wide_float& dt) {
          const wide_float d = tw - tau;
          const wide_float delta = dt + eps * boost::multiprecision::abs(d);
          wide_float g = d > 0 ? wide_float(boost::multiprecision::pow(d, static_cast<int>(s)))
                               : wide_float(0);
          wide_float error = n *
                                 boost::multiprecision::pow(boost::multiprecision::abs(d) + delta,
                                                            static_cast<int>(s) - 1) *
                                 delta +
                             n * eps * g;
          return std::pair{std::move(g), std::move(error)};
        });
    wide_float denominator = 1;
    for (std::size_t j = 0; j < s; ++j) denominator *= static_cast<double>(j + 1) * w_[j];
    exact_ = static_cast<double>(sum.value / denominator);
    error_bound_ =
        static_cast<double>(sum.error_bound / boost::multiprecision::abs(sum.value) + 2 * n * eps);
    require(error_bound_ <= max_relative_error, "w",
            fmt::format("[{}] with t = {} (relative rounding bound {:.3g})", fmt::join(w_, ", "),
                        t_, error_bound_),
            "parameters whose closed form is accurate to 1e-10 relative (a smaller s)");
  }
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
    return info;
  }
  double relative_error_bound() const noexcept { return error_bound_; }

 private:
  std::vector<double> w_;
  double t_, exact_, error_bound_;
};

}  // namespace quadmc
