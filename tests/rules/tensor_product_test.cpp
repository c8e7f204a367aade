#include "quadmc/rules/tensor_product.hpp"

#include "log_log_slope.hpp"
#include "quadmc/functions/stability_1d.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace {

using quadmc::test_support::eps;

// exp(x₁ + … + x_s) on a box: smooth, not a polynomial, and a product of 1D factors, so
// ∫ = Π(e^{b_j} − e^{a_j}) in closed form.
struct exp_of_sum {
  quadmc::box domain;
  std::size_t dimension() const { return domain.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = dimension();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < s; ++j) sum += x[i * s + j];
      y[i] = std::exp(sum);
    }
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info i;
    i.name = "exp_of_sum";
    i.domain = domain;
    i.exact = 1.0;
    for (std::size_t j = 0; j < domain.dimension(); ++j) {
      i.exact *= std::exp(domain.upper[j]) - std::exp(domain.lower[j]);
    }
    return i;
  }
};

// A product of cubics, (x₁³ − x₁)(x₂³ + 2)(…): Simpson's tensor product is exact for it.
struct cubic_product {
  std::size_t s;
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      double p = 1.0;
      for (std::size_t j = 0; j < s; ++j) {
        const double t = x[i * s + j];
        p *= j % 2 == 0 ? t * t * t - t + 1.0 : t * t * t + 2.0;
      }
      y[i] = p;
    }
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info i;
    i.name = "cubic_product";
    i.domain = quadmc::box{std::vector<double>(s, -1.0), std::vector<double>(s, 2.0)};
    return i;
  }
};

// A configurable integrand for the failure paths: NaN in one corner of [0, 1]^s, or a
// domain/dimension that does not fit.
struct broken_integrand {
  std::size_t s = 2;
  quadmc::box domain = quadmc::box::unit(2);
  std::size_t dimension() const { return s; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      y[i] = (x[i * s] > 0.7 && x[i * s + 1] < 0.2) ? std::nan("") : 1.0;
    }
  }
  quadmc::integrand_info info() const {
    quadmc::integrand_info i;
    i.name = "broken";
    i.domain = domain;
    return i;
  }
};

// ∫ over [−1, 2]^s of the cubic product: per axis ∫(x³ − x + 1) = 15/4 − 3/2 + 3 = 5.25 and
// ∫(x³ + 2) = 15/4 + 6 = 9.75. Bound: 4·m^s ulp (stated in the task for exactness tests) of
// the volume 3^s times max|f| (3^s·… ≤ 7·10 per pair of axes).
TEST(TensorProduct, SimpsonExactForProductsOfCubics) {
  for (std::size_t s : {1U, 2U, 3U}) {
    double exact = 1.0;
    double max_f = 1.0;
    for (std::size_t j = 0; j < s; ++j) {
      exact *= j % 2 == 0 ? 5.25 : 9.75;
      max_f *= j % 2 == 0 ? 7.0 : 10.0;
    }
    const auto r = quadmc::integrate(cubic_product{s}, quadmc::simpson_rule{}, 6);
    const double points = std::pow(7.0, static_cast<double>(s));
    EXPECT_EQ(r.evaluations, static_cast<std::uint64_t>(points));
    EXPECT_NEAR(r.value, exact, 4.0 * points * eps * std::pow(3.0, s) * max_f) << "s = " << s;
  }
}

// The 1D case of the kernel is the composite rule: with one axis, integrate(f, rule, n) on the
// box [a, b] equals the plain-callable form bit for bit (same nodes, same summation order).
TEST(TensorProduct, OneDimensionIsTheCompositeRule) {
  const exp_of_sum f{quadmc::box{{-1.0}, {2.0}}};
  const auto a = quadmc::integrate(f, quadmc::gauss_legendre_rule(4), 1000);
  const auto b = quadmc::integrate([](double x) { return std::exp(x); }, -1.0, 2.0,
                                   quadmc::gauss_legendre_rule(4), 1000);
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.evaluations, 4000U);
  EXPECT_NEAR(a.value, f.info().exact, 1e-13 * f.info().exact);
}

