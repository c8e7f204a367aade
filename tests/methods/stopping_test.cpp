// Tests of control = "tolerance" on the sample-mean methods (lib/src/methods/stopping.cpp): which
// rules each set takes and why it refuses the others, keys refused without the control or with a
// rule that does not read them, the plan-time budget check, and cells run to a tolerance.
#include "method_error.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace quadmc {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(StoppingMethods, EachSetTakesTheRulesItsStructureAllows) {
  EXPECT_EQ(error_of("sobol", {{"stopping", "replicates"}}), "no error");
  EXPECT_EQ(error_of("sobol", {{"stopping", "guaranteed"}, {"randomization", "lms_shift"}}),
            "no error");
  EXPECT_EQ(error_of("lattice", {{"stopping", "guaranteed"}}), "no error");
  EXPECT_EQ(error_of("halton", {{"stopping", "replicates"}}), "no error");
  EXPECT_EQ(error_of("plain_mc", {{"stopping", "guaranteed"}}), "no error");
  EXPECT_EQ(error_of("jittered", {{"stopping", "clt"}}), "no error");
  // An Owen scramble is no digital shift: the Walsh bound does not hold for it.
  const std::string owen = error_of("sobol", {{"stopping", "guaranteed"}});
  EXPECT_TRUE(contains(owen, "stopping")) << owen;
  EXPECT_TRUE(contains(owen, "lms_shift")) << owen;
  EXPECT_TRUE(contains(owen, "\"owen\"")) << owen;
  EXPECT_TRUE(contains(error_of("sobol", {{"stopping", "clt"}}), "replicates"));
  EXPECT_TRUE(contains(error_of("halton", {{"stopping", "guaranteed"}}), "no guaranteed rule"));
  EXPECT_TRUE(contains(error_of("jittered", {{"stopping", "replicates"}}), "strata change"));
  EXPECT_TRUE(contains(error_of("sobol", {{"stopping", "replicates"}, {"randomization", "none"}}),
                       "nothing to replicate"));
  EXPECT_TRUE(contains(error_of("sobol", {{"stopping", "often"}}), "replicates, guaranteed, clt"));
}

TEST(StoppingMethods, KeysBelongToTheirRuleAndToControlTolerance) {
  const auto m = make_method("sobol", {{"stopping", "replicates"}, {"replications", 8}});
  const auto fixed = m->refuses(cell_control::fixed_size);
  ASSERT_TRUE(fixed.has_value());
  EXPECT_EQ(fixed->key, "stopping");
  EXPECT_TRUE(contains(fixed->message, "control = \"tolerance\"")) << fixed->message;
  EXPECT_FALSE(m->refuses(cell_control::tolerance).has_value());
  EXPECT_FALSE(make_method("sobol")->refuses(cell_control::fixed_size).has_value());
  // fudge is the guaranteed net rules' constant; replications the replicate rule's.
  const std::string fudge = error_of("sobol", {{"stopping", "replicates"}, {"fudge", 3.0}});
  EXPECT_TRUE(contains(fudge, "fudge")) << fudge;
  EXPECT_TRUE(contains(error_of("plain_mc", {{"replications", 4}}), "replications"));
  EXPECT_TRUE(contains(error_of("sobol", {{"stopping", "replicates"}, {"n_init", 300}}),
                       "nearest 256 and 512"));
  EXPECT_TRUE(contains(error_of("plain_mc", {{"alpha", 1.5}}), "0 < alpha < 1"));
  EXPECT_TRUE(contains(error_of("plain_mc", {{"inflate", 0.9}}), "≥ 1"));
  // The unjittered grid has no rule: its single run has no error estimate, and its points are not
  // extensible; the refusal names both reasons at `control`.
  const auto grid = make_method("unjittered")->refuses(cell_control::tolerance);
  ASSERT_TRUE(grid.has_value());
  EXPECT_EQ(grid->key, "control");
  EXPECT_TRUE(contains(grid->message, "no stopping rule")) << grid->message;
}

TEST(StoppingMethods, TheBudgetMustHoldTheFirstStage) {
  const auto replicates = make_method("sobol", {{"stopping", "replicates"}});
  EXPECT_TRUE(replicates->tolerance_size_for(16 * 256, 2).size);
  const sizing short_of = replicates->tolerance_size_for(16 * 256 - 1, 2);
  EXPECT_FALSE(short_of.size);
  EXPECT_TRUE(contains(short_of.reason, "R·n_init = 16·256")) << short_of.reason;
  EXPECT_FALSE(make_method("plain_mc")->tolerance_size_for(2047, 2).size);
  EXPECT_TRUE(make_method("plain_mc")->tolerance_size_for(2048, 2).size);
  EXPECT_FALSE(
      make_method("lattice", {{"stopping", "guaranteed"}})->tolerance_size_for(1023, 2).size);
}

// One repetition of a cell to `tolerance` on a Genz Gaussian in s = 2.
repetition_result run_to(const std::string& name, const option_table& options, double tolerance) {
  integrand_params params;
  params.dimension = 2;
  params.seed = 5;
  const any_integrand f = make_integrand("genz_gaussian", params);
  const auto m = make_method(name, options);
  const cell_size size = *m->tolerance_size_for(std::uint64_t{1} << 22, 2).size;
  const method_cell cell{f, params, size, cell_control::tolerance, tolerance, 17, 0};
  repetition_result r = m->run(cell, {2026, 2});
  r.seconds = std::abs(r.value - f.info().exact);  // the true error, for the caller
  return r;
}

TEST(StoppingMethods, CellsToAToleranceReportTheirClaimAndWhatTheySpent) {
  for (const auto& [name, options] :
       {std::pair<std::string, option_table>{"sobol", {{"stopping", "replicates"}}},
        {"sobol", {{"stopping", "guaranteed"}, {"randomization", "lms_shift"}}},
        {"lattice", {{"stopping", "guaranteed"}, {"periodization", "baker"}}},
        {"halton", {}},
        {"plain_mc", {}},
        {"plain_mc", {{"stopping", "guaranteed"}}},
        {"jittered", {}}}) {
    const repetition_result r = run_to(name, options, 1e-3);
    SCOPED_TRACE(name);
    EXPECT_GT(r.evaluations, 0U);
    EXPECT_LE(r.error_estimate, 1e-3);
    // Each claim is a 99 % interval or a bound: an error beyond 3× it would be a bug, not chance
    // (for a normal error, P(|e| > 3·2.58σ) < 1e-14).
    EXPECT_LE(r.seconds, 3 * r.error_estimate);
  }
  // The same cell on 1 and 3 threads: the same bits.
  integrand_params params;
  params.dimension = 3;
  const any_integrand f = make_integrand("genz_oscillatory", params);
  const auto m = make_method("lattice", {{"stopping", "guaranteed"}});
  const cell_size size = *m->tolerance_size_for(std::uint64_t{1} << 20, 3).size;
  const method_cell cell{f, params, size, cell_control::tolerance, 1e-6, 3, 0};
  const repetition_result one = m->run(cell, {1, 1});
  const repetition_result three = m->run(cell, {1, 3});
  EXPECT_EQ(one.value, three.value);
  EXPECT_EQ(one.error_estimate, three.error_estimate);
  EXPECT_EQ(one.evaluations, three.evaluations);
}

}  // namespace
}  // namespace quadmc
