// Irradiance from a rectangular Lambertian area light, optionally behind a rectangular occluder:
// the rendering integrand of [Ramamoorthi 2009, §2.2.3] (solid-angle and area sampling),
// written two ways on [0,1]²:
//   (i)  over the hemisphere of directions at x:  E = ∫_Ω L_i(x, ω) cosθ dω, with the uniform
//        hemisphere map z = cosθ = u₁, φ = 2πu₂ in the local frame of n (Jacobian dω = 2π du);
//   (ii) over the light's area:  E = ∫_A' L V(x, x') cosθ cosθ' / |x − x'|² dA', with
//        x' = corner + s·edge_u + t·edge_v (Jacobian dA' = |edge_u × edge_v| ds dt).
// Exact reference: Lambert's formula for a polygonal luminaire (Lambert 1760; the "vector
// irradiance" form of Arvo, "Applications of irradiance tensors...", SIGGRAPH 1995, eq. 3):
//   E = L/2 · |Σ_edges θ_i · n·Γ̂_i|,  θ_i = ∠(v_i − x, v_{i+1} − x),  Γ̂_i = unit
//   (v_i−x)×(v_{i+1}−x).
// With an occluder, the part of the light hidden from x is the occluder's central projection
// from x onto the light's plane, clipped to the light rectangle (Sutherland & Hodgman, CACM 1974);
// its Lambert value is subtracted.
//
// Use it for convergence studies of hemisphere vs area sampling with a known answer. Not for
// lights that straddle the horizon of x (Lambert's formula would need clipping at the horizon:
// such setups are rejected), nor for occluders that are not strictly between x and the light's
// plane (rejected: the shadow projection is only a convex polygon in that case).
//
// No-occluder setups cast no visibility ray at all: evaluate() picks a kernel templated on
// whether there is an occluder once per batch, never per point
// (docs/design.md#skip-what-a-scene-does-not-need).
#pragma once

#include "quadmc/functions/integrand.hpp"
#include "quadmc/functions/orthonormal_basis.hpp"
#include "quadmc/functions/vec3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

namespace quadmc {

// The points corner + s·edge_u + t·edge_v, s, t ∈ [0,1]. edge_u ⊥ edge_v is required (validate).
// The emitting (facing) side is normal() = normalize(edge_u × edge_v).
struct rectangle {
  vec3 corner, edge_u, edge_v;

  constexpr vec3 point(double s, double t) const noexcept {
    return corner + s * edge_u + t * edge_v;
  }
  vec3 normal() const noexcept { return normalize(cross(edge_u, edge_v)); }
  double area() const noexcept { return length(cross(edge_u, edge_v)); }
};

struct irradiance_setup {
  vec3 x;  // the shaded point
  vec3 n;  // unit surface normal at x
  rectangle light;
  double radiance;  // L, constant over the light and over directions (Lambertian emitter)
  std::optional<rectangle> occluder;  // blocks from both sides
};

// Throws quadmc::invalid_argument naming the field ("radiance", "n", "light", "occluder", …) when
// the radiance is not finite and > 0, n is not unit (|‖n‖ − 1| > 1e-9), a rectangle is
// degenerate or its edges are not perpendicular (|cos| > 1e-9), the light does not face x
// (normal · (x − corner) ≤ 0), any light corner is not strictly above the tangent plane of x, or
// any occluder corner is not strictly between x and the light's plane.
void validate(const irradiance_setup& setup);

// E by Lambert's formula, minus the Lambert value of the clipped shadow of the occluder.
// Validates the setup.
double irradiance_exact(const irradiance_setup& setup);

// ∫_P cosθ dω over the convex polygon P (vertices in order, either orientation) seen from x with
// normal n: the projected solid angle, Lambert's formula without L. P must lie above x's tangent
// plane. Degenerate (repeated) vertices are allowed.
double projected_solid_angle(vec3 x, vec3 n, std::span<const vec3> polygon);

// The part of the light hidden by the occluder, as a convex polygon on the light's plane (the
// occluder's projection from x, clipped to the light); empty without occluder or when the shadow
// misses the light.
std::vector<vec3> occluder_shadow(const irradiance_setup& setup);

// The same shadow in the light's (s, t) parameters, s, t ∈ [0,1]: for integrating over the
// light's parameter square piecewise.
std::vector<std::array<double, 2>> occluder_shadow_st(const irradiance_setup& setup);

// L if the ray x + t·w (t > 0) hits the light's front face and not the occluder, else 0. w must
// be a unit vector; the setup is not validated here (call validate once, outside the loop).
double incident_radiance(const irradiance_setup& setup, vec3 w);

// Whether the segment from x to p_on_light misses the occluder; true without occluder.
bool visible(const irradiance_setup& setup, vec3 p_on_light);

// A test scene: x = origin, n = +z, a 1 × √1.04 light at height ≈ 1 tilted by atan(0.2) towards
// x; with_occluder adds a 0.3 × 0.25 occluder at height 0.5 whose shadow crosses two edges of the
// light (so the clipping is exercised).
irradiance_setup default_irradiance_setup(bool with_occluder);

namespace detail {

// A rectangle prepared for ray tests: the plane's unit normal and the dual basis that turns a
// point of the plane into its (s, t) parameters (edge/|edge|², valid because edges are ⊥).
struct rectangle_frame {
  vec3 corner{}, normal{}, dual_u{}, dual_v{};

