// Tests of scene/paired_timing.hpp: which plan cells are timed again (the winners
// time_to_error_cells chose), how often and in which order (quadmc, peer, quadmc, peer, …), the
// budget and a failing call, and the pass as run_scene runs it. A fake timer stands for the clock
// wherever order or values are checked; no test asserts anything about speed.
#include "quadmc/scene/paired_timing.hpp"

#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/run_scene.hpp"
#include "scene_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {
namespace {

using test_support::replace;

// Two integrands (s = 2, 3), quadmc's genz_malik to two relative tolerances, and a "peer" — the
// suite's Sobol' method labelled peer_sobol, which makes it a peer by its name — on an N ladder,
// so that a pair's peer cell is a ladder cell (its smallest N meeting the target). Stable timing
// 0: the run times each cell once, and the pass is left to each test (rounds 0 here).
constexpr std::string_view pair_scene = R"(name = "pairs"
threads = 1
[[integrand]]
family = "genz_gaussian"
dimensions = [2, 3]
[[method]]
name = "genz_malik"
control = "tolerance"
tolerance_kind = "relative"
tolerances = [1e-3, 1e-6]
[[method]]
name = "sobol"
label = "peer_sobol"
repetitions = 4
[budget]
N = [64, 256, 1024, 4096, 16384]
timing_min_seconds = 0
paired_timing_rounds = 0
)";

scene_results run_pair_scene(std::string_view text = pair_scene) {
  return run_scene(make_plan(parse_scene(text, "pairs.toml")));
}

// The plan cell a test expects for (method label, integrand, N or tolerance), found by hand.
std::size_t plan_cell_of(const plan& p, std::string_view label, std::string_view integrand,
                         std::uint64_t n, double tolerance) {
  for (std::size_t k = 0; k < p.cells.size(); ++k) {
    const plan_cell& c = p.cells[k];
    if (p.source.methods[c.method].label != label) continue;
    if (p.source.integrands[c.integrand].name != integrand) continue;
    if (std::isnan(tolerance) ? c.nominal_N == n : c.tolerance == tolerance) return k;
  }
  ADD_FAILURE() << "no plan cell " << label << " × " << integrand;
  return p.cells.size();
}

// A timer that records which cell it timed and returns 1, 2, 3, … ms: the values tell the calls
// apart, so each pair's rounds can be traced to the calls that made them.
struct recording_timer {
  std::vector<std::size_t> calls;
  double operator()(std::size_t index) {
    calls.push_back(index);
    return 1e-3 * static_cast<double>(calls.size());
  }
};

cell_timer timer_of(recording_timer& t) {
  return [&t](std::size_t index) { return t(index); };
}

TEST(PairedTiming, TimesEachCellsTwoWinnersAlternatelyRoundByRound) {
  const scene_results r = run_pair_scene();
  const std::vector<time_to_error_cell> cells = time_to_error_cells(r.tables);
  std::vector<const time_to_error_cell*> both;
  for (const time_to_error_cell& c : cells) {
    if (c.has_both()) both.push_back(&c);
  }
  ASSERT_GE(both.size(), 2u) << "the scene should give cells that both sides reach";

  for (const std::size_t rounds : {5u, 7u}) {
    recording_timer timer;
    const paired_timing_outcome out =
        time_pairs(r.plan, r.tables, {.rounds = rounds, .budget_spent = {}}, timer_of(timer));
    EXPECT_EQ(out.rounds, rounds);
    EXPECT_TRUE(out.not_paired.empty());
    ASSERT_EQ(out.pairs.size(), both.size());
    ASSERT_EQ(timer.calls.size(), both.size() * 2 * rounds);
    for (std::size_t j = 0; j < both.size(); ++j) {
      const time_to_error_cell& c = *both[j];
      const time_to_error_pair& pair = out.pairs[j];
      EXPECT_TRUE(pairs_cell(pair, c)) << "pair " << j;
      EXPECT_EQ(pair.quadmc_method, "genz_malik");
      EXPECT_EQ(pair.peer_method, "peer_sobol");
      EXPECT_EQ(pair.family, "genz_gaussian");
      ASSERT_EQ(pair.rounds(), rounds);
      // The winners' plan cells: genz_malik's cell at this tolerance, and peer_sobol's at the
      // smallest N whose RMSE meets the target (the row time_to_error_cells chose).
      const time_to_error_entry& peer = c.methods[*c.best_peer];
      const std::uint64_t peer_n = r.tables[peer.table].rows[peer.row].n;
      EXPECT_EQ(pair.peer_n, peer_n);
      EXPECT_EQ(pair.quadmc_n, 0u) << "a tolerance cell has no N";
      EXPECT_EQ(pair.peer_evaluations, peer.evaluations);
      const std::size_t quadmc_cell =
          plan_cell_of(r.plan, "genz_malik", c.integrand, 0, c.tolerance);
      const std::size_t peer_cell = plan_cell_of(r.plan, "peer_sobol", c.integrand, peer_n,
                                                 std::numeric_limits<double>::quiet_NaN());
      for (std::size_t i = 0; i < rounds; ++i) {
        // Calls of pair j: 2·rounds of them, quadmc then peer in every round.
        const std::size_t at = 2 * rounds * j + 2 * i;
        EXPECT_EQ(timer.calls[at], quadmc_cell) << "pair " << j << ", round " << i + 1;
        EXPECT_EQ(timer.calls[at + 1], peer_cell) << "pair " << j << ", round " << i + 1;
        EXPECT_EQ(pair.quadmc_seconds[i], 1e-3 * static_cast<double>(at + 1));
        EXPECT_EQ(pair.peer_seconds[i], 1e-3 * static_cast<double>(at + 2));
      }
    }
  }
}

