// Tests of scene/run.hpp: the runner executes the plan's cells with each method's options (here
// the tensor rules' accumulator), reports progress per repetition, and pools one series per
// (integrand, method label).
#include "quadmc/scene/run.hpp"

#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/scene/parse.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {
namespace {

// Midpoint with n = 2²² panels on eˣ, [0, 1]: the discretization error (e − 1)/(24n²) ≈ 4e-15 is
// a few ulp of I ≈ 1.72, and a naive left-to-right sum of 4·10⁶ terms loses far more than that
// (its bias grows like ε·n, tensor_product_test.cpp), while Neumaier stays at the discretization
// error plus ~2ε·I. So the two labels must give two series with different values: the option
// reached the kernel.
constexpr std::string_view accumulators = R"(name = "acc"
threads = 2
[[integrand]]
family = "exp"
[[method]]
name = "midpoint"
accumulator = "naive"
panels = [4194304]
[[method]]
name = "midpoint"
accumulator = "neumaier"
panels = [4194304]
[[method]]
name = "plain_mc"
repetitions = 3
[budget]
N = [1000]
)";

// Regression ("reproducing one row alone"): a Genz instance was drawn from the
// integrand's position in the scene, and a cell's points from the integrand's and the method's
// positions, so the time-to-error page's product peak at s = 8 could not be re-run alone (another
// instance, 2,005 evaluations for 1e-3 instead of 401). Now a row's numbers depend on (seed,
// family, s, instance) and on the integrand's name and the method's label only: the same row
// placed second, after another integrand and method, gives bitwise the same estimates.
TEST(RunPlan, OneRowReRunAloneGivesItsNumbers) {
  constexpr std::string_view row = R"(
[[integrand]]
family = "genz_product_peak"
dimension = 8
ensemble = 2
[[method]]
name = "plain_mc"
repetitions = 2
[[method]]
name = "genz_malik"
control = "tolerance"
tolerances = [1e-3]
)";
  constexpr std::string_view before = R"(seed = 5
[[integrand]]
family = "genz_gaussian"
dimension = 8
[[method]]
name = "sobol"
label = "sobol_first"
)";
  constexpr std::string_view budget = R"(
[budget]
N = [512]
)";
  const run_output alone =
      run_plan(make_plan(parse_scene(fmt::format("seed = 5{}{}", row, budget), "alone.toml")));
  const run_output second =
      run_plan(make_plan(parse_scene(fmt::format("{}{}{}", before, row, budget), "second.toml")));
  ASSERT_EQ(alone.series.size(), 2u);
  ASSERT_EQ(second.series.size(), 6u);  // three methods on each of the two integrands
  const auto series_of = [](const run_output& out, std::string_view integrand,
                            std::string_view method) -> const convergence_series& {
    for (const auto& s : out.series) {
      if (s.integrand == integrand && s.method == method) return s;
    }
    throw std::runtime_error(fmt::format("no series {} × {}", method, integrand));
  };
  for (const std::string_view method : {"plain_mc", "genz_malik"}) {
    const auto& a = series_of(alone, "genz_product_peak_s8", method);
    const auto& b = series_of(second, "genz_product_peak_s8", method);
    EXPECT_EQ(a.reference, b.reference) << method;
    ASSERT_EQ(a.cells.size(), b.cells.size()) << method;
    for (std::size_t c = 0; c < a.cells.size(); ++c) {
      ASSERT_EQ(a.cells[c].repetitions.size(), b.cells[c].repetitions.size()) << method;
      for (std::size_t r = 0; r < a.cells[c].repetitions.size(); ++r) {
        EXPECT_EQ(a.cells[c].repetitions[r].value, b.cells[c].repetitions[r].value) << method;
        EXPECT_EQ(a.cells[c].repetitions[r].evaluations, b.cells[c].repetitions[r].evaluations)
            << method;
      }
    }
  }
}

