// Tests for theoretical_rate.hpp's building blocks against the rows of docs/theory.md#rate-table
// (which method uses which block is tested per method in tests/methods/theory_test.cpp).
#include "quadmc/analysis/theoretical_rate.hpp"

#include "quadmc/core/errors.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <string>

namespace quadmc {
namespace {

using test_support::nan;

integrand_class of(smoothness cls, std::size_t s, double alpha = nan) {
  return integrand_class{cls, s, alpha};
}

TEST(CompositeRuleRate, OrderOverSOnSmoothFAndCapsOnRoughF) {
  // Tensor product, N = nˢ: O(N^(−r/s)) (docs/theory.md#tensor-products).
  EXPECT_EQ(*composite_rule_rate(4, of(smoothness::smooth, 2)).slope, -2.0);
  EXPECT_EQ(*composite_rule_rate(2, of(smoothness::analytic, 4)).slope, -0.5);
  // A kink caps at 2, a jump at 1 (docs/theory.md#kinks, #jumps); a rule of order 1 keeps 1.
  EXPECT_EQ(*composite_rule_rate(4, of(smoothness::c0, 1)).slope, -2.0);
  EXPECT_EQ(*composite_rule_rate(1, of(smoothness::c0, 1)).slope, -1.0);
  EXPECT_EQ(*composite_rule_rate(6, of(smoothness::discontinuous, 2)).slope, -0.5);
  // f ~ x^α: n^−min(r, 1 + α); √x assumed when α is not given, except the rectangles' O(h) for f
  // of bounded variation (docs/theory.md#endpoint-singularities).
  EXPECT_EQ(*composite_rule_rate(4, of(smoothness::singular, 1, -0.5)).slope, -0.5);
  EXPECT_EQ(*composite_rule_rate(2, of(smoothness::singular, 1, 3.0)).slope, -2.0);
  EXPECT_EQ(*composite_rule_rate(4, of(smoothness::singular, 1)).slope, -1.5);
  EXPECT_EQ(*composite_rule_rate(1, of(smoothness::singular, 1)).slope, -1.0);
  EXPECT_THROW(composite_rule_rate(0, of(smoothness::smooth, 1)), invalid_argument);
  EXPECT_THROW(composite_rule_rate(2, of(smoothness::smooth, 0)), invalid_argument);
}

TEST(ExtrapolatedTrapezoidRate, NoSlopeOnSmoothFTrapezoidRateOtherwise) {
  EXPECT_FALSE(extrapolated_trapezoid_rate(of(smoothness::analytic, 1)).slope);
  EXPECT_FALSE(extrapolated_trapezoid_rate(of(smoothness::smooth, 1)).slope);
  EXPECT_EQ(*extrapolated_trapezoid_rate(of(smoothness::c0, 1)).slope, -2.0);
  EXPECT_EQ(*extrapolated_trapezoid_rate(of(smoothness::discontinuous, 1)).slope, -1.0);
}

TEST(SparseGridRate, MixedSmoothnessBoundOnC0AndNoSlopeElsewhere) {
  // docs/theory.md#sparse-grid-rates: −1 for bounded mixed first derivatives whatever s;
  // analytic, smooth, jumps and singularities have none.
  for (const std::size_t s : {1u, 4u, 16u}) {
    const theoretical_rate c0 = sparse_grid_rate({smoothness::c0, s});
    ASSERT_TRUE(c0.slope.has_value());
    EXPECT_EQ(*c0.slope, -1.0);
    for (const smoothness other : {smoothness::analytic, smoothness::smooth,
                                   smoothness::discontinuous, smoothness::singular}) {
      const theoretical_rate r = sparse_grid_rate({other, s});
      EXPECT_FALSE(r.slope.has_value()) << to_string(other);
      EXPECT_NE(r.source.find("docs/theory.md#sparse-grid-rates"), std::string::npos);
    }
  }
  EXPECT_NE(sparse_grid_rate({smoothness::analytic, 8}).note.find("equal N"), std::string::npos);
  EXPECT_THROW(sparse_grid_rate({smoothness::c0, 0}), invalid_argument);
}

TEST(MonteCarloRates, RootNUnlessTheVarianceIsInfinite) {
  // ∫x^(2α) diverges for α ≤ −1/2 (docs/theory.md#infinite-variance): exactly at the boundary.
  EXPECT_FALSE(infinite_variance_rate(of(smoothness::singular, 1, -0.4)));
  EXPECT_TRUE(infinite_variance_rate(of(smoothness::singular, 1, -0.5)));
  EXPECT_FALSE(infinite_variance_rate(of(smoothness::discontinuous, 1, -0.9)))
      << "α describes a singular f only";
  const theoretical_rate plain = root_n_rate(of(smoothness::c0, 7), "note", "source");
  EXPECT_EQ(*plain.slope, -0.5);
  EXPECT_EQ(plain.note, "note");
  EXPECT_EQ(plain.source, "source");
  EXPECT_FALSE(root_n_rate(of(smoothness::singular, 1, -1.0), "n", "s").slope);
  EXPECT_FALSE(plain.adaptive);
  // An adaptive method's rate is the same −1/2, marked adaptive; with infinite variance it has
  // no slope, and nothing to adapt towards.
  const theoretical_rate adaptive = adaptive_monte_carlo_rate(of(smoothness::c0, 7), "n", "s");
  EXPECT_EQ(*adaptive.slope, -0.5);
  EXPECT_TRUE(adaptive.adaptive);
  EXPECT_FALSE(adaptive_monte_carlo_rate(of(smoothness::singular, 1, -1.0), "n", "s").adaptive);
}

// A scrambled net on a jump: He & Wang's −1/2 − 1/(4s − 2) for a curved or oblique boundary;
// jumps on coordinate planes only (a product of piecewise-smooth factors, bounded Hardy–Krause
// variation) give Koksma–Hlawka's N^−1 up to (log N)^(s−1) (docs/theory.md#scrambled-nets).
TEST(ScrambledNetRate, JumpsOnCoordinatePlanesHaveBoundedVariation) {
  const theoretical_rate curved = scrambled_net_rate(of(smoothness::discontinuous, 2));
  EXPECT_NEAR(*curved.slope, -0.5 - 1.0 / 6.0, 1e-15);
  EXPECT_EQ(curved.log_power, 0.0);
  integrand_class planes = of(smoothness::discontinuous, 4);
  planes.separable_jumps = true;
  const theoretical_rate separable = scrambled_net_rate(planes);
  EXPECT_EQ(*separable.slope, -1.0);
  EXPECT_EQ(separable.log_power, 3.0);
  EXPECT_NE(separable.source.find("[Niederreiter 1992]"), std::string::npos);
  // In s = 1 every jump is "on a coordinate plane", and the 1D net is jittered: He & Wang's
  // formula gives that −1 itself, with no log factor.
  integrand_class one_d = of(smoothness::discontinuous, 1);
  one_d.separable_jumps = true;
  EXPECT_EQ(*scrambled_net_rate(one_d).slope, -1.0);
  EXPECT_EQ(scrambled_net_rate(one_d).log_power, 0.0);
}

TEST(OnePointPerStratumRate, JitteredRates) {
  // −1/2 − 1/s for Lipschitz f, −1/2 − 1/(2s) for an indicator (docs/theory.md#jittered).
  EXPECT_EQ(*one_point_per_stratum_rate(of(smoothness::smooth, 2)).slope, -1.0);
  EXPECT_EQ(*one_point_per_stratum_rate(of(smoothness::c0, 1)).slope, -1.5);
  EXPECT_EQ(*one_point_per_stratum_rate(of(smoothness::discontinuous, 2)).slope, -0.75);
  EXPECT_FALSE(one_point_per_stratum_rate(of(smoothness::singular, 1)).slope);
}

TEST(ShiftedLatticeRate, PeriodizationOrderSetsTheSlope) {
  // none and the baker's map as before (docs/theory.md#lattice-rules): −1, and −2 on smooth f.
  const lattice_periodizing none{};
  const lattice_periodizing baker{"baker", 0, false};
  const theoretical_rate plain = shifted_lattice_rate(of(smoothness::smooth, 2), none);
  EXPECT_EQ(*plain.slope, -1.0);
  EXPECT_EQ(plain.note, "randomly shifted lattice, f not periodic: N^(-1+e)");
  const theoretical_rate tent = shifted_lattice_rate(of(smoothness::analytic, 2), baker);
  EXPECT_EQ(*tent.slope, -2.0);
  EXPECT_EQ(tent.note, "shifted lattice + baker's transform: N^(-2+e)");
  EXPECT_EQ(*shifted_lattice_rate(of(smoothness::c0, 2), baker).slope, -1.0);
  EXPECT_FALSE(shifted_lattice_rate(of(smoothness::singular, 1, -0.75), baker).slope)
      << "infinite variance";
  // A weighted periodization periodic through order k = m − 1: −(m + 1) on smooth f
  // (docs/theory.md#lattice-periodizations), −1 on kinks, none on jumps or singular f.
  for (int k = 0; k <= 3; ++k) {
    const lattice_periodizing weighted{"c", k, true};
    const theoretical_rate r = shifted_lattice_rate(of(smoothness::smooth, 3), weighted);
    EXPECT_EQ(*r.slope, -(k + 2.0)) << k;
    EXPECT_NE(r.source.find("#lattice-periodizations"), std::string::npos) << r.source;
    EXPECT_EQ(*shifted_lattice_rate(of(smoothness::c0, 3), weighted).slope, -1.0) << k;
    EXPECT_FALSE(shifted_lattice_rate(of(smoothness::discontinuous, 2), weighted).slope) << k;
    const theoretical_rate singular =
        shifted_lattice_rate(of(smoothness::singular, 1, -0.75), weighted);
    EXPECT_FALSE(singular.slope) << k;
    EXPECT_EQ(singular.note.find("infinite variance"), std::string::npos)
        << "g = f(φ)φ' need not share f's infinite variance: " << singular.note;
  }
}

}  // namespace
}  // namespace quadmc