TEST(PairedTiming, NoRoundsTimeNothing) {
  const scene_results r = run_pair_scene();
  recording_timer timer;
  const paired_timing_outcome out =
      time_pairs(r.plan, r.tables, {.rounds = 0, .budget_spent = {}}, timer_of(timer));
  EXPECT_TRUE(timer.calls.empty());
  EXPECT_FALSE(out.ran());
  EXPECT_EQ(out.rounds, 0u);
  // The run itself, with paired_timing_rounds = 0, did not pair either.
  EXPECT_FALSE(r.paired_timing.ran());
}

TEST(PairedTiming, ASpentBudgetStartsNoPairAndSaysWhy) {
  const scene_results r = run_pair_scene();
  std::size_t both = 0;
  for (const time_to_error_cell& c : time_to_error_cells(r.tables)) both += c.has_both();
  recording_timer timer;
  paired_timing_options options;
  options.rounds = 5;
  std::size_t asked = 0;
  // Spent after the first pair: that pair is timed whole, the others not at all.
  options.budget_spent = [&]() -> std::optional<std::string> {
    return asked++ == 0 ? std::nullopt : std::optional<std::string>("budget spent (test)");
  };
  const paired_timing_outcome out = time_pairs(r.plan, r.tables, options, timer_of(timer));
  ASSERT_EQ(out.pairs.size(), 1u);
  EXPECT_EQ(out.pairs[0].rounds(), 5u);
  EXPECT_EQ(timer.calls.size(), 10u);
  ASSERT_EQ(out.not_paired.size(), both - 1);
  for (const std::string& why : out.not_paired) {
    EXPECT_NE(why.find("budget spent (test)"), std::string::npos) << why;
    EXPECT_NE(why.find("genz_gaussian, s = "), std::string::npos) << why;
  }
}

// A call that fails while a pair is timed costs that pair only: it is listed with the error, and
// the other pairs are timed.
TEST(PairedTiming, AFailingCallCostsItsPairOnly) {
  const scene_results r = run_pair_scene();
  std::size_t both = 0;
  for (const time_to_error_cell& c : time_to_error_cells(r.tables)) both += c.has_both();
  std::size_t calls = 0;
  const cell_timer failing_once = [&](std::size_t) -> double {
    if (++calls == 4) throw std::runtime_error("the peer's process ended");  // pair 1, round 2
    return 1e-3;
  };
  const paired_timing_outcome out =
      time_pairs(r.plan, r.tables, {.rounds = 5, .budget_spent = {}}, failing_once);
  ASSERT_EQ(out.not_paired.size(), 1u);
  EXPECT_NE(out.not_paired[0].find("genz_malik × peer_sobol: the peer's process ended"),
            std::string::npos)
      << out.not_paired[0];
  EXPECT_EQ(out.pairs.size(), both - 1);
  // A timing of 0 s (below the clock) cannot make a ratio: refused the same way.
  const paired_timing_outcome zero = time_pairs(r.plan, r.tables, {.rounds = 5, .budget_spent = {}},
                                                [](std::size_t) { return 0.0; });
  EXPECT_TRUE(zero.pairs.empty());
  EXPECT_EQ(zero.not_paired.size(), both);
}

