// weighted_sum: vol·Σ w_i f(x_i) over any weighted point set — weights of both signs, an
// s-dimensional lattice, a tensor grid with and without its fast path — with the documented
// summation order, thread independence, exactness, and its errors.
#include "quadmc/rules/weighted_sum.hpp"

#include "hand_built_rules.hpp"
#include "log_log_slope.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/tensor_product_grid.hpp"
#include "reference_weighted_sum.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace quadmc;
using quadmc::testing::extrapolated_midpoint;
using quadmc::testing::fibonacci_lattice;

using quadmc::test_support::eps;
constexpr double pi = std::numbers::pi;
using quadmc::testing::all_accumulators;

using quadmc::test_support::bits;

// f(x) = g(x) on a box, one point at a time.
template <class G>
struct pointwise {
  G g;
  box domain;
  std::size_t dimension() const { return domain.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = dimension();
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = g(x.subspan(i * s, s));
  }
  integrand_info info() const {
    integrand_info i;
    i.name = "pointwise";
    i.domain = domain;
    return i;
  }
};
template <class G>
pointwise<G> on(box domain, G g) {
  return pointwise<G>{std::move(g), std::move(domain)};
}

// A set's points one at a time, for reference_weighted_sum.
template <class P>
auto point_by_point(const P& points) {
  return [&points](std::uint64_t p, std::span<double> t, double& w) {
    points.generate(p, t, std::span<double>(&w, 1));
  };
}

// A tensor grid behind a type without mapped(): weighted_sum then maps every batch itself.
template <class G>
struct without_fast_path {
  const G* grid;
  std::uint64_t size() const { return grid->size(); }
  std::size_t dimension() const { return grid->dimension(); }
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    grid->generate(first, nodes, weights);
  }
};
static_assert(
    !box_mapped_point_set<without_fast_path<tensor_product_grid<simpson_rule::node_set>>>);

// --- Weights of both signs: one Richardson step on the midpoint rule ---------------------------

// The midpoint error has the Euler–Maclaurin expansion M_n − I = Σ_k B_2k(½)h^2k/(2k)!·Δf^(2k−1)
// with h = (b − a)/n, Δg = g(b) − g(a), and B_n(½) = −(1 − 2^(1−n))B_n (Abramowitz & Stegun,
// ch. 23): B_2(½) = −1/12, B_4(½) = 7/240, B_6(½) = −31/1344. In R_n = (4M_2n − M_n)/3 the h² terms
// cancel; the h⁴ term gets the factor (4/16 − 1)/3 = −1/4, so R_n − I = −7h⁴Δf'''/23040 + ch⁶Δf⁽⁵⁾
// + …, and for f = eˣ (every Δf⁽ᵏ⁾ the same) the next term changes the ratio by
// −(155/15482880)/(7/23040)·h² = −0.0330·h². On [1, 2] with h = 1/n the test allows 0.04/n², which
// also covers rounding (ε·Σ|w f| ≈ 1e-15 against an error ≥ 1e-10 at n ≤ 32).
TEST(WeightedSum, ExtrapolatedMidpointErrorIsTheEulerMaclaurinH4Term) {
  const auto f = on(box{{1.0}, {2.0}}, [](std::span<const double> x) { return std::exp(x[0]); });
  const double e = std::numbers::e;
  const double exact = e * e - e;
  const double leading = -7.0 * (e * e - e) / 23040.0;
  std::vector<double> n_values, errors;
  for (const std::uint64_t n : {8U, 16U, 32U, 64U}) {
    const rule_result r = weighted_sum(f, extrapolated_midpoint(n));
    EXPECT_EQ(r.evaluations, 3 * n);
    const double nd = static_cast<double>(n);
    const double error = r.value - exact;
    if (n <= 32) {
      EXPECT_NEAR(error * nd * nd * nd * nd / leading, 1.0, 0.04 / (nd * nd)) << "n = " << n;
    }
    n_values.push_back(nd);
    errors.push_back(error);
  }
  // O(n⁻⁴): the local slope of log|error| on log n is −4 + 0.066/n², within 0.0011 of −4 here.
  EXPECT_NEAR(quadmc::testing::log_log_slope(n_values, errors), -4.0, 0.01);
}