// The scene's `rng` reaches every method that draws random numbers (core/rng.hpp): under ARS the
// random methods give other numbers than under Philox, bitwise the same for 1 and 2 threads (the
// counter layout is the same, so thread independence holds for either); the deterministic rule
// and the integrands themselves (their exact values: a Genz instance is drawn from Philox under
// both) do not change.
TEST(RunPlan, TheSceneGeneratorKeysEveryRandomMethodAndStaysThreadIndependent) {
  constexpr std::string_view methods = R"(seed = 11
[[integrand]]
family = "genz_gaussian"
dimension = 3
[[method]]
name = "plain_mc"
repetitions = 3
[[method]]
name = "jittered"
repetitions = 2
[[method]]
name = "latin_hypercube"
repetitions = 2
[[method]]
name = "sobol"
repetitions = 2
[[method]]
name = "vegas"
repetitions = 2
[[method]]
name = "midpoint"
[budget]
N = [512]
)";
  const auto run_with = [&](std::string_view rng, unsigned threads) {
    scene sc = parse_scene(fmt::format("{}{}", rng, methods), "rng.toml");
    sc.threads = threads;
    return run_plan(make_plan(sc));
  };
  const run_output philox = run_with("", 1);
  const run_output ars1 = run_with("rng = \"ars4x32_7\"\n", 1);
  const run_output ars2 = run_with("rng = \"ars4x32_7\"\n", 2);
  ASSERT_EQ(philox.series.size(), 6u);
  ASSERT_EQ(ars1.series.size(), 6u);
  ASSERT_EQ(ars2.series.size(), 6u);
  for (std::size_t k = 0; k < philox.series.size(); ++k) {
    const convergence_series& p = philox.series[k];
    const convergence_series& a = ars1.series[k];
    const convergence_series& b = ars2.series[k];
    EXPECT_EQ(p.reference, a.reference) << p.method;
    ASSERT_EQ(a.cells.size(), 1u);
    ASSERT_EQ(a.cells[0].repetitions.size(), p.cells[0].repetitions.size()) << p.method;
    bool any_differs = false;
    for (std::size_t r = 0; r < a.cells[0].repetitions.size(); ++r) {
      EXPECT_EQ(a.cells[0].repetitions[r].value, b.cells[0].repetitions[r].value) << p.method;
      EXPECT_EQ(a.cells[0].repetitions[r].evaluations, b.cells[0].repetitions[r].evaluations)
          << p.method;
      any_differs |= a.cells[0].repetitions[r].value != p.cells[0].repetitions[r].value;
    }
    EXPECT_EQ(any_differs, p.method != "midpoint") << p.method;
  }
}

// A tolerance the method cannot reach within its budget: genz_malik to 1e-300 stops at
// max_evaluations with its own estimate far above the target, and the cell says so (reached 0),
// while 1e-2 is reached; a sized cell has no `reached`.
TEST(RunPlan, ToleranceCellsSayWhetherTheyReachedTheTarget) {
  const plan p = make_plan(parse_scene(R"(seed = 1
[[integrand]]
family = "genz_gaussian"
dimension = 2
[[method]]
name = "genz_malik"
control = "tolerance"
tolerances = [1e-2, 1e-300]
[[method]]
name = "plain_mc"
repetitions = 4
[budget]
N = [256]
max_evaluations = 2000
)",
                                       "reach.toml"));
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 2u);
  const auto& cells = out.series[0].cells;
  ASSERT_EQ(cells.size(), 2u);
  const cell_statistics easy =
      compute_cell_statistics(cells[0].repetitions, out.series[0].reference);
  const cell_statistics hard =
      compute_cell_statistics(cells[1].repetitions, out.series[0].reference);
  EXPECT_EQ(easy.reached, 1.0) << easy.error_estimate;
  EXPECT_EQ(hard.reached, 0.0) << hard.error_estimate;
  EXPECT_LE(hard.evaluations, 2000u);
  EXPECT_GT(hard.error_estimate, 1e-300);
  EXPECT_TRUE(std::isnan(
      compute_cell_statistics(out.series[1].cells[0].repetitions, out.series[1].reference)
          .reached));
}

