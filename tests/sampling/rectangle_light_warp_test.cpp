#include "quadmc/sampling/rectangle_light_warp.hpp"

#include "histogram_chi_square.hpp"
#include "quadmc/sampling/independent_points.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <vector>

namespace {

using namespace quadmc;

// Faces down (normal = edge_u × edge_v ∝ (0, 0.2, −1)), towards points below it.
const rectangle light{{-0.5, 0.2, 1.0}, {0.0, 1.0, 0.2}, {1.0, 0.0, 0.0}};
using test_support::warp_alpha;
using test_support::warp_samples;

using gk = boost::math::quadrature::gauss_kronrod<double, 21>;

// ∫_light p dA = ∫∫ p·|edge_u × edge_v| ds dt = 1.
TEST(RectangleLightWarp, PdfIntegratesToOneOverTheLight) {
  const rectangle_light_warp w(light);
  const double jacobian = length(cross(light.edge_u, light.edge_v));
  const double total = gk::integrate(
      [&](double s) {
        return gk::integrate(
            [&](double t) {
              const vec3 p = light.point(s, t);
              const double x[3] = {p.x, p.y, p.z};
              return w.pdf(std::span<const double>(x, 3)) * jacobian;
            },
            0.0, 1.0);
      },
      0.0, 1.0);
  EXPECT_NEAR(total, 1.0, 1e-13);
}

// The solid-angle density integrates to 1 over the solid angle the light subtends:
// ∫ p_ω dω = ∫ p_ω cosθ'/r² dA.
TEST(RectangleLightWarp, SolidAnglePdfIntegratesToOne) {
  const rectangle_light_warp w(light);
  const vec3 from{0.1, 0.0, 0.0};
  const double jacobian = w.area();
  const vec3 nl = light.normal();
  const double total = gk::integrate(
      [&](double s) {
        return gk::integrate(
            [&](double t) {
              const vec3 p = light.point(s, t);
              const vec3 d = p - from;
              const double r2 = dot(d, d);
              const double cos_light = -dot(nl, d) / std::sqrt(r2);
              return w.solid_angle_pdf(from, p) * cos_light / r2 * jacobian;
            },
            0.0, 1.0);
      },
      0.0, 1.0);
  EXPECT_NEAR(total, 1.0, 1e-12);
}

// Histogram in the light's (s, t) parameters recovered with the dual basis (edges ⊥).
TEST(RectangleLightWarp, SamplesAreUniformOnTheLight) {
  const rectangle_light_warp w(light);
  std::vector<double> u(2 * warp_samples);
  independent_points(2, warp_samples, 4, 4).generate(0, u);
  constexpr std::size_t ns = 20, nt = 20;
  std::vector<double> counts(ns * nt, 0.0);
  const double jacobian = w.area();
  for (std::uint64_t i = 0; i < warp_samples; ++i) {
    double x[3];
    w.sample(std::span<const double>(&u[2 * i], 2), x);
    const vec3 q = vec3{x[0], x[1], x[2]} - light.corner;
    const double s = dot(q, light.edge_u) / length_squared(light.edge_u);
    const double t = dot(q, light.edge_v) / length_squared(light.edge_v);
    ASSERT_GE(s, -1e-15);
    ASSERT_LE(t, 1 + 1e-15);
    counts[std::min<std::size_t>(ns - 1, std::size_t(s * ns)) * nt +
           std::min<std::size_t>(nt - 1, std::size_t(t * nt))] += 1.0;
  }
  const auto r = test_support::chi_square_test(
      counts, ns, nt, 0.0, 1.0, 0.0, 1.0,
      [&](double s, double t) {
        const vec3 p = light.point(s, t);
        const double x[3] = {p.x, p.y, p.z};
        return w.pdf(std::span<const double>(x, 3)) * jacobian;
      },
      warp_samples, warp_alpha);
  EXPECT_TRUE(r.passes()) << "χ² = " << r.statistic << " > " << r.critical;
}

TEST(RectangleLightWarp, RejectsADegenerateLight) {
  EXPECT_THROW(rectangle_light_warp(rectangle{{0, 0, 1}, {1, 0, 0}, {0, 0, 0}}), invalid_argument);
}

}  // namespace
