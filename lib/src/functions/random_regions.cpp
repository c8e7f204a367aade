// The random-region families of random_regions.hpp: their draws, exact areas and references.
#include "quadmc/functions/random_regions.hpp"

#include "quadmc/core/normal_quantile.hpp"
#include "quadmc/core/rng.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace quadmc {

namespace {

// The stream of a family's draws for one instance seed: named after the family, so that two
// families drawn from one seed are independent (core/rng.hpp, name_id).
random_stream draws_of(std::string_view family, std::uint64_t seed) {
  return random_stream(seed, stream_id({name_id(family)}));
}

// G(u) = ∫₀ᵘ √(r² − t²) dt = (u√(r² − u²) + r²·asin(u/r))/2 for |u| ≤ r.
double half_chord_integral(double u, double r) noexcept {
  const double h = std::sqrt(std::max(0.0, r * r - u * u));
  return 0.5 * (u * h + r * r * std::asin(std::clamp(u / r, -1.0, 1.0)));
}

// The area of the disk of radius r centred at 0 in the quadrant {u ≤ a, v ≤ b}: over u, the
// chord's part below b is b + h(u) where h(u) = √(r² − u²) ≥ |b| (|u| ≤ c = √(r² − b²)), the
// whole chord 2h(u) beyond c when b ≥ 0, and nothing there when b < 0.
double quadrant_area(double a, double b, double r) noexcept {
  if (b <= -r || a <= -r) return 0.0;
  const double top = std::min(a, r);
  const double c = b >= r ? 0.0 : std::sqrt(r * r - b * b);
  double area = 0.0;
  // [−r, −c] and [c, r]: the whole chord (b ≥ 0) or none of it (b < 0).
  if (b >= 0.0) {
    const double left = std::min(top, -c);
    if (left > -r) area += 2.0 * (half_chord_integral(left, r) - half_chord_integral(-r, r));
    if (top > c) area += 2.0 * (half_chord_integral(top, r) - half_chord_integral(c, r));
  }
  // [−c, c]: b + h(u).
  const double right = std::min(top, c);
  if (right > -c) {
    area += b * (right + c) + half_chord_integral(right, r) - half_chord_integral(-c, r);
  }
  return area;
}

// erf(b) − erf(a) for a ≤ b without cancellation: through erfc where both are on one side.
double erf_difference(double a, double b) noexcept {
  if (a >= 0.0) return std::erfc(a) - std::erfc(b);
  if (b <= 0.0) return std::erfc(-b) - std::erfc(-a);
  return std::erf(b) - std::erf(a);
}

void require_unit_square_point(std::span<const double> p, std::string_view key) {
  require(p.size() == 2, key, p.size(), "2 coordinates (the family lives on [0,1]²)");
  for (const double v : p) {
    require(std::isfinite(v) && v >= 0.0 && v <= 1.0, key, v, "a point of [0,1]²");
  }
}

}  // namespace

heaviside_parameters heaviside_random_parameters(std::size_t s, std::uint64_t seed) {
  require(s >= 1 && s <= half_space_indicator::max_dimension, "dimension", s,
          "1 ≤ s ≤ 20 (the half-space volume sums 2^s terms)");
  const random_stream rng = draws_of("heaviside_random", seed);
  heaviside_parameters out{std::vector<double>(s), std::vector<double>(s)};
  // A uniform direction: s standard normals, normalised (the normal density is a function of the
  // norm alone). Each normal is the quantile of (k + ½)/2^52, k from 52 random bits: strictly
  // inside (0, 1), so finite.
  double norm = 0.0;
  for (std::size_t j = 0; j < s; ++j) {
    const auto k = static_cast<double>(rng.bits(j) >> 12);
    out.normal[j] = normal_quantile(std::ldexp(k + 0.5, -52));
    norm += out.normal[j] * out.normal[j];
  }
  norm = std::sqrt(norm);
  for (std::size_t j = 0; j < s; ++j) {
    out.normal[j] /= norm;
    out.point[j] = rng.uniform(s + j);
  }
  return out;
}

disk_parameters disk_random_parameters(std::uint64_t seed) {
  const random_stream rng = draws_of("disk_random", seed);
  return {{rng.uniform(0), rng.uniform(1)}, 0.1 + 0.3 * rng.uniform(2)};
}

gaussian_2d_parameters gaussian_random_parameters(std::uint64_t seed) {
  const random_stream rng = draws_of("gaussian_random", seed);
  // σ log-uniform in [0.05, 0.5): a factor 10 of widths, from a narrow bump to a gentle slope.
  const auto scale = [&](std::uint64_t i) { return 0.05 * std::pow(10.0, rng.uniform(i)); };
  return {
      {rng.uniform(0), rng.uniform(1)}, {scale(2), scale(3)}, std::numbers::pi * rng.uniform(4)};
}