// --- Summation order and thread independence ---------------------------------------------------

// Every accumulator on 1, 2, 3 and 8 threads gives the bits of reference_weighted_sum, so the
// same bits for any thread count. The extrapolated midpoint set with n = 100 000 has 300 000
// points (19 chunks, the last partial); the lattice F_25 = 75 025 points (5 chunks).
template <class F, class P>
void expect_reference_bits(const F& f, const P& points, const std::string& label) {
  for (const summation accumulate : all_accumulators) {
    const double expected = quadmc::testing::reference_weighted_sum(
        f, points.size(), point_by_point(points), accumulate);
    for (const unsigned threads : {1U, 2U, 3U, 8U}) {
      const rule_result r = weighted_sum(f, points, threads, accumulate);
      EXPECT_EQ(bits(r.value), bits(expected))
          << label << " " << to_string(accumulate) << " threads = " << threads;
      EXPECT_EQ(r.evaluations, points.size());
    }
  }
}

TEST(WeightedSum, BitwiseTheReferenceOrderForAnyThreadCount) {
  const auto f1 =
      on(box{{-0.5}, {2.0}}, [](std::span<const double> x) { return 1.0 / (1.0 + x[0] * x[0]); });
  expect_reference_bits(f1, extrapolated_midpoint(100000), "extrapolated midpoint");
  const auto f2 = on(box{{-1.0, 0.0}, {1.0, 2.0}},
                     [](std::span<const double> x) { return std::exp(x[0] - 0.5 * x[1] * x[1]); });
  expect_reference_bits(f2, fibonacci_lattice(25), "Fibonacci lattice");
}

// f asking for blocks of 2^14 points per call (integrand_info::evaluation_block, as a Python
// callable does): nodes and sums stay per batch, so every accumulator gives the reference order's
// bits; the largest call is a whole chunk.
template <class F>
struct in_blocks {
  F f;
  std::atomic<std::size_t>* largest;  // called from several threads
  std::size_t dimension() const { return f.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    std::size_t seen = largest->load();
    while (seen < y.size() && !largest->compare_exchange_weak(seen, y.size())) {
    }
    f.evaluate(x, y);
  }
  integrand_info info() const {
    integrand_info i = f.info();
    i.evaluation_block = std::size_t{1} << 14;
    return i;
  }
};

TEST(WeightedSum, ValuesPerBlockGiveTheReferenceBits) {
  std::atomic<std::size_t> largest = 0;
  const auto f =
      on(box{{-0.5}, {2.0}}, [](std::span<const double> x) { return 1.0 / (1.0 + x[0] * x[0]); });
  expect_reference_bits(in_blocks<decltype(f)>{f, &largest}, extrapolated_midpoint(100000),
                        "extrapolated midpoint in blocks");
  EXPECT_EQ(largest.load(), rule_chunk_points);
}

// The fast path (a tensor grid's mapped()) and the kernel's own map give the same bits.
TEST(WeightedSum, FastPathAndGenericMapGiveTheSameBits) {
  for (const std::size_t s : {1U, 2U, 3U}) {
    box domain;
    for (std::size_t j = 0; j < s; ++j) {
      domain.lower.push_back(-1.0 - 0.5 * static_cast<double>(j));
      domain.upper.push_back(0.75 + static_cast<double>(j));
    }
    const auto f = on(domain, [](std::span<const double> x) {
      double v = 0.0;
      for (const double xj : x) v += std::sin(xj) * xj;
      return std::exp(v);
    });
    const std::uint64_t n = s == 1 ? 20000 : 40;  // 1D: more than 2^14 nodes, not tabulated
    const tensor_product_grid grid(simpson_rule{}.nodes(n), s);
    const without_fast_path<decltype(grid)> generic{&grid};
    for (const summation accumulate : all_accumulators) {
      const double fast = weighted_sum(f, grid, 2, accumulate).value;
      EXPECT_EQ(bits(weighted_sum(f, generic, 2, accumulate).value), bits(fast))
          << "s = " << s << " " << to_string(accumulate);
      EXPECT_EQ(bits(integrate(f, simpson_rule{}, n, 2, accumulate).value), bits(fast))
          << "s = " << s << " " << to_string(accumulate);
    }
  }
}

