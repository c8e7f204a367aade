// The MPI runner (bench/quadmc/mpi_run.hpp) as a function, on the ranks mpirun starts this test
// with (tests/mpi/CMakeLists.txt: 2 and 3 ranks): every repetition of every cell is bitwise what
// run_plan gives on one process, for every split policy; a cell that fails on one rank makes
// the MPI scheduler throw on every rank, and rank 0's message names the cell, the cause and
// the rank. Here, unlike through the command, the plan can hold integrands that fail mid-run.
#include "mpi_run.hpp"

#include "quadmc/scene/cell_scheduler.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"
#include "quadmc/scene/schedule.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace {

quadmc_cli::mpi::world the_world;

using quadmc_cli::mpi::split_policy;

// eˣ on [0, 1], except NaN at one point: what a family with a hole in its formula would give.
struct exp_with_a_hole {
  double hole;
  std::size_t dimension() const noexcept { return 1; }
  void evaluate(std::span<const double> x, std::span<double> y) const noexcept {
    for (std::size_t i = 0; i < y.size(); ++i) {
      y[i] = x[i] == hole ? std::numeric_limits<double>::quiet_NaN() : std::exp(x[i]);
    }
  }
  quadmc::integrand_info info() const {
    return quadmc::integrand_info{.name = "exp_with_a_hole",
                                  .formula = "eˣ, NaN at one point",
                                  .domain = quadmc::box::unit(1),
                                  .exact = std::exp(1.0) - 1.0,
                                  .reference = "closed form"};
  }
};

quadmc::plan plan_of(const char* text) {
  return quadmc::make_plan(quadmc::parse_scene(text, "mpi_runner_test.toml"));
}

// The scene of the bitwise checks: every kind of method, ensembles, a naive sum.
constexpr const char* every_kind = R"(seed = 11
threads = 2
[[integrand]]
family = "genz_gaussian"
dimension = 3
[[integrand]]
family = "genz_continuous"
dimension = 2
ensemble = 2
[[method]]
name = "simpson"
[[method]]
name = "trapezoid"
accumulator = "naive"
[[method]]
name = "plain_mc"
repetitions = 3
[[method]]
name = "jittered"
repetitions = 2
integrands = ["genz_continuous_s2"]
[[method]]
name = "sobol"
repetitions = 4
[[method]]
name = "genz_malik"
control = "budget"
[[method]]
name = "vegas"
control = "budget"
repetitions = 2
[budget]
N = { from = 256, to = 262144, factor = 8 }
)";

// Every repetition of every cell of `p` under `policies` is bitwise what one process computes.
void expect_every_repetition_bitwise(const quadmc::plan& p,
                                     std::initializer_list<split_policy> policies) {
  const quadmc::run_output one = quadmc::run_plan(p);
  for (const split_policy policy : policies) {
    quadmc_cli::mpi::mpi_scheduler scheduler(the_world, policy);
    const quadmc::run_output many = quadmc::run_plan(p, {}, scheduler);
    if (the_world.rank != 0) {
      EXPECT_TRUE(many.series.empty());
      continue;
    }
    ASSERT_EQ(many.series.size(), one.series.size());
    for (std::size_t s = 0; s < one.series.size(); ++s) {
      const auto& a = one.series[s];
      const auto& b = many.series[s];
      ASSERT_EQ(a.method, b.method);
      ASSERT_EQ(a.integrand, b.integrand);
      ASSERT_EQ(a.cells.size(), b.cells.size()) << a.method << " × " << a.integrand;
      for (std::size_t c = 0; c < a.cells.size(); ++c) {
        ASSERT_EQ(a.cells[c].repetitions.size(), b.cells[c].repetitions.size());
        for (std::size_t r = 0; r < a.cells[c].repetitions.size(); ++r) {
          const auto& x = a.cells[c].repetitions[r];
          const auto& y = b.cells[c].repetitions[r];
          const std::string where = a.method + " × " + a.integrand +
                                    ", N = " + std::to_string(a.cells[c].n) + ", repetition " +
                                    std::to_string(r) + ", policy " +
                                    std::to_string(static_cast<int>(policy));
          EXPECT_EQ(std::bit_cast<std::uint64_t>(x.value), std::bit_cast<std::uint64_t>(y.value))
              << where;
          EXPECT_EQ(std::bit_cast<std::uint64_t>(x.std_error),
                    std::bit_cast<std::uint64_t>(y.std_error))
              << where;
          EXPECT_EQ(std::bit_cast<std::uint64_t>(x.error_estimate),
                    std::bit_cast<std::uint64_t>(y.error_estimate))
              << where;
          EXPECT_EQ(x.evaluations, y.evaluations) << where;
        }
      }
    }
  }
}

TEST(MpiRunner, EveryRepetitionIsBitwiseWhatOneProcessComputes) {
  expect_every_repetition_bitwise(plan_of(every_kind),
                                  {split_policy::automatic, split_policy::all, split_policy::none});
}