TEST(RunPlan, AccumulatorReachesTheRuleAndProgressIsPerRepetition) {
  const plan p = make_plan(parse_scene(accumulators, "acc.toml"));
  std::vector<run_progress> reports;
  run_options options;
  options.on_progress = [&](const run_progress& r) { reports.push_back(r); };
  const run_output out = run_plan(p, options);
  ASSERT_EQ(out.series.size(), 3u);
  EXPECT_EQ(out.series[0].method, "midpoint_naive");
  EXPECT_EQ(out.series[1].method, "midpoint_neumaier");
  const double exact = std::exp(1.0) - 1.0;
  const double naive = out.series[0].cells.at(0).repetitions.at(0).value;
  const double neumaier = out.series[1].cells.at(0).repetitions.at(0).value;
  const double n = 4194304.0;
  const double eps = std::numeric_limits<double>::epsilon();
  // Neumaier: midpoint error (e − 1)/(24n²) (Burden & Faires §4.4) plus a few ε·I of rounding.
  EXPECT_NEAR(neumaier, exact, exact / (24 * n * n) + 8 * eps * exact);
  EXPECT_GT(std::abs(naive - exact), 10.0 * std::abs(neumaier - exact))
      << "naive " << naive << ", neumaier " << neumaier;
  // Progress: one report per rule cell, and for the 3 repetitions of plain_mc two intermediate
  // reports plus the cell's own; evaluations grow monotonically to the total.
  ASSERT_EQ(reports.size(), 5u);
  EXPECT_EQ(reports[2].cells_done, 2u);
  EXPECT_EQ(reports[2].evaluations_done, 2 * 4194304u + 1000u);
  EXPECT_EQ(reports.back().cells_done, 3u);
  EXPECT_EQ(reports.back().evaluations_done, reports.back().evaluations_total);
  for (std::size_t i = 1; i < reports.size(); ++i) {
    EXPECT_GT(reports[i].evaluations_done, reports[i - 1].evaluations_done) << i;
  }
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// An ensemble of K instances revisits the same N ladder once per instance: the runner must pool
// them into one cell per N (K × repetitions estimates each), referenced to the mean of the
// instances' exact values, and the series must analyse (distinct N).
TEST(RunPlan, EnsembleInstancesArePooledIntoOneCellPerN) {
  constexpr std::string_view text = R"(name = "ens"
seed = 1
threads = 1
[[integrand]]
family = "genz_gaussian"
dimension = 2
ensemble = 3
[[method]]
name = "plain_mc"
repetitions = 4
[budget]
N = [64, 256, 1024]
)";
  const plan p = make_plan(parse_scene(text, "ens.toml"));
  ASSERT_EQ(p.instances.size(), 3u);
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 1u);
  const convergence_series& series = out.series.front();
  ASSERT_EQ(series.cells.size(), 3u);
  double mean_exact = 0.0;
  for (const plan_instance& inst : p.instances) mean_exact += inst.function.info().exact / 3.0;
  EXPECT_NEAR(series.reference, mean_exact, 4 * std::numeric_limits<double>::epsilon());
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(series.cells[k].n, (std::uint64_t{64} << (2 * k)));
    EXPECT_EQ(series.cells[k].repetitions.size(), 12u) << "3 instances × 4 repetitions";
    EXPECT_EQ(series.cells[k].instances, 3u);
  }
  const convergence_table table = analyse_convergence(series);
  EXPECT_EQ(table.rows.size(), 3u);
  // The ensemble's statistics: the mean of the instances' MSE is the pooled RMSE squared, the
  // median and the worst instance bracket it.
  for (const convergence_row& row : table.rows) {
    EXPECT_EQ(row.ensemble.instances, 3u);
    EXPECT_NEAR(row.ensemble.mse_mean, row.stats.rmse * row.stats.rmse,
                1e-12 * row.ensemble.mse_mean);
    EXPECT_LE(row.ensemble.mse_median, row.ensemble.mse_worst);
    EXPECT_GE(row.ensemble.mse_worst, row.ensemble.mse_mean);
    EXPECT_LE(row.ensemble.mse_ci95_low, row.ensemble.mse_mean);
    EXPECT_GE(row.ensemble.mse_ci95_high, row.ensemble.mse_mean);
  }
}