// --- Exactness ---------------------------------------------------------------------------------

// The bounds: every value f(x) is off by its own rounding and by |∇f|·|x|·ε from the rounding of
// the node map; the sum adds (2 + log2 256)ε·Σ|w f| (weighted_point_set.hpp). With the
// derivative and coordinate bounds of each case this is below K·ε·vol·Σ|w|·max|f| for the K
// stated, which is what is asserted.

// R_n is exact for cubics: the h² term cancels and f''' is constant, so Δf''' = 0. On [−1, 2]:
// ∫(x³ − 2x² + x + 1) = (4 − 16/3 + 2 + 2) − (1/4 + 2/3 + 1/2 − 1) = 9/4; |f| ≤ 3, |f'| ≤ 8,
// |x| ≤ 2: per value ≤ 16ε + 8ε, K = 64 with Σ|w| = 5/3.
TEST(WeightedSum, ExtrapolatedMidpointIsExactForCubics) {
  const auto f = on(box{{-1.0}, {2.0}}, [](std::span<const double> x) {
    const double t = x[0];
    return ((t - 2.0) * t + 1.0) * t + 1.0;
  });
  for (const std::uint64_t n : {1U, 3U, 10U, 1000U}) {
    EXPECT_NEAR(weighted_sum(f, extrapolated_midpoint(n)).value, 2.25,
                64.0 * eps * 3.0 * (5.0 / 3.0) * 3.0)
        << "n = " << n;
  }
}

// Gauss–Legendre with m = 3 nodes per panel is exact to degree 5 on each axis, so its tensor grid
// integrates (x⁵ + x²)(y⁴ − y + 2) on [0, 1] × [−1, 2] exactly: (1/6 + 1/3)·(33/5 − 3/2 + 6) =
// 5.55. |f| ≤ 2·16, |∇f| ≤ 7·33, |x| ≤ 2: K = 64 is generous.
TEST(WeightedSum, GaussLegendreTensorGridIsExactToDegreeFivePerAxis) {
  const auto f = on(box{{0.0, -1.0}, {1.0, 2.0}}, [](std::span<const double> x) {
    const double a = x[0];
    const double b = x[1];
    return (a * a * a * a * a + a * a) * (b * b * b * b - b + 2.0);
  });
  for (const std::uint64_t n : {1U, 2U, 7U}) {
    const tensor_product_grid grid(gauss_legendre_rule(3).nodes(n), 2);
    EXPECT_NEAR(weighted_sum(f, grid).value, 5.55, 64.0 * eps * 3.0 * 32.0 * 7.0) << "n = " << n;
  }
}

// A rank-1 lattice rule integrates exp(2πi h·t) exactly (to 0) unless h·z ≡ 0 mod N (Sloan &
// Joe). With N = F_20 = 6765, z = (1, 4181) the frequencies of cos(2πt₁)cos(2πt₂) (h = (±1, ±1):
// h·z = ±1 ± 4181) and sin 2π(2t₁ − 3t₂) (h·z = 2 − 12543 ≡ 989) are not in the dual lattice, so
// on [−1, 1] × [0, 2] (t₁ = (x + 1)/2, t₂ = y/2) f = 1 + cos(πx)cos(πy) + sin(π(2x − 3y)) has
// Q(f) = vol·1 = 4 = I. Arguments up to 8π are rounded to 8πε, the map to 2ε·|∇f| ≤ 12πε:
// K = 256 with max|f| = 3. A frequency in the dual lattice is aliased to the constant: h = (4181,
// −1) has h·z = 0, so Q(1 + cos 2π(4181t₁ − t₂)) = 2 where the integral is 1. There the argument
// reaches 2π·4181, rounded by ≤ 2π·4181·ε per value (t₁ = i/N and the product): ≤ 6e-12 < 1e-10.
TEST(WeightedSum, FibonacciLatticeIsExactOffItsDualLattice) {
  const fibonacci_lattice lattice(20);
  ASSERT_EQ(lattice.size(), 6765U);
  ASSERT_EQ(lattice.generator(), 4181U);
  const box domain{{-1.0, 0.0}, {1.0, 2.0}};
  const auto f = on(domain, [](std::span<const double> x) {
    return 1.0 + std::cos(pi * x[0]) * std::cos(pi * x[1]) +
           std::sin(pi * (2.0 * x[0] - 3.0 * x[1]));
  });
  EXPECT_NEAR(weighted_sum(f, lattice).value, 4.0, 256.0 * eps * 4.0 * 3.0);
  // On the dual lattice: t = (i/N, {4181 i/N}) makes 4181t₁ − t₂ an integer, cos(2π·integer) = 1.
  const auto aliased = on(box::unit(2), [](std::span<const double> t) {
    return 1.0 + std::cos(2.0 * pi * (4181.0 * t[0] - t[1]));
  });
  EXPECT_NEAR(weighted_sum(aliased, lattice).value, 2.0, 1e-10);
}

