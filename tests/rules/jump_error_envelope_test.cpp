// Tests for jump_error_envelope.hpp: the constants against their derivation in the header, the
// envelope against the measured error of every rule on steps at every position in a panel (it
// holds, and it is attained with the jump on a node), on Genz's discontinuous family with its
// smooth part in s = 1, 2, 3, and for Romberg.
#include "quadmc/rules/jump_error_envelope.hpp"

#include "quadmc/functions/classic_1d.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/functions/indicators.hpp"
#include "quadmc/rules/romberg.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace quadmc {
namespace {

using quadmc::test_support::eps;

// The sums of a rule on [0, 1] with |f| ≤ 1 add terms of total magnitude ≤ 1: pairwise summation
// errs by ≤ ε·log₂(nodes) (summation.hpp), the weights and the reference 1 − c by an ε each; 32ε
// covers log₂ of every node count used here (≤ 2¹⁴ points) with room.
constexpr double rounding = 32 * eps;

TEST(JumpErrorEnvelope, JumpConstantsAreTheDerivedOnes) {
  // The table of the header: d(θ, λ)'s sup for each rule, derived by hand there.
  EXPECT_NEAR(jump_defect_constant(left_rectangle_rule{}), 1.0, 4 * eps);
  EXPECT_NEAR(jump_defect_constant(right_rectangle_rule{}), 1.0, 4 * eps);
  EXPECT_NEAR(jump_defect_constant(midpoint_rule{}), 0.5, 4 * eps);
  EXPECT_NEAR(jump_defect_constant(trapezoid_rule{}), 0.5, 4 * eps);
  EXPECT_NEAR(jump_defect_constant(simpson_rule{}), 1.0 / 3.0, 4 * eps);  // per pair H = 2h
  EXPECT_NEAR(jump_defect_constant(gauss_legendre_rule(2)), 0.5 / std::sqrt(3.0), 4 * eps);
  EXPECT_NEAR(jump_defect_constant(gauss_legendre_rule(3)), 2.0 / 9.0, 4 * eps);
  EXPECT_EQ(panels_per_cell(simpson_rule{}), 2u);
  EXPECT_EQ(panels_per_cell(midpoint_rule{}), 1u);
  // Every supported m: between half the largest weight (at that node max(C_j − τ_j, τ_j −
  // C_{j−1}) ≥ ŵ_j/2) and the largest weight (Chebyshev–Markov–Stieltjes).
  for (unsigned m : gauss_legendre_rule::supported_points) {
    const gauss_legendre_rule rule(m);
    double largest = 0.0;
    for (unsigned j = 0; j < m; ++j) largest = std::max(largest, rule.unit_weight(j));
    const double k = jump_defect_constant(rule);
    EXPECT_LT(k, largest) << "m = " << m;
    EXPECT_GE(k, largest / 2.0 * (1 - 4 * eps)) << "m = " << m;
  }
}

TEST(JumpErrorEnvelope, CutCellAndTaylorConstantsAreTheDerivedOnes) {
  // L = 1/4 + Σ ŵ|τ − 1/2|: midpoint 1/4, trapezoid and rectangles 1/4 + 1/2, Simpson
  // 1/4 + 2·(1/6)(1/2).
  EXPECT_DOUBLE_EQ(cut_cell_constant(midpoint_rule{}), 0.25);
  EXPECT_DOUBLE_EQ(cut_cell_constant(trapezoid_rule{}), 0.75);
  EXPECT_DOUBLE_EQ(cut_cell_constant(left_rectangle_rule{}), 0.75);
  EXPECT_DOUBLE_EQ(cut_cell_constant(simpson_rule{}), 5.0 / 12.0);
  // T_k/k!: midpoint k = 2 is (1/12)/2 = 1/24, the classical constant; trapezoid
  // (1/12 + 1/4)/2 = 1/6 (twice-loose against its 1/12); Gauss m = 3, k = 4: (1/80 + 1/80)/24
  // = 1/960 (the rule is exact for (x − 1/2)⁴, so Σŵ(τ − 1/2)⁴ = ∫ = 1/80).
  EXPECT_NEAR(taylor_cell_constant(midpoint_rule{}, 2), 1.0 / 24.0, 4 * eps);
  EXPECT_NEAR(taylor_cell_constant(trapezoid_rule{}, 2), 1.0 / 6.0, 4 * eps);
  EXPECT_NEAR(taylor_cell_constant(gauss_legendre_rule(3), 4), 1.0 / 960.0, 1e-15);
  EXPECT_TRUE(testing::throws_with<invalid_argument>(
      [] { (void)taylor_cell_constant(midpoint_rule{}, 3); }, "order 2"));
}

// Every position of a unit step in a panel, for n panels: a grid of c plus every node and the
// doubles either side of it (the sup is a one-sided limit at a node). Returns the largest
// |error|/envelope and checks |error| ≤ envelope + rounding at each c.
template <class R>
double worst_step_ratio(const R& rule, std::uint64_t n) {
  std::vector<double> positions;
  for (int i = 1; i < 4000; ++i) positions.push_back(i / 4000.0);
  const auto q = rule.nodes(n);
  for (std::uint64_t k = 0; k < q.size(); ++k) {
    const double t = q.node(k);
    for (double c : {std::nextafter(t, 0.0), t, std::nextafter(t, 1.0)}) {
      if (c > 0.0 && c <= 1.0) positions.push_back(c);
    }
  }
  double worst = 0.0;
  for (double c : positions) {
    const step_1d f(c);
    const integrand_info info = f.info();
    const double error = std::abs(integrate(f, rule, n).value - info.exact);
    const std::optional<double> envelope = jump_error_envelope(rule, info, n);
    EXPECT_TRUE(envelope.has_value());
    if (!envelope) return 0.0;
    EXPECT_LE(error, *envelope + rounding) << rule.name() << " n = " << n << " c = " << c;
    worst = std::max(worst, error / *envelope);
  }
  return worst;
}

// The envelope of a step is K·H alone (its pieces are constant), and it is attained: with the
// jump on a node (right rectangle, midpoint, trapezoid, Simpson's middle node, Gauss's middle
// node for m = 3) or a double away from one (left rectangle, Gauss m = 2). A constant too small,
// e.g. halved, fails the ≤ above; one too large fails the attainment below.
TEST(JumpErrorEnvelope, StepErrorStaysUnderTheEnvelopeAndAttainsIt) {
  for (std::uint64_t n : {4u, 6u, 10u}) {
    EXPECT_NEAR(worst_step_ratio(left_rectangle_rule{}, n), 1.0, 1e-9) << n;
    EXPECT_NEAR(worst_step_ratio(right_rectangle_rule{}, n), 1.0, 1e-9) << n;
    EXPECT_NEAR(worst_step_ratio(midpoint_rule{}, n), 1.0, 1e-9) << n;
    EXPECT_NEAR(worst_step_ratio(trapezoid_rule{}, n), 1.0, 1e-9) << n;
    EXPECT_NEAR(worst_step_ratio(simpson_rule{}, n), 1.0, 1e-9) << n;
    EXPECT_NEAR(worst_step_ratio(gauss_legendre_rule(2), n), 1.0, 1e-9) << n;
    EXPECT_NEAR(worst_step_ratio(gauss_legendre_rule(3), n), 1.0, 1e-9) << n;
  }
}

TEST(JumpErrorEnvelope, AJumpOnANodeAttainsTheBoundExactly) {
  // Dyadic n and c = 1/2 keep every weight, node and sum exact: the right rectangle counts the
  // node at 1/2 as 1 and errs by exactly h; the trapezoid gives it weight h and errs by h/2.
  for (std::uint64_t n = 2; n <= 1024; n *= 2) {
    const step_1d f(0.5);
    const double h = 1.0 / static_cast<double>(n);
    EXPECT_EQ(std::abs(integrate(f, right_rectangle_rule{}, n).value - 0.5), h);
    EXPECT_EQ(*jump_error_envelope(right_rectangle_rule{}, f.info(), n), h);
    EXPECT_EQ(std::abs(integrate(f, trapezoid_rule{}, n).value - 0.5), h / 2);
    EXPECT_EQ(*jump_error_envelope(trapezoid_rule{}, f.info(), n), h / 2);
  }
  // An end-point jump: the step at c = 1 is 1 only at x = 1 (∫ = 0); the trapezoid's end
  // weight h/2 is its whole error, K·H again.
  const step_1d end(1.0);
  EXPECT_EQ(integrate(end, trapezoid_rule{}, 8).value, 1.0 / 16.0);
  EXPECT_EQ(*jump_error_envelope(trapezoid_rule{}, end.info(), 8), 1.0 / 16.0);
}

// |error| ≤ envelope + rounding for every rule and n = 1 … 120 (Simpson even) on f with a smooth
// part: the cut-cell and smooth terms carry it where the jump term alone would not.
template <class F>
void expect_within(const F& f, double rounding_scale) {
  const integrand_info info = f.info();
  for (std::uint64_t n = 1; n <= 120; ++n) {
    auto check = [&](const auto& rule) {
      const std::optional<double> envelope = jump_error_envelope(rule, info, n);
      ASSERT_TRUE(envelope.has_value()) << info.name << " " << rule.name();
      const double error = std::abs(integrate(f, rule, n).value - info.exact);
      EXPECT_LE(error, *envelope + rounding * rounding_scale)
          << info.name << " " << rule.name() << " n = " << n;
    };
    check(left_rectangle_rule{});
    check(right_rectangle_rule{});
    check(midpoint_rule{});
    check(trapezoid_rule{});
    if (n % 2 == 0) check(simpson_rule{});
    check(gauss_legendre_rule(2));
    check(gauss_legendre_rule(5));
  }
}

TEST(JumpErrorEnvelope, HoldsOnGenzDiscontinuousWithItsSmoothPart) {
  // Σ|w f| ≤ M₀ = e^{max(0, a·u)}; the rounding allowance scales with it.
  expect_within(genz_discontinuous({2.5}, {0.6}), std::exp(1.5));
  expect_within(genz_discontinuous({4.0}, {0.5}), std::exp(2.0));  // the cut on dyadic nodes
  // A small jump e^{−7.2} ≈ 7e-4 beside a large smooth part (M₂ = 64): the smooth bounds carry
  // the envelope at small n.
  expect_within(genz_discontinuous({-8.0}, {0.9}), 1.0);
  // The 1D disk and half-space: two jumps, one jump.
  expect_within(disk_indicator({0.4}, 0.3), 1.0);
  expect_within(half_space_indicator({3.0}, 1.7), 1.0);
}

TEST(JumpErrorEnvelope, HoldsOnGenzDiscontinuousAsATensorProduct) {
  const genz_discontinuous f2({1.5, 2.8}, {0.45, 0.7});
  const genz_discontinuous f3({0.9, 1.4, 2.0}, {0.3, 0.62, 0.5}, {1, 2, 3});
  for (std::uint64_t n = 2; n <= 24; n += 2) {
    for (const genz_discontinuous* f : {&f2, &f3}) {
      const integrand_info info = f->info();
      const double scale = info.derivative_bound[0].value_or(1.0);
      auto check = [&](const auto& rule) {
        const std::optional<double> envelope = jump_error_envelope(rule, info, n);
        ASSERT_TRUE(envelope.has_value()) << rule.name();
        const double error = std::abs(integrate(*f, rule, n).value - info.exact);
        EXPECT_LE(error, *envelope + rounding * scale)
            << "s = " << info.dimension() << " " << rule.name() << " n = " << n;
      };
      check(midpoint_rule{});
      check(trapezoid_rule{});
      check(simpson_rule{});
      check(gauss_legendre_rule(3));
    }
  }
}

TEST(JumpErrorEnvelope, NoEnvelopeWithoutSeparableJumpsOrBounds) {
  // Curved boundary, smooth f: no factors or no jump, so the slope verdict stays.
  EXPECT_FALSE(jump_error_envelope(midpoint_rule{}, disk_indicator({0.5, 0.5}, 0.4).info(), 8));
  EXPECT_FALSE(jump_error_envelope(midpoint_rule{}, exp_1d().info(), 8));
  EXPECT_FALSE(jump_error_envelope(midpoint_rule{}, genz_discontinuous({1.0}, {1.0}).info(), 8));
  // A jump without M₁: the cut cells cannot be bounded.
  integrand_info info = step_1d(0.3).info();
  info.separable_factors[0].derivative_bound[1].reset();
  EXPECT_FALSE(jump_error_envelope(midpoint_rule{}, info, 8));
  EXPECT_TRUE(testing::throws_with<invalid_argument>(
      [] { (void)jump_error_envelope(simpson_rule{}, step_1d(0.3).info(), 7); }, "even"));
}

TEST(JumpErrorEnvelope, RombergCoefficientsAreTheExtrapolationsWeights) {
  // R(1, 1) = (4T₂ − T₁)/3 (Simpson), R(2, 2) = (64T₄ − 20T₂ + T₁)/45 (Boole).
  const std::vector<double> one = romberg_coefficients(1);
  ASSERT_EQ(one.size(), 2u);
  EXPECT_NEAR(one[0], -1.0 / 3.0, 4 * eps);
  EXPECT_NEAR(one[1], 4.0 / 3.0, 4 * eps);
  const std::vector<double> two = romberg_coefficients(2);
  ASSERT_EQ(two.size(), 3u);
  EXPECT_NEAR(two[0], 1.0 / 45.0, 4 * eps);
  EXPECT_NEAR(two[1], -20.0 / 45.0, 4 * eps);
  EXPECT_NEAR(two[2], 64.0 / 45.0, 4 * eps);
  for (unsigned k = 0; k <= 30; ++k) {
    double sum = 0.0;
    for (double c : romberg_coefficients(k)) sum += c;
    EXPECT_NEAR(sum, 1.0, 16 * eps) << "k = " << k;  // exact on constants
  }
}

TEST(JumpErrorEnvelope, RombergStaysUnderItsEnvelope) {
  romberg_options options;
  options.relative_tolerance = 0.0;
  for (unsigned k = 1; k <= 14; ++k) {
    options.min_levels = k;
    options.max_levels = k;
    for (double c : {0.5, 0.75, 1.0 / std::sqrt(2.0), 0.93750095367431640625, 1.0}) {
      const step_1d f(c);
      const double error = std::abs(romberg(f, options).value - f.info().exact);
      EXPECT_LE(error, *romberg_jump_error_envelope(f.info(), k) + rounding)
          << "k = " << k << " c = " << c;
    }
    const genz_discontinuous g({2.5}, {0.6});
    const double error = std::abs(romberg(g, options).value - g.info().exact);
    EXPECT_LE(error, *romberg_jump_error_envelope(g.info(), k) + rounding * std::exp(1.5))
        << "k = " << k;
  }
  EXPECT_FALSE(romberg_jump_error_envelope(exp_1d().info(), 4));
}

}  // namespace
}  // namespace quadmc