// Threads: an empty run_options::threads takes the scene's, an explicit 0 means all cores (not
// "the scene's", as it once did), and the run reports the threads it really used: plain MC at
// N = 65536 has several chunks per repetition (sample_mean.hpp), Simpson at N = 9 one.
TEST(RunPlan, ThreadsAllowedAndThreadsUsed) {
  constexpr std::string_view text = R"(name = "threads"
threads = 1
[[integrand]]
family = "exp"
[[method]]
name = "plain_mc"
repetitions = 1
[[method]]
name = "simpson"
[budget]
N = [9, 65536]
)";
  const plan p = make_plan(parse_scene(text, "threads.toml"));
  const unsigned cores = resolve_threads(0);

  const run_output scene_value = run_plan(p);
  EXPECT_EQ(scene_value.threads_allowed, 1u);
  EXPECT_EQ(scene_value.threads, 1u);

  run_options all_cores;
  all_cores.threads = 0u;
  const run_output all = run_plan(p, all_cores);
  EXPECT_EQ(all.threads_allowed, cores);
  EXPECT_EQ(all.threads, std::min(cores, all.threads_allowed));
  EXPECT_GE(all.threads, std::min(cores, 2u)) << "65536 points are more than one chunk";

  // Only the one-chunk cell: however many threads are allowed, one is used.
  const plan small = make_plan(parse_scene(R"(name = "small"
[[integrand]]
family = "exp"
[[method]]
name = "simpson"
[budget]
N = [9]
)",
                                           "small.toml"));
  run_options many;
  many.threads = 64u;
  const run_output one = run_plan(small, many);
  EXPECT_EQ(one.threads_allowed, 64u);
  EXPECT_EQ(one.threads, 1u);
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// The ensemble shift (run.hpp): every pooled estimate is value_k + (Ī − I_k), so that against
// the series' reference Ī its error is instance k's own error value_k − I_k. A deterministic rule
// makes each instance's error a fixed number, computed here directly with the library (same
// rule, same n per axis, same accumulator, same thread count: the same bits), so the pooled
// error must equal it up to the roundings of the shift: fl(Ī − I_k) and fl(value_k + shift)
// are each within ε/2 of their exact sums, and the test's two subtractions add ε/2·|error| each,
// so |pooled error − own error| ≤ ε·(|Ī − I_k| + |pooled value| + |own error|). Without the
// shift the pooled error would be off by Ī − I_k, with the wrong sign by 2(Ī − I_k); the test
// asserts that these differences exceed the tolerance by orders of magnitude for these drawn
// instances, so both mutations fail.
TEST(RunPlan, EnsembleErrorsAreEachInstancesOwnError) {
  constexpr std::string_view text = R"(name = "shift"
seed = 5
threads = 1
[[integrand]]
family = "genz_gaussian"
dimension = 2
ensemble = 4
[[method]]
name = "midpoint"
[budget]
N = [16, 64, 256]
)";
  const plan p = make_plan(parse_scene(text, "shift.toml"));
  ASSERT_EQ(p.instances.size(), 4u);
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 1u);
  const convergence_series& series = out.series.front();
  const double mean_reference = series.reference;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  std::size_t checked = 0;
  for (const plan_cell& cell : p.cells) {
    const plan_instance& inst = p.instance_of(cell);
    const double exact = inst.function.info().exact;
    const double own_value =
        integrate(inst.function, midpoint_rule{}, cell.per_axis, 1, summation::pairwise).value;
    const double own_error = own_value - exact;
    const auto pooled_cell =
        std::find_if(series.cells.begin(), series.cells.end(),
                     [&](const convergence_cell& c) { return c.n == cell.nominal_N; });
    ASSERT_NE(pooled_cell, series.cells.end()) << "N = " << cell.nominal_N;
    ASSERT_EQ(pooled_cell->repetitions.size(), p.instances.size()) << "one estimate per instance";
    // Cells run in (integrand, instance, method, N) order, so repetition k is instance k.
    const double pooled_value = pooled_cell->repetitions.at(cell.instance).value;
    const double pooled_error = pooled_value - mean_reference;
    const double shift = mean_reference - exact;
    const double tolerance = eps * (std::abs(shift) + std::abs(pooled_value) + std::abs(own_error));
    EXPECT_NEAR(pooled_error, own_error, tolerance)
        << "instance " << cell.instance << ", N = " << cell.nominal_N;
    // The instances must differ enough that a missing or reversed shift is visible.
    EXPECT_GT(std::abs(shift), 1e6 * tolerance) << "instance " << cell.instance;
    ++checked;
  }
  EXPECT_EQ(checked, 4u * 3u) << "4 instances × 3 N";
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// eˣ on [0, 1], except NaN at one point: what a family with a hole in its formula would give.
struct exp_with_a_hole {
  double hole;
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      y[i] = x[i] == hole ? std::numeric_limits<double>::quiet_NaN() : std::exp(x[i]);
    }
  }
  integrand_info info() const {
    return integrand_info{.name = "exp_with_a_hole",
                          .formula = "eˣ, NaN at one point",
                          .domain = box::unit(1),
                          .exact = std::exp(1.0) - 1.0,
                          .reference = "closed form"};
  }
};

