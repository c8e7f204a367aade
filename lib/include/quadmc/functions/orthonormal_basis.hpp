// An orthonormal frame (t1, t2, n) around a unit normal n, to carry directions sampled in the
// z-up local frame of sampling/hemisphere_warps.hpp to world space and back. The one frame of the
// library: the irradiance integrands (irradiance.hpp) build their hemisphere directions with it
// and the irradiance estimators (estimators/irradiance_estimators.hpp) their samples, so it lives
// in functions/, the lowest layer that both use.
//
// Method: Duff, Burgess, Christensen, Hery, Kensler, Liani & Villemin, "Building an Orthonormal
// Basis, Revisited", JCGT 6(1), 2017, Listing 3: branch-free but for the sign of n.z, no
// normalisation and no division by a small number (Frisvad's 2012 version divides by 1 + n.z,
// which loses all accuracy as n.z → −1). Use it with a unit n; a non-unit n gives a non-
// orthonormal frame (validate lengths at the boundary, as irradiance.hpp does).
#pragma once

#include "quadmc/functions/vec3.hpp"

#include <cmath>

namespace quadmc {

struct orthonormal_basis {
  vec3 t1, t2, n;

  explicit orthonormal_basis(vec3 normal) noexcept : n(normal) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    t1 = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    t2 = {b, sign + n.y * n.y * a, -n.y};
  }

  // Local (x, y, z) with z along n → world.
  constexpr vec3 to_world(vec3 local) const noexcept {
    return local.x * t1 + local.y * t2 + local.z * n;
  }
  constexpr vec3 to_local(vec3 world) const noexcept {
    return {dot(world, t1), dot(world, t2), dot(world, n)};
  }
};

}  // namespace quadmc
