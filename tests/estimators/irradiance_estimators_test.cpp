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
// false-alarm probability ≈ 6e-5 per check, normal approximation of a mean of 200 runs).
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
// weighting a smaller one than uniform (their per-sample variances differ by large factors; the
// assertion compares the variance estimates of N = 10⁵ samples, each known to about 1%).
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