// --- Errors -------------------------------------------------------------------------------------

// First node in index order with x > 0.75: the M_8 nodes (k + ½)/8 come first, k = 6 gives
// 0.8125; on [2, 4] it is 2 + 2·0.8125 = 3.625 (box coordinates, not unit-cube ones). With
// n = 10 000 the first is k = 15 000 of M_20000, (15 000.5)/20 000 = 0.750025, in chunk 0; the
// M_n nodes above 0.75 fail in chunk 1 too, and every thread count reports chunk 0's point.
TEST(WeightedSum, NonFiniteValueNamesThePoint) {
  using quadmc::testing::throws_with;
  const auto nan_above = [](double c) {
    return [c](std::span<const double> x) { return x[0] > c ? std::nan("") : 1.0; };
  };
  EXPECT_TRUE(throws_with<non_finite_value>(
      [&] { (void)weighted_sum(on(box::unit(1), nan_above(0.75)), extrapolated_midpoint(4)); },
      "pointwise returned nan at x = (0.8125)"));
  EXPECT_TRUE(throws_with<non_finite_value>(
      [&] {
        (void)weighted_sum(on(box{{2.0}, {4.0}}, nan_above(3.5)), extrapolated_midpoint(4));
      },
      "pointwise returned nan at x = (3.625)"));
  for (const unsigned threads : {1U, 2U, 8U}) {
    EXPECT_TRUE(throws_with<non_finite_value>(
        [&] {
          (void)weighted_sum(on(box::unit(1), nan_above(0.75)), extrapolated_midpoint(10000),
                             threads);
        },
        "pointwise returned nan at x = (0.750025)"))
        << "threads = " << threads;
  }
}

// A set without points, to reach the kernel's own check.
struct empty_set {
  std::uint64_t size() const { return 0; }
  std::size_t dimension() const { return 1; }
  void generate(std::uint64_t, std::span<double>, std::span<double>) const {}
};

TEST(WeightedSum, RejectsBadInput) {
  using quadmc::testing::throws_with;
  const auto one = [](std::span<const double>) { return 1.0; };
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { (void)weighted_sum(on(box::unit(2), one), extrapolated_midpoint(4)); },
      "invalid weighted point set dimension = 1: expected the integrand's dimension 2"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { (void)weighted_sum(on(box::unit(1), one), empty_set{}); },
      "invalid weighted point set size N = 0: expected at least 1 point"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] {
        (void)weighted_sum(on(box{{1.0}, {0.0}}, one), extrapolated_midpoint(4));
      },
      "invalid domain.upper[0] = 0: expected ≥ domain.lower[0] = 1"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] { (void)weighted_sum(on(box{}, one), extrapolated_midpoint(4)); },
      "invalid integrand dimension s = 0: expected at least 1"));
  EXPECT_TRUE(throws_with<invalid_argument>(
      [&] {
        (void)weighted_sum(on(box{{0.0}, {std::numeric_limits<double>::infinity()}}, one),
                           extrapolated_midpoint(4));
      },
      "invalid domain.upper[0] = inf: expected a finite number"));
}

}  // namespace
