// The random integrands of the rendering community's sampler tests (the randomly placed and
// oriented edges and disks of [Pilleboue et al. 2015], which UTK's integration test runs by the
// thousand): families whose every instance is drawn from the seed, so that an
// ensemble of many instances judges a point set on edges and bumps of every orientation, not
// on the few fixed, axis-aligned ones that flatter grid-like sets
// (docs/theory.md#random-ensembles).
//
//   heaviside_random  1 if n·(x − p) ≤ 0 on [0,1]^s: n a uniformly random unit normal, p a
//                     uniform point of the cube (so the plane cuts it); exact volume by the
//                     half-space closed form (indicators.hpp, weights of any sign)
//   disk_random       1 if ‖x − c‖ ≤ r on [0,1]²: c uniform in the square, r uniform in
//                     [0.1, 0.4]; the disk may leave the square, exact area of the intersection
//                     in closed form
//   gaussian_random   exp(−½ (x − μ)ᵀ R diag(σ₁⁻², σ₂⁻²) Rᵀ (x − μ)) on [0,1]²: μ uniform in the
//                     square, σₖ log-uniform in [0.05, 0.5], R a rotation by a uniform angle;
//                     the reference is the inner integral in closed form (erf) and the outer one
//                     by adaptive Gauss–Kronrod, with its error estimate
//
// Use them as `ensemble = M` families: each instance is a new edge or bump. Not for rates of one
// fixed integrand (their instances differ), and not smooth-boundary-free: a disk clipped by the
// square has corners on its boundary, which the indicator rates of docs/theory.md ignore.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/indicators.hpp"
#include "quadmc/functions/integrand.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

// The parameters each family draws from (seed, dimension) when a scene omits them.
struct heaviside_parameters {
  std::vector<double> normal;  // unit length
  std::vector<double> point;   // in [0,1)^s
};
heaviside_parameters heaviside_random_parameters(std::size_t s, std::uint64_t seed);

struct disk_parameters {
  std::vector<double> center;  // in [0,1)²
  double r = 0.0;              // in [0.1, 0.4)
};
disk_parameters disk_random_parameters(std::uint64_t seed);

struct gaussian_2d_parameters {
  std::vector<double> mean;    // in [0,1)²
  std::vector<double> scales;  // σ₁, σ₂ in [0.05, 0.5)
  double angle = 0.0;          // radians, in [0, π)
};
gaussian_2d_parameters gaussian_random_parameters(std::uint64_t seed);

// 1 if n·(x − p) ≤ 0, a half-space of any orientation through p.
class heaviside_random {
 public:
  heaviside_random(std::vector<double> normal, std::vector<double> point);  // random_regions.cpp
  std::size_t dimension() const noexcept { return region_.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    region_.evaluate(x, y);
  }
  integrand_info info() const;

 private:
  // {n·x ≤ n·p}, the lengths of n and p and p's place in the cube checked.
  static half_space_indicator through(const std::vector<double>& normal,
                                      const std::vector<double>& point);

  half_space_indicator region_;
};

// 1 if ‖x − c‖ ≤ r on the unit square; the disk may extend beyond it.
class disk_random {
 public:
  disk_random(std::vector<double> center, double r);
  std::size_t dimension() const noexcept { return 2; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double dx = x[2 * i] - cx_;
      const double dy = x[2 * i + 1] - cy_;
      y[i] = dx * dx + dy * dy <= r2_ ? 1.0 : 0.0;
    }
  }
  integrand_info info() const;
  // The area of the disk (centre (cx, cy), radius r) inside [0,1]², in closed form: the
  // inclusion–exclusion of four quadrant areas {u ≤ a, v ≤ b} of the disk, each a sum of
  // ∫√(r² − u²) du = (u√(r² − u²) + r²·asin(u/r))/2 over at most three pieces.
  static double square_area(double cx, double cy, double r) noexcept;

 private:
  double cx_, cy_, r_, r2_;
  double area_;
};

// An anisotropic, rotated Gaussian bump on the unit square.
class gaussian_random {
 public:
  gaussian_random(std::vector<double> mean, std::vector<double> scales, double angle);
  std::size_t dimension() const noexcept { return 2; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double dx = x[2 * i] - mx_;
      const double dy = x[2 * i + 1] - my_;
      y[i] = std::exp(-0.5 * (a11_ * dx * dx + 2.0 * a12_ * dx * dy + a22_ * dy * dy));
    }
  }
  integrand_info info() const;
  double reference_error() const noexcept { return error_; }

 private:
  double mx_, my_, a11_, a12_, a22_;  // mean and the precision matrix R diag(σ⁻²) Rᵀ
  std::vector<double> scales_;
  double angle_;
  double integral_ = 0.0;
  double error_ = 0.0;  // Gauss–Kronrod's error estimate of integral_
};

}  // namespace quadmc
