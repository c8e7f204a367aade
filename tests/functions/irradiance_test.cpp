// Irradiance from a rectangular light: Lambert's polygon formula against nested Gauss–Kronrod of
// both integrand forms (split at their jumps), with and without occluder; validation messages.
#include "quadmc/functions/irradiance.hpp"

#include "quadmc/core/rng.hpp"
#include "reference_quadrature.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace quadmc {
namespace {

using test::at;
using test::gauss_kronrod;
using test::relative_error;

std::array<vec3, 4> corners(const rectangle& r) {
  return {r.point(0, 0), r.point(1, 0), r.point(1, 1), r.point(0, 1)};
}

// The hemisphere form over (u₁, u₂). For a fixed azimuth φ = 2πu₂ the directions form a
// quarter circle from the horizon to n, in the plane through x with normal m = −sinφ·t1 + cosφ·t2;
// the integrand can jump only where that arc crosses an edge of the light or of the occluder
// (the 3D rectangles, not the library's shadow polygon). Those crossings, z = n·q/|q| for the
// edge point q with m·q = 0 on the φ side, split the inner u₁ integral into smooth pieces. The
// outer u₂ integral is split at the azimuths of all corners and of the shadow's vertices (kinks).
double hemisphere_reference(const irradiance_setup& setup) {
  const irradiance_hemisphere f(setup);
  const orthonormal_basis frame(setup.n);
  std::vector<std::array<vec3, 4>> rects = {corners(setup.light)};
  if (setup.occluder) rects.push_back(corners(*setup.occluder));
  std::vector<double> breaks;
  auto add_azimuth = [&](vec3 p) {
    const vec3 d = p - setup.x;
    double u2 = std::atan2(dot(d, frame.t2), dot(d, frame.t1)) / (2.0 * std::numbers::pi);
    breaks.push_back(u2 < 0.0 ? u2 + 1.0 : u2);
  };
  for (const auto& r : rects) {
    for (vec3 p : r) add_azimuth(p);
  }
  for (vec3 p : occluder_shadow(setup)) add_azimuth(p);
  return gauss_kronrod(
      [&](double u2) {
        const double phi = 2.0 * std::numbers::pi * u2;
        const vec3 m = -std::sin(phi) * frame.t1 + std::cos(phi) * frame.t2;
        const vec3 d = std::cos(phi) * frame.t1 + std::sin(phi) * frame.t2;
        std::vector<double> z;
        for (const auto& r : rects) {
          for (int k = 0; k < 4; ++k) {
            const vec3 p = r[k] - setup.x, e = r[(k + 1) % 4] - r[k];
            const double lambda = -dot(m, p) / dot(m, e);
            const vec3 q = p + lambda * e;
            if (lambda >= 0.0 && lambda <= 1.0 && dot(d, q) >= 0.0)
              z.push_back(dot(setup.n, q) / length(q));
          }
        }
        return gauss_kronrod([&](double u1) { return at(f, {u1, u2}); }, 0.0, 1.0, z);
      },
      0.0, 1.0, breaks);
}

// The area form over (s, t): smooth without occluder. With one, for fixed s the segment from x to
// light.point(s, t) crosses the occluder's outline where light.point(s, t) lies in the plane
// through x and an occluder edge: m·(light.point(s, t) − x) = 0 with m = (q_k − x) × (q_{k+1} − x),
// linear in t. Those t split the inner integral; the outer one is split at the shadow's vertices.
double area_reference(const irradiance_setup& setup) {
  const irradiance_area f(setup);
  std::vector<double> breaks;
  for (const auto& st : occluder_shadow_st(setup)) breaks.push_back(st[0]);
  return gauss_kronrod(
      [&](double s) {
        std::vector<double> t_breaks;
        if (setup.occluder) {
          const auto q = corners(*setup.occluder);
          const vec3 p0 = setup.light.point(s, 0.0) - setup.x;
          for (int k = 0; k < 4; ++k) {
            const vec3 m = cross(q[k] - setup.x, q[(k + 1) % 4] - setup.x);
            t_breaks.push_back(-dot(m, p0) / dot(m, setup.light.edge_v));
          }
        }
        return gauss_kronrod([&](double t) { return at(f, {s, t}); }, 0.0, 1.0, t_breaks);
      },
      0.0, 1.0, breaks);
}

// A second scene: x off to the side with a tilted normal, so the light does not contain the
// zenith (two jumps per azimuth) and the occluder's shadow lies inside the light (unclipped).
irradiance_setup side_setup(bool with_occluder) {
  irradiance_setup s = default_irradiance_setup(with_occluder);
  s.x = {0.9, 0.7, 0.0};
  s.n = normalize(vec3{0.2, 0.1, 1.0});
  // Near the segment from x to the light's centre, so its shadow falls inside the light.
  if (with_occluder) s.occluder = rectangle{{0.45, 0.25, 0.5}, {0.0, 0.2, 0.0}, {0.2, 0.0, 0.05}};
  return s;
}

// 1e-10 is the bar of docs/design.md#accuracy-targets: with every jump on a breakpoint, nested
// Gauss–Kronrod reaches ~1e-15 (measured errors are printed).
constexpr double irradiance_tolerance = 1e-10;

TEST(Irradiance, LambertAgreesWithBothFormsIntegratedNumerically) {
  for (int scene = 0; scene < 2; ++scene) {
    for (bool occluded : {false, true}) {
      const irradiance_setup setup =
          scene == 0 ? default_irradiance_setup(occluded) : side_setup(occluded);
      const double exact = irradiance_exact(setup);
      const double hemisphere = hemisphere_reference(setup);
      const double area = area_reference(setup);
      const double e_h = relative_error(hemisphere, exact);
      const double e_a = relative_error(area, exact);
      std::printf(
          "irradiance scene %d occluder %d: exact %.15g, hemisphere relative error vs "
          "independent integration %.2e, area %.2e\n",
          scene, occluded ? 1 : 0, exact, e_h, e_a);
      EXPECT_LT(e_h, irradiance_tolerance) << "scene " << scene << " occluder " << occluded;
      EXPECT_LT(e_a, irradiance_tolerance) << "scene " << scene << " occluder " << occluded;
      EXPECT_LT(relative_error(hemisphere, area), 2 * irradiance_tolerance);
      EXPECT_EQ(irradiance_hemisphere(setup).info().exact, exact);
      EXPECT_EQ(irradiance_area(setup).info().exact, exact);
    }
  }
}

TEST(Irradiance, DefaultOccluderShadowIsClippedByTwoLightEdges) {
  const auto shadow = occluder_shadow_st(default_irradiance_setup(true));
  ASSERT_GE(shadow.size(), 4u);
  int on_s0 = 0, on_t0 = 0;
  for (const auto& st : shadow) {
    on_s0 += st[0] == 0.0;
    on_t0 += st[1] == 0.0;
    EXPECT_GE(st[0], 0.0);
    EXPECT_LE(st[0], 1.0);
    EXPECT_GE(st[1], 0.0);
    EXPECT_LE(st[1], 1.0);
  }
  EXPECT_GE(on_s0 + on_t0, 3) << "the shadow should be cut by the sides s = 0 and t = 0";
}

TEST(Irradiance, ShadowInsideMissingOrCoveringTheLight) {
  irradiance_setup s = default_irradiance_setup(false);
  const double bare = irradiance_exact(s);
  // Shadow well inside the light: Lambert of the light minus Lambert of the unclipped projection.
  s.occluder = rectangle{{0.05, -0.05, 0.5}, {0.0, 0.1, 0.0}, {0.1, 0.0, 0.02}};
  ASSERT_EQ(occluder_shadow(s).size(), 4u);
  const double inside = irradiance_exact(s);
  EXPECT_LT(inside, bare);
  EXPECT_LT(relative_error(inside, area_reference(s)), irradiance_tolerance);
  // Shadow missing the light: the occluder changes nothing.
  s.occluder = rectangle{{2.0, 2.0, 0.5}, {0.0, 0.1, 0.0}, {0.1, 0.0, 0.0}};
  EXPECT_TRUE(occluder_shadow(s).empty());
  EXPECT_EQ(irradiance_exact(s), bare);
  // An occluder larger than the light's projection: nothing is visible.
  s.occluder = rectangle{{-2.0, -2.0, 0.5}, {0.0, 4.0, 0.0}, {4.0, 0.0, 0.0}};
  EXPECT_NEAR(irradiance_exact(s), 0.0, 1e-15);
}

TEST(Irradiance, IncidentRadianceAndVisibilityMatchTheIntegrands) {
  for (bool occluded : {false, true}) {
    const irradiance_setup setup = default_irradiance_setup(occluded);
    const irradiance_hemisphere h(setup);
    const irradiance_area a(setup);
    const orthonormal_basis frame(setup.n);
    const random_stream rng(7, 0);
    int lit = 0, blocked = 0;
    for (std::uint64_t i = 0; i < 2000; ++i) {
      const double u1 = rng.uniform(2 * i), u2 = rng.uniform(2 * i + 1);
      const double r = std::sqrt(1.0 - u1 * u1), phi = 2.0 * std::numbers::pi * u2;
      const vec3 w = r * std::cos(phi) * frame.t1 + r * std::sin(phi) * frame.t2 + u1 * setup.n;
      EXPECT_EQ(at(h, {u1, u2}), 2.0 * std::numbers::pi * u1 * incident_radiance(setup, w))
          << "u = (" << u1 << ", " << u2 << ")";
      lit += incident_radiance(setup, w) > 0.0;
      const bool v = visible(setup, setup.light.point(u1, u2));
      blocked += !v;
      EXPECT_EQ(at(a, {u1, u2}) == 0.0, !v) << "s, t = " << u1 << ", " << u2;
    }
    EXPECT_GT(lit, 0);
    EXPECT_EQ(blocked > 0, occluded);
  }
  EXPECT_TRUE(visible(default_irradiance_setup(false), {0.0, 0.0, 1.0}));
}

TEST(Irradiance, SmoothnessAndNames) {
  EXPECT_EQ(irradiance_area(default_irradiance_setup(false)).info().regularity,
            smoothness::analytic);
  EXPECT_EQ(irradiance_area(default_irradiance_setup(true)).info().regularity,
            smoothness::discontinuous);
  EXPECT_EQ(irradiance_hemisphere(default_irradiance_setup(false)).info().name,
            "irradiance_hemisphere");
  EXPECT_EQ(irradiance_area(default_irradiance_setup(false)).info().name, "irradiance_area");
}

std::string validation_message(const irradiance_setup& s) {
  return test_support::message_of([&] { validate(s); });
}

TEST(Irradiance, BadSetupsAreRejectedWithTheFieldNamed) {
  irradiance_setup s = default_irradiance_setup(true);
  EXPECT_EQ(validation_message(s), "no exception");

  irradiance_setup away = s;
  std::swap(away.light.edge_u, away.light.edge_v);  // normal now points up, away from x
  EXPECT_NE(validation_message(away).find("invalid light"), std::string::npos);
  EXPECT_NE(validation_message(away).find("facing x"), std::string::npos);

  irradiance_setup degenerate = s;
  degenerate.light.edge_v = {0.0, 0.0, 0.0};
  EXPECT_NE(validation_message(degenerate).find("non-degenerate"), std::string::npos);

  irradiance_setup skew = s;
  skew.light.edge_v = {1.0, 0.5, 0.0};
  EXPECT_NE(validation_message(skew).find("perpendicular"), std::string::npos);

  irradiance_setup dark = s;
  dark.radiance = 0.0;
  EXPECT_NE(validation_message(dark).find("invalid radiance = 0"), std::string::npos);
  dark.radiance = -1.0;
  EXPECT_NE(validation_message(dark).find("invalid radiance = -1"), std::string::npos);

  irradiance_setup bad_n = s;
  bad_n.n = {0.0, 0.0, 2.0};
  EXPECT_NE(validation_message(bad_n).find("invalid n"), std::string::npos);

  irradiance_setup horizon = s;
  horizon.n = {1.0, 0.0, 0.0};  // half the light is behind the tangent plane
  EXPECT_NE(validation_message(horizon).find("tangent plane"), std::string::npos);

  irradiance_setup above = s;
  above.occluder->corner.z = 1.5;  // beyond the light
  EXPECT_NE(validation_message(above).find("invalid occluder"), std::string::npos);
  EXPECT_NE(validation_message(above).find("strictly between"), std::string::npos);

  irradiance_setup below = s;
  below.occluder->corner.z = -0.5;  // behind x
  EXPECT_NE(validation_message(below).find("invalid occluder"), std::string::npos);

  EXPECT_THROW(irradiance_hemisphere{away}, invalid_argument);
  EXPECT_THROW(irradiance_area{dark}, invalid_argument);
}

TEST(Vec3Ops, AreConstexprAndCorrect) {
  constexpr vec3 a{1, 2, 3}, b{4, 5, 6};
  static_assert(dot(a, b) == 32.0);
  static_assert(cross(a, b) == vec3{-3, 6, -3});
  static_assert(a + b == vec3{5, 7, 9} && b - a == vec3{3, 3, 3} && 2.0 * a == a * 2.0);
  EXPECT_DOUBLE_EQ(length(normalize(b)), 1.0);
}

}  // namespace
}  // namespace quadmc
