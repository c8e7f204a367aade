// Tests of scene/schedule.hpp in one process, on synthetic costs: the LPT bound, ties, one huge
// cell, the split policies, the cost model's fit and the probes it is fitted at. The MPI runner
// that applies the assignment is tested under mpirun (tests/mpi/).
#include "quadmc/scene/schedule.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/scene/parse.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace quadmc {
namespace {

std::vector<double> loads(const std::vector<cell_placement>& placement,
                          const std::vector<double>& cost, unsigned processes) {
  std::vector<double> load(processes, 0.0);
  for (std::size_t i = 0; i < cost.size(); ++i) {
    if (!placement[i].split) load[placement[i].rank] += cost[i];
  }
  return load;
}

// Graham's bound for list scheduling, which LPT is an instance of: the makespan is at most
// total/K + the largest cell. Checked on 200 fixed pseudo-random cost vectors (exponential costs
// over 5 orders of magnitude, 1 … 60 cells, K = 1 … 7); no split, so every cell counts.
TEST(Schedule, LptMakespanIsWithinGrahamsBound) {
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> exponent(-3.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    const auto cells = static_cast<std::size_t>(1 + rng() % 60);
    const auto processes = static_cast<unsigned>(1 + rng() % 7);
    std::vector<double> cost(cells);
    for (double& c : cost) c = std::pow(10.0, exponent(rng));
    const std::vector<bool> shares(cells, true);
    const auto placement = assign_cells(cost, shares, processes, split_policy::none);
    ASSERT_EQ(placement.size(), cells);
    for (const cell_placement& p : placement) {
      EXPECT_FALSE(p.split);
      EXPECT_LT(p.rank, processes);
    }
    const auto load = loads(placement, cost, processes);
    const double total = std::accumulate(cost.begin(), cost.end(), 0.0);
    const double largest = *std::max_element(cost.begin(), cost.end());
    EXPECT_LE(*std::max_element(load.begin(), load.end()),
              total / processes + largest + 1e-12 * total)
        << "trial " << trial;
  }
}

// Equal costs keep plan order and go round the ranks from rank 0, so every process computes the
// same assignment.
TEST(Schedule, TiesKeepPlanOrderAndTheLowestRank) {
  const std::vector<double> cost(5, 1.0);
  const auto placement = assign_cells(cost, std::vector<bool>(5, true), 2, split_policy::none);
  const unsigned expected[] = {0, 1, 0, 1, 0};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(placement[i].rank, expected[i]) << i;
}

// One cell far above a quarter of the fair share: split when its method shares chunks (every
// rank then takes the small ones by LPT), a rank of its own when it does not; `all` and `none`
// split every cell and no cell.
TEST(Schedule, OneHugeCellIsSplitOnlyWhenItsMethodSharesChunks) {
  const std::vector<double> cost = {100.0, 1.0, 2.0, 3.0};
  const auto shared = assign_cells(cost, {true, true, true, true}, 2, split_policy::automatic);
  EXPECT_TRUE(shared[0].split);
  EXPECT_FALSE(shared[1].split || shared[2].split || shared[3].split);
  // total/(4K) = 106/8 = 13.25: only the huge cell is above it. LPT on 3, 2, 1: ranks 0, 1, 1.
  EXPECT_EQ(shared[3].rank, 0u);
  EXPECT_EQ(shared[2].rank, 1u);
  EXPECT_EQ(shared[1].rank, 1u);

  const auto whole = assign_cells(cost, {false, true, true, true}, 2, split_policy::automatic);
  EXPECT_FALSE(whole[0].split);
  EXPECT_EQ(whole[0].rank, 0u);
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(whole[i].rank, 1u) << i;

  for (const cell_placement& p :
       assign_cells(cost, {false, false, false, false}, 2, split_policy::all)) {
    EXPECT_TRUE(p.split);
  }
  for (const cell_placement& p :
       assign_cells(cost, {true, true, true, true}, 2, split_policy::none)) {
    EXPECT_FALSE(p.split);
  }
}

TEST(Schedule, BadInputIsRefusedNamingIt) {
  EXPECT_THROW(assign_cells(std::vector<double>{1.0}, {true}, 0, split_policy::none),
               invalid_argument);
  EXPECT_THROW(assign_cells(std::vector<double>{1.0, 2.0}, {true}, 2, split_policy::none),
               invalid_argument);
  const std::string m = test_support::message_of([] {
    assign_cells(std::vector<double>{1.0, std::nan("")}, {true, true}, 2, split_policy::none);
  });
  EXPECT_NE(m.find("invalid cost[1] = nan"), std::string::npos) << m;
  EXPECT_THROW(fit_series_cost(1, -1.0, 2, 1.0), invalid_argument);
}

// The line through the two timings; a slope lost in the noise falls back to the probe's mean time
// per evaluation (keeping the fixed part), a series timed once to that mean alone; no cell is
// free.
TEST(Schedule, SeriesCostIsTheLineThroughItsTwoTimings) {
  const series_cost line = fit_series_cost(1, 1e-5, 1001, 2e-5);
  EXPECT_DOUBLE_EQ(line.fixed, 1e-5);
  EXPECT_DOUBLE_EQ(line.per_evaluation, 1e-5 / 1000.0);
  const series_cost noisy = fit_series_cost(10, 3e-5, 1000, 2e-5);
  EXPECT_EQ(noisy.fixed, 3e-5);
  EXPECT_DOUBLE_EQ(noisy.per_evaluation, 2e-8);
  const series_cost once = fit_series_cost(500, 1e-3, 500, 1e-3);
  EXPECT_EQ(once.fixed, 0.0);
  EXPECT_DOUBLE_EQ(once.per_evaluation, 2e-6);
  EXPECT_EQ(fit_series_cost(0, 0.0, 0, 0.0).per_evaluation, 1e-12);
}

// Probes and costs on a real plan: per (integrand, method) series, the smallest cell and the
// largest of at most 2^16 evaluations (the smallest when all are larger); a cell's cost is
// repetitions × (fixed + evaluations × per_evaluation).
TEST(Schedule, ProbesAndCostsOfAPlan) {
  const plan p = make_plan(parse_scene(R"(seed = 1
[[integrand]]
family = "exp"
[[method]]
name = "plain_mc"
repetitions = 3
[[method]]
name = "midpoint"
panels = [100000, 200000]
[budget]
N = [16, 1024, 1048576]
)",
                                       "probes.toml"));
  const cost_probes probes = choose_cost_probes(p);
  ASSERT_EQ(probes.series_of.size(), p.cells.size());
  ASSERT_EQ(probes.smallest.size(), 2u);
  const auto& mc = probes.smallest[0];
  EXPECT_EQ(p.cells[mc].evaluations, 16u);
  EXPECT_EQ(p.cells[probes.probe[0]].evaluations, 1024u);
  EXPECT_EQ(p.cells[probes.smallest[1]].evaluations, 100000u);
  EXPECT_EQ(probes.probe[1], probes.smallest[1]) << "every midpoint cell is above 2^16";