TEST(PairedTiming, TheWinningPlanCellOfATableRow) {
  const scene_results r = run_pair_scene();
  for (const convergence_table& t : r.tables) {
    for (std::size_t row = 0; row < t.rows.size(); ++row) {
      const plan_cell& c = r.plan.cells[winning_plan_cell(r.plan, t, row)];
      EXPECT_EQ(r.plan.source.methods[c.method].label, t.method);
      EXPECT_EQ(r.plan.source.integrands[c.integrand].name, t.integrand);
      EXPECT_EQ(c.instance, 0u);
      if (std::isnan(t.rows[row].tolerance)) {
        EXPECT_EQ(c.nominal_N, t.rows[row].n);
      } else {
        EXPECT_EQ(c.tolerance, t.rows[row].tolerance);
      }
    }
  }
  // A table the plan did not run (another method) is refused, not matched to a wrong cell.
  convergence_table foreign = r.tables.front();
  foreign.method = "midpoint";
  EXPECT_THROW((void)winning_plan_cell(r.plan, foreign, 0), invalid_argument);
  EXPECT_THROW((void)winning_plan_cell(r.plan, r.tables.front(), r.tables.front().rows.size()),
               invalid_argument);
}

TEST(PairedTiming, WhichScenesCanPair) {
  const scene with_peer = parse_scene(pair_scene, "pairs.toml");
  EXPECT_TRUE(may_pair_time_to_error(with_peer));
  // No peer; no tolerance method; nothing but peers.
  EXPECT_FALSE(may_pair_time_to_error(
      parse_scene(replace(pair_scene, "label = \"peer_sobol\"", "label = \"own_sobol\""), "a")));
  EXPECT_FALSE(may_pair_time_to_error(
      parse_scene(replace(pair_scene,
                          "control = \"tolerance\"\ntolerance_kind = \"relative\"\n"
                          "tolerances = [1e-3, 1e-6]\n",
                          ""),
                  "b")));
  EXPECT_FALSE(
      may_pair_time_to_error(parse_scene(replace(pair_scene, "name = \"genz_malik\"\n",
                                                 "name = \"genz_malik\"\nlabel = \"peer_gm\"\n"),
                                         "c")));
}

// End to end with the runner's own timer (time_cell_estimate): run_scene pairs every cell both
// sides reach, budget.paired_timing_rounds rounds each, every time a usable one; a scene with
// nothing to pair runs no pass.
TEST(PairedTiming, RunScenePairsTheWinnersWithTheRunnersTimer) {
  const scene_results r =
      run_pair_scene(replace(pair_scene, "paired_timing_rounds = 0", "paired_timing_rounds = 5"));
  std::size_t both = 0;
  for (const time_to_error_cell& c : time_to_error_cells(r.tables)) both += c.has_both();
  const paired_timing_outcome& out = r.paired_timing;
  EXPECT_EQ(out.rounds, 5u);
  EXPECT_TRUE(out.not_paired.empty()) << out.not_paired.front();
  ASSERT_EQ(out.pairs.size(), both);
  for (const time_to_error_pair& pair : out.pairs) {
    ASSERT_EQ(pair.rounds(), 5u);
    const paired_ratio ratio = summarise_pair(pair);  // throws for an unusable time
    EXPECT_LE(ratio.min, ratio.median);
    EXPECT_LE(ratio.median, ratio.max);
  }
  EXPECT_GE(out.seconds, 0.0);

  const scene_results own = run_pair_scene(
      replace(replace(pair_scene, "paired_timing_rounds = 0", "paired_timing_rounds = 5"),
              "label = \"peer_sobol\"", "label = \"own_sobol\""));
  EXPECT_EQ(own.paired_timing.rounds, 5u);
  EXPECT_FALSE(own.paired_timing.ran());
}

}  // namespace
}  // namespace quadmc
