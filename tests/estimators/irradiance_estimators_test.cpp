#include "quadmc/estimators/irradiance_estimators.hpp"

#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

namespace {

using namespace quadmc;

// Each technique, with and without occluder, with independent and jittered points: the mean of
// R = 200 runs lies within 4 standard errors of Lambert's exact irradiance (irradiance_exact;
// false-alarm probability 8.9e-5 per check: Student's t with 199 degrees of freedom, the runs
// being means of 256 samples and close to normal).
template <class Estimator>
void expect_unbiased(Estimator estimator, const std::string& name) {
  for (bool occluded : {false, true}) {
    const irradiance_setup setup = default_irradiance_setup(occluded);
    const double exact = irradiance_exact(setup);
    welford plain, jittered;
    for (int r = 0; r < 200; ++r) {
      plain.add(estimator(setup, independent_points(2, 256, 1, r)).value);
      jittered.add(estimator(setup, jittered_points(2, 256, 2, r)).value);
    }
    EXPECT_NEAR(plain.mean(), exact, 4 * plain.std_error())
        << name << ", occluder " << occluded << ", independent points";
    EXPECT_NEAR(jittered.mean(), exact, 4 * jittered.std_error())
        << name << ", occluder " << occluded << ", jittered points";
    std::cout << "[ measured ] " << name << (occluded ? " (occluded)" : "")
              << ": per-run SD independent " << std::sqrt(plain.variance()) << ", jittered "
              << std::sqrt(jittered.variance()) << " (N = 256, E = " << exact << ")\n";
  }
}

TEST(IrradianceEstimators, UniformHemisphereIsUnbiased) {
  expect_unbiased([](const auto& s, const auto& p) { return irradiance_uniform_hemisphere(s, p); },
                  "uniform hemisphere");
}
TEST(IrradianceEstimators, CosineHemisphereIsUnbiased) {
  expect_unbiased([](const auto& s, const auto& p) { return irradiance_cosine_hemisphere(s, p); },
                  "cosine hemisphere");
}
TEST(IrradianceEstimators, LightAreaIsUnbiased) {
  expect_unbiased([](const auto& s, const auto& p) { return irradiance_light_area(s, p); },
                  "light area");
}

// For a small light, area sampling has a smaller variance than hemisphere sampling, and cosine
// weighting a smaller one than uniform. The per-sample variances differ by factors ≈ 2 (uniform
// against cosine) and ≈ 50 (cosine against area); each sample variance of N = 10⁵ values has a
// relative SD √((κ + 2)/N), κ the excess kurtosis of Y, ≈ 1/p for a Y that is non-zero with
// probability p (the light's share of the directions, p ≈ 0.1 for the hemisphere techniques):
// about 1%. The closer pair is then ~50 SDs of ln(ratio) apart: no false alarm in practice.
TEST(IrradianceEstimators, AreaSamplingBeatsHemisphereSamplingForThisLight) {
  const irradiance_setup setup = default_irradiance_setup(false);
  const auto u = irradiance_uniform_hemisphere(setup, independent_points(2, 100000, 3, 3));
  const auto c = irradiance_cosine_hemisphere(setup, independent_points(2, 100000, 4, 4));
  const auto a = irradiance_light_area(setup, independent_points(2, 100000, 5, 5));
  std::cout << "[ measured ] per-sample variance: uniform " << u.variance << ", cosine "
            << c.variance << ", light area " << a.variance << "\n";
  EXPECT_LT(a.variance, c.variance);
  EXPECT_LT(c.variance, u.variance);
}

TEST(IrradianceEstimators, RejectsAPointSetThatIsNotTwoDimensional) {
  EXPECT_THROW(
      irradiance_light_area(default_irradiance_setup(false), independent_points(3, 4, 1, 1)),
      invalid_argument);
}

}  // namespace
