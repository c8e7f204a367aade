// Tests for theoretical_rate.hpp against the rows of docs/theory.md#rate-table.
#include "quadmc/analysis/theoretical_rate.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

namespace quadmc {
namespace {

constexpr double tight = 1e-15;

TEST(TheoreticalRate, TensorNewtonCotesOnSmoothF) {
  // docs/theory.md#tensor-products: n per axis, N = nˢ: O(N^(−r/s)), r = 1, 2, 4.
  EXPECT_NEAR(*theoretical_slope("midpoint", "smooth", 1).slope, -2.0, tight);
  EXPECT_NEAR(*theoretical_slope("trapezoid", "analytic", 3).slope, -2.0 / 3.0, tight);
  EXPECT_NEAR(*theoretical_slope("simpson", "smooth", 2).slope, -2.0, tight);
  EXPECT_NEAR(*theoretical_slope("left_rectangle", "smooth", 1).slope, -1.0, tight);
  EXPECT_NEAR(*theoretical_slope("right_rectangle", "analytic", 4).slope, -0.25, tight);
  EXPECT_NEAR(*theoretical_slope("unjittered", "smooth", 2).slope, -1.0, tight)
      << "a cell-centre grid is the midpoint rule";
}

TEST(TheoreticalRate, RoughIntegrandsCapTheOrder) {
  // C⁰ kink: midpoint/trapezoid stay O(n⁻²), Simpson drops to O(n⁻²); jump: O(n⁻¹);
  // √x: O(n^−1.5) for midpoint, trapezoid, Simpson (docs/theory.md#kinks, docs/theory.md#jumps,
  // docs/theory.md#endpoint-singularities).
  EXPECT_NEAR(*theoretical_slope("simpson", "C0", 1).slope, -2.0, tight);
  EXPECT_NEAR(*theoretical_slope("simpson", "C0", 2).slope, -1.0, tight);
  EXPECT_NEAR(*theoretical_slope("midpoint", "C0", 1).slope, -2.0, tight);
  EXPECT_NEAR(*theoretical_slope("simpson", "discontinuous", 2).slope, -0.5, tight);
  EXPECT_NEAR(*theoretical_slope("trapezoid", "discontinuous", 1).slope, -1.0, tight);
  EXPECT_NEAR(*theoretical_slope("simpson", "singular", 1).slope, -1.5, tight);
  EXPECT_NEAR(*theoretical_slope("romberg", "C0", 1).slope, -2.0, tight);
}

TEST(TheoreticalRate, MonteCarloFamily) {
  EXPECT_NEAR(*theoretical_slope("plain_mc", "discontinuous", 7).slope, -0.5, tight);
  EXPECT_NEAR(*theoretical_slope("latin_hypercube", "smooth", 5).slope, -0.5, tight);
  EXPECT_NEAR(*theoretical_slope("importance", "analytic", 1).slope, -0.5, tight);
  // Jittered: smooth −1/2 − 1/s, indicator −1/2 − 1/(2s) (docs/theory.md#jittered).
  EXPECT_NEAR(*theoretical_slope("jittered", "smooth", 2).slope, -1.0, tight);
  EXPECT_NEAR(*theoretical_slope("jittered", "smooth", 1).slope, -1.5, tight);
  EXPECT_NEAR(*theoretical_slope("jittered", "discontinuous", 2).slope, -0.75, tight);
  EXPECT_NEAR(*theoretical_slope("padded_jittered", "smooth", 2).slope, -1.0, tight);
  EXPECT_NEAR(*theoretical_slope("padded_jittered", "smooth", 6).slope, -0.5, tight);
}

TEST(TheoreticalRate, ExponentialRulesHaveNoFiniteSlope) {
  for (const char* method : {"gauss_legendre", "romberg"}) {
    const theoretical_rate rate = theoretical_slope(method, "analytic", 1);
    EXPECT_FALSE(rate.slope.has_value()) << method;
    EXPECT_NE(rate.note.find("exponential"), std::string::npos) << method << ": " << rate.note;
  }
}

TEST(TheoreticalRate, EveryEntryHasANoteAndKnownMethodsHaveASource) {
  for (std::string_view method : tabulated_methods()) {
    for (std::string_view cls : smoothness_classes()) {
      for (std::size_t s : {1u, 2u, 5u}) {
        const theoretical_rate rate = theoretical_slope(method, cls, s);
        EXPECT_FALSE(rate.note.empty()) << method << " / " << cls << " / s = " << s;
        EXPECT_FALSE(rate.source.empty()) << method << " / " << cls << " / s = " << s;
        if (rate.slope) {
          EXPECT_LT(*rate.slope, 0.0) << method << " / " << cls;
        }
      }
    }
  }
}

TEST(TheoreticalRate, UnknownMethodHasNoEntryUnknownClassThrows) {
  const theoretical_rate rate = theoretical_slope("sobol_owen", "smooth", 2);
  EXPECT_FALSE(rate.slope.has_value());
  EXPECT_NE(rate.note.find("sobol_owen"), std::string::npos);
  EXPECT_THROW(theoretical_slope("midpoint", "c0", 1), invalid_argument) << "case matters: C0";
  EXPECT_THROW(theoretical_slope("midpoint", "smooth", 0), invalid_argument);
}

}  // namespace
}  // namespace quadmc

