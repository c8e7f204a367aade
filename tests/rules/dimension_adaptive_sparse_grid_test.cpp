// dimension_adaptive_sparse_grid: the Gerstner–Griebel algorithm — what it spends, where it
// spends it, exactness, its estimate and Σ|w|, and its bad-input errors.
#include "quadmc/rules/dimension_adaptive_sparse_grid.hpp"

#include "clenshaw_curtis_table.hpp"
#include "quadmc/rules/smolyak_grid.hpp"
#include "support/floating_point.hpp"
#include "throws_with.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace {

using namespace quadmc;

using quadmc::test_support::eps;

using quadmc::testing::cc;

// exp(Σ c_j x_j) on [0, 1]^s: ∫ = Π (e^(c_j) − 1)/c_j (c_j = 0: 1), and counts its points.
struct exponential {
  std::vector<double> c;
  std::size_t dimension() const { return c.size(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = c.size();
    for (std::size_t i = 0; i < y.size(); ++i) {
      double v = 0.0;
      for (std::size_t j = 0; j < s; ++j) v += c[j] * x[i * s + j];
      y[i] = std::exp(v);
    }
  }
  integrand_info info() const {
    integrand_info i;
    i.name = "exponential";
    i.domain = box::unit(c.size());
    return i;
  }
  double exact() const {
    double p = 1.0;
    for (const double cj : c) p *= cj == 0.0 ? 1.0 : std::expm1(cj) / cj;
    return p;
  }
};

TEST(DimensionAdaptiveSparseGrid, SpendsAtMostItsBudgetAndConvergesOnASmoothIntegrand) {
  const exponential f{{0.9, 0.7, 0.5, 0.3}};
  double previous = std::numeric_limits<double>::infinity();
  for (const std::uint64_t budget : {10u, 100u, 1000u, 10000u}) {
    adaptive_sparse_grid_options o;
    o.max_evaluations = budget;
    const adaptive_sparse_grid_result r = dimension_adaptive_sparse_grid(f, cc(), o);
    EXPECT_LE(r.evaluations, budget);
    const double error = std::abs(r.value - f.exact());
    EXPECT_LT(error, previous) << budget;
    EXPECT_LE(error, r.error_estimate) << budget;
    previous = error;
  }
  EXPECT_LT(previous, 1e-10);
}

TEST(DimensionAdaptiveSparseGrid, SpendsNothingOnADimensionTheIntegrandIgnores) {
  // f depends on x_1 only: every surplus with k_2 > 0 or k_3 > 0 vanishes (to rounding), so the
  // grid refines the first axis and stops on the others after their first level.
  const exponential f{{1.5, 0.0, 0.0}};
  adaptive_sparse_grid_options o;
  o.max_evaluations = 200;
  o.absolute_tolerance = 1e-13;
  const adaptive_sparse_grid_result r = dimension_adaptive_sparse_grid(f, cc(), o);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.value, f.exact(), 1e-13);
  // The 1D rule at the level that resolves e^(1.5x) (≤ 17 nodes) plus the first neighbours of
  // the other two axes (2 new nodes each, and a few of their products): far below 17³.
  EXPECT_LE(r.evaluations, 60u);
}

TEST(DimensionAdaptiveSparseGrid, IsTheSmolyakGridWhenItsIndexSetIsTheSimplex) {
  // On a polynomial of total degree ≤ 3 in s = 3 every surplus with |k| ≥ 2 vanishes, so the
  // result is exact and Σ|w| is that of the rule the run built.
  struct cubic {
    std::size_t dimension() const { return 3; }
    void evaluate(std::span<const double> x, std::span<double> y) const {
      for (std::size_t i = 0; i < y.size(); ++i) {
        const double a = x[3 * i], b = x[3 * i + 1], c = x[3 * i + 2];
        y[i] = 1.0 + a * a * b + c * c * c - a * b * c;
      }
    }
    integrand_info info() const {
      integrand_info i;
      i.name = "cubic";
      i.domain = box::unit(3);
      return i;
    }
  };
  adaptive_sparse_grid_options o;
  o.max_evaluations = 500;
  o.absolute_tolerance = 1e-14;
  const adaptive_sparse_grid_result r = dimension_adaptive_sparse_grid(cubic{}, cc(), o);
  const double exact = 1.0 + 1.0 / 6.0 + 0.25 - 0.125;
  EXPECT_NEAR(r.value, exact, 16 * eps);
  EXPECT_GE(r.absolute_weight_sum, 1.0 - 1e-14);
}

TEST(DimensionAdaptiveSparseGrid, DoesNotStopOnTheCentreValueAlone) {
  // (x₁ − 1/2)² vanishes at the centre: η = |f(centre)| = 0 there, which says nothing about the
  // rest of the cube. The grid refines the centre first and then integrates the quadratic exactly
  // (Clenshaw–Curtis level 1 is exact to degree 3): ∫ = 1/12.
  struct centred_quadratic {
    std::size_t dimension() const { return 2; }
    void evaluate(std::span<const double> x, std::span<double> y) const {
      for (std::size_t i = 0; i < y.size(); ++i) y[i] = (x[2 * i] - 0.5) * (x[2 * i] - 0.5);
    }
    integrand_info info() const {
      integrand_info i;
      i.name = "centred_quadratic";
      i.domain = box::unit(2);
      return i;
    }
  };
  adaptive_sparse_grid_options o;
  o.max_evaluations = 100;
  o.absolute_tolerance = 1e-12;
  const adaptive_sparse_grid_result r =
      dimension_adaptive_sparse_grid(centred_quadratic{}, cc(), o);
  EXPECT_GT(r.evaluations, 1u);
  EXPECT_NEAR(r.value, 1.0 / 12.0, 8 * eps);
}

TEST(DimensionAdaptiveSparseGrid, RejectsABudgetAboveItsCap) {
  const exponential f{{1.0}};
  adaptive_sparse_grid_options o;
  o.max_evaluations = adaptive_sparse_grid_max_evaluations + 1;
  EXPECT_TRUE(quadmc::testing::throws_with<invalid_argument>(
      [&] { dimension_adaptive_sparse_grid(f, cc(), o); }, "every value is kept"));
  o.max_evaluations = 0;
  EXPECT_TRUE(quadmc::testing::throws_with<invalid_argument>(
      [&] { dimension_adaptive_sparse_grid(f, cc(), o); }, "max_evaluations"));
}

}  // namespace