// Slope −r/s against N = n^s (n panels per axis; the spec's N, not the (n + 1)^s evaluations of
// the end-point rules, which differ by a factor (1 + 1/n)^s that fades along the ladder). Ladder
// n = 4 … 32: the error stays above 1e-9 (Simpson, s = 2), far above rounding, and N ≤ 33⁴ ≈
// 1.2e6 points keeps the test to about a second at -O2.
template <class R>
double tensor_slope(const R& rule, std::size_t s) {
  const exp_of_sum f{quadmc::box::unit(s)};
  const double exact = f.info().exact;
  std::vector<double> big_n;
  std::vector<double> errors;
  for (std::uint64_t n : {4U, 6U, 8U, 12U, 16U, 24U, 32U}) {
    const auto r = quadmc::integrate(f, rule, n, 2);
    big_n.push_back(std::pow(static_cast<double>(n), static_cast<double>(s)));
    errors.push_back(r.value - exact);
  }
  return quadmc::testing::log_log_slope(big_n, errors);
}

TEST(TensorProduct, ConvergesAtMinusROverS) {
  for (std::size_t s : {2U, 3U, 4U}) {
    const double sd = static_cast<double>(s);
    EXPECT_NEAR(tensor_slope(quadmc::midpoint_rule{}, s), -2.0 / sd, 0.1) << "midpoint s = " << s;
    EXPECT_NEAR(tensor_slope(quadmc::trapezoid_rule{}, s), -2.0 / sd, 0.1) << "trapezoid s = " << s;
    EXPECT_NEAR(tensor_slope(quadmc::simpson_rule{}, s), -4.0 / sd, 0.1) << "simpson s = " << s;
  }
}

// Chunks of 2^14 points folded in order: 1, 2, 3 and 8 threads give the same bits. 3D
// trapezoid, midpoint and Simpson with 60 panels = 61³ = 226 981 points = 14 chunks, the last one
// partial; 1D Gauss with 100 000 panels × 3 = 18.3 chunks.
TEST(TensorProduct, BitwiseIdenticalForAnyThreadCount) {
  const exp_of_sum f3{quadmc::box{{0.0, -0.5, 0.25}, {1.0, 0.5, 2.0}}};
  const exp_of_sum f1{quadmc::box{{-1.0}, {1.0}}};
  const auto serial3 = quadmc::integrate(f3, quadmc::trapezoid_rule{}, 60, 1);
  const auto serial1 = quadmc::integrate(f1, quadmc::gauss_legendre_rule(3), 100000, 1);
  for (unsigned threads : {2U, 3U, 8U}) {
    const auto r3 = quadmc::integrate(f3, quadmc::trapezoid_rule{}, 60, threads);
    const auto r1 = quadmc::integrate(f1, quadmc::gauss_legendre_rule(3), 100000, threads);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r3.value), std::bit_cast<std::uint64_t>(serial3.value))
        << "threads = " << threads;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r1.value), std::bit_cast<std::uint64_t>(serial1.value))
        << "threads = " << threads;
    EXPECT_EQ(r3.evaluations, 61U * 61U * 61U);
    // The other composite rules on the same 3D grid size (midpoint 60³, Simpson 61³).
    EXPECT_EQ(
        std::bit_cast<std::uint64_t>(
            quadmc::integrate(f3, quadmc::midpoint_rule{}, 60, threads).value),
        std::bit_cast<std::uint64_t>(quadmc::integrate(f3, quadmc::midpoint_rule{}, 60, 1).value))
        << "midpoint, threads = " << threads;
    EXPECT_EQ(
        std::bit_cast<std::uint64_t>(
            quadmc::integrate(f3, quadmc::simpson_rule{}, 60, threads).value),
        std::bit_cast<std::uint64_t>(quadmc::integrate(f3, quadmc::simpson_rule{}, 60, 1).value))
        << "simpson, threads = " << threads;
  }
  EXPECT_NEAR(serial3.value, f3.info().exact, 1e-3 * f3.info().exact);  // h² = 1/3600
}