half_space_indicator heaviside_random::through(const std::vector<double>& normal,
                                               const std::vector<double>& point) {
  require(point.size() == normal.size(), "point", point.size(),
          fmt::format("length s = {} (the length of normal)", normal.size()));
  // t = n·p: the plane through p. p inside the cube makes the plane cut it unless p is a vertex,
  // which half_space_indicator then refuses by name.
  double t = 0.0;
  for (std::size_t j = 0; j < point.size(); ++j) {
    require(std::isfinite(point[j]) && point[j] >= 0.0 && point[j] <= 1.0, "point", point[j],
            "a point of [0,1]^s");
    t += normal[j] * point[j];
  }
  return half_space_indicator(normal, t);
}

heaviside_random::heaviside_random(std::vector<double> normal, std::vector<double> point)
    : region_(through(normal, point)) {}

integrand_info heaviside_random::info() const {
  integrand_info info = region_.info();
  info.name = "heaviside_random";
  info.formula = "1 if n·(x − p) ≤ 0 else 0";
  info.reference = info.reference + " with w = n, t = n·p";
  return info;
}

double disk_random::square_area(double cx, double cy, double r) noexcept {
  return quadrant_area(1.0 - cx, 1.0 - cy, r) - quadrant_area(-cx, 1.0 - cy, r) -
         quadrant_area(1.0 - cx, -cy, r) + quadrant_area(-cx, -cy, r);
}

disk_random::disk_random(std::vector<double> center, double r) {
  require_unit_square_point(center, "center");
  require(std::isfinite(r) && r > 0.0 && r <= 1.0, "r", r, "a radius 0 < r ≤ 1");
  cx_ = center[0];
  cy_ = center[1];
  r_ = r;
  r2_ = r * r;
  area_ = square_area(cx_, cy_, r_);
}

integrand_info disk_random::info() const {
  integrand_info info{.name = "disk_random",
                      .formula = "1 if ‖x − c‖ ≤ r else 0 (the disk clipped to the square)",
                      .domain = box::unit(2),
                      .exact = area_,
                      .reference =
                          "closed form: four quadrant areas of the disk, each by "
                          "∫√(r² − u²) du",
                      .regularity = smoothness::discontinuous};
  info.derivative_bound[0] = 1.0;
  return info;
}

gaussian_random::gaussian_random(std::vector<double> mean, std::vector<double> scales, double angle)
    : scales_(std::move(scales)), angle_(angle) {
  require_unit_square_point(mean, "mean");
  require(scales_.size() == 2, "scales", scales_.size(), "2 widths σ₁, σ₂");
  for (const double sigma : scales_) {
    require(std::isfinite(sigma) && sigma >= 0.01 && sigma <= 10.0, "scales", sigma,
            "widths 0.01 ≤ σ ≤ 10");
  }
  require(std::isfinite(angle_), "angle", angle_, "a finite angle in radians");
  mx_ = mean[0];
  my_ = mean[1];
  // A = R diag(σ₁⁻², σ₂⁻²) Rᵀ with R the rotation by the angle.
  const double c = std::cos(angle_), s = std::sin(angle_);
  const double p1 = 1.0 / (scales_[0] * scales_[0]), p2 = 1.0 / (scales_[1] * scales_[1]);
  a11_ = c * c * p1 + s * s * p2;
  a12_ = c * s * (p1 - p2);
  a22_ = s * s * p1 + c * c * p2;
  // ∫₀¹ e^(−Q/2) dy with Q = a22(dy + a12·dx/a22)² + (det A/a22)·dx² in closed form:
  // e^(−det·dx²/(2·a22))·√(π/(2·a22))·[erf(k(1 − my + m)) − erf(k(−my + m))], k = √(a22/2),
  // m = a12·dx/a22; then over x by adaptive 61-point Gauss–Kronrod, whose error estimate is
  // kept: an analytic integrand, so it converges to rounding.
  const double det = a11_ * a22_ - a12_ * a12_;
  const double k = std::sqrt(0.5 * a22_);
  const double inner_scale = std::sqrt(std::numbers::pi / (2.0 * a22_));
  const auto inner = [&](double x) {
    const double dx = x - mx_;
    const double shift = a12_ * dx / a22_;
    return std::exp(-0.5 * det * dx * dx / a22_) * inner_scale *
           erf_difference(k * (-my_ + shift), k * (1.0 - my_ + shift));
  };
  // Tolerance 1e-14 relative: below it the halving never ends where rounding is all that is
  // left, and the error estimate grows with the 2^15 leaves' rounding instead of shrinking.
  integral_ = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(inner, 0.0, 1.0, 15,
                                                                            1e-14, &error_);
  require(error_ <= 1e-12 * integral_, "scales", fmt::format("[{}]", fmt::join(scales_, ", ")),
          fmt::format("a bump whose reference converges to 1e-12 relative (estimated error {:.3g} "
                      "of {:.17g})",
                      error_, integral_));
}

integrand_info gaussian_random::info() const {
  integrand_info info{
      .name = "gaussian_random",
      .formula = "exp(−½ (x − μ)ᵀ R diag(σ⁻²) Rᵀ (x − μ))",
      .domain = box::unit(2),
      .exact = integral_,
      .reference = fmt::format("inner integral by erf, outer by adaptive Gauss–Kronrod (61 "
                               "points), estimated error {:.2g}",
                               error_),
      .regularity = smoothness::analytic};
  info.derivative_bound[0] = 1.0;
  return info;
}

}  // namespace quadmc
