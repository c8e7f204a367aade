// Tests of random_regions.hpp: every exact area or reference against an independent computation
// on 24 instances drawn as a scene draws them (the square clipped by the plane, as a polygon, in
// s = 2; that polygon's area integrated over the third axis in s = 3; the disk's chord length
// and the Gaussian itself integrated by adaptive quadrature), the draws' ranges, and the
// half-space's weights of any sign.
#include "quadmc/functions/random_regions.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/functions/catalogue.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace {

using namespace quadmc;

constexpr int instances = 24;

std::uint64_t instance_seed(int k) {
  return stream_id({20261205, static_cast<std::uint64_t>(k)});
}

// The area of {x ∈ [0,1]²: a·x ≤ t}: the square clipped by the half-plane (Sutherland–Hodgman:
// keep the vertices inside, add the crossings of each edge), then the shoelace formula.
double clipped_square_area(double a1, double a2, double t) {
  const std::array<std::array<double, 2>, 4> square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  std::vector<std::array<double, 2>> polygon;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& p = square[i];
    const auto& q = square[(i + 1) % 4];
    const double fp = a1 * p[0] + a2 * p[1] - t;
    const double fq = a1 * q[0] + a2 * q[1] - t;
    if (fp <= 0) polygon.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      const double lambda = fp / (fp - fq);
      polygon.push_back({p[0] + lambda * (q[0] - p[0]), p[1] + lambda * (q[1] - p[1])});
    }
  }
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto& p = polygon[i];
    const auto& q = polygon[(i + 1) % polygon.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * std::abs(twice);
}

TEST(RandomRegions, HeavisideVolumesAgreeWithTheClippedSquare) {
  for (int k = 0; k < instances; ++k) {
    const heaviside_parameters d = heaviside_random_parameters(2, instance_seed(k));
    const double t = d.normal[0] * d.point[0] + d.normal[1] * d.point[1];
    const heaviside_random f(d.normal, d.point);
    EXPECT_NEAR(f.info().exact, clipped_square_area(d.normal[0], d.normal[1], t), 1e-14)
        << "instance " << k;
  }
}

// In s = 3 the slice at x₃ = z is the square clipped by a₁x₁ + a₂x₂ ≤ t − a₃z, a piecewise
// quadratic function of z whose kinks are where the line passes a vertex of the square: a
// 61-point Gauss–Kronrod rule between the kinks integrates it exactly up to rounding.
TEST(RandomRegions, HeavisideVolumesInThreeDimensionsAgreeWithTheSlicesIntegrated) {
  for (int k = 0; k < instances; ++k) {
    const heaviside_parameters d = heaviside_random_parameters(3, instance_seed(k));
    const auto& n = d.normal;
    const double t = n[0] * d.point[0] + n[1] * d.point[1] + n[2] * d.point[2];
    std::vector<double> cuts{0.0, 1.0};
    for (const double v1 : {0.0, 1.0}) {
      for (const double v2 : {0.0, 1.0}) {
        const double z = (t - n[0] * v1 - n[1] * v2) / n[2];
        if (z > 0.0 && z < 1.0) cuts.push_back(z);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    double volume = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      volume += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
          [&](double z) { return clipped_square_area(n[0], n[1], t - n[2] * z); }, cuts[i],
          cuts[i + 1], 0);
    }
    const heaviside_random f(d.normal, d.point);
    EXPECT_NEAR(f.info().exact, volume, 1e-13) << "instance " << k;
  }
}

// The length of {y ∈ [0,1]: (x − cx)² + (y − cy)² ≤ r²}, integrated over x between the points
// where it is not smooth (the disk's ends, where a chord end crosses y = 0 or 1, the square's
// sides), in the angle θ of x = cx − r·cos θ: the chord's half-length r·sin θ and dx = r·sin θ dθ
// are analytic in θ, so adaptive Gauss–Kronrod converges to rounding on every piece.
double disk_area_by_chords(double cx, double cy, double r) {
  const auto chord = [&](double x) {
    const double h = std::sqrt(std::max(0.0, r * r - (x - cx) * (x - cx)));
    return std::max(0.0, std::min(1.0, cy + h) - std::max(0.0, cy - h));
  };
  const double lo = std::max(0.0, cx - r), hi = std::min(1.0, cx + r);
  std::vector<double> cuts{lo, hi};
  for (const double edge : {cy, 1.0 - cy}) {
    if (edge < r) {
      const double w = std::sqrt(r * r - edge * edge);
      cuts.insert(cuts.end(), {cx - w, cx + w});
    }
  }
  std::erase_if(cuts, [&](double c) { return c < lo || c > hi; });
  std::sort(cuts.begin(), cuts.end());
  const auto angle = [&](double x) { return std::acos(std::clamp((cx - x) / r, -1.0, 1.0)); };
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] <= cuts[i]) continue;
    area += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        [&](double theta) { return chord(cx - r * std::cos(theta)) * r * std::sin(theta); },
        angle(cuts[i]), angle(cuts[i + 1]), 15, 1e-14);
  }
  return area;
}

