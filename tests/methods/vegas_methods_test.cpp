// Tests of the vegas method (lib/src/methods/vegas_methods.cpp): its options with their errors, its
// sizes and controls, its theory, and a run reporting σ̂ as its error estimate with χ²/dof and Q.
#include "quadmc/estimators/vegas.hpp"
#include "quadmc/methods/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace quadmc {
namespace {

std::string error_of(const option_table& options) {
  try {
    make_method("vegas", options);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(VegasMethod, ReadsItsOptionsAndRefusesBadOnes) {
  EXPECT_EQ(error_of({{"iterations", 5}, {"training_iterations", 2}, {"alpha", 1.0}}), "no error");
  EXPECT_NE(error_of({{"iterations", 1}}).find("iterations"), std::string::npos);
  EXPECT_NE(error_of({{"iterations", 4}, {"training_iterations", 4}}).find("training_iterations"),
            std::string::npos)
      << error_of({{"iterations", 4}, {"training_iterations", 4}});
  EXPECT_NE(error_of({{"beta", 1.5}}).find("beta"), std::string::npos);
  EXPECT_NE(error_of({{"alpha", -1.0}}).find("alpha"), std::string::npos);
  EXPECT_NE(error_of({{"evaluations_per_iteration", 8}}).find("evaluations_per_iteration"),
            std::string::npos);
  EXPECT_NE(error_of({{"panels", 4}}).find("panels"), std::string::npos);
}

TEST(VegasMethod, SizesAndControls) {
  const auto m = make_method("vegas", {{"iterations", 4}});
  // Four iterations of at least 16 evaluations each.
  EXPECT_FALSE(m->size_for(63, 2).size);
  EXPECT_NE(m->size_for(63, 2).reason.find("64"), std::string::npos) << m->size_for(63, 2).reason;
  EXPECT_EQ(m->size_for(64, 2).size->evaluations, 64u);
  EXPECT_EQ(m->size_for(1'000'000, 8).size->evaluations, 1'000'000u);
  const method_descriptor* d = find_method("vegas");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->kind, method_kind::randomized);
  EXPECT_EQ(d->controls.front(), cell_control::budget);
  EXPECT_TRUE(d->supports(cell_control::tolerance));
  EXPECT_FALSE(d->supports(cell_control::fixed_size));
}

TEST(VegasMethod, TheoryIsTheRootNRate) {
  const auto m = make_method("vegas");
  const theoretical_rate rate = m->theory({smoothness::analytic, 4, std::nan("")});
  ASSERT_TRUE(rate.slope.has_value());
  EXPECT_DOUBLE_EQ(*rate.slope, -0.5);
  EXPECT_NE(rate.source.find("docs/theory.md#vegas"), std::string::npos);
}

// One repetition through the method is the estimator's run with the cell's budget, stream and
// seed, and reports σ̂ both as std_error and as its error estimate, with χ²/dof and Q.
TEST(VegasMethod, RunReportsItsEstimateAndConsistency) {
  integrand_params params;
  params.dimension = 2;
  params.vectors["a"] = {20.0, 20.0};
  params.vectors["u"] = {0.3, 0.7};
  const any_integrand f = make_integrand("genz_gaussian", params);
  const auto m = make_method("vegas");
  const cell_size size = *m->size_for(50'000, 2).size;
  const method_cell cell{f, params, size, cell_control::budget, std::nan(""), 17};
  const repetition_result r = m->run(cell, {3, 2});
  const vegas_result direct = vegas(f, {.max_evaluations = 50'000}, 3, 17);
  EXPECT_EQ(r.value, direct.value);
  EXPECT_EQ(r.std_error, direct.std_error);
  EXPECT_EQ(r.error_estimate, direct.std_error);
  EXPECT_EQ(r.evaluations, direct.evaluations);
  EXPECT_EQ(r.chi2_per_dof, direct.chi2_per_dof);
  EXPECT_EQ(r.q_value, direct.q);
  EXPECT_TRUE(std::isfinite(r.chi2_per_dof));

  // Tolerance control: stops at σ̂ ≤ tolerance within the budget.
  const double tolerance = 1e-4 * f.info().exact;
  const cell_size cap = *m->size_for(std::uint64_t{1} << 24, 2).size;
  const method_cell to_tolerance{f, params, cap, cell_control::tolerance, tolerance, 17};
  const repetition_result t = m->run(to_tolerance, {3, 1});
  EXPECT_LE(t.error_estimate, tolerance);
  EXPECT_LE(t.evaluations, std::uint64_t{1} << 24);
}

}  // namespace
}  // namespace quadmc
