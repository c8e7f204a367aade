// Directions on the upper hemisphere (z ≥ 0, z-up local frame) from two uniforms
// (docs/theory.md#hemisphere-sampling; [Pharr et al. 2016, §13.6.1 and §13.6.3]). Densities are
// with respect to solid angle.
//
//  - uniform_hemisphere_warp: z = U₁, φ = 2πU₂, p = 1/(2π). Since dω = dz dφ (Archimedes),
//    uniform z and φ give uniform directions. Use it when nothing is known about the incident
//    light; it wastes samples near the horizon where cos θ is small.
//  - cosine_hemisphere_warp: p = cos θ/π ([Malley 1988]'s method: a uniform disk point lifted to
//    the hemisphere, z = √(1 − r²) = √(1 − U₁)). Use it for irradiance E = ∫L cos θ dω: the
//    estimator becomes π·L, removing the cosine from the variance. Not for light that arrives near
//    the horizon only.
// To go from the local frame to world space around a normal n use functions/orthonormal_basis.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>

namespace quadmc {

class uniform_hemisphere_warp {
 public:
  std::size_t input_dimension() const noexcept { return 2; }
  std::size_t output_dimension() const noexcept { return 3; }
  void sample(std::span<const double> u, std::span<double> w) const noexcept {
    const double z = u[0];
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * std::numbers::pi * u[1];
    w[0] = r * std::cos(phi);
    w[1] = r * std::sin(phi);
    w[2] = z;
  }
  double pdf(std::span<const double> w) const noexcept {
    return w[2] >= 0.0 ? 0.5 * std::numbers::inv_pi : 0.0;
  }
};

class cosine_hemisphere_warp {
 public:
  std::size_t input_dimension() const noexcept { return 2; }
  std::size_t output_dimension() const noexcept { return 3; }
  void sample(std::span<const double> u, std::span<double> w) const noexcept {
    const double r = std::sqrt(u[0]);
    const double phi = 2.0 * std::numbers::pi * u[1];
    w[0] = r * std::cos(phi);
    w[1] = r * std::sin(phi);
    // √(1 − U₁) rather than √(1 − r²): the same value without the rounding of r² .
    w[2] = std::sqrt(1.0 - u[0]);
  }
  double pdf(std::span<const double> w) const noexcept {
    return w[2] >= 0.0 ? w[2] * std::numbers::inv_pi : 0.0;
  }
};

}  // namespace quadmc