  const std::vector<series_cost> series = {{1e-6, 1e-8}, {0.0, 2e-9}};
  const std::vector<double> cost = cell_costs(p, probes, series);
  for (std::size_t i = 0; i < p.cells.size(); ++i) {
    const series_cost& c = series[probes.series_of[i]];
    EXPECT_DOUBLE_EQ(
        cost[i], static_cast<double>(p.cells[i].repetitions) *
                     (c.fixed + static_cast<double>(p.cells[i].evaluations) * c.per_evaluation));
  }
  EXPECT_TRUE(cell_shares_chunks(p, 0));
  EXPECT_THROW(cell_shares_chunks(p, p.cells.size()), invalid_argument);

  // Timed here: one cost per series, each a real fit (not the nominal cost of a failed probe,
  // whose fixed part is 0 and slope 1e-8), above the floor of 1e-12 s per evaluation.
  const std::vector<series_cost> timed = time_series_costs(p, probes, run_context{1, 1});
  ASSERT_EQ(timed.size(), 2u);
  for (const series_cost& c : timed) {
    EXPECT_GT(c.fixed + c.per_evaluation, 0.0);
    EXPECT_GE(c.per_evaluation, 1e-12);
    EXPECT_TRUE(std::isfinite(c.fixed) && std::isfinite(c.per_evaluation));
  }
}

// eˣ but NaN everywhere: every repetition fails, as a cell that only the run finds bad.
struct not_a_number_anywhere {
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double>, std::span<double> y) const noexcept {
    for (double& v : y) v = std::numeric_limits<double>::quiet_NaN();
  }
  integrand_info info() const {
    return integrand_info{.name = "nan",
                          .formula = "NaN",
                          .domain = box::unit(1),
                          .exact = std::exp(1.0) - 1.0,
                          .reference = "closed form"};
  }
};

// A series whose probe fails keeps the nominal cost: the run proper reports the failure, with
// its cell and repetition; the scheduler must not fail first with less to say.
TEST(Schedule, AFailingProbeKeepsTheNominalCost) {
  plan p = make_plan(parse_scene(R"(seed = 1
[[integrand]]
family = "exp"
[[method]]
name = "midpoint"
[budget]
N = [16, 1024]
)",
                                 "failing.toml"));
  p.instances[0].function = any_integrand(not_a_number_anywhere{});
  const std::vector<series_cost> timed =
      time_series_costs(p, choose_cost_probes(p), run_context{1, 1});
  ASSERT_EQ(timed.size(), 1u);
  EXPECT_EQ(timed[0].fixed, series_cost{}.fixed);
  EXPECT_EQ(timed[0].per_evaluation, series_cost{}.per_evaluation);
}

}  // namespace
}  // namespace quadmc