// ARS-4x32-7 has Philox's counter layout (core/rng.hpp), so a rank's chunks draw what one
// process's would: the same check, with the policy that splits the most.
TEST(MpiRunner, EveryRepetitionUnderArsIsBitwiseWhatOneProcessComputes) {
  const quadmc::plan p = plan_of((std::string("rng = \"ars4x32_7\"\n") + every_kind).c_str());
  ASSERT_EQ(p.source.rng, quadmc::rng_kind::ars4x32_7);
  expect_every_repetition_bitwise(p, {split_policy::all});
}

// `auto` splits the costly cells whose method shares chunks — the naive sum too, split exactly
// (core/split_naive_sum.hpp) — and gives a costly cell whose method does not (Romberg's
// extrapolation table) to one rank; `all` splits every cell (Romberg's then runs whole on every
// rank, still exact: the test above) and `none` none. The three cells of about 2^21 evaluations
// or more are each about a third of the plan's cost, far above the threshold total/(4K).
TEST(MpiRunner, AutoSplitsOnlyCellsWhoseMethodSharesChunks) {
  const quadmc::plan p = plan_of(R"([[integrand]]
family = "exp"
[[method]]
name = "midpoint"
accumulator = "naive"
[[method]]
name = "midpoint"
accumulator = "pairwise"
[[method]]
name = "romberg"
[budget]
N = [1024, 4194304]
)");
  ASSERT_EQ(p.cells.size(), 6u);
  for (const split_policy policy :
       {split_policy::automatic, split_policy::all, split_policy::none}) {
    quadmc_cli::mpi::mpi_scheduler scheduler(the_world, policy);
    (void)quadmc::run_plan(p, {}, scheduler);
    const std::vector<quadmc_cli::mpi::cell_placement>& placement = scheduler.placement();
    ASSERT_EQ(placement.size(), p.cells.size());
    for (std::size_t i = 0; i < p.cells.size(); ++i) {
      const bool shares = quadmc::cell_shares_chunks(p, i);
      EXPECT_EQ(shares, p.source.methods[p.cells[i].method].label != "romberg");
      const bool large = p.cells[i].evaluations > (std::uint64_t{1} << 20);
      const bool expected =
          policy == split_policy::all || (policy == split_policy::automatic && shares && large);
      EXPECT_EQ(placement[i].split, expected)
          << "cell " << i << " (" << p.source.methods[p.cells[i].method].label
          << ", N = " << p.cells[i].nominal_N << "), policy " << static_cast<int>(policy);
      if (!placement[i].split) {
        EXPECT_LT(placement[i].rank, the_world.size);
      }
    }
    const std::string csv = quadmc::cells_csv(p, placement);
    EXPECT_EQ(csv.rfind("integrand,instance,s,method,N,tolerance,evaluations,repetitions,"
                        "shares_chunks,placement\n",
                        0),
              0u);
    if (policy == split_policy::automatic) {
      EXPECT_NE(csv.find("exp,0,1,midpoint_pairwise,4194304,,4194304,1,1,split\n"),
                std::string::npos)
          << csv;
      EXPECT_NE(csv.find("exp,0,1,midpoint_naive,4194304,,4194304,1,1,split\n"), std::string::npos)
          << csv;
      EXPECT_NE(csv.find("exp,0,1,romberg,4194304,,2097153,1,0,rank "), std::string::npos) << csv;
    }
  }
}

// Trapezoid with 2^17 panels evaluates x = 0.75 in chunk 6 of its 9 (2^14 nodes each): split
// across ranks, the failing chunk is another rank's than rank 0's first; unsplit, the cell runs
// on whichever rank the costs gave it.
TEST(MpiRunner, ACellThatFailsOnOneRankFailsTheRunOnEveryRank) {
  quadmc::plan p = plan_of(R"([[integrand]]
family = "exp"
[[method]]
name = "trapezoid"
[[method]]
name = "plain_mc"
repetitions = 2
[budget]
N = [1025, 131073]
)");
  p.instances[0].function = quadmc::any_integrand(exp_with_a_hole{0.75});
  for (const split_policy policy : {split_policy::all, split_policy::none}) {
    std::string message;
    try {
      quadmc_cli::mpi::mpi_scheduler scheduler(the_world, policy);
      (void)quadmc::run_plan(p, {}, scheduler);
    } catch (const quadmc::run_error& e) {
      message = e.what();
    }
    ASSERT_FALSE(message.empty()) << "rank " << the_world.rank << " did not throw";
    if (the_world.rank == 0) {
      EXPECT_EQ(
          message.rfind("trapezoid × exp, N = 1025 (1025 evaluations), repetition 1 of 1: ", 0), 0u)
          << message;
      EXPECT_NE(message.find("exp_with_a_hole returned nan at x = (0.75)"), std::string::npos)
          << message;
      EXPECT_NE(message.find("(on MPI rank "), std::string::npos) << message;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  the_world = quadmc_cli::mpi::start(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  const int status = RUN_ALL_TESTS();
  quadmc_cli::mpi::finish();
  return status;
}