TEST(RandomRegions, DiskAreasAgreeWithTheChordsIntegrated) {
  int clipped = 0;
  for (int k = 0; k < instances; ++k) {
    const disk_parameters d = disk_random_parameters(instance_seed(k));
    const disk_random f(d.center, d.r);
    EXPECT_NEAR(f.info().exact, disk_area_by_chords(d.center[0], d.center[1], d.r), 1e-13)
        << "instance " << k << ": c = (" << d.center[0] << ", " << d.center[1] << "), r = " << d.r;
    const bool inside = d.center[0] >= d.r && d.center[0] <= 1 - d.r && d.center[1] >= d.r &&
                        d.center[1] <= 1 - d.r;
    clipped += inside ? 0 : 1;
  }
  EXPECT_GE(clipped, 12) << "most draws must test the clipping";
  // Closed cases: a disk inside (πr²), a quarter disk at a corner, half a disk on a side.
  EXPECT_NEAR(disk_random::square_area(0.5, 0.5, 0.3), std::numbers::pi * 0.09, 1e-15);
  EXPECT_NEAR(disk_random::square_area(0.0, 0.0, 0.5), std::numbers::pi / 16, 1e-15);
  EXPECT_NEAR(disk_random::square_area(0.5, 1.0, 0.25), std::numbers::pi / 32, 1e-15);
  EXPECT_NEAR(disk_random::square_area(0.5, 0.5, 1.0), 1.0, 1e-15) << "the disk covers it";
}

// The Gaussian's reference (erf inside, Gauss–Kronrod outside) against the bump itself
// integrated by nested adaptive Gauss–Kronrod (no erf): both converge to rounding on an analytic
// integrand, so they agree to the outer rules' tolerances.
TEST(RandomRegions, GaussianReferencesAgreeWithTheBumpIntegratedTwice) {
  for (int k = 0; k < instances; ++k) {
    const gaussian_2d_parameters d = gaussian_random_parameters(instance_seed(k));
    const gaussian_random f(d.mean, d.scales, d.angle);
    const auto value = [&](double x, double y) {
      const std::array<double, 2> point{x, y};
      std::array<double, 1> out{};
      f.evaluate(point, out);
      return out[0];
    };
    using rule = boost::math::quadrature::gauss_kronrod<double, 61>;
    const double twice = rule::integrate(
        [&](double x) {
          return rule::integrate([&](double y) { return value(x, y); }, 0.0, 1.0, 15, 1e-14);
        },
        0.0, 1.0, 15, 1e-14);
    EXPECT_NEAR(f.info().exact / twice, 1.0, 1e-11) << "instance " << k;
    EXPECT_LE(f.reference_error(), 1e-12 * f.info().exact);
  }
}

// The draws: a unit normal and a point of the cube; another seed, another instance; the scene's
// families take them when the keys are omitted and the keys when they are given.
TEST(RandomRegions, DrawsAreInRangeAndFollowTheSeed) {
  for (int k = 0; k < instances; ++k) {
    const heaviside_parameters h = heaviside_random_parameters(5, instance_seed(k));
    double norm = 0.0;
    for (std::size_t j = 0; j < 5; ++j) {
      norm += h.normal[j] * h.normal[j];
      EXPECT_GE(h.point[j], 0.0);
      EXPECT_LT(h.point[j], 1.0);
    }
    EXPECT_NEAR(norm, 1.0, 1e-15);
    const disk_parameters d = disk_random_parameters(instance_seed(k));
    EXPECT_GE(d.r, 0.1);
    EXPECT_LT(d.r, 0.4);
    const gaussian_2d_parameters g = gaussian_random_parameters(instance_seed(k));
    for (const double sigma : g.scales) {
      EXPECT_GE(sigma, 0.05);
      EXPECT_LT(sigma, 0.5);
    }
  }
  integrand_params p;
  p.dimension = 2;
  p.seed = 1;
  const double first = make_integrand("disk_random", p).info().exact;
  p.seed = 2;
  EXPECT_NE(make_integrand("disk_random", p).info().exact, first);
  p.scalars["r"] = 0.2;
  p.vectors["center"] = {0.5, 0.5};
  EXPECT_NEAR(make_integrand("disk_random", p).info().exact, std::numbers::pi * 0.04, 1e-15);
}

// Weights of any sign: {−2x ≤ −1} = [½, 1]; {x₁ − x₂ ≤ 0} is half the square; a plane that
// misses the cube is refused with the range it must lie in.
TEST(RandomRegions, HalfSpaceTakesWeightsOfAnySign) {
  EXPECT_NEAR(half_space_indicator({-2.0}, -1.0).info().exact, 0.5, 1e-15);
  EXPECT_NEAR(half_space_indicator({1.0, -1.0}, 0.0).info().exact, 0.5, 1e-15);
  EXPECT_NEAR(half_space_indicator({-1.0, -1.0}, -1.5).info().exact, 0.125, 1e-15);
  EXPECT_THROW(half_space_indicator({1.0, -1.0}, 1.0), invalid_argument);
  EXPECT_THROW(half_space_indicator({1.0, 0.0}, 0.5), invalid_argument);
}

}  // namespace
