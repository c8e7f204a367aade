// The rendering estimators for the irradiance E = ∫_Ω L_i(x, ω) cosθ dω at x from a rectangular
// area light (functions/irradiance.hpp; [Ramamoorthi 2009, §2.2.3]), each fed by any point set on
// [0,1)² (docs/theory.md#irradiance-derivation):
//
//  - irradiance_uniform_hemisphere: ω uniform, p = 1/(2π): Y = 2π·L_i(ω)·cosθ.
//  - irradiance_cosine_hemisphere: p = cosθ/π: Y = π·L_i(ω) (the cosine cancels).
//  - irradiance_light_area: x' uniform on the light, p = 1/A per area, i.e. p_ω = r²/(A cosθ')
//    per solid angle: Y = L·V(x, x')·cosθ·cosθ'/r²·A (docs/theory.md#irradiance-derivation).
// Use the light-area one for small or distant lights (every sample hits the light); the
// hemisphere ones waste every direction that misses it, which is most of them for a small light.
// A setup without occluder casts no visibility test
// (docs/design.md#skip-what-a-scene-does-not-need).
#pragma once

#include "quadmc/estimators/estimate.hpp"
#include "quadmc/estimators/sample_mean.hpp"
#include "quadmc/functions/irradiance.hpp"
#include "quadmc/functions/orthonormal_basis.hpp"
#include "quadmc/functions/vec3.hpp"
#include "quadmc/sampling/hemisphere_warps.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/rectangle_light_warp.hpp"

#include <numbers>
#include <string>

namespace quadmc {

namespace detail {

inline void require_two_dimensional(std::size_t s) {
  require(s == 2, "point set dimension", s, "2 (directions and light points take two uniforms)");
}

template <class HemisphereWarp, point_set P>
estimate irradiance_hemisphere_estimate(const irradiance_setup& setup, const P& points,
                                        unsigned threads) {
  validate(setup);
  require_two_dimensional(points.dimension());
  const orthonormal_basis frame(setup.n);
  const HemisphereWarp warp;
  return sample_mean(points, threads, [&](std::uint64_t, std::span<double> u, std::span<double> y) {
    double w[3];
    for (std::size_t i = 0; i < y.size(); ++i) {
      warp.sample(std::span<const double>(u.data() + 2 * i, 2), w);
      const double p = warp.pdf(std::span<const double>(w, 3));
      const vec3 world = frame.to_world({w[0], w[1], w[2]});
      // cosθ = local z; p > 0 for every z ≥ 0 the warps produce except the
      // cosine warp's horizon z = 0, where L·cosθ = 0 too.
      const double li = incident_radiance(setup, world);
      y[i] = li == 0.0 || w[2] == 0.0 ? 0.0 : li * w[2] / p;
    }
  });
}

}  // namespace detail

template <point_set P>
estimate irradiance_uniform_hemisphere(const irradiance_setup& setup, const P& points,
                                       unsigned threads = 1) {
  return detail::irradiance_hemisphere_estimate<uniform_hemisphere_warp>(setup, points, threads);
}

template <point_set P>
estimate irradiance_cosine_hemisphere(const irradiance_setup& setup, const P& points,
                                      unsigned threads = 1) {
  return detail::irradiance_hemisphere_estimate<cosine_hemisphere_warp>(setup, points, threads);
}

template <point_set P>
estimate irradiance_light_area(const irradiance_setup& setup, const P& points,
                               unsigned threads = 1) {
  validate(setup);
  detail::require_two_dimensional(points.dimension());
  const rectangle_light_warp warp(setup.light);
  const vec3 light_normal = setup.light.normal();
  const double scale = setup.radiance * warp.area();  // L / p_A = L·A
  const bool occluded = setup.occluder.has_value();
  return sample_mean(points, threads, [&](std::uint64_t, std::span<double> u, std::span<double> y) {
    for (std::size_t i = 0; i < y.size(); ++i) {
      const vec3 on_light = warp.sample(u[2 * i], u[2 * i + 1]);
      const vec3 d = on_light - setup.x;
      const double r2 = dot(d, d);
      // cosθ·cosθ'/r² = (n·d)(−N·d)/r⁴ with d unnormalised.
      double v = scale * dot(setup.n, d) * -dot(light_normal, d) / (r2 * r2);
      if (occluded && !visible(setup, on_light)) v = 0.0;
      y[i] = v;
    }
  });
}

}  // namespace quadmc
