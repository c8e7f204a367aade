// A uniform point on a rectangular area light: x' = corner + U₁·edge_u + U₂·edge_v, density 1/A
// with respect to area (docs/theory.md#irradiance-derivation; [Ramamoorthi 2009, §2.2.3]).
//
// Use it for direct lighting from a rectangle (estimators/irradiance_estimators.hpp): the
// estimator L·V·cosθ·cosθ'/|x − x'|²·A then has no variance from directions that miss the light,
// which hemisphere sampling wastes. Not ideal for a light that is large and close (the 1/r² term
// then varies strongly); solid-angle sampling of the spherical rectangle ([Ureña et al. 2013]) is
// better there and not implemented.
//
// Area and solid angle: a density p_A per unit area seen from x is the density
// p_ω = p_A·|x − x'|²/cosθ' per unit solid angle ([Pharr et al. 2016, §5.5.3], dω = cosθ' dA/r²);
// solid_angle_pdf() does that conversion.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/irradiance.hpp"
#include "quadmc/functions/vec3.hpp"

#include <cmath>
#include <cstddef>
#include <span>

namespace quadmc {

class rectangle_light_warp {
 public:
  explicit rectangle_light_warp(const rectangle& light) : light_(light), area_(light.area()) {
    require(std::isfinite(area_) && area_ > 0.0, "light area", area_, "a finite area > 0");
  }
  std::size_t input_dimension() const noexcept { return 2; }
  std::size_t output_dimension() const noexcept { return 3; }
  double area() const noexcept { return area_; }
  const rectangle& light() const noexcept { return light_; }

  vec3 sample(double u1, double u2) const noexcept { return light_.point(u1, u2); }
  void sample(std::span<const double> u, std::span<double> x) const noexcept {
    const vec3 p = sample(u[0], u[1]);
    x[0] = p.x;
    x[1] = p.y;
    x[2] = p.z;
  }
  // 1/A on the light (the point is assumed to lie on it: the warp never produces another).
  double pdf(std::span<const double> /*x*/) const noexcept { return 1.0 / area_; }

  // The same density per unit solid angle seen from `from`; 0 when the light's back faces it.
  double solid_angle_pdf(vec3 from, vec3 on_light) const noexcept {
    const vec3 d = on_light - from;
    const double r2 = dot(d, d);
    const double cos_light = -dot(light_.normal(), d) / std::sqrt(r2);
    return cos_light > 0.0 ? r2 / (cos_light * area_) : 0.0;
  }

 private:
  rectangle light_;
  double area_;
};

}  // namespace quadmc