// Finite values whose sum overflows: 1e308 everywhere, exact 1e308.
struct huge_constant {
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double>, std::span<double> y) const noexcept {
    for (double& v : y) v = 1e308;
  }
  integrand_info info() const {
    return integrand_info{.name = "huge_constant",
                          .formula = "1e308",
                          .domain = box::unit(1),
                          .exact = 1e308,
                          .reference = "closed form"};
  }
};

std::string run_error_of(const plan& p) {
  try {
    run_plan(p);
  } catch (const run_error& e) {
    return e.what();
  }
  return "no run_error";
}

// "invalid error[0] = -nan" named neither the cell nor the key. A value that is not finite now
// stops the run with the cell (method, integrand, N, repetition) before the cause and its point.
TEST(RunPlan, ANonFiniteValueNamesTheCellAndThePoint) {
  plan p = make_plan(parse_scene(R"([[integrand]]
family = "exp"
[[method]]
name = "trapezoid"
[budget]
N = [3, 5]
)",
                                 "hole.toml"));
  // Trapezoid with n = 4 panels on [0, 1] evaluates x = 0.75.
  p.instances[0].function = any_integrand(exp_with_a_hole{0.75});
  const std::string m = run_error_of(p);
  EXPECT_EQ(m.rfind("trapezoid × exp, N = 5 (5 evaluations), repetition 1 of 1: ", 0), 0u) << m;
  EXPECT_NE(m.find("exp_with_a_hole returned nan at x = (0.75)"), std::string::npos) << m;
}

TEST(RunPlan, AnEstimateThatOverflowsNamesTheCell) {
  plan p = make_plan(parse_scene(R"([[integrand]]
family = "exp"
[[method]]
name = "plain_mc"
repetitions = 2
[budget]
N = [4]
)",
                                 "huge.toml"));
  p.instances[0].function = any_integrand(huge_constant{});
  // 4·1e308 overflows in the batch sum (Neumaier's correction then gives inf − inf = NaN).
  const std::string m = run_error_of(p);
  EXPECT_EQ(
      m.rfind("plain_mc × exp, N = 4 (4 evaluations), repetition 1 of 2: the estimate is ", 0), 0u)
      << m;
  EXPECT_NE(m.find("the sum of its values (f·volume, or f/p for importance sampling) overflowed"),
            std::string::npos)
      << m;
}

