// Tests for functions/orthonormal_basis.hpp: orthonormal, right-handed frames for random and
// extreme normals, and the local z axis mapped onto the normal.
#include "quadmc/functions/orthonormal_basis.hpp"

#include "quadmc/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace {

using namespace quadmc;

void expect_orthonormal(vec3 n) {
  const orthonormal_basis b(n);
  // Duff et al. report errors of a few ulps; 8ε leaves room for the 3-term dot products.
  const double tol = 8 * std::numeric_limits<double>::epsilon();
  EXPECT_NEAR(dot(b.t1, b.t1), 1.0, tol) << n.x << " " << n.y << " " << n.z;
  EXPECT_NEAR(dot(b.t2, b.t2), 1.0, tol);
  EXPECT_NEAR(dot(b.t1, b.t2), 0.0, tol);
  EXPECT_NEAR(dot(b.t1, n), 0.0, tol);
  EXPECT_NEAR(dot(b.t2, n), 0.0, tol);
  // Right-handed: t1 × t2 = n.
  const vec3 c = cross(b.t1, b.t2);
  EXPECT_NEAR(c.x, n.x, tol);
  EXPECT_NEAR(c.y, n.y, tol);
  EXPECT_NEAR(c.z, n.z, tol);
  // Round trip.
  const vec3 w = normalize(vec3{0.3, -0.5, 0.8});
  const vec3 back = b.to_world(b.to_local(w));
  EXPECT_NEAR(back.x, w.x, tol);
  EXPECT_NEAR(back.y, w.y, tol);
  EXPECT_NEAR(back.z, w.z, tol);
}

TEST(OrthonormalBasis, IsOrthonormalForRandomAndExtremeNormals) {
  expect_orthonormal({0, 0, 1});
  expect_orthonormal({0, 0, -1});  // Frisvad's version divides by zero here
  expect_orthonormal(normalize(vec3{1e-9, 0, -1}));
  expect_orthonormal({1, 0, 0});
  const random_stream u(1, 1);
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const double z = 2 * u.uniform(2 * i) - 1, phi = 2 * std::numbers::pi * u.uniform(2 * i + 1);
    const double r = std::sqrt(1 - z * z);
    expect_orthonormal({r * std::cos(phi), r * std::sin(phi), z});
  }
}

TEST(OrthonormalBasis, LocalZIsTheNormal) {
  const vec3 n = normalize(vec3{1, 2, 3});
  const vec3 w = orthonormal_basis(n).to_world({0, 0, 1});
  EXPECT_NEAR(w.x, n.x, 1e-15);
  EXPECT_NEAR(w.y, n.y, 1e-15);
  EXPECT_NEAR(w.z, n.z, 1e-15);
}

}  // namespace