// Midpoint nodes (k + ½)/10: the first point in flat order (last axis fastest) with x₁ > 0.7
// and x₂ < 0.2 is (0.75, 0.05).
TEST(TensorProduct, NonFiniteValueNamesThePoint) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::non_finite_value>(
      [] { (void)quadmc::integrate(broken_integrand{}, quadmc::midpoint_rule{}, 10); },
      "broken returned nan at x = (0.75, 0.05)"));
  // parallel_reduce rethrows the lowest-numbered failing chunk, so with threads the point is the
  // same as a serial run's: n = 1000, first x₁ node above 0.7 is 0.7005, first x₂ node 0.0005.
  for (unsigned threads : {1U, 2U, 8U}) {
    EXPECT_TRUE(quadmc::testing::throws_with<quadmc::non_finite_value>(
        [threads] {
          (void)quadmc::integrate(broken_integrand{}, quadmc::midpoint_rule{}, 1000, threads);
        },
        "broken returned nan at x = (0.7005, 0.0005)"))
        << "threads = " << threads;
  }
}

TEST(TensorProduct, GridSizeOverflowIsDetectedExactly) {
  using quadmc::testing::throws_with;
  // 2^16 nodes in 4D is exactly 2^64: one too many. 2^16 − 1 fits.
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::tensor_grid_size(65536, 4); },
      "invalid nodes per axis = 65536: expected nodes^s ≤ 2^64 − 1 for s = 4"));
  EXPECT_EQ(quadmc::tensor_grid_size(65535, 4), 65535ULL * 65535ULL * 65535ULL * 65535ULL);
  // 3^40 ≈ 1.2e19 < 2^64 ≈ 1.8e19 < 3^41.
  std::uint64_t three_40 = 1;
  for (int i = 0; i < 40; ++i) three_40 *= 3;
  EXPECT_EQ(quadmc::tensor_grid_size(3, 40), three_40);
  EXPECT_THROW((void)quadmc::tensor_grid_size(3, 41), quadmc::invalid_argument);
  // Through integrate: trapezoid with 2^16 − 1 panels has 2^16 nodes per axis.
  EXPECT_TRUE(throws_with<quadmc::invalid_argument>(
      [] {
        (void)quadmc::integrate(exp_of_sum{quadmc::box::unit(4)}, quadmc::trapezoid_rule{}, 65535);
      },
      "nodes per axis = 65536"));
}

TEST(TensorProduct, RejectsBadInput) {
  using quadmc::invalid_argument;
  using quadmc::testing::throws_with;
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] {
        (void)quadmc::integrate(broken_integrand{0, quadmc::box{}}, quadmc::midpoint_rule{}, 4);
      },
      "invalid integrand dimension s = 0: expected at least 1"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] {
        (void)quadmc::integrate(broken_integrand{2, quadmc::box::unit(3)}, quadmc::midpoint_rule{},
                                4);
      },
      "invalid integrand domain dimension = 3: expected the integrand's dimension 2"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] { (void)quadmc::integrate(exp_of_sum{quadmc::box::unit(2)}, quadmc::midpoint_rule{}, 0); },
      "invalid n = 0"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] {
        (void)quadmc::integrate(exp_of_sum{quadmc::box{{0.0, 1.0}, {1.0, 0.5}}},
                                quadmc::midpoint_rule{}, 4);
      },
      "invalid domain.upper[1] = 0.5: expected ≥ domain.lower[1] = 1"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [inf] {
        (void)quadmc::integrate(exp_of_sum{quadmc::box{{0.0, -inf}, {1.0, 0.5}}},
                                quadmc::midpoint_rule{}, 4);
      },
      "invalid domain.lower[1] = -inf: expected a finite number"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] {
        (void)quadmc::integrate(exp_of_sum{quadmc::box{{0.0}, {std::nan("")}}},
                                quadmc::midpoint_rule{}, 4);
      },
      "invalid domain.upper[0] = nan: expected a finite number"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] {
        (void)quadmc::integrate(exp_of_sum{quadmc::box{{-1e308}, {1e308}}}, quadmc::midpoint_rule{},
                                4);
      },
      "expected a finite number (the bounds are too far apart for double)"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] {
        (void)quadmc::integrate([](double x) { return x; }, 2.0, 1.0, quadmc::midpoint_rule{}, 4);
      },
      "invalid b = 1: expected ≥ a = 2"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [] { (void)quadmc::integrate(exp_of_sum{quadmc::box::unit(2)}, quadmc::simpson_rule{}, 5); },
      "invalid n = 5: expected an even number"));
}

