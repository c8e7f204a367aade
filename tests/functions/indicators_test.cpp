// Ball and half-space indicators: exact volumes against nested Gauss–Kronrod of the indicator's
// section lengths, split where the sections change formula.
#include "quadmc/functions/indicators.hpp"

#include "quadmc/functions/catalogue.hpp"

#include "jump_metadata.hpp"
#include "reference_quadrature.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cstdio>

namespace quadmc {
namespace {

using test::at;
using test::gauss_kronrod;
using test::relative_error;

TEST(Ball, AreaAndVolumeMatchNestedIntegration) {
  // 2D: ∫ over x of the measured chord {y : f(x, y) = 1}, integrated by GK split at the two
  // boundary points c₂ ± √(r² − (x − c₁)²) (so the inner integrand is smooth on each piece).
  const disk_indicator disk({0.5, 0.45}, 0.4);
  const double r = 0.4;
  const double area = boost::math::quadrature::tanh_sinh<double>().integrate(
      [&](double x) {
        const double h = std::sqrt(std::max(0.0, r * r - (x - 0.5) * (x - 0.5)));
        return gauss_kronrod(
            [&](double y) {
              return at(disk, {x, y});
            },
            0.0, 1.0, {0.45 - h, 0.45 + h});
      },
      0.5 - r, 0.5 + r);
  const double e2 = relative_error(area, disk.info().exact);
  // 3D: the volume as ∫∫_disk 2√(r² − ρ²), polar-free nested tanh–sinh (square-root endpoints).
  const disk_indicator ball({0.5, 0.5, 0.5}, 0.3);
  const double R = 0.3;
  boost::math::quadrature::tanh_sinh<double> ts;
  const double volume = ts.integrate(
      [&](double x) {
        const double hx = std::sqrt(std::max(0.0, R * R - x * x));
        return ts.integrate(
            [&](double y) { return 2.0 * std::sqrt(std::max(0.0, R * R - x * x - y * y)); }, -hx,
            hx);
      },
      -R, R);
  const double e3 = relative_error(volume, ball.info().exact);
  std::printf("ball relative error vs independent integration: s = 2 %.2e, s = 3 %.2e\n", e2, e3);
  EXPECT_LT(e2, 1e-10);
  EXPECT_LT(e3, 1e-10);
  // Recurrence V_s(r) = V_{s−2}(r)·2πr²/s, an identity independent of the Γ formula.
  for (std::size_t s = 3; s <= 12; ++s) {
    EXPECT_NEAR(disk_indicator::ball_volume(s, 0.4),
                disk_indicator::ball_volume(s - 2, 0.4) * 2 * std::numbers::pi * 0.16 / s,
                1e-14 * disk_indicator::ball_volume(s, 0.4));
  }
  EXPECT_DOUBLE_EQ(disk_indicator({0.5}, 0.25).info().exact, 0.5);
}

TEST(Ball, BadParametersAreNamed) {
  auto message = [](std::vector<double> c, double r) -> std::string {
    try {
      disk_indicator b(std::move(c), r);
    } catch (const invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_NE(message({0.5, 0.5}, -0.1).find("invalid r = -0.1"), std::string::npos);
  EXPECT_NE(message({0.5, 0.5}, 0.0).find("invalid r = 0"), std::string::npos);
  EXPECT_NE(message({0.5, 0.2}, 0.3).find("invalid center = 0.2"), std::string::npos);
  EXPECT_NE(message({0.5, 0.9}, 0.3).find("inside [0,1]^s"), std::string::npos);
  EXPECT_NE(message({}, 0.3).find("invalid center"), std::string::npos);
}

TEST(HalfSpace, VolumeMatchesNestedIntegration) {
  // 2D, w = (1, 1), t = 1.5: the square minus a corner triangle, 1 − 0.5² / 2 = 0.875.
  const half_space_indicator f2({1.0, 1.0}, 1.5);
  EXPECT_NEAR(f2.info().exact, 0.875, 1e-15);
  // 3D with unequal weights: ∫∫ of the x₃-section length clamp((t − w₁x − w₂y)/w₃, 0, 1), split
  // where the clamp switches (y) and where those switch points leave [0, 1] (x).
  const std::vector<double> w = {0.7, 1.3, 0.9};
  const double t = 1.6;
  const half_space_indicator f3(w, t);
  std::vector<double> xb;
  for (double c : {t, t - w[1], t - w[2], t - w[1] - w[2]}) xb.push_back(c / w[0]);
  const double numeric = gauss_kronrod(
      [&](double x) {
        const double y0 = (t - w[0] * x) / w[1], y1 = (t - w[0] * x - w[2]) / w[1];
        return gauss_kronrod(
            [&](double y) {
              // Inner x₃ integral: split at the jump x₃ = (t − w₁x − w₂y)/w₃.
              const double z = (t - w[0] * x - w[1] * y) / w[2];
              return gauss_kronrod([&](double x3) { return at(f3, {x, y, x3}); }, 0.0, 1.0, {z});
            },
            0.0, 1.0, {y0, y1});
      },
      0.0, 1.0, xb);
  const double err = relative_error(numeric, f3.info().exact);
  std::printf("half_space relative error vs independent integration: s = 3 %.2e\n", err);
  EXPECT_LT(err, 1e-10);
  // Simplex corner: t ≤ min w gives t^s/(s!·Π w).
  const half_space_indicator corner({1.0, 2.0, 4.0, 1.5}, 0.5);
  EXPECT_NEAR(corner.info().exact, std::pow(0.5, 4) / (24 * 12.0), 1e-15);
  // Symmetry: t = Σw/2 halves the cube for any s.
  for (std::size_t s = 1; s <= 16; ++s) {
    EXPECT_NEAR(half_space_indicator(std::vector<double>(s, 1.0), 0.5 * s).info().exact, 0.5, 1e-15)
        << "s = " << s;
  }
}

TEST(Indicators, OneDimensionalCasesCarryTheirJumpsHigherOnesNone) {
  // 1D ball: the interval [c − r, c + r], jumps of size 1 at both ends inside (0, 1).
  const disk_indicator interval({0.5}, 0.3);
  test::expect_factors_describe(interval, {0.0}, {1.0});
  ASSERT_EQ(interval.info().separable_factors.at(0).jumps.size(), 2u);
  // An end of the interval at an end of [0, 1]: f is 1 up to it, no jump there.
  const disk_indicator touching({0.25}, 0.25);
  test::expect_factors_describe(touching, {0.0}, {1.0});
  EXPECT_EQ(touching.info().separable_factors.at(0).jumps.size(), 1u);
  // 1D half-space 1{w·x ≤ t}: one jump at t/w.
  const half_space_indicator half({2.0}, 0.7);
  test::expect_factors_describe(half, {0.0}, {1.0});
  EXPECT_EQ(half.info().separable_factors.at(0).jumps.at(0).location, 0.35);
  // Curved and oblique boundaries in s ≥ 2 are not products of 1D factors: none claimed.
  EXPECT_TRUE(disk_indicator({0.5, 0.5}, 0.45).info().separable_factors.empty());
  EXPECT_TRUE(half_space_indicator({1.0, 1.0}, 1.2).info().separable_factors.empty());
}

TEST(HalfSpace, BadParametersAreNamed) {
  // Weights of any sign are fine (random_regions_test.cpp); a zero weight is not.
  try {
    half_space_indicator f({1.0, 0.0}, 0.5);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("invalid w = 0"), std::string::npos) << e.what();
  }
  try {
    half_space_indicator f({1.0, 1.0}, 2.0);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("invalid t = 2"), std::string::npos);
  }
  // The plane must cut the cube: t = Σw leaves nothing to cut.
  EXPECT_THROW(half_space_indicator(std::vector<double>(3, 1.0), 3.0), invalid_argument);
  // The worst cancellation at the largest s (t = Σw/2, all 2^20 terms alive) stays far inside
  // what 50 digits can carry: the accuracy rejection never fires for unit weights.
  EXPECT_LT(half_space_indicator(std::vector<double>(20, 1.0), 10.0).relative_error_bound(), 1e-25);
}

// w = (1e308, 1e308), t = 1.5e308 gave exact = 0 (s!·Π wᵢ = inf in double) and a run that fitted
// a "shallower" slope to a wrong reference. The region does not change when w and t are scaled
// together: the volume is that of w = (1, 1), t = 1.5, i.e. 1 − 0.5²/2 = 0.875.
TEST(HalfSpace, HugeWeightsGiveTheVolumeOfTheScaledProblem) {
  const half_space_indicator huge({1e308, 1e308}, 1.5e308);
  EXPECT_NEAR(huge.info().exact, 0.875, 1e-15);
  const half_space_indicator tiny({1e-300, 3e-300}, 2e-300);
  const half_space_indicator unit({1.0, 3.0}, 2.0);
  EXPECT_NEAR(tiny.info().exact, unit.info().exact, 1e-15);
  // The scaled comparison decides the same points as the unscaled one.
  EXPECT_EQ(at(huge, {0.7, 0.79}), 1.0);  // 1.49e308 ≤ 1.5e308
  EXPECT_EQ(at(huge, {0.7, 0.81}), 0.0);  // 1.51e308 (inf in double) > 1.5e308
  // The default t = 0.6·Σw is finite although Σw = 2e308 overflows.
  integrand_params p;
  p.dimension = 2;
  p.vectors["w"] = {1e308, 1e308};
  EXPECT_NEAR(make_integrand("half_space", p).info().exact, 1.0 - 0.8 * 0.8 / 2.0, 1e-15);
  // Weights further apart than double's range are refused, naming w.
  try {
    half_space_indicator f({1e300, 1e-300}, 1.0);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("invalid w = 1e-300"), std::string::npos) << e.what();
  }
}

// The volume of a ball of radius 1/2 is below 1e-308 from s ≈ 340 on (Γ(s/2 + 1) overflows too):
// such a reference was 0 and is now refused.
TEST(Ball, VolumesBelowTheNormalRangeAreRefused) {
  EXPECT_GT(disk_indicator(std::vector<double>(300, 0.5), 0.5).info().exact, 1e-300);
  try {
    disk_indicator f(std::vector<double>(400, 0.5), 0.5);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("invalid r = 0.5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace quadmc
