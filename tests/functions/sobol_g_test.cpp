// Sobol' g-function: ∫ = 1 exactly, checked by Gauss–Kronrod split at the kink x = 1/2.
#include "quadmc/functions/sobol_g.hpp"

#include "reference_quadrature.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace quadmc {
namespace {

using test::at;
using test::gauss_kronrod;

TEST(SobolG, IntegralIsOneByNestedGaussKronrod) {
  // 1D factors for several aᵢ, then the 2D and 3D functions nested (kink at 1/2 on each axis).
  for (double a : {0.0, 0.5, 4.5, 99.0}) {
    const sobol_g f({a});
    const double v = gauss_kronrod([&](double x) { return at(f, {x}); }, 0.0, 1.0, {0.5});
    EXPECT_NEAR(v, 1.0, 1e-14) << "a = " << a;
  }
  const sobol_g f2(sobol_g::default_a(2));
  const double v2 = gauss_kronrod(
      [&](double x) {
        return gauss_kronrod([&](double y) { return at(f2, {x, y}); }, 0.0, 1.0, {0.5});
      },
      0.0, 1.0, {0.5});
  const sobol_g f3({0.0, 1.0, 4.5});
  const double v3 = gauss_kronrod(
      [&](double x) {
        return gauss_kronrod(
            [&](double y) {
              return gauss_kronrod([&](double z) { return at(f3, {x, y, z}); }, 0.0, 1.0, {0.5});
            },
            0.0, 1.0, {0.5});
      },
      0.0, 1.0, {0.5});
  std::printf("sobol_g relative error vs independent integration: s = 2 %.2e, s = 3 %.2e\n",
              std::abs(v2 - 1.0), std::abs(v3 - 1.0));
  EXPECT_NEAR(v2, 1.0, 1e-13);
  EXPECT_NEAR(v3, 1.0, 1e-13);
  EXPECT_EQ(f3.info().exact, 1.0);
  EXPECT_EQ(f3.info().regularity, smoothness::c0);
}

TEST(SobolG, DefaultAAndBounds) {
  EXPECT_EQ(sobol_g::default_a(3), (std::vector<double>{0.0, 0.5, 1.0}));
  const sobol_g f({0.0, 1.0});
  // Peak at a corner: (2/1)·(3/2) = 3; steepest along x₁: 4·(3/2) = 6.
  EXPECT_EQ(*f.info().derivative_bound[0], 3.0);
  EXPECT_EQ(*f.info().derivative_bound[1], 6.0);
  EXPECT_EQ(at(f, {0.0, 0.0}), 3.0);
}

TEST(SobolG, BadParametersAreNamed) {
  try {
    sobol_g f({0.5, -1.0});
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("invalid a = -1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sobol_g({}), invalid_argument);
}

// With aᵢ = 0 the largest value is 2^s: at s = 1024 it is 2^1024 = inf at the corners (a
// trapezoid node), while the exact integral is 1. Refused, naming a.
TEST(SobolG, ALargestValueThatOverflowsIsRefused) {
  EXPECT_THROW(sobol_g(std::vector<double>(1024, 0.0)), invalid_argument);
  const sobol_g f(std::vector<double>(1023, 0.0));
  EXPECT_EQ(f.info().derivative_bound[0], std::ldexp(1.0, 1023));
}

}  // namespace
}  // namespace quadmc
