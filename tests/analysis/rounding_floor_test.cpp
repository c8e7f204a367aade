// Tests for rounding_floor.hpp: synthetic floors are flagged, clean ladders are not.
#include "quadmc/analysis/rounding_floor.hpp"

#include "quadmc/analysis/power_law_fit.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace quadmc {
namespace {

using quadmc::test_support::eps;

std::vector<double> doubling_ladder(int first, int last) {
  std::vector<double> n;
  for (int k = first; k <= last; ++k) n.push_back(std::ldexp(1.0, k));
  return n;
}

TEST(RoundingFloor, FlagsAFlatNoisyFloorAndRecoversTheSlopeBeforeIt) {
  // A midpoint-like ladder 0.1·N⁻² reaching a flat floor of rounding noise 3e-16·(1 + ½ sin k)
  // (|I| = 1): the curve crosses the floor near N = 2^23.
  const std::vector<double> n = doubling_ladder(1, 30);
  std::vector<double> error;
  for (std::size_t k = 0; k < n.size(); ++k) {
    error.push_back(0.1 / (n[k] * n[k]) + 3e-16 * (1.0 + 0.5 * std::sin(static_cast<double>(k))));
  }
  const rounding_floor floor = detect_rounding_floor(n, error, 1.0);
  ASSERT_TRUE(floor.reached());
  for (std::size_t k = 0; k < n.size(); ++k) {
    const double method_error = 0.1 / (n[k] * n[k]);
    // Points whose method error is below half the smallest noise value are pure floor.
    if (method_error < 0.5 * 1.5e-16) {
      EXPECT_TRUE(floor.flags[k]) << "k = " << k;
    }
    // Points a thousand times above the noise are the method's own.
    if (method_error > 1e3 * 4.5e-16) {
      EXPECT_FALSE(floor.flags[k]) << "k = " << k;
    }
  }
  // Every point from the first floor point on is flagged.
  for (std::size_t k = *floor.first; k < n.size(); ++k) EXPECT_TRUE(floor.flags[k]) << k;
  EXPECT_EQ(floor.count(), n.size() - *floor.first);
  EXPECT_GT(floor.attainable_accuracy, 0.0);
  EXPECT_LT(floor.attainable_accuracy, 1e-13);
  EXPECT_GE(floor.floor_level, 1.5e-16);
  EXPECT_LE(floor.floor_level, 1e-14);

  // With the floor excluded the fit sees the clean rate: on the last unflagged point (error
  // ≥ ℓ ≈ 1e-14) the noise (≤ 4.5e-16) is a few per cent, so −2 within 0.05.
  std::vector<double> fit_n, fit_e;
  for (std::size_t k = 0; k < n.size(); ++k) {
    if (!floor.flags[k]) {
      fit_n.push_back(n[k]);
      fit_e.push_back(error[k]);
    }
  }
  const double clean_slope = fit_power_law(fit_n, fit_e).slope;
  EXPECT_NEAR(clean_slope, -2.0, 0.05);
  EXPECT_GT(fit_power_law(n, error).slope, clean_slope + 0.1)
      << "without the exclusion the floor flattens the fit";
}

TEST(RoundingFloor, FlagsARisingFloorOfNaiveSummation) {
  // N⁻² until naive summation's ε·√N·… rounding takes over and grows: error = N⁻² + ε·N/100.
  const std::vector<double> n = doubling_ladder(2, 30);
  std::vector<double> error;
  for (double nk : n) error.push_back(1.0 / (nk * nk) + eps * nk / 100.0);
  const rounding_floor floor = detect_rounding_floor(n, error, 1.0);
  ASSERT_TRUE(floor.reached());
  // The minimum of N⁻² + εN/100 is near N = (200/ε)^(1/3) ≈ 2^20; the rise from there on
  // must be flagged, the steep part (N ≤ 2^14, error ≥ 3.7e-9) must not.
  for (std::size_t k = 0; k < n.size(); ++k) {
    if (n[k] >= std::ldexp(1.0, 21)) {
      EXPECT_TRUE(floor.flags[k]) << "N = " << n[k];
    }
    if (n[k] <= std::ldexp(1.0, 14)) {
      EXPECT_FALSE(floor.flags[k]) << "N = " << n[k];
    }
  }
}

// Method error 0.05·N⁻² plus rounding noise ε·√N·|Z| (a random-walk rounding error), j = log₂N
// = 1…30, Z_j independent standard normals by Box–Muller from a Philox stream. The two terms
// cross near j = 19 ((0.05/ε)^0.4 = 2^19.0). Where can the floor start?
//  - Not before 2^18: for j ≤ 17, e_j ≥ 0.05·4^−j is far above ℓ (no (i)) and above B·ℓ for
//    j ≤ 14 (no stall); at j = 15…17 a stall needs e_{j+1} > e_j/2, i.e. noise
//    ε·2^{(j+1)/2}|Z| > 0.05·4^−j/4: |Z| > 6.4 at j = 17, > 36 at 16, > 200 at 15.
//    P(first < 2^18) ≤ 1.6e-10 per ladder.
//  - Not long after the crossover: no floor point up to j = K means no stall there, so from j₀ = 19
//    there is a chain j₀ < j₁ < … (steps 1 or 2, past K) along which the error at least halves at
//    each step, hence ε·2^{j_i/2}|Z_{j_i}| ≤ 2^−i·e_19. Given Z_19 these are independent, with
//    P(|Z| ≤ t) ≤ t·√(2/π); summing over all chains and integrating over Z_19 bounds
//    P(first > 2^K) by 0.061 for K = 22 and 2.3e-8 for K = 28 (leaving the band B·ℓ needs
//    |Z| > 23 for j ≥ 19: negligible). A simulation of 10⁶ ladders gives 0.008 and 0 (none after
//    2^24): the bound is conservative.
// Over M = 200 ladders (seed 99, streams 0…199): every floor starts in [2^18, 2^28] (false alarm
// ≤ 200·(1.6e-10 + 2.3e-8) = 4.7e-6), and at most 27 start after 2^22 (P(Binomial(200, 0.061)
// > 27) = 4.2e-5): total ≤ 5e-5. What it detects: a rule whose floor starts two doublings later
// than this one (23% of ladders after 2^22, by the simulation) fails with probability ≥ 0.999;
// one that fires before the crossover (a κ or band too large, a stall test that ignores the
// improvement) fails the 2^18 bound.
TEST(RoundingFloor, FlagsARandomFloorGrowingLikeSqrtN) {
  constexpr std::uint64_t ladders = 200;
  const std::vector<double> n = doubling_ladder(1, 30);
  std::size_t late = 0;
  for (std::uint64_t m = 0; m < ladders; ++m) {
    const random_stream stream(99, m);
    std::vector<double> error;
    for (std::size_t k = 0; k < n.size(); ++k) {
      const double u1 = 1.0 - stream.uniform(2 * k), u2 = stream.uniform(2 * k + 1);
      const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
      error.push_back(0.05 / (n[k] * n[k]) + eps * std::sqrt(n[k]) * std::abs(z));
    }
    const rounding_floor floor = detect_rounding_floor(n, error, 1.0);
    ASSERT_TRUE(floor.reached()) << "stream " << m;
    const double first_n = n[*floor.first];
    EXPECT_GE(first_n, std::ldexp(1.0, 18)) << "stream " << m << ": before the crossover";
    EXPECT_LE(first_n, std::ldexp(1.0, 28)) << "stream " << m;
    if (first_n > std::ldexp(1.0, 22)) ++late;
  }
  EXPECT_LE(late, 27u) << "floors starting after 2^22, of " << ladders;
}

TEST(RoundingFloor, LeavesCleanLaddersUnflagged) {
  // An exact N⁻² ladder down to 1e-12: converging all the way, no floor.
  const std::vector<double> n = doubling_ladder(1, 20);
  std::vector<double> power, monte_carlo, jump;
  for (std::size_t k = 0; k < n.size(); ++k) {
    power.push_back(1.0 / (n[k] * n[k]));
    // Monte Carlo-like RMSE with ±30% wobble, and a Newton–Cotes rule across a jump whose error
    // is O(1/n) but not monotone in n (docs/theory.md#jumps).
    monte_carlo.push_back(0.3 / std::sqrt(n[k]) * (1.0 + 0.3 * std::sin(3.0 * k)));
    jump.push_back((1.0 + 0.9 * std::sin(static_cast<double>(k))) / n[k]);
  }
  for (const auto* ladder : {&power, &monte_carlo, &jump}) {
    const rounding_floor floor = detect_rounding_floor(n, *ladder, 1.0);
    EXPECT_FALSE(floor.reached()) << "first flagged index " << floor.first.value_or(0);
    EXPECT_EQ(std::count(floor.flags.begin(), floor.flags.end(), true), 0);
    EXPECT_EQ(floor.attainable_accuracy, *std::min_element(ladder->begin(), ladder->end()));
    EXPECT_TRUE(std::isnan(floor.floor_level));
  }
}

TEST(RoundingFloor, ExactZeroIsAlwaysAFloorPoint) {
  // A rule exact for this integrand from N = 8 on (e.g. Simpson on a cubic): error 0 exactly.
  const std::vector<double> n = {2.0, 4.0, 8.0, 16.0};
  const std::vector<double> error = {1e-3, 1e-5, 0.0, 0.0};
  for (double scale : {1.0, 0.0}) {
    const rounding_floor floor = detect_rounding_floor(n, error, scale);
    ASSERT_TRUE(floor.reached()) << "scale " << scale;
    EXPECT_EQ(*floor.first, 2u);
    EXPECT_EQ(floor.attainable_accuracy, 1e-5);
    EXPECT_EQ(floor.floor_level, 0.0);
  }
}

TEST(RoundingFloor, FloorAtTheFirstPointReportsTheBestFloorError) {
  const std::vector<double> n = {10.0, 20.0, 40.0};
  const std::vector<double> error = {2e-16, 1e-16, 3e-16};  // e.g. importance with p ∝ f
  const rounding_floor floor = detect_rounding_floor(n, error, 1.0);
  ASSERT_TRUE(floor.reached());
  EXPECT_EQ(*floor.first, 0u);
  EXPECT_EQ(floor.attainable_accuracy, 1e-16);
  EXPECT_EQ(floor.floor_level, 2e-16);
}

TEST(RoundingFloor, RoundingLevelFollowsTheFormula) {
  // ℓ(N) = 2·ε·S·log₂N: N = 2^20, S = 3.
  EXPECT_DOUBLE_EQ(rounding_level(std::ldexp(1.0, 20), 3.0), 2.0 * eps * 3.0 * 20.0);
  EXPECT_DOUBLE_EQ(rounding_level(1.0, 1.0), 2.0 * eps) << "log₂ clamps at 1";
}

TEST(RoundingFloor, APerPointScaleRaisesTheLevelWhereARuleAmplifiesRounding) {
  // A ladder that flattens at 1e-13 (S = 1). With S = 1 everywhere the flat points are 17× above
  // ℓ(N) and only the stall rule (within 10⁴·ℓ, no later improvement by 2×) flags them; with the
  // scales of a rule whose Σ|w| is 1000 there, ℓ = 2ε·1000·log₂N is above them: at the floor.
  const std::vector<double> n = {1e2, 1e3, 1e4, 1e5, 1e6};
  const std::vector<double> error = {1e-4, 1e-6, 1e-13, 1.1e-13, 0.9e-13};
  const rounding_floor plain = detect_rounding_floor(n, error, 1.0);
  const std::vector<double> scales = {1.0, 1.0, 1000.0, 1000.0, 1000.0};
  const rounding_floor scaled = detect_rounding_floor(n, error, scales);
  ASSERT_TRUE(scaled.reached());
  EXPECT_EQ(*scaled.first, 2u);
  // Every point above is at the floor with the scales: e_k ≤ ℓ(N_k).
  for (std::size_t k = 2; k < n.size(); ++k) {
    EXPECT_LE(error[k], rounding_level(n[k], scales[k])) << k;
    EXPECT_GT(error[k], rounding_level(n[k], 1.0)) << k;
  }
  // One scale for all gives the same as the scalar form, bit for bit.
  const rounding_floor same = detect_rounding_floor(n, error, std::vector<double>(5, 1.0));
  EXPECT_EQ(same.flags, plain.flags);
  EXPECT_THROW(detect_rounding_floor(n, error, std::vector<double>{1.0, 1.0}), invalid_argument);
  EXPECT_THROW(detect_rounding_floor(n, error, std::vector<double>{1, 1, -1, 1, 1}),
               invalid_argument);
}

// The level of a series' rounding model: max(ε_f, σ(N)) with ε_f the evaluation format's epsilon
// and σ(N) the accumulator's term. Double evaluation with the pairwise sum is the default level.
TEST(RoundingFloor, RoundingLevelKnowsThePrecisionAndTheAccumulator) {
  const double n = std::ldexp(1.0, 20);
  const rounding_model pairwise{evaluation_precision::double_precision, summation::pairwise};
  EXPECT_EQ(rounding_level(n, 3.0, pairwise), rounding_level(n, 3.0));
  const double eps_f = std::numeric_limits<float>::epsilon();
  const rounding_model in_float{evaluation_precision::single_precision, summation::pairwise};
  EXPECT_DOUBLE_EQ(rounding_level(n, 3.0, in_float), 2.0 * eps_f * 3.0);
  const rounding_model naive{evaluation_precision::double_precision, summation::naive};
  EXPECT_DOUBLE_EQ(rounding_level(n, 3.0, naive), 2.0 * eps * 3.0 * 1024.0) << "ε·√N";
  const rounding_model compensated{evaluation_precision::double_precision, summation::neumaier};
  EXPECT_DOUBLE_EQ(rounding_level(n, 3.0, compensated), 2.0 * eps * 3.0);
  EXPECT_EQ(in_float.describe(), "float evaluation, pairwise sum");
}

// A ladder that flattens at 1e-9·|I| (float values averaged over the nodes) is at the floor for
// float evaluation (ℓ = 2ε_f ≈ 2.4e-7) and a clean ladder for double's level (≈ 1e-14): the
// double detector would fit the flat part.
TEST(RoundingFloor, FloatEvaluationHasAFloatFloor) {
  const std::vector<double> n = doubling_ladder(1, 12);
  std::vector<double> error;
  for (const double x : n)
    error.push_back(0.1 / (x * x * x * x) + 1e-9 * (1.0 + 0.3 * std::sin(x)));
  const rounding_model in_float{evaluation_precision::single_precision, summation::pairwise};
  const rounding_floor f = detect_rounding_floor(n, error, 1.0, in_float);
  ASSERT_TRUE(f.reached());
  // 0.1/N⁴ falls below 2ε_f ≈ 2.4e-7 at N ≈ 25, so N = 32 is the first point at the floor.
  EXPECT_EQ(n[*f.first], 32.0);
  EXPECT_FALSE(detect_rounding_floor(n, error, 1.0).reached());
}

TEST(RoundingFloor, RejectsBadLadders) {
  const std::vector<double> e = {1e-2, 1e-3, 1e-4};
  EXPECT_THROW(detect_rounding_floor(std::vector<double>{1.0, 4.0, 2.0}, e, 1.0), invalid_argument);
  EXPECT_THROW(detect_rounding_floor(std::vector<double>{1.0, 2.0}, e, 1.0), invalid_argument);
  EXPECT_THROW(detect_rounding_floor(std::vector<double>{1.0, 2.0, 4.0},
                                     std::vector<double>{1e-2, -1.0, 1e-4}, 1.0),
               invalid_argument);
  EXPECT_THROW(detect_rounding_floor(std::vector<double>{1.0, 2.0, 4.0}, e, -1.0),
               invalid_argument);
  EXPECT_THROW(
      detect_rounding_floor(std::vector<double>{1.0, 2.0, 4.0}, e, 1.0,
                            {.kappa = 2.0, .band = 1e4, .stall_factor = 1.0, .stall_window = 2}),
      invalid_argument);
}

// add_reference_floor: the first error below factor·u starts the floor (unless the rounding floor
// started earlier), every later point joins it, and the floor's level and the attainable accuracy
// are recomputed over the joined floor.
TEST(ReferenceFloor, StartsTheFloorAtTheFirstErrorBelowTenTimesTheUncertainty) {
  const std::vector<double> n{4, 16, 64, 256, 1024};
  const std::vector<double> error{1e-2, 1e-4, 1e-6, 2e-8, 1e-9};
  rounding_floor floor = detect_rounding_floor(n, error, 1.0);
  ASSERT_FALSE(floor.reached());
  add_reference_floor(floor, error, 1e-8, 10.0);  // level 1e-7: first below it is 2e-8 (k = 3)
  ASSERT_TRUE(floor.reached());
  EXPECT_EQ(*floor.first, 3u);
  EXPECT_EQ(*floor.reference_first, 3u);
  EXPECT_EQ(floor.flags, (std::vector<bool>{false, false, false, true, true}));
  EXPECT_EQ(floor.count(), 2u);
  EXPECT_DOUBLE_EQ(floor.floor_level, 0.5 * (2e-8 + 1e-9));  // median of the two
  EXPECT_EQ(floor.attainable_accuracy, 1e-6);
}

TEST(ReferenceFloor, AnErrorAtExactlyTenTimesIsStillFittedAndZeroUncertaintyIsNoFloor) {
  const std::vector<double> n{4, 16, 64};
  const std::vector<double> error{1e-2, 1e-3, 1e-4};
  rounding_floor floor = detect_rounding_floor(n, error, 1.0);
  add_reference_floor(floor, error, 1e-5, 10.0);  // 1e-4 is not below 10·1e-5
  EXPECT_FALSE(floor.reached());
  EXPECT_FALSE(floor.reference_first.has_value());
  add_reference_floor(floor, error, 0.0, 10.0);
  EXPECT_FALSE(floor.reached());
}

TEST(ReferenceFloor, AnEarlierRoundingFloorKeepsItsStart) {
  // A flat floor from k = 2 (S = 1: ℓ(64) = 2ε·6 = 2.7e-15, and 3e-15 stalls: the next two are
  // not below half of it); the reference floor 10·2.45e-16 = 2.45e-15 starts at k = 4, later:
  // the rounding floor stays as detected.
  const std::vector<double> n{4, 16, 64, 256, 1024};
  const std::vector<double> error{1e-8, 1e-11, 3e-15, 2.5e-15, 2.4e-15};
  rounding_floor floor = detect_rounding_floor(n, error, 1.0);
  ASSERT_TRUE(floor.reached());
  ASSERT_EQ(*floor.first, 2u);
  const rounding_floor before = floor;
  add_reference_floor(floor, error, 2.45e-16, 10.0);
  EXPECT_EQ(floor.first, before.first);
  EXPECT_EQ(floor.flags, before.flags);
  EXPECT_EQ(floor.floor_level, before.floor_level);
  ASSERT_TRUE(floor.reference_first.has_value());
  EXPECT_EQ(*floor.reference_first, 4u);
}

TEST(ReferenceFloor, RejectsBadUncertaintyFactorOrSizes) {
  const std::vector<double> n{4, 16};
  const std::vector<double> error{1e-2, 1e-3};
  rounding_floor floor = detect_rounding_floor(n, error, 1.0);
  EXPECT_THROW(add_reference_floor(floor, error, -1e-9, 10.0), invalid_argument);
  EXPECT_THROW(add_reference_floor(floor, error, std::numeric_limits<double>::infinity(), 10.0),
               invalid_argument);
  EXPECT_THROW(add_reference_floor(floor, error, 1e-9, 0.0), invalid_argument);
  const std::vector<double> three{1e-2, 1e-3, 1e-4};
  EXPECT_THROW(add_reference_floor(floor, three, 1e-9, 10.0), invalid_argument);
}

}  // namespace
}  // namespace quadmc
