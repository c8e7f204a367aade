// Every method's theory (its descriptor's choice of rate, methods/method.hpp) against the rows of
// docs/theory.md#rate-table: the table the suite's "theory" column comes from.
#include "quadmc/core/errors.hpp"
#include "quadmc/methods/registry.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

namespace quadmc {
namespace {

constexpr double tight = 1e-15;
using test_support::nan;

// Options a method needs to exist at all (importance has no default warp, the external methods
// no default file; a file is read only by a run).
option_table required_options(std::string_view method) {
  if (method == "importance") return {{"warp", "power"}};
  if (method == "external_points" || method == "external_rule") return {{"path", "{N}_{r}.csv"}};
  return {};
}

theoretical_rate theory_of(std::string_view method, smoothness cls, std::size_t s, double alpha,
                           option_table options) {
  if (options.empty()) options = required_options(method);
  return make_method(method, options)->theory(integrand_class{cls, s, alpha});
}

TEST(TheoreticalRate, TensorNewtonCotesOnSmoothF) {
  // docs/theory.md#tensor-products: n per axis, N = nˢ: O(N^(−r/s)), r = 1, 2, 4.
  EXPECT_NEAR(*theory_of("midpoint", smoothness::smooth, 1, nan, {}).slope, -2.0, tight);
  EXPECT_NEAR(*theory_of("trapezoid", smoothness::analytic, 3, nan, {}).slope, -2.0 / 3.0, tight);
  EXPECT_NEAR(*theory_of("simpson", smoothness::smooth, 2, nan, {}).slope, -2.0, tight);
  EXPECT_NEAR(*theory_of("left_rectangle", smoothness::smooth, 1, nan, {}).slope, -1.0, tight);
  EXPECT_NEAR(*theory_of("right_rectangle", smoothness::analytic, 4, nan, {}).slope, -0.25, tight);
  EXPECT_NEAR(*theory_of("unjittered", smoothness::smooth, 2, nan, {}).slope, -1.0, tight)
      << "a cell-centre grid is the midpoint rule";
}

TEST(TheoreticalRate, RoughIntegrandsCapTheOrder) {
  // C⁰ kink: midpoint/trapezoid stay O(n⁻²), Simpson drops to O(n⁻²); jump: O(n⁻¹);
  // √x: O(n^−1.5) for midpoint, trapezoid, Simpson (docs/theory.md#kinks, docs/theory.md#jumps,
  // docs/theory.md#endpoint-singularities).
  EXPECT_NEAR(*theory_of("simpson", smoothness::c0, 1, nan, {}).slope, -2.0, tight);
  EXPECT_NEAR(*theory_of("simpson", smoothness::c0, 2, nan, {}).slope, -1.0, tight);
  EXPECT_NEAR(*theory_of("midpoint", smoothness::c0, 1, nan, {}).slope, -2.0, tight);
  EXPECT_NEAR(*theory_of("simpson", smoothness::discontinuous, 2, nan, {}).slope, -0.5, tight);
  EXPECT_NEAR(*theory_of("trapezoid", smoothness::discontinuous, 1, nan, {}).slope, -1.0, tight);
  EXPECT_NEAR(*theory_of("simpson", smoothness::singular, 1, nan, {}).slope, -1.5, tight);
  EXPECT_NEAR(*theory_of("romberg", smoothness::c0, 1, nan, {}).slope, -2.0, tight);
}

TEST(TheoreticalRate, MonteCarloFamily) {
  EXPECT_NEAR(*theory_of("plain_mc", smoothness::discontinuous, 7, nan, {}).slope, -0.5, tight);
  EXPECT_NEAR(*theory_of("latin_hypercube", smoothness::smooth, 5, nan, {}).slope, -0.5, tight);
  EXPECT_NEAR(*theory_of("importance", smoothness::analytic, 1, nan, {}).slope, -0.5, tight);
  // Jittered: smooth −1/2 − 1/s, indicator −1/2 − 1/(2s) (docs/theory.md#jittered).
  EXPECT_NEAR(*theory_of("jittered", smoothness::smooth, 2, nan, {}).slope, -1.0, tight);
  EXPECT_NEAR(*theory_of("jittered", smoothness::smooth, 1, nan, {}).slope, -1.5, tight);
  EXPECT_NEAR(*theory_of("jittered", smoothness::discontinuous, 2, nan, {}).slope, -0.75, tight);
  EXPECT_NEAR(*theory_of("padded_jittered", smoothness::smooth, 2, nan, {}).slope, -1.0, tight);
  EXPECT_NEAR(*theory_of("padded_jittered", smoothness::smooth, 6, nan, {}).slope, -0.5, tight);
}

TEST(TheoreticalRate, RombergHasNoFiniteSlopeOnAnalyticF) {
  // Extrapolation converges exponentially on analytic f (docs/theory.md#exponential-convergence);
  // composite Gauss–Legendre always has its m, hence the algebraic order 2m (below).
  const theoretical_rate rate = theory_of("romberg", smoothness::analytic, 1, nan, {});
  EXPECT_FALSE(rate.slope.has_value());
  EXPECT_NE(rate.note.find("exponential"), std::string::npos) << rate.note;
  EXPECT_FALSE(theory_of("romberg", smoothness::smooth, 1, nan, {}).slope.has_value());
}

TEST(TheoreticalRate, EveryEntryHasANoteAndASource) {
  for (const method_descriptor* d : method_registry()) {
    const std::string_view method = d->name;
    for (smoothness cls : {smoothness::analytic, smoothness::smooth, smoothness::c0,
                           smoothness::discontinuous, smoothness::singular}) {
      for (std::size_t s : {1u, 2u, 5u}) {
        const theoretical_rate rate = theory_of(method, cls, s, nan, {});
        EXPECT_FALSE(rate.note.empty()) << method << " / " << to_string(cls) << " / s = " << s;
        EXPECT_FALSE(rate.source.empty()) << method << " / " << to_string(cls) << " / s = " << s;
        if (rate.slope) {
          EXPECT_LT(*rate.slope, 0.0) << method << " / " << to_string(cls);
        }
      }
    }
  }
}

TEST(TheoreticalRate, UnknownMethodIsAnErrorAndSZeroThrows) {
  EXPECT_THROW(make_method("sobol_owen"), invalid_argument);
  EXPECT_THROW(theory_of("midpoint", smoothness::smooth, 0, nan, {}), invalid_argument);
}

TEST(TheoreticalRate, CompositeGaussLegendreWithKnownOrder) {
  // m = 3 nodes per panel: order 2m = 6 on smooth f, N = (3n)^s (docs/theory.md#gauss-legendre).
  EXPECT_DOUBLE_EQ(
      theory_of("gauss_legendre", smoothness::analytic, 1, nan, {{"m", 3}}).slope.value(), -6.0);
  EXPECT_DOUBLE_EQ(
      theory_of("gauss_legendre", smoothness::smooth, 2, nan, {{"m", 3}}).slope.value(), -3.0);
  // A jump or a kink caps it like any composite rule.
  EXPECT_DOUBLE_EQ(
      theory_of("gauss_legendre", smoothness::discontinuous, 1, nan, {{"m", 3}}).slope.value(),
      -1.0);
  EXPECT_DOUBLE_EQ(theory_of("gauss_legendre", smoothness::c0, 1, nan, {{"m", 3}}).slope.value(),
                   -2.0);
}

TEST(TheoreticalRate, IrradianceEstimatorsAreMonteCarlo) {
  for (const char* m :
       {"irradiance_hemisphere_uniform", "irradiance_hemisphere_cosine", "irradiance_light_area"}) {
    EXPECT_DOUBLE_EQ(theory_of(m, smoothness::discontinuous, 2, nan, {}).slope.value(), -0.5) << m;
  }
}

TEST(TheoreticalRate, EndpointSingularityExponentSetsTheRuleRate) {
  // f ~ x^α: composite rules converge as n^−min(r, 1+α) (docs/theory.md#endpoint-singularities).
  EXPECT_DOUBLE_EQ(theory_of("simpson", smoothness::singular, 1, 0.5, {}).slope.value(),
                   -1.5);  // √x
  EXPECT_DOUBLE_EQ(theory_of("midpoint", smoothness::singular, 1, -0.5, {}).slope.value(),
                   -0.5);  // 1/√x
  EXPECT_DOUBLE_EQ(theory_of("trapezoid", smoothness::singular, 1, 0.0, {}).slope.value(),
                   -1.0);  // log x
  EXPECT_DOUBLE_EQ(theory_of("left_rectangle", smoothness::singular, 1, 0.5, {}).slope.value(),
                   -1.0);
  // Monte Carlo: finite variance for √x and log x, none for 1/√x (∫x^−1 diverges).
  EXPECT_DOUBLE_EQ(theory_of("plain_mc", smoothness::singular, 1, 0.0, {}).slope.value(), -0.5);
  EXPECT_FALSE(theory_of("plain_mc", smoothness::singular, 1, -0.5, {}).slope.has_value());
}

TEST(TheoreticalRate, LatinHypercubeInOneDimensionIsJittered) {
  // One point per stratum in 1D: Stein's residual e = f − additive part is 0
  // (docs/theory.md#latin-hypercube).
  EXPECT_DOUBLE_EQ(theory_of("latin_hypercube", smoothness::analytic, 1, nan, {}).slope.value(),
                   -1.5);
  EXPECT_DOUBLE_EQ(theory_of("latin_hypercube", smoothness::analytic, 2, nan, {}).slope.value(),
                   -0.5);
}

}  // namespace
}  // namespace quadmc
