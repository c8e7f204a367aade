// Tests for core/normal_quantile.hpp: the one Φ⁻¹(0.975) of the suite against Boost.Math and
// against Φ itself, and the quantile's argument checks.
#include "quadmc/core/normal_quantile.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/normal.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace {

using namespace quadmc;

using quadmc::test_support::eps;

static_assert(normal_quantile_975() > 1.95 && normal_quantile_975() < 1.97,
              "usable in constant expressions");

TEST(NormalQuantile, TheConstantIsBoostsQuantileBitForBit) {
  const double boost_z =
      boost::math::quantile(boost::math::normal_distribution<double>(0.0, 1.0), 0.975);
  EXPECT_EQ(normal_quantile_975(), boost_z);
  EXPECT_EQ(normal_quantile(0.975), normal_quantile_975());
  // The level the CLT interval computes for c = 0.95 rounds to the same double.
  EXPECT_EQ(normal_quantile(0.5 * (1.0 + 0.95)), normal_quantile_975());
}

TEST(NormalQuantile, InvertsThePhiOfTheCMathLibrary) {
  // Φ(z) = erfc(−z/√2)/2 from libm, independent of Boost. Φ′(z) = φ(z) ≈ 0.058 at z ≈ 1.96, so a
  // z off by one ulp (2.2e-16) moves Φ by 1.3e-17: 2ε on Φ allows z a few tens of ulp at most.
  const double z = normal_quantile_975();
  EXPECT_NEAR(0.5 * std::erfc(-z / std::numbers::sqrt2), 0.975, 2 * eps);
  // Elsewhere: allow z four ulp (Φ moves by φ(z)·4ε|z|) and erfc, the scaling by 1/√2 and the
  // halving 4ε relative.
  for (double p : {1e-10, 0.01, 0.3, 0.5, 0.8, 0.999}) {
    const double zp = normal_quantile(p);
    const double density = std::exp(-0.5 * zp * zp) / std::sqrt(2.0 * std::numbers::pi);
    const double tol = 4 * eps * p + density * 4 * eps * std::abs(zp);
    EXPECT_NEAR(0.5 * std::erfc(-zp / std::numbers::sqrt2), p, tol) << p;
  }
}

TEST(NormalQuantile, IsOddAboutOneHalf) {
  EXPECT_EQ(normal_quantile(0.5), 0.0);
  EXPECT_NEAR(normal_quantile(0.025), -normal_quantile_975(), 4 * eps);
}

TEST(NormalQuantile, RejectsLevelsOutsideTheOpenUnitInterval) {
  EXPECT_THROW(normal_quantile(0.0), invalid_argument);
  EXPECT_THROW(normal_quantile(1.0), invalid_argument);
  EXPECT_THROW(normal_quantile(std::numeric_limits<double>::quiet_NaN()), invalid_argument);
  try {
    normal_quantile(1.5);
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "invalid p = 1.5: expected 0 < p < 1");
  }
}

}  // namespace