TEST(TheoreticalRate, CompositeGaussLegendreWithKnownOrder) {
  // m = 3 nodes per panel: order 2m = 6 on smooth f, N = (3n)^s (docs/theory.md#gauss-legendre).
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("gauss_legendre", "analytic", 1, 6).slope.value(),
                   -6.0);
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("gauss_legendre", "smooth", 2, 6).slope.value(), -3.0);
  // A jump or a kink caps it like any composite rule.
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("gauss_legendre", "discontinuous", 1, 6).slope.value(),
                   -1.0);
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("gauss_legendre", "C0", 1, 6).slope.value(), -2.0);
}

TEST(TheoreticalRate, IrradianceEstimatorsAreMonteCarlo) {
  for (const char* m :
       {"irradiance_hemisphere_uniform", "irradiance_hemisphere_cosine", "irradiance_light_area"}) {
    EXPECT_DOUBLE_EQ(quadmc::theoretical_slope(m, "discontinuous", 2).slope.value(), -0.5) << m;
  }
}

TEST(TheoreticalRate, EndpointSingularityExponentSetsTheRuleRate) {
  // f ~ x^α: composite rules converge as n^−min(r, 1+α) (docs/theory.md#endpoint-singularities).
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("simpson", "singular", 1, 0, 0.5).slope.value(),
                   -1.5);  // √x
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("midpoint", "singular", 1, 0, -0.5).slope.value(),
                   -0.5);  // 1/√x
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("trapezoid", "singular", 1, 0, 0.0).slope.value(),
                   -1.0);  // log x
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("left_rectangle", "singular", 1, 0, 0.5).slope.value(),
                   -1.0);
  // Monte Carlo: finite variance for √x and log x, none for 1/√x (∫x^−1 diverges).
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("plain_mc", "singular", 1, 0, 0.0).slope.value(),
                   -0.5);
  EXPECT_FALSE(quadmc::theoretical_slope("plain_mc", "singular", 1, 0, -0.5).slope.has_value());
}

TEST(TheoreticalRate, LatinHypercubeInOneDimensionIsJittered) {
  // One point per stratum in 1D: Stein's residual e = f − additive part is 0
  // (docs/theory.md#latin-hypercube).
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("latin_hypercube", "analytic", 1).slope.value(), -1.5);
  EXPECT_DOUBLE_EQ(quadmc::theoretical_slope("latin_hypercube", "analytic", 2).slope.value(), -0.5);
}