// Simpson on eˣ over [0, 700]: I ≈ 1.0e304 and the first errors ≈ 1e302 square to inf; the run
// ended with "invalid error[0] = -nan". The cell statistics scale the errors, so the series
// analyses with finite errors and the slope of Simpson's h⁴.
TEST(RunPlan, HugeIntegralsAnalyseWithFiniteErrors) {
  const plan p = make_plan(parse_scene(R"([[integrand]]
family = "exp"
lower = 0.0
upper = 700.0
[[method]]
name = "simpson"
panels = [2048, 4096, 8192, 16384]
[budget]
N = [8]
)",
                                       "big.toml"));
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 1u);
  const convergence_table table = analyse_convergence(out.series[0]);
  ASSERT_EQ(table.rows.size(), 4u);
  for (const auto& row : table.rows) {
    EXPECT_TRUE(std::isfinite(row.stats.rmse) && row.stats.rmse > 1e200) << row.stats.rmse;
  }
  // h = 700/n: Simpson's error (b − a)h⁴f⁽⁴⁾/180 falls 16× per doubling while h ≫ 1 is far from
  // asymptotic only in the constant; the fitted slope of |error| against N = n + 1 is −4 ± 0.1.
  ASSERT_TRUE(table.fit.ok());
  EXPECT_NEAR(table.fit.slope, -4.0, 0.1);
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// tolerance_kind = "relative": the method is asked for tolerance·|I|. On eˣ over [0, 10]
// (I = e¹⁰ − 1 ≈ 2.2·10⁴) a relative 1e-9 is an absolute 2.2·10⁻⁵: Romberg's own estimate must
// be below that, and an absolute 1e-9 (10⁴ times tighter) must spend more evaluations.
TEST(RunPlan, ARelativeToleranceIsAFractionOfTheIntegral) {
  constexpr std::string_view text = R"(name = "rel"
threads = 1
[[integrand]]
family = "exp"
lower = 0.0
upper = 10.0
[[method]]
name = "romberg"
label = "relative"
control = "tolerance"
tolerance_kind = "relative"
tolerances = [1e-9]
[[method]]
name = "romberg"
label = "absolute"
control = "tolerance"
tolerances = [1e-9]
[budget]
N = [33]
)";
  const plan p = make_plan(parse_scene(text, "rel.toml"));
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 2u);
  const double integral = std::exp(10.0) - 1.0;
  const repetition_result& relative = out.series[0].cells.at(0).repetitions.at(0);
  const repetition_result& absolute = out.series[1].cells.at(0).repetitions.at(0);
  EXPECT_LE(relative.error_estimate, 1e-9 * integral);
  EXPECT_LE(absolute.error_estimate, 1e-9);
  EXPECT_LT(relative.evaluations, absolute.evaluations);
  EXPECT_EQ(out.series[0].cells[0].tolerance, 1e-9) << "the series keeps the scene's tolerance";
}