  rectangle_frame() = default;
  explicit rectangle_frame(const rectangle& r)
      : corner(r.corner),
        normal(r.normal()),
        dual_u(r.edge_u / length_squared(r.edge_u)),
        dual_v(r.edge_v / length_squared(r.edge_v)) {}

  // Whether origin + t·dir meets the closed rectangle for some t ∈ (0, t_max). Branch-free: a
  // ray parallel to the plane gets a huge t (denominator replaced by a tiny number, no division
  // by zero) and fails the parameter tests.
  bool hit(vec3 origin, vec3 dir, double t_max) const noexcept {
    const double denom = dot(normal, dir);
    const double safe = denom != 0.0 ? denom : 1e-300;
    const double t = dot(normal, corner - origin) / safe;
    const vec3 q = origin + t * dir - corner;
    const double s = dot(q, dual_u);
    const double v = dot(q, dual_v);
    return (t > 0.0) & (t < t_max) & (s >= 0.0) & (s <= 1.0) & (v >= 0.0) & (v <= 1.0);
  }
};

}  // namespace detail

// (i) f(u) = 2π·u₁·L_i(x, ω(u)) on [0,1]², name "irradiance_hemisphere". Discontinuous (the
// light's outline in direction space), with or without occluder.
class irradiance_hemisphere {
 public:
  explicit irradiance_hemisphere(irradiance_setup setup);

  std::size_t dimension() const noexcept { return 2; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    if (setup_.occluder) {
      evaluate_kernel<true>(x, y);
    } else {
      evaluate_kernel<false>(x, y);
    }
  }
  integrand_info info() const;
  const irradiance_setup& setup() const noexcept { return setup_; }

 private:
  template <bool Occluded>
  void evaluate_kernel(std::span<const double> x, std::span<double> y) const noexcept {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double z = x[2 * i];
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = two_pi * x[2 * i + 1];
      const vec3 w = frame_.to_world({r * std::cos(phi), r * std::sin(phi), z});
      bool lit = light_.hit(setup_.x, w, inf_);
      if constexpr (Occluded) lit &= !occluder_.hit(setup_.x, w, inf_);
      y[i] = lit ? two_pi * z * setup_.radiance : 0.0;
    }
  }

  static constexpr double inf_ = std::numeric_limits<double>::infinity();
  irradiance_setup setup_;
  orthonormal_basis frame_;
  detail::rectangle_frame light_, occluder_;
  double exact_;
};

// (ii) f(s, t) = L·A·V·cosθ·cosθ'/|x − x'|² at x' = light.point(s, t), name "irradiance_area".
// Analytic without occluder (r and both cosines are bounded away from 0 on a validated setup),
// discontinuous along the shadow outline with one.
class irradiance_area {
 public:
  explicit irradiance_area(irradiance_setup setup);

  std::size_t dimension() const noexcept { return 2; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    if (setup_.occluder) {
      evaluate_kernel<true>(x, y);
    } else {
      evaluate_kernel<false>(x, y);
    }
  }
  integrand_info info() const;
  const irradiance_setup& setup() const noexcept { return setup_; }

 private:
  template <bool Occluded>
  void evaluate_kernel(std::span<const double> x, std::span<double> y) const noexcept {
    const rectangle& l = setup_.light;
    for (std::size_t i = 0; i < y.size(); ++i) {
      const vec3 d = l.point(x[2 * i], x[2 * i + 1]) - setup_.x;
      const double r2 = dot(d, d);
      // cosθ·cosθ'/r² = (n·d)(−N·d)/r⁴ with d = x' − x unnormalised.
      double v = scale_ * dot(setup_.n, d) * -dot(light_normal_, d) / (r2 * r2);
      if constexpr (Occluded) v = occluder_.hit(setup_.x, d, 1.0) ? 0.0 : v;
      y[i] = v;
    }
  }

  irradiance_setup setup_;
  vec3 light_normal_;
  double scale_;  // L·A
  detail::rectangle_frame occluder_;
  double exact_;
};

}  // namespace quadmc
