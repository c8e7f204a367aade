// Tests of periodized_monte_carlo.hpp (docs/theory.md#lattice-periodizations): the weighted sample
// mean over a shifted lattice, bitwise the same for any thread count and any evaluation block,
// the box mapped after the transform, the catalogue's lattice entry taking this path for c0 …
// c3sin, and an overflowing Jacobian reported, not averaged.
#include "quadmc/estimators/periodized_monte_carlo.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "test_integrands.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

namespace quadmc {
namespace {

// e^−(x²+y²) on [0,1]², and x·e^y on [0,2]×[1,3] (the box mapped after the transform).
const any_integrand periodized_gaussian(test_support::make_integrand(
    "e^-(x²+y²) on [0,1]²", box::unit(2), 0.25 * std::numbers::pi * std::pow(std::erf(1.0), 2),
    [](std::span<const double> x) { return std::exp(-(x[0] * x[0] + x[1] * x[1])); }));
const any_integrand periodized_on_box(test_support::make_integrand(
    "x·e^y on [0,2]×[1,3]", box{{0.0, 1.0}, {2.0, 3.0}}, 2.0 * (std::exp(3.0) - std::exp(1.0)),
    [](std::span<const double> x) { return x[0] * std::exp(x[1]); }));

// The Gaussian, asking for blocks of four batches per call: the weights then come from the heap.
struct gaussian_in_blocks {
  std::size_t dimension() const noexcept { return 2; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    periodized_gaussian.evaluate(x, y);
  }
  integrand_info info() const {
    integrand_info i = periodized_gaussian.info();
    i.evaluation_block = 4 * batch_points;
    return i;
  }
};

bool same_bits(const estimate& a, const estimate& b) {
  return std::memcmp(&a.value, &b.value, sizeof(double)) == 0 && a.evaluations == b.evaluations;
}

template <class T>
class PeriodizedMonteCarlo : public ::testing::Test {};
using transforms =
    ::testing::Types<c0_transform, c1_transform, c1sin_transform, c2sin_transform, c3sin_transform>;
TYPED_TEST_SUITE(PeriodizedMonteCarlo, transforms);

// 2^15 points (3 chunks of sample_mean): 1, 2, 3 and 8 threads and blocks of 1024 points give the
// same bits; the value is near the integral (a shifted lattice of 2^15 points on these smooth f
// errs by O(N^−1) or less even before the transform: 1e-3 relative is a bound, not a fit), and
// one shift estimates no error of its own.
TYPED_TEST(PeriodizedMonteCarlo, IsBitwiseTheSameForAnyThreadCountAndBlock) {
  using T = TypeParam;
  const std::uint64_t n = std::uint64_t{1} << 15;
  const rank1_lattice_points<no_periodization> points(2, n, 42, 7);
  for (const any_integrand* f : {&periodized_gaussian, &periodized_on_box}) {
    const estimate one = periodized_monte_carlo<T>(*f, points, 1);
    const double exact = f->info().exact;
    EXPECT_NEAR(one.value, exact, 1e-3 * std::max(1.0, std::abs(exact)))
        << T::name << " on " << f->info().name;
    EXPECT_TRUE(std::isnan(one.std_error)) << T::name;
    EXPECT_EQ(one.evaluations, n);
    for (unsigned t : {2u, 3u, 8u}) {
      EXPECT_TRUE(same_bits(one, periodized_monte_carlo<T>(*f, points, t)))
          << T::name << " on " << f->info().name << ", " << t << " threads";
    }
  }
  EXPECT_TRUE(same_bits(periodized_monte_carlo<T>(periodized_gaussian, points, 1),
                        periodized_monte_carlo<T>(gaussian_in_blocks{}, points, 3)))
      << T::name << ": blocks of 1024 points";
}

// The catalogue's lattice with periodization = c0 … c3sin is this estimator over the lattice
// points themselves (periodization none), bit for bit.
TEST(PeriodizedMonteCarloCatalogue, LatticeEntryTakesThisPath) {
  const point_set_entry& lattice = *find_point_set("lattice");
  const std::uint64_t n = std::uint64_t{1} << 12;
  const rank1_lattice_points<no_periodization> points(2, n, 5, 6);
  point_set_options o;
  o.periodic = periodization::c1sin;
  EXPECT_TRUE(same_bits(lattice.monte_carlo(periodized_gaussian, {5, 6}, n, 2, o),
                        periodized_monte_carlo<c1sin_transform>(periodized_gaussian, points, 1)));
  o.periodic = periodization::c3sin;
  EXPECT_TRUE(same_bits(lattice.monte_carlo(periodized_gaussian, {5, 6}, n, 2, o),
                        periodized_monte_carlo<c3sin_transform>(periodized_gaussian, points, 1)));
  EXPECT_FALSE(same_bits(lattice.monte_carlo(periodized_gaussian, {5, 6}, n, 2, o),
                         lattice.monte_carlo(periodized_gaussian, {5, 6}, n, 2)))
      << "c3sin is not the plain lattice";
}

// ∏φ' ≤ (8/3)^s: in s = 800 a point near the cube's centre (every φ' ≈ 8/3 for c3sin) has a
// weight of about 10^340, beyond a double; the estimator says so instead of averaging an infinity.
TEST(PeriodizedMonteCarloCatalogue, OverflowingJacobianIsAnError) {
  const std::size_t s = 800;
  const any_integrand one(test_support::make_integrand(
      "1 on [0,1]^800", box::unit(s), 1.0, [](std::span<const double>) { return 1.0; }));
  // The unshifted lattice's point N/2 is (1/2, …, 1/2): every z_j is odd.
  const rank1_lattice_points<no_periodization> points(s, 64, 0, 0, false);
  EXPECT_THROW(periodized_monte_carlo<c3sin_transform>(one, points, 1), non_finite_value);
}

}  // namespace
}  // namespace quadmc