// Cells run to a tolerance through the runner: each records the evaluations it spent and its own
// error estimate, tighter tolerances spend more, and the series analyses against evaluations
// spent (budget control likewise spends at most its N).
TEST(RunPlan, ToleranceAndBudgetCellsRecordWhatTheySpent) {
  constexpr std::string_view text = R"(name = "tol"
threads = 1
[[integrand]]
family = "exp"
[[method]]
name = "romberg"
control = "tolerance"
tolerances = [1e-4, 1e-8, 1e-12]
[[method]]
name = "romberg"
label = "romberg_budget"
control = "budget"
[budget]
N = [33, 1025, 1048577]
)";
  const plan p = make_plan(parse_scene(text, "tol.toml"));
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 2u);
  const convergence_series& tol = out.series[0];
  ASSERT_EQ(tol.cells.size(), 3u);
  std::uint64_t spent = 0;
  for (const convergence_cell& cell : tol.cells) {
    ASSERT_EQ(cell.repetitions.size(), 1u);
    const repetition_result& r = cell.repetitions[0];
    EXPECT_LE(r.error_estimate, cell.tolerance);
    EXPECT_GE(r.evaluations, spent);
    spent = r.evaluations;
    EXPECT_TRUE(std::isnan(cell.error_envelope))
        << "no a-priori envelope for a cell stopping early";
  }
  const convergence_table table = analyse_convergence(tol);
  EXPECT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.rows.front().tolerance, 1e-4);
  EXPECT_FALSE(std::isnan(table.rows.front().stats.error_estimate));
  // The budget cells: never more than N, and the largest stops well short of 2^20 + 1.
  const convergence_series& budget = out.series[1];
  for (const convergence_cell& cell : budget.cells) {
    EXPECT_LE(cell.repetitions[0].evaluations, cell.n);
  }
  EXPECT_LT(budget.cells.back().repetitions[0].evaluations, 1048577u);
  // Two budgets that both converge early spend the same: one point of the fit, not two.
  const convergence_table spent_budget = analyse_convergence(budget);
  EXPECT_EQ(spent_budget.rows.size(), 3u);
  EXPECT_EQ(spent_budget.rows[1].stats.evaluations, spent_budget.rows[2].stats.evaluations);
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// A given reference replaces the exact value in the series: the estimates are the method's own
// (not shifted), and every error is measured from the given value. reference = 1.7 is 0.018 off
// e − 1, far more than the midpoint errors (e − 1)/(24n²) ≤ 4.5e-3 at n = 4, so errors against
// the exact value and against 1.7 cannot be confused.
TEST(RunPlan, AGivenReferenceReplacesTheExactValueInTheSeries) {
  constexpr std::string_view base = R"(name = "given"
[[integrand]]
family = "exp"
REFERENCE
[[method]]
name = "midpoint"
panels = [4, 16, 64]
[budget]
N = [4]
)";
  const auto text = [&](std::string_view reference) {
    std::string s(base);
    s.replace(s.find("REFERENCE"), 9, reference);
    return s;
  };
  const run_output exact = run_plan(make_plan(parse_scene(text(""), "exact.toml")), run_options{});
  const run_output given = run_plan(
      make_plan(parse_scene(text("reference = 1.7\nreference_uncertainty = 1e-4"), "given.toml")),
      run_options{});
  ASSERT_EQ(given.series.size(), 1u);
  const convergence_series& series = given.series[0];
  EXPECT_EQ(series.reference, 1.7);
  EXPECT_EQ(series.reference_uncertainty, 1e-4);
  EXPECT_EQ(exact.series[0].reference, std::exp(1.0) - 1.0);
  EXPECT_EQ(exact.series[0].reference_uncertainty, 0.0);
  ASSERT_EQ(series.cells.size(), 3u);
  for (std::size_t k = 0; k < series.cells.size(); ++k) {
    // The same rule on the same integrand: bitwise the same estimate, only the reference differs.
    EXPECT_EQ(series.cells[k].repetitions.at(0).value,
              exact.series[0].cells[k].repetitions.at(0).value);
  }
  const convergence_table table = analyse_convergence(series);
  for (const convergence_row& row : table.rows) {
    EXPECT_DOUBLE_EQ(row.stats.rmse, std::abs(row.stats.estimate_mean - 1.7)) << "N = " << row.n;
    // (e − 1) − 1.7 = 0.01828…, less the midpoint error (e − 1)/(24n²) ≤ 4.5e-3 (the midpoint
    // rule underestimates a convex f): at least 0.0137, while |estimate − (e − 1)| ≤ 4.5e-3.
    EXPECT_GT(row.stats.rmse, 0.0137) << "N = " << row.n;
  }
}

}  // namespace
}  // namespace quadmc
