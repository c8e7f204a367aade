// Validation, Lambert's polygon formula and the occluder's clipped shadow for irradiance.hpp.
// Sources: Arvo, SIGGRAPH 1995 (vector irradiance, eq. 3); Sutherland & Hodgman, "Reentrant
// polygon clipping", CACM 17(1), 1974.
#include "quadmc/functions/irradiance.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace quadmc {
namespace {

std::string text(vec3 v) {
  return fmt::format("({:.17g}, {:.17g}, {:.17g})", v.x, v.y, v.z);
}

std::string text(const rectangle& r) {
  return fmt::format("{{corner {}, edge_u {}, edge_v {}}}", text(r.corner), text(r.edge_u),
                     text(r.edge_v));
}

bool finite(vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::array<vec3, 4> corners(const rectangle& r) {
  return {r.corner, r.corner + r.edge_u, r.corner + r.edge_u + r.edge_v, r.corner + r.edge_v};
}

// require() with the value's text formatted only when the check fails: validate() runs once per
// exact value, and an image asks for one per pixel (estimators/irradiance_image.hpp).
template <class Describe>
void check(bool ok, std::string_view parameter, Describe&& describe, std::string_view expected) {
  if (!ok) require(false, parameter, describe(), expected);
}

void validate_rectangle(const rectangle& r, std::string_view name) {
  check(
      finite(r.corner) && finite(r.edge_u) && finite(r.edge_v), name, [&] { return text(r); },
      "finite corner and edges");
  const double lu = length(r.edge_u);
  const double lv = length(r.edge_v);
  // A relative test: a rectangle's area is |u||v|; anything far below that is a sliver.
  check(
      lu > 0.0 && lv > 0.0 && r.area() > 1e-12 * lu * lv, name, [&] { return text(r); },
      "a non-degenerate rectangle (non-zero, non-parallel edges)");
  // The (s, t) parameters use the dual basis edge/|edge|², exact only for perpendicular edges.
  check(
      std::abs(dot(r.edge_u, r.edge_v)) <= 1e-9 * lu * lv, name, [&] { return text(r); },
      "perpendicular edges (|edge_u · edge_v| ≤ 1e-9·|edge_u|·|edge_v|)");
}

}  // namespace

void validate(const irradiance_setup& setup) {
  require(std::isfinite(setup.radiance) && setup.radiance > 0.0, "radiance", setup.radiance,
          "a finite radiance > 0");
  check(
      finite(setup.x), "x", [&] { return text(setup.x); }, "a finite point");
  check(
      finite(setup.n) && std::abs(length(setup.n) - 1.0) <= 1e-9, "n",
      [&] { return text(setup.n); }, "a unit normal (|‖n‖ − 1| ≤ 1e-9)");
  validate_rectangle(setup.light, "light");
  const vec3 normal = setup.light.normal();
  const double d_x = dot(normal, setup.x - setup.light.corner);
  check(
      d_x > 0.0, "light", [&] { return text(setup.light); },
      "a light facing x: normalize(edge_u × edge_v) · (x − corner) > 0");
  for (const vec3& c : corners(setup.light)) {
    // Lambert's formula integrates cosθ over the whole polygon; a light crossing the horizon of
    // x would need the polygon clipped at the tangent plane first.
    check(
        dot(setup.n, c - setup.x) > 0.0, "light", [&] { return text(setup.light); },
        "all four corners strictly above the tangent plane of x (n · (corner − x) > 0)");
  }
  if (setup.occluder) {
    validate_rectangle(*setup.occluder, "occluder");
    for (const vec3& c : corners(*setup.occluder)) {
      // Strictly between: the central projection from x then maps the occluder onto a convex
      // polygon of the light's plane (no vertex at or beyond the vanishing line).
      const double d = dot(normal, c - setup.light.corner);
      check(
          d > 0.0 && d < d_x, "occluder", [&] { return text(*setup.occluder); },
          "all four corners strictly between x and the light's plane");
    }
  }
}

double projected_solid_angle(vec3 x, vec3 n, std::span<const vec3> polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const vec3 a = polygon[i] - x;
    const vec3 b = polygon[(i + 1) % polygon.size()] - x;
    const vec3 c = cross(a, b);
    const double lc = length(c);
    if (lc == 0.0) continue;  // a repeated vertex (from clipping) adds a zero-length edge
    // θ by atan2(|a×b|, a·b): accurate for the tiny angles of short clipped edges, where
    // acos(â·b̂) loses half the digits.
    sum += std::atan2(lc, dot(a, b)) * dot(n, c) / lc;
  }
  return 0.5 * std::abs(sum);
}