// --- Accumulators (enum summation) and the rounding floor -------------------------------------

// 1/(1 + x²) on [0, 1], ∫ = π/4: smooth, cheap, every term positive. At n = 10⁸ the midpoint
// error f''·h²/24 ≤ 2/(24·10¹⁶) ≈ 8e-18 and the trapezoid error h²/12·|f'(1) − f'(0)| ≈ 4e-18 are
// below ε·π/4 ≈ 1.7e-16, so what is measured is rounding alone.
double inverse_quadratic(double x) {
  return 1.0 / (1.0 + x * x);
}
constexpr double quarter_pi = 0.78539816339744830962;  // π/4

template <class R>
double error_at(const R& rule, std::uint64_t n, quadmc::summation sum, unsigned threads) {
  return std::abs(quadmc::integrate(inverse_quadratic, 0.0, 1.0, rule, n, threads, sum).value -
                  quarter_pi);
}

// Compensated sums keep the error at a few ε·|I| (Higham §4.3: 2ε·Σ|x| + O(nε²), plus ε per
// node a + w·t and per f): the bound 100·ε·|I| of docs/design.md#accuracy-targets has a wide
// margin. A naive left-to-right sum of 10⁸ positive terms of ≈ 10⁻⁸ into a total ≈ 0.8 loses about
// half an ulp of the total per add with a bias that does not average out (Higham §4.2): its error
// is orders of magnitude above 100·ε·|I|, which the test asserts, together with "naive is worse
// than compensated".
TEST(TensorProductSummation, CompensatedReachesEpsilonAtHundredMillionPanels) {
  using quadmc::summation;
  const std::uint64_t n = 100'000'000;
  const double bound = 100.0 * eps * quarter_pi;
  const double mid_neumaier = error_at(quadmc::midpoint_rule{}, n, summation::neumaier, 2);
  const double trap_neumaier = error_at(quadmc::trapezoid_rule{}, n, summation::neumaier, 2);
  const double mid_pairwise = error_at(quadmc::midpoint_rule{}, n, summation::pairwise, 2);
  const double mid_naive = error_at(quadmc::midpoint_rule{}, n, summation::naive, 1);
  const double trap_naive = error_at(quadmc::trapezoid_rule{}, n, summation::naive, 1);
  EXPECT_LE(mid_neumaier, bound) << "midpoint, neumaier, n = " << n;
  EXPECT_LE(trap_neumaier, bound) << "trapezoid, neumaier, n = " << n;
  EXPECT_LE(mid_pairwise, bound) << "midpoint, pairwise (default), n = " << n;
  EXPECT_GT(mid_naive, bound) << "midpoint, naive, n = " << n;
  EXPECT_GT(trap_naive, bound) << "trapezoid, naive, n = " << n;
  EXPECT_GT(mid_naive, 10.0 * mid_neumaier) << "naive must be worse than compensated";
  EXPECT_GT(trap_naive, 10.0 * trap_neumaier) << "naive must be worse than compensated";
  std::printf(
      "n = 1e8 errors/(ε|I|): midpoint neumaier %.3g pairwise %.3g naive %.3g; "
      "trapezoid neumaier %.3g naive %.3g\n",
      mid_neumaier / (eps * quarter_pi), mid_pairwise / (eps * quarter_pi),
      mid_naive / (eps * quarter_pi), trap_neumaier / (eps * quarter_pi),
      trap_naive / (eps * quarter_pi));
}

