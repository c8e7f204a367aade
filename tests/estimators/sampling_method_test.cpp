#include "quadmc/estimators/sampling_method.hpp"

#include "quadmc/core/simd_level.hpp"
#include "quadmc/estimators/confidence_interval.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "test_integrands.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

namespace {

using namespace quadmc;

const any_integrand gaussian(test_support::make_integrand(
    "e^-(x²+y²) on [0,1]²", box::unit(2), 0.25 * std::numbers::pi * std::pow(std::erf(1.0), 2),
    [](std::span<const double> x) { return std::exp(-(x[0] * x[0] + x[1] * x[1])); }));

bool bitwise_equal(const estimate& a, const estimate& b) {
  return std::memcmp(&a, &b, sizeof(estimate)) == 0 ||
         (std::memcmp(&a.value, &b.value, sizeof(double)) == 0 &&
          (std::memcmp(&a.std_error, &b.std_error, sizeof(double)) == 0 ||
           (std::isnan(a.std_error) && std::isnan(b.std_error))) &&
          a.evaluations == b.evaluations);
}

constexpr point_set_kind all_kinds[] = {point_set_kind::independent, point_set_kind::jittered,
                                        point_set_kind::unjittered, point_set_kind::padded_jittered,
                                        point_set_kind::latin_hypercube};

// N = 40 000 = 200² (4 chunks) is valid for every point set: 1, 2, 3 and 8 threads agree bitwise.
// At every SIMD level of this CPU (the level changes the last bits of exp/cos, never the
// dependence on the thread count).
TEST(SamplingMethod, EveryMethodIsBitwiseIdenticalForAnyThreadCount) {
  const simd_level saved = active_simd_level();
  for (simd_level level : available_simd_levels()) {
    set_simd_level(level);
    // A scalar integrand and a catalogue one that uses vector exp (functions/genz.hpp).
    integrand_params p;
    p.dimension = 2;
    const any_integrand genz = make_integrand("genz_gaussian", p);
    for (const any_integrand* f : {&gaussian, &genz}) {
      for (point_set_kind kind : all_kinds) {
        const estimate one = run_monte_carlo(kind, *f, 42, 7, 40000, 1);
        EXPECT_NEAR(one.value, f->info().exact,
                    6 * (std::isnan(one.std_error) ? 1e-3 : one.std_error))
            << to_string(kind) << ", " << f->info().name;
        for (unsigned t : {2u, 3u, 8u}) {
          EXPECT_TRUE(bitwise_equal(one, run_monte_carlo(kind, *f, 42, 7, 40000, t)))
              << to_string(kind) << ", " << f->info().name << ", " << t << " threads, level "
              << to_string(level);
        }
      }
    }
  }
  set_simd_level(saved);
  const irradiance_setup setup = default_irradiance_setup(true);
  for (auto technique : {irradiance_sampling::uniform_hemisphere,
                         irradiance_sampling::cosine_hemisphere, irradiance_sampling::light_area}) {
    const estimate one = run_irradiance(technique, point_set_kind::jittered, setup, 1, 2, 40000, 1);
    for (unsigned t : {2u, 3u, 8u}) {
      EXPECT_TRUE(bitwise_equal(
          one, run_irradiance(technique, point_set_kind::jittered, setup, 1, 2, 40000, t)));
    }
  }
}

TEST(SamplingMethod, NamesRoundTripAndUnknownNamesAreListed) {
  for (point_set_kind kind : all_kinds) EXPECT_EQ(parse_point_set_kind(to_string(kind)), kind);
  EXPECT_EQ(parse_point_set_kind("plain"), point_set_kind::independent);
  try {
    parse_point_set_kind("sobol");
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("invalid point set = sobol: expected one of"),
              std::string::npos)
        << e.what();
  }
}

TEST(SamplingMethod, AcceptsSizeFollowsTheStratificationPolicy) {
  EXPECT_TRUE(accepts_size(point_set_kind::jittered, 2, 400));
  EXPECT_FALSE(accepts_size(point_set_kind::jittered, 2, 401));
  EXPECT_FALSE(accepts_size(point_set_kind::unjittered, 3, 100));
  EXPECT_TRUE(accepts_size(point_set_kind::latin_hypercube, 3, 101));
  EXPECT_FALSE(accepts_size(point_set_kind::independent, 0, 10));
  EXPECT_FALSE(accepts_size(point_set_kind::independent, 2, 0));
  EXPECT_THROW(run_monte_carlo(point_set_kind::jittered, gaussian, 1, 1, 401, 1), invalid_argument);
  EXPECT_THROW(run_monte_carlo(point_set_kind::independent, gaussian, 1, 1, 0, 1),
               invalid_argument);
}

// e^x on [1, 2] with the truncated exponential warp of rate 1 carried to [1, 2]: p ∝ f, so the
// estimate is exact to rounding (∫₁² eˣ dx = e² − e).
TEST(SamplingMethod, ImportanceByNameMapsTheWarpToTheInterval) {
  const any_integrand f(
      test_support::make_integrand("e^x on [1,2]", box{{1.0}, {2.0}}, std::exp(2.0) - std::exp(1.0),
                                   [](std::span<const double> x) { return std::exp(x[0]); }));
  const estimate e = run_importance(point_set_kind::latin_hypercube, f,
                                    unit_warp_kind::truncated_exponential, 1.0, 3, 4, 1000, 2);
  EXPECT_NEAR(e.value, f.info().exact, 16 * std::numeric_limits<double>::epsilon() * e.value);
  const estimate p =
      run_importance(point_set_kind::independent, f, unit_warp_kind::power, 1.0, 3, 4, 100000, 2);
  EXPECT_NEAR(p.value, f.info().exact, 5 * p.std_error);
  EXPECT_THROW(run_importance(point_set_kind::independent, gaussian, unit_warp_kind::power, 1.0, 1,
                              1, 10, 1),
               invalid_argument);
}

}  // namespace
