// Tests of the romberg method (lib/src/methods/romberg_methods.cpp): its 2^k + 1 grids and its
// three controls, each spending what it says and reporting its own error estimate.
#include "quadmc/methods/registry.hpp"
#include "quadmc/rules/romberg.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace quadmc {
namespace {

TEST(RombergMethod, UsesPowersOfTwoPanels) {
  const auto m = make_method("romberg");
  // 2^k + 1 nodes: N = 17 → 16 panels (order 2·4 + 2 = 10), N = 16 → 8 panels.
  EXPECT_EQ(m->size_for(17, 1).size->per_axis, 16u);
  EXPECT_EQ(m->size_for(17, 1).size->order, 10);
  EXPECT_EQ(m->size_for(16, 1).size->per_axis, 8u);
  EXPECT_EQ(m->size_for(3, 1).size->per_axis, 2u);
  EXPECT_FALSE(m->size_for(2, 1).size);
  EXPECT_TRUE(m->incompatibility({"genz_gaussian", 2, false}).has_value());
  EXPECT_FALSE(m->incompatibility({"exp", 1, false}).has_value());
  EXPECT_TRUE(find_method("romberg")->supports(cell_control::tolerance));
  EXPECT_TRUE(find_method("romberg")->supports(cell_control::budget));
  EXPECT_FALSE(find_method("simpson")->supports(cell_control::tolerance));
}

repetition_result run(cell_control control, std::uint64_t budget, double tolerance) {
  integrand_params params;
  const any_integrand f = make_integrand("exp", params);
  const auto m = make_method("romberg");
  const cell_size size = *m->size_for(budget, 1).size;
  const method_cell cell{f, params, size, control, tolerance, 0};
  return m->run(cell, {0, 1});
}

TEST(RombergMethod, FixedSizeRunsEveryLevel) {
  // 2^10 + 1 evaluations exactly, with the estimate of the last level.
  const repetition_result r = run(cell_control::fixed_size, 1025, std::nan(""));
  EXPECT_EQ(r.evaluations, 1025u);
  EXPECT_FALSE(std::isnan(r.error_estimate));
  romberg_options options;
  options.relative_tolerance = 0.0;
  options.min_levels = options.max_levels = 10;
  EXPECT_EQ(r.value, romberg(make_integrand("exp", {}), options).value);
}

TEST(RombergMethod, BudgetStopsEarlyAtItsDefaultTolerance) {
  // eˣ converges to 1e-12·∫|f| long before 2^20 + 1 evaluations: the cell spends fewer.
  const repetition_result r = run(cell_control::budget, (1u << 20) + 1, std::nan(""));
  EXPECT_LT(r.evaluations, (1u << 20) + 1);
  EXPECT_LE(r.error_estimate, 1e-12 * (std::exp(1.0) - 1.0));
  EXPECT_NEAR(r.value, std::exp(1.0) - 1.0, 1e-12);
}

TEST(RombergMethod, ToleranceRunsUntilItsEstimateIsBelowIt) {
  // Tighter tolerances spend more, each estimate is below its tolerance, and on eˣ the estimate
  // |R(k,k) − R(k−1,k−1)| bounds the true error (the previous entry's error dominates on smooth
  // f: rules/romberg.hpp).
  std::uint64_t spent = 0;
  for (const double tolerance : {1e-4, 1e-8, 1e-12}) {
    const repetition_result r = run(cell_control::tolerance, (1u << 24) + 1, tolerance);
    EXPECT_LE(r.error_estimate, tolerance);
    EXPECT_LE(std::abs(r.value - (std::exp(1.0) - 1.0)), r.error_estimate) << tolerance;
    EXPECT_GE(r.evaluations, spent) << tolerance;
    spent = r.evaluations;
  }
  // A budget too small for the tolerance: it stops at the budget with a larger estimate.
  const repetition_result short_of = run(cell_control::tolerance, 9, 1e-14);
  EXPECT_EQ(short_of.evaluations, 9u);
  EXPECT_GT(short_of.error_estimate, 1e-14);
}

}  // namespace
}  // namespace quadmc