TEST(TensorProductSummation, DefaultIsPairwiseAndEveryPolicyIsThreadIndependent) {
  using quadmc::summation;
  const exp_of_sum f{quadmc::box{{0.0, -1.0}, {1.0, 0.5}}};
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  const double by_default = quadmc::integrate(f, quadmc::simpson_rule{}, 300).value;
  EXPECT_EQ(bits(by_default),
            bits(quadmc::integrate(f, quadmc::simpson_rule{}, 300, 1, summation::pairwise).value));
  for (summation sum :
       {summation::pairwise, summation::neumaier, summation::naive, summation::long_double}) {
    const double one = quadmc::integrate(f, quadmc::simpson_rule{}, 300, 1, sum).value;
    for (unsigned threads : {2U, 3U}) {
      EXPECT_EQ(bits(one),
                bits(quadmc::integrate(f, quadmc::simpson_rule{}, 300, threads, sum).value))
          << to_string(sum) << ", threads = " << threads;
    }
    // 301² = 90601 terms: every accumulator is within its own bound of the same sum, far below
    // Simpson's error (b − a)h⁴M₄/180 ≈ 1e-10 here, so all agree to 1e-12 relative.
    EXPECT_NEAR(one, by_default, 1e-12 * std::abs(by_default)) << to_string(sum);
  }
}

// The naive accumulator is a single left-to-right sum. Midpoint with n = 2¹⁶ panels on [0, 1]:
// the first term is w·f = 2⁻¹⁶·1, every later one 2⁻¹⁶·2⁻⁵³ = 2⁻⁶⁹, exactly half an ulp of the
// running 2⁻¹⁶, so each add rounds back to it (ties to even): the sum stays 2⁻¹⁶ across all four
// chunks. A chunked or pairwise "naive" would add the tiny terms among themselves first and keep
// them; Neumaier keeps them all, giving (1 + (n − 1)·2⁻⁵³)·2⁻¹⁶ rounded once.
TEST(TensorProductSummation, NaiveIsGenuinelyLeftToRight) {
  using quadmc::summation;
  const std::uint64_t n = std::uint64_t{1} << 16;
  const double tiny = 0x1p-53;
  const auto g = [tiny](double x) { return x < 1.0 / static_cast<double>(n) ? 1.0 : tiny; };
  for (unsigned threads : {1U, 2U}) {
    EXPECT_EQ(
        quadmc::integrate(g, 0.0, 1.0, quadmc::midpoint_rule{}, n, threads, summation::naive).value,
        0x1p-16)
        << "threads = " << threads;
    EXPECT_EQ(
        quadmc::integrate(g, 0.0, 1.0, quadmc::midpoint_rule{}, n, threads, summation::neumaier)
            .value,
        std::ldexp(1.0 + static_cast<double>(n - 1) * tiny, -16))
        << "threads = " << threads;
  }
}

// --- Shifted and scaled domains ----------------------------------------------------------------

double relative_error(const quadmc::shifted_exp_1d& f, std::uint64_t n) {
  const double exact = f.info().exact;
  return std::abs(quadmc::integrate(f, quadmc::midpoint_rule{}, n).value - exact) / exact;
}

// shifted_exp is e^t/w on t = (x − a)/w, so every box has ∫ = e − 1 and the same discretization
// error as [0, 1]. Scaling by a power of ten costs only the rounding of x = a + w·t and of
// (x − a)/w (a few ε per node, summed with weights h: ≤ 100ε·|I| with margin). A box far from 0
// adds a perturbation the library cannot remove: x is rounded to a multiple of ulp(a), so t is
// off by ≤ ulp(a)/(2w) and |Δ∫| ≤ ulp(a)/(2w)·max|g'| = ulp(a)/(2w)·e. Stated factor: the relative
// error on [10⁸, 10⁸ + 1] is within that additive bound of the unshifted one (midpoint n = 1000:
// unshifted ≈ 4.2e-8, the bound adds ≤ 1.2e-8, i.e. a factor ≤ 1.3).
TEST(ShiftedDomains, ScaledBoxesKeepTheUnshiftedRelativeError) {
  const std::uint64_t n = 1000;
  const double unshifted = relative_error(quadmc::shifted_exp_1d(0.0, 1.0), n);
  // Midpoint: E ≈ h²/24·(f'(1) − f'(0)) = 10⁻⁶/24·(e − 1): relative 10⁻⁶/24 ≈ 4.17e-8.
  EXPECT_NEAR(unshifted, 1e-6 / 24.0, 1e-9);
  for (const auto& [lo, hi] : {std::pair{0.0, 1e-100}, std::pair{-1e100, 1e100}}) {
    const double scaled = relative_error(quadmc::shifted_exp_1d(lo, hi), n);
    EXPECT_NEAR(scaled, unshifted, 100.0 * eps) << "[" << lo << ", " << hi << "]";
  }
}