std::vector<std::array<double, 2>> occluder_shadow_st(const irradiance_setup& setup) {
  std::vector<std::array<double, 2>> poly;
  if (!setup.occluder) return poly;
  const rectangle& light = setup.light;
  const vec3 normal = light.normal();
  const double d_x = dot(normal, setup.x - light.corner);
  const vec3 dual_u = light.edge_u / length_squared(light.edge_u);
  const vec3 dual_v = light.edge_v / length_squared(light.edge_v);
  for (const vec3& q : corners(*setup.occluder)) {
    const double d_q = dot(normal, q - light.corner);
    const vec3 p = setup.x + (q - setup.x) * (d_x / (d_x - d_q));  // central projection from x
    poly.push_back({dot(p - light.corner, dual_u), dot(p - light.corner, dual_v)});
  }
  // Sutherland–Hodgman against the four sides s ≥ 0, s ≤ 1, t ≥ 0, t ≤ 1 of the parameter square.
  for (int side = 0; side < 4 && !poly.empty(); ++side) {
    const int axis = side / 2;
    const double sign = side % 2 == 0 ? 1.0 : -1.0;
    const double bound = side % 2 == 0 ? 0.0 : 1.0;
    auto inside_by = [&](const std::array<double, 2>& p) { return sign * (p[axis] - bound); };
    std::vector<std::array<double, 2>> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const auto& a = poly[i];
      const auto& b = poly[(i + 1) % poly.size()];
      const double da = inside_by(a);
      const double db = inside_by(b);
      if (da >= 0.0) out.push_back(a);
      if ((da >= 0.0) != (db >= 0.0)) {
        const double k = da / (da - db);
        std::array<double, 2> c = {a[0] + k * (b[0] - a[0]), a[1] + k * (b[1] - a[1])};
        c[static_cast<std::size_t>(axis)] = bound;  // exactly on the side, not 1 ulp off
        out.push_back(c);
      }
    }
    poly = std::move(out);
  }
  if (poly.size() < 3) poly.clear();
  return poly;
}

std::vector<vec3> occluder_shadow(const irradiance_setup& setup) {
  std::vector<vec3> out;
  for (const auto& st : occluder_shadow_st(setup)) out.push_back(setup.light.point(st[0], st[1]));
  return out;
}

double irradiance_exact(const irradiance_setup& setup) {
  validate(setup);
  const auto light = corners(setup.light);
  double e = projected_solid_angle(setup.x, setup.n, light);
  const auto shadow = occluder_shadow(setup);
  if (!shadow.empty()) e -= projected_solid_angle(setup.x, setup.n, shadow);
  return setup.radiance * e;
}

double incident_radiance(const irradiance_setup& setup, vec3 w) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  bool lit = detail::rectangle_frame(setup.light).hit(setup.x, w, inf);
  if (setup.occluder) lit &= !detail::rectangle_frame(*setup.occluder).hit(setup.x, w, inf);
  return lit ? setup.radiance : 0.0;
}

bool visible(const irradiance_setup& setup, vec3 p_on_light) {
  if (!setup.occluder) return true;
  return !detail::rectangle_frame(*setup.occluder).hit(setup.x, p_on_light - setup.x, 1.0);
}

irradiance_setup default_irradiance_setup(bool with_occluder) {
  irradiance_setup s{
      .x = {0.0, 0.0, 0.0},
      .n = {0.0, 0.0, 1.0},
      // edge_u × edge_v = (0.2, 0, −1): faces down towards x, tilted by atan(0.2).
      .light = {.corner = {-0.3, -0.5, 1.0}, .edge_u = {0.0, 1.0, 0.0}, .edge_v = {1.0, 0.0, 0.2}},
      .radiance = 1.0,
      .occluder = std::nullopt,
  };
  if (with_occluder) {
    s.occluder = rectangle{
        .corner = {-0.25, -0.35, 0.5}, .edge_u = {0.0, 0.3, 0.0}, .edge_v = {0.25, 0.0, 0.0}};
  }
  return s;
}

irradiance_hemisphere::irradiance_hemisphere(irradiance_setup setup)
    : setup_(std::move(setup)), frame_(setup_.n), exact_(irradiance_exact(setup_)) {  // validates
  light_ = detail::rectangle_frame(setup_.light);
  if (setup_.occluder) occluder_ = detail::rectangle_frame(*setup_.occluder);
}

integrand_info irradiance_hemisphere::info() const {
  integrand_info info{
      .name = "irradiance_hemisphere",
      .formula = "2π·u₁·L_i(x, ω), ω = (√(1−u₁²)cos 2πu₂, √(1−u₁²)sin 2πu₂, u₁) in the frame of n",
      .domain = box::unit(2),
      .exact = exact_,
      .reference = setup_.occluder
                       ? "Lambert's polygon formula minus the Sutherland–Hodgman-clipped shadow"
                       : "Lambert's polygon formula",
      .regularity = smoothness::discontinuous,
  };
  info.derivative_bound[0] = 2.0 * std::numbers::pi * setup_.radiance;  // sup of 2π·z·L
  return info;
}

irradiance_area::irradiance_area(irradiance_setup setup)
    : setup_(std::move(setup)),
      light_normal_(setup_.light.normal()),
      scale_(setup_.radiance * setup_.light.area()),
      exact_(irradiance_exact(setup_)) {  // validates
  if (setup_.occluder) occluder_ = detail::rectangle_frame(*setup_.occluder);
}

integrand_info irradiance_area::info() const {
  return integrand_info{
      .name = "irradiance_area",
      .formula = "L·A·V(x, x')·cosθ·cosθ'/|x − x'|², x' = corner + s·edge_u + t·edge_v",
      .domain = box::unit(2),
      .exact = exact_,
      .reference = setup_.occluder
                       ? "Lambert's polygon formula minus the Sutherland–Hodgman-clipped shadow"
                       : "Lambert's polygon formula",
      .regularity = setup_.occluder ? smoothness::discontinuous : smoothness::analytic,
  };
}

}  // namespace quadmc