TEST(ShiftedDomains, FarFromZeroTheNodeRoundingBoundHolds) {
  const std::uint64_t n = 1000;
  const double a = 1e8;
  const double unshifted = relative_error(quadmc::shifted_exp_1d(0.0, 1.0), n);
  const double shifted = relative_error(quadmc::shifted_exp_1d(a, a + 1.0), n);
  const double ulp = std::nextafter(a + 1.0, 2 * a) - (a + 1.0);  // 2⁻²⁶ ≈ 1.49e-8
  const double e = std::exp(1.0);
  const double node_bound = ulp / 2.0 * e / (e - 1.0);  // relative: |Δ∫|/(e − 1)
  EXPECT_LE(std::abs(shifted - unshifted), node_bound + 100.0 * eps)
      << "shifted " << shifted << ", unshifted " << unshifted;
  EXPECT_LE(shifted, 1.3 * unshifted) << "the stated factor";
}

// --- Bad input: one test each, asserting the type and the message ------------------------------

TEST(BadInput, ZeroPanels) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::integrate(inverse_quadratic, 0.0, 1.0, quadmc::trapezoid_rule{}, 0); },
      "invalid n = 0"));
}

TEST(BadInput, OddPanelsForSimpson) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::integrate(inverse_quadratic, 0.0, 1.0, quadmc::simpson_rule{}, 7); },
      "invalid n = 7: expected an even number"));
}

TEST(BadInput, ZeroDimension) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] {
        (void)quadmc::integrate(broken_integrand{0, quadmc::box{}}, quadmc::midpoint_rule{}, 4);
      },
      "invalid integrand dimension s = 0: expected at least 1"));
}

// Documented convention (tensor_product.hpp): a > b is rejected, never read as −∫_b^a.
TEST(BadInput, ReversedBounds) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] { (void)quadmc::integrate(inverse_quadratic, 1.0, 0.0, quadmc::midpoint_rule{}, 4); },
      "invalid b = 0: expected ≥ a = 1 (swap the bounds for a reversed interval)"));
}

TEST(BadInput, NaNBound) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] {
        (void)quadmc::integrate(inverse_quadratic, std::nan(""), 1.0, quadmc::midpoint_rule{}, 4);
      },
      "invalid a = nan: expected a finite number"));
}

TEST(BadInput, InfiniteBound) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] {
        (void)quadmc::integrate(inverse_quadratic, 0.0, std::numeric_limits<double>::infinity(),
                                quadmc::midpoint_rule{}, 4);
      },
      "invalid b = inf: expected a finite number"));
}

// nˢ > 2⁶⁴: 2¹⁶ midpoint nodes in 4D is exactly 2⁶⁴ points.
TEST(BadInput, EvaluationCountOverflow) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::invalid_argument>(
      [] {
        (void)quadmc::integrate(exp_of_sum{quadmc::box::unit(4)}, quadmc::midpoint_rule{}, 65536);
      },
      "invalid nodes per axis = 65536: expected nodes^s ≤ 2^64 − 1 for s = 4"));
}

TEST(BadInput, IntegrandReturningNaNNamesThePoint) {
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::non_finite_value>(
      [] {
        (void)quadmc::integrate([](double x) { return x > 0.5 ? std::nan("") : x; }, 0.0, 1.0,
                                quadmc::midpoint_rule{}, 4);
      },
      "function returned nan at x = (0.625)"));
}

TEST(BadInput, IntegrandReturningInfinityNamesThePoint) {
  // 1/x at the trapezoid's node x = 0.
  EXPECT_TRUE(quadmc::testing::throws_with<quadmc::non_finite_value>(
      [] {
        (void)quadmc::integrate([](double x) { return 1.0 / x; }, 0.0, 1.0,
                                quadmc::trapezoid_rule{}, 4);
      },
      "function returned inf at x = (0)"));
}

}  // namespace
