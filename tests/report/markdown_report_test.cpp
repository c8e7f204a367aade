// Tests for markdown_report.hpp: header, slope summary, per-integrand tables, plot links.
#include "quadmc/report/markdown_report.hpp"

#include "../analysis/series_builder.hpp"
#include "support/floating_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::cell_at;
using test::monte_carlo_theory;
using test::repetition;
using test::rule_theory;
using test::series_of;

using test_support::nan;

std::vector<convergence_table> markdown_sample_tables() {
  convergence_series rule = series_of("genz|odd", 1, "trapezoid", smoothness::analytic, 2.0,
                                      rule_theory(2, smoothness::analytic));
  convergence_series mc = series_of("genz|odd", 1, "plain_mc", smoothness::analytic, 2.0,
                                    monte_carlo_theory(smoothness::analytic));
  for (int k = 1; k <= 26; ++k) {
    const double n = std::ldexp(1.0, k);
    const auto nk = static_cast<std::uint64_t>(n);
    // Trapezoid-like 0.5·N⁻² reaching a floor of ±5e-16.
    rule.cells.push_back(cell_at(
        nk, {repetition(2.0 + 0.5 / (n * n) + (k % 2 ? 5e-16 : -5e-16), nan, nk, 1e-8 * n)}));
    if (k <= 12) {
      mc.cells.push_back(
          cell_at(nk, {repetition(2.0 + 1.0 / std::sqrt(n), 1.0 / std::sqrt(n), nk, 1e-6 * n),
                       repetition(2.0 - 1.0 / std::sqrt(n), 1.0 / std::sqrt(n), nk, 1e-6 * n)}));
    }
  }
  return {analyse_convergence(rule), analyse_convergence(mc)};
}

// A midpoint ladder on a step that stays flat at 2⁻²⁰ under its envelope 1/(2N) (the run of ones
// of convergence_table_test.cpp): an envelope series.
convergence_table envelope_table() {
  const double c = 0.93750095367431640625;
  convergence_series series = series_of("step", 1, "midpoint", smoothness::discontinuous, 1.0 - c,
                                        rule_theory(2, smoothness::discontinuous));
  for (int k = 4; k <= 10; ++k) {
    const auto n = static_cast<std::uint64_t>(1) << k;
    series.cells.push_back(cell_at(n, {repetition(1.0 - c + std::ldexp(1.0, -20), nan, n, 1e-9)}, n,
                                   0.5 / static_cast<double>(n)));
  }
  return analyse_convergence(series);
}

// Every table row has its header's number of cells: '|' outside escapes per line.
void expect_rectangular_tables(const std::string& page) {
  std::size_t start = 0;
  std::size_t expected = 0;
  while (start < page.size()) {
    const std::size_t end = page.find('\n', start);
    const std::string line = page.substr(start, end - start);
    start = end + 1;
    if (line.empty() || line[0] != '|') {
      expected = 0;
      continue;
    }
    std::size_t bars = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++bars;
    }
    if (expected == 0) expected = bars;
    EXPECT_EQ(bars, expected) << line;
  }
}

// A cell run to a tolerance whose own estimate is still above the target when its budget runs
// out (genz_malik at 1e-300 spent 99,977 of 100,000 evaluations) was a row like any other: now
// the table says ❌ and the page lists it under "Targets not reached"; a page whose every cell
// got there says so in one line, and a page without tolerance cells has no such section.
TEST(MarkdownReport, ToleranceCellsThatStoppedOnTheirBudgetAreListed) {
  convergence_series s = series_of("peak", 2, "genz_malik", smoothness::analytic, 1.0,
                                   rule_theory(7, smoothness::analytic));
  const double tolerances[] = {1e-3, 1e-300};
  const double estimates[] = {2e-4, 3e-9};
  const std::uint64_t spent[] = {153, 99977};
  for (int k = 0; k < 2; ++k) {
    repetition_result r = repetition(1.0 + estimates[k] / 2, nan, spent[k], 1e-3);
    r.error_estimate = estimates[k];
    r.target = tolerances[k];
    convergence_cell c = cell_at(0, {r});
    c.tolerance = tolerances[k];
    s.cells.push_back(c);
  }
  const std::vector<convergence_table> tables = {analyse_convergence(s)};
  const std::string page = render_results_markdown(run_info{}, tables);
  EXPECT_NE(page.find("## Targets not reached\n\n1 cell run to a tolerance spent its budget"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("- peak (s = 2), genz_malik, tolerance 1.000e-300: 1 of 1 repetition stopped "
                      "with its error estimate above the target (99977 evaluations, error "
                      "estimate 3.000e-09)"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("| 1.000e-300 | 99977 | 1.500e-09 | ❌ 0 of 1 |"), std::string::npos) << page;
  EXPECT_NE(page.find("| 1.000e-03 | 153 | 1.000e-04 | ✅ |"), std::string::npos) << page;
  expect_rectangular_tables(page);

  // A relative tolerance: the estimate is set beside it as a fraction of |I|; 2 of 3 repetitions
  // short of the target are counted in the plural.
  convergence_series relative = s;
  relative.relative_tolerance = true;
  relative.reference = 2.0;
  for (auto& c : relative.cells) {
    for (auto& r : c.repetitions) r.value += 1.0;
    c.repetitions.push_back(c.repetitions.front());
    c.repetitions.push_back(c.repetitions.front());
    c.repetitions.back().error_estimate = 0.0;  // this one reached every target
  }
  const std::vector<convergence_table> relative_tables = {analyse_convergence(relative)};
  const std::string relative_page = render_results_markdown(run_info{}, relative_tables);
  EXPECT_NE(relative_page.find("genz_malik, relative tolerance 1.000e-300: 2 of 3 repetitions "
                               "stopped with their error estimates above the target"),
            std::string::npos)
      << relative_page;
  // The RMS of the estimates (3e-9, 3e-9, 0) is 2.449e-9, half of it relative to |I| = 2.
  EXPECT_NE(relative_page.find("error estimate 2.449e-09 = 1.225e-09 of |I|)"), std::string::npos)
      << relative_page;

  s.cells.pop_back();
  const std::vector<convergence_table> all_reached = {analyse_convergence(s)};
  const std::string reached = render_results_markdown(run_info{}, all_reached);
  EXPECT_NE(reached.find("## Targets not reached\n\nNone: every cell run to a tolerance"),
            std::string::npos)
      << reached;
  const std::vector<convergence_table> sized_tables = markdown_sample_tables();
  const std::string sized = render_results_markdown(run_info{}, sized_tables);
  EXPECT_EQ(sized.find("Targets not reached"), std::string::npos);
}

TEST(MarkdownReport, EnvelopeSeriesShowsItsVerdictRatioAndEnvelopeColumn) {
  run_info info;
  info.scene = "jumps";
  const std::vector<convergence_table> tables = {envelope_table()};
  ASSERT_EQ(tables[0].verdict, slope_verdict::within_envelope);
  const std::string page = render_results_markdown(info, tables);
  // The summary keeps slope and theory beside the envelope verdict.
  EXPECT_NE(page.find("| step | 1 | midpoint | 0.000 ± 0.000 | -1.000 | within_envelope |"),
            std::string::npos)
      << page;
  // The page says what the two envelope verdicts mean.
  EXPECT_NE(page.find("*within_envelope*"), std::string::npos);
  EXPECT_NE(page.find("*above_envelope*"), std::string::npos);
  // The method section: the verdict with the largest error/envelope 2⁻²⁰·2¹⁰·2 = 1/512, and an
  // envelope column with 1/(2N) (N = 16: 3.125e-02).
  EXPECT_NE(page.find("verdict within_envelope (largest error/envelope 0.00195)"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("| \\|error\\| | envelope | std error |"), std::string::npos) << page;
  EXPECT_NE(page.find("| 16 | 16 | 9.537e-07 | 3.125e-02 |"), std::string::npos) << page;
  expect_rectangular_tables(page);
}

// A quasi-Monte Carlo series whose small-N cells carry discrepancies: its table shows the three
// beside the RMSE (each the root mean square over the repetitions), "—" where N was too large
// to compute them; a series without discrepancies gets no such columns.
TEST(MarkdownReport, DiscrepancyColumnsStandBesideTheErrorOfQuasiMonteCarloCells) {
  convergence_series qmc = series_of("genz|odd", 1, "sobol", smoothness::analytic, 2.0,
                                     monte_carlo_theory(smoothness::analytic));
  for (const std::uint64_t n : {16u, 64u, 4096u}) {
    std::vector<repetition_result> reps;
    for (const double sign : {1.0, -1.0}) {
      repetition_result r = repetition(2.0 + sign / static_cast<double>(n), nan, n, 1e-6);
      if (n <= 64) {
        // Repetition 1: (0.03, 0.3, 3); repetition 2: (0.04, 0.4, 4), divided by N.
        const double k = (sign > 0 ? 3.0 : 4.0) / static_cast<double>(n);
        r.l2_star_discrepancy = 0.01 * k;
        r.centered_discrepancy = 0.1 * k;
        r.wraparound_discrepancy = k;
      }
      reps.push_back(r);
    }
    qmc.cells.push_back(cell_at(n, reps));
  }
  convergence_series mc = series_of("genz|odd", 1, "plain_mc", smoothness::analytic, 2.0,
                                    monte_carlo_theory(smoothness::analytic));
  for (const std::uint64_t n : {16u, 64u, 4096u}) {
    const double e = 1.0 / std::sqrt(static_cast<double>(n));
    mc.cells.push_back(
        cell_at(n, {repetition(2.0 + e, e, n, 1e-6), repetition(2.0 - e, e, n, 1e-6)}));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(qmc), analyse_convergence(mc)};
  const std::string page = render_results_markdown(run_info{}, tables);
  const std::string header =
      "| N | evaluations | RMSE | L2-star discrepancy | centered discrepancy | wrap-around "
      "discrepancy | std error |";
  ASSERT_NE(page.find(header), std::string::npos) << page;
  EXPECT_EQ(page.find(header), page.rfind(header)) << "only the sobol table has the columns";
  // N = 16: RMSE 1/16; discrepancies √((3² + 4²)/2)/16 = 5/(√2·16) = 0.2209709… times 0.01,
  // 0.1 and 1.
  EXPECT_NE(page.find("| 16 | 16 | 6.250e-02 | 2.210e-03 | 2.210e-02 | 2.210e-01 |"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("| 4096 | 4096 | 2.441e-04 | — | — | — |"), std::string::npos) << page;
  // The plain MC table keeps its own layout.
  EXPECT_NE(page.find("| N | evaluations | RMSE | std error |"), std::string::npos) << page;
  expect_rectangular_tables(page);
}

// Two methods on one family in s = 2 and 4 (a `dimensions` list: names end in _s<s>): the table
// names at each N the method of smaller error, with that error; a method without a cell at N
// competes with its cell of the largest N' < N ("at N = N'"), an N where only one method
// competes is "—", and a family with one method has no table.
TEST(MarkdownReport, WhoLeadsAtEqualNPerFamilyAndDimension) {
  std::vector<convergence_table> tables;
  for (const std::size_t s : {2u, 4u}) {
    const std::string name = s == 2 ? "fam_s2" : "fam_s4";
    convergence_series a = series_of(name, s, "rule_a", smoothness::analytic, 1.0,
                                     rule_theory(2, smoothness::analytic, s));
    convergence_series b = series_of(name, s, "rule_b", smoothness::analytic, 1.0,
                                     rule_theory(4, smoothness::analytic, s));
    for (const std::uint64_t n : {16u, 64u, 256u}) {
      const double x = static_cast<double>(n);
      // rule_a: 4/N, but 1/N at (s = 2, N = 16) and 16/N at (s = 2, N = 256); rule_b: 2/N, run
      // at N = 16, 64 in s = 2 and at N = 64, 256 in s = 4.
      const double ea = s == 2 && n == 16 ? 1.0 / x : s == 2 && n == 256 ? 16.0 / x : 4.0 / x;
      a.cells.push_back(cell_at(n, {repetition(1.0 + ea, nan, n, 1e-6)}));
      if ((s == 2 && n != 256) || (s == 4 && n != 16)) {
        b.cells.push_back(cell_at(n, {repetition(1.0 + 2.0 / x, nan, n, 1e-6)}));
      }
    }
    tables.push_back(analyse_convergence(a));
    tables.push_back(analyse_convergence(b));
  }
  convergence_series alone = series_of("solo", 1, "rule_a", smoothness::analytic, 1.0,
                                       rule_theory(2, smoothness::analytic));
  for (const std::uint64_t n : {16u, 64u, 256u}) {
    alone.cells.push_back(
        cell_at(n, {repetition(1.0 + 1.0 / static_cast<double>(n), nan, n, 1e-6)}));
  }
  tables.push_back(analyse_convergence(alone));
  const std::string page = render_results_markdown(run_info{}, tables);
  const auto at = page.find("## Who leads at equal N");
  ASSERT_NE(at, std::string::npos) << page;
  const std::string section = page.substr(at, page.find("\n## ", at + 1) - at);
  EXPECT_NE(section.find("### fam\n"), std::string::npos) << section;
  EXPECT_EQ(section.find("### solo"), std::string::npos) << section;
  EXPECT_NE(section.find("| s | N = 16 | N = 64 | N = 256 |"), std::string::npos) << section;
  EXPECT_NE(section.find("| 2 | rule_a (6.250e-02) | rule_b (3.125e-02) | rule_b (3.125e-02 at N "
                         "= 64) |"),
            std::string::npos)
      << section;
  EXPECT_NE(section.find("| 4 | — | rule_b (3.125e-02) | rule_b (7.812e-03) |"), std::string::npos)
      << section;
  expect_rectangular_tables(page);
}

// Regression: the page of a run with plots = false embedded plots that were not written, and
// with csv = false pointed to CSV files that did not exist.
TEST(MarkdownReport, ThePageLinksOnlyTheFilesTheRunWrote) {
  const std::vector<convergence_table> tables = markdown_sample_tables();
  run_info info;
  info.scene = "unit";
  const std::string all = render_results_markdown(info, tables);
  EXPECT_NE(all.find(".svg)"), std::string::npos);
  EXPECT_NE(all.find("`convergence.csv`"), std::string::npos);
  EXPECT_NE(all.find("](slope_against_theory.svg)"), std::string::npos) << all;
  EXPECT_NE(all.find("](who_leads.png)"), std::string::npos) << all;
  info.plots = false;
  const std::string no_plots = render_results_markdown(info, tables);
  EXPECT_EQ(no_plots.find(".svg"), std::string::npos) << no_plots;
  EXPECT_EQ(no_plots.find(".png"), std::string::npos) << no_plots;
  EXPECT_NE(no_plots.find("`convergence.csv`"), std::string::npos);
  info.csv = false;
  const std::string neither = render_results_markdown(info, tables);
  EXPECT_EQ(neither.find(".svg"), std::string::npos) << neither;
  EXPECT_EQ(neither.find(".csv`"), std::string::npos) << neither;
  EXPECT_NE(neither.find("[output] turns csv off"), std::string::npos) << neither;
}

// The answer (answer_first.hpp) sits between the title with the scene's description and the
// metadata list, in five lines at most, and says what the "Who leads" table further down says:
// change the table's winner and the answer changes with it.
TEST(MarkdownReport, TheAnswerComesFirstInFiveLinesAtMost) {
  run_info info;
  info.scene = "answered";
  info.description = "What the scene is for.";
  info.seed = 7;
  auto tables = markdown_sample_tables();
  std::string page = render_results_markdown(info, tables);
  const std::size_t start = page.find("What the scene is for.\n\n");
  const std::size_t metadata = page.find("- seed: 7\n");
  ASSERT_NE(start, std::string::npos) << page;
  ASSERT_NE(metadata, std::string::npos) << page;
  const std::string block = page.substr(start, metadata - start);
  std::size_t lines = 0;
  for (std::size_t at = block.find("\n> - "); at != std::string::npos;
       at = block.find("\n> - ", at + 1)) {
    ++lines;
  }
  EXPECT_GE(lines, 1u) << block;
  EXPECT_LE(lines, 5u) << block;
  EXPECT_LT(page.find("**Slopes:**"), metadata);
  EXPECT_LT(metadata, page.find("## Who leads at equal N"));
  // trapezoid (0.5/N²) against plain_mc (1/√N): the rule leads the table and the answer.
  EXPECT_NE(page.find("| 1 | trapezoid ("), std::string::npos) << page;
  // It leads from the first N until its own errors reach the rounding floor (±5e-16), where a
  // lead is rounding, not convergence (answer_first.hpp).
  EXPECT_NE(block.find("`trapezoid` leads `genz|odd` (s = 1) at every N until the rounding floor "
                       "at N = "),
            std::string::npos)
      << block;
  // The rule ten million times worse: plain_mc leads both.
  convergence_series rule = series_of("genz|odd", 1, "trapezoid", smoothness::analytic, 2.0,
                                      rule_theory(2, smoothness::analytic));
  for (int k = 1; k <= 12; ++k) {
    const auto n = std::uint64_t{1} << k;
    const double x = static_cast<double>(n);
    rule.cells.push_back(cell_at(n, {repetition(2.0 + 5e6 / (x * x), nan, n, 1e-8 * x)}));
  }
  tables.front() = analyse_convergence(rule);
  page = render_results_markdown(info, tables);
  EXPECT_NE(page.find("| 1 | plain_mc ("), std::string::npos) << page;
  const std::string changed = page.substr(0, page.find("- seed: 7\n"));
  EXPECT_NE(changed.find("`plain_mc` leads `genz|odd` (s = 1)"), std::string::npos) << changed;
  EXPECT_EQ(changed.find("`trapezoid` leads"), std::string::npos) << changed;
}

TEST(MarkdownReport, PlotFileNamesArePredictable) {
  // A name that already ends in "_s<s>" (a default name, a `dimensions` expansion) is used as it
  // is; any other gets "_s=<s>".
  EXPECT_EQ(convergence_plot_file("gaussian_s3", 3), "error_gaussian_s3.svg");
  EXPECT_EQ(work_precision_plot_file("gaussian_s3", 3), "work_precision_gaussian_s3.svg");
  EXPECT_EQ(convergence_plot_file("gaussian_s3", 4), "error_gaussian_s3_s=4.svg");
  EXPECT_EQ(convergence_plot_file("exp", 1), "error_exp_s=1.svg");
  EXPECT_EQ(plot_stem("disk indicator/r=0.3"), "disk~20indicator~2Fr~3D0.3");
  EXPECT_EQ(plot_stem("genz_gaussian-2.5"), "genz_gaussian-2.5") << "scene names stay as they are";
}

TEST(MarkdownReport, PlotFileNamesAreDistinctForDistinctSeries) {
  // Regression: `x` and `x_s1` in s = 1 both drew "x_s1.svg", and `y`'s work-precision plot had
  // the name of the error plot of an integrand called `work_precision_y`. Every name of both kinds
  // over these (integrand, s) pairs must be distinct: the pairs are built to collide under
  // simpler rules (suffix dropped or always added, '_' for unsafe bytes, '~' or '=' kept).
  const std::vector<std::string> names{"x",
                                       "x_s1",
                                       "x_s1_s1",
                                       "x_s=1",
                                       "x~s1",
                                       "y",
                                       "work_precision_y",
                                       "error_y",
                                       "a b",
                                       "a_b",
                                       "a~20b",
                                       "a=b",
                                       "a_s01",
                                       "é",
                                       "~C3~A9",
                                       "x_s12",
                                       "x_s2",
                                       "x_s",
                                       "",
                                       "_s1",
                                       "s1",
                                       "work_precision_x_s1",
                                       "error_x_s1"};
  std::set<std::string> files;
  std::size_t made = 0;
  for (const std::string& name : names) {
    for (const std::size_t s : {1u, 2u, 12u}) {
      files.insert(convergence_plot_file(name, s));
      files.insert(work_precision_plot_file(name, s));
      made += 2;
    }
  }
  EXPECT_EQ(files.size(), made);
}

TEST(MarkdownReport, DescriptionAndThreadsUsedAreOnThePage) {
  run_info info;
  info.scene = "described";
  info.description = "  Why this scene exists: **Simpson** against plain MC.\n";
  info.threads = 1;
  info.threads_allowed = 64;
  const auto tables = markdown_sample_tables();
  const std::string page = render_results_markdown(info, tables);
  // The author's Markdown, trimmed, right under the title, and the answer right under it.
  EXPECT_EQ(page.rfind("# Results: described\n\nWhy this scene exists: **Simpson** against plain "
                       "MC.\n\n> - ",
                       0),
            0u)
      << page;
  EXPECT_NE(page.find("- threads: 1 used (64 allowed"), std::string::npos) << page;
  info.threads_allowed = 1;
  EXPECT_NE(render_results_markdown(info, tables).find("- threads: 1\n"), std::string::npos);
}

TEST(MarkdownReport, HeaderNamesWhatMadeThePage) {
  run_info info;
  info.scene = "traced";
  info.machine = "2 hardware threads, SIMD level avx2 (QUADMC_SIMD to choose)";
  info.build.version = "0.1.0";
  info.build.commit = "0123456789abcdef0123456789abcdef01234567";
  info.build.compiler = "GNU 12.2.0 (Release)";
  info.build.simd_levels_available = {"scalar", "sse2", "avx2"};
  info.build.simd_level = "avx2";
  const std::string page = render_results_markdown(info, markdown_sample_tables());
  EXPECT_NE(page.find("- quadmc: 0.1.0, commit 0123456789abcdef0123456789abcdef01234567\n"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("- compiler: GNU 12.2.0 (Release)\n"), std::string::npos) << page;
  EXPECT_NE(page.find("- SIMD levels available: scalar, sse2, avx2\n"), std::string::npos) << page;
  // .ci/run reads the level a page ran at from its first "SIMD level <name>": the machine line,
  // which the list of available levels must not precede or imitate.
  const std::size_t first = page.find("SIMD level ");
  ASSERT_NE(first, std::string::npos) << page;
  EXPECT_EQ(page.substr(first, std::string("SIMD level avx2 ").size()), "SIMD level avx2 ");
  EXPECT_EQ(page.find("SIMD level ", first + 1), std::string::npos) << page;
  // A caller that does not know (a library user's own run_info) gets no such lines.
  const std::string bare = render_results_markdown(run_info{}, markdown_sample_tables());
  EXPECT_EQ(bare.find("- quadmc:"), std::string::npos) << bare;
  EXPECT_EQ(bare.find("SIMD levels available"), std::string::npos) << bare;
}

TEST(MarkdownReport, ReferencesThatAreNotExactAreListedBeforeTheTables) {
  run_info info;
  info.scene = "refs";
  const auto tables = markdown_sample_tables();
  const std::string without = render_results_markdown(info, tables);
  EXPECT_EQ(without.find("References without a closed form"), std::string::npos) << without;
  info.references = {"g: reference = 0.5 ± 1e-09 (given, uncertainty 1e-09)"};
  const std::string page = render_results_markdown(info, tables);
  const auto at = page.find("- g: reference = 0.5 ± 1e-09 (given, uncertainty 1e-09)\n");
  ASSERT_NE(at, std::string::npos) << page;
  EXPECT_LT(page.find("References without a closed form"), at);
  EXPECT_NE(page.find("errors below 10 times its uncertainty are floor points"), std::string::npos);
  EXPECT_LT(at, page.find("## Findings"));
}

// Effective dimensions: a row per integrand in s ≥ 2, the numbers where they are exact, the
// estimates with their intervals and how they were made where they are not, a dash and the
// reason where neither exists (what the integrand threw, its pipe escaped); no section when every
// integrand is one-dimensional.
TEST(MarkdownReport, EffectiveDimensionsStandBeforeTheSlopes) {
  run_info info;
  info.scene = "dims";
  const auto tables = markdown_sample_tables();
  info.effective_dimensions = {{"line", 1, 1, std::nullopt, std::nullopt, {}}};
  EXPECT_EQ(render_results_markdown(info, tables).find("## Effective dimensions"),
            std::string::npos);
  effective_dimensions exact;
  exact.truncation = 3;
  exact.superposition = 1;
  exact.truncation_shares = {0.5, 0.9, 0.995, 1.0};
  exact.superposition_shares = {0.992, 1.0, 1.0, 1.0};
  effective_dimension_estimate additive;
  additive.samples = 4096;
  additive.evaluations = 50000;
  additive.truncation = 2;
  additive.truncation_low = 2;
  additive.truncation_high = 3;
  additive.first_coordinate = {0.9, 0.88, 0.92};
  additive.first_order = estimated_share{0.995, 0.991, 0.998};
  additive.mean_dimension = estimated_share{1.01, 1.005, 1.015};
  additive.first_order_samples = 1024;
  additive.superposition_low = 1;
  additive.superposition_high = 1;
  effective_dimension_estimate undecided = additive;
  undecided.first_order = estimated_share{0.99, 0.985, 0.995};
  undecided.superposition_high = 0;
  effective_dimension_estimate wide = additive;
  wide.truncation_high = 2;
  wide.first_order.reset();
  wide.mean_dimension.reset();
  wide.superposition_low = wide.superposition_high = 0;
  info.effective_dimensions = {{"product", 4, 1, exact, std::nullopt, {}},
                               {"asian", 16, 3, std::nullopt, additive, {}},
                               {"undecided", 8, 1, std::nullopt, undecided, {}},
                               {"wide", 1024, 1, std::nullopt, wide, {}},
                               {"flat", 2, 1, std::nullopt, std::nullopt, {}},
                               {"thrower", 3, 1, std::nullopt, std::nullopt, "f: a | b failed"}};
  const std::string page = render_results_markdown(info, tables);
  const auto section = page.find("## Effective dimensions");
  ASSERT_NE(section, std::string::npos) << page;
  EXPECT_LT(section, page.find("## Slopes"));
  for (const std::string row :
       {"| product | 4 | 3 | 1 | 0.500 | 0.992 | exact: a product of one-variable factors |",
        "| asian | 16 | 2 [2, 3] | 1 | 0.900 [0.880, 0.920] | 0.995 [0.991, 0.998] | estimated: "
        "pick-freeze, 4096 rows, 50000 evaluations, 95 % intervals; mean dimension 1.010 "
        "[1.005, 1.015], order 1 from the first 1024 rows (instance 0 of the ensemble of 3) |",
        "| undecided | 8 | 2 [2, 3] | 1 or ≥ 2 | 0.900 [0.880, 0.920] | 0.990 [0.985, 0.995] |",
        "| wide | 1024 | 2 | — | 0.900 [0.880, 0.920] | — | estimated: pick-freeze, 4096 rows, "
        "50000 evaluations, 95 % intervals; order 1 not estimated (64 rows of s² coordinates "
        "above its budget) |",
        "| flat | 2 | — | — | — | — | not computed: not a product of one-variable factors, and "
        "its sampled variance is 0 or a sampled value not finite |",
        "| thrower | 3 | — | — | — | — | not computed: not a product of one-variable factors, and "
        "the integrand failed while it was sampled for an estimate: f: a \\| b failed |"}) {
    EXPECT_NE(page.find(row), std::string::npos) << row << "\n" << page;
  }
}

TEST(MarkdownReport, PageHasHeaderSummaryTablesAndLinks) {
  run_info info;
  info.scene = "default";
  info.seed = 42;
  info.threads = 2;
  info.build.compiler = "GCC 12.2.0";
  info.run_seconds = 12.5;
  info.skipped = {"simpson s = 6: 7^6 > budget"};
  const auto tables = markdown_sample_tables();
  const std::string page = render_results_markdown(info, tables);
  EXPECT_EQ(page.rfind("# Results: default\n", 0), 0u);
  EXPECT_NE(page.find("- seed: 42"), std::string::npos);
  EXPECT_NE(page.find("- threads: 2"), std::string::npos);
  EXPECT_NE(page.find("- compiler: GCC 12.2.0"), std::string::npos);
  EXPECT_EQ(page.find("- machine:"), std::string::npos) << "empty fields are omitted";
  EXPECT_NE(page.find("- simpson s = 6: 7^6 > budget"), std::string::npos);
  // The skip list is folded, with its count, so the slope table stays on the first screen.
  EXPECT_NE(page.find("<summary>Skipped by the plan: 1 cell "), std::string::npos) << page;
  EXPECT_LT(page.find("</details>"), page.find("## Slopes"));
  // Summary rows: the integrand's '|' is escaped so the table keeps its columns.
  EXPECT_NE(page.find("| genz\\|odd | 1 | trapezoid | -2.0"), std::string::npos) << page;
  EXPECT_NE(page.find("| genz\\|odd | 1 | plain_mc | -0.500 ± 0.000 | -0.500 | agrees |"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("![error against N](error_genz~7Codd_s=1.svg)"), std::string::npos) << page;
  EXPECT_NE(page.find("![work-precision](work_precision_genz~7Codd_s=1.svg)"), std::string::npos);
  EXPECT_EQ(page.find("- threads: 2\n"), page.find("- threads:")) << "used = allowed: one number";
  // One section for the (integrand, s) group, with both methods and a work-precision table.
  EXPECT_NE(page.find("## genz\\|odd (s = 1)"), std::string::npos);
  EXPECT_EQ(page.find("## genz\\|odd (s = 1)"), page.rfind("## genz\\|odd (s = 1)"));
  EXPECT_NE(page.find("### trapezoid"), std::string::npos);
  EXPECT_NE(page.find("### plain_mc"), std::string::npos);
  EXPECT_NE(page.find("| \\|error\\| |"), std::string::npos) << "deterministic: |error|";
  EXPECT_NE(page.find("| RMSE |"), std::string::npos) << "repetitions: RMSE";
  EXPECT_NE(page.find("▼"), std::string::npos) << "the trapezoid floor points are marked";
  EXPECT_NE(page.find("rounding floor from N = "), std::string::npos);
  EXPECT_NE(page.find("| method | 1e-02 | 1e-03 |"), std::string::npos) << page;
  EXPECT_NE(page.find("not reached"), std::string::npos) << "MC never reaches 1e-8 at N = 4096";
  expect_rectangular_tables(page);
}

// A method with its own error estimate gets a reliability row: errors of ±0.5ê and 2ê in every
// cell of plain_mc (1 of 2 within ê, both within 3ê); a page whose methods have none has no
// such section.
TEST(MarkdownReport, ReliabilityTableWhereAMethodHasAnEstimate) {
  convergence_series mc = series_of("gauss", 2, "plain_mc", smoothness::analytic, 1.0,
                                    monte_carlo_theory(smoothness::analytic, 2));
  for (int k = 2; k <= 6; ++k) {
    const auto n = std::uint64_t{1} << (2 * k);
    const double e = 1.0 / std::sqrt(static_cast<double>(n));
    repetition_result a = repetition(1.0 + 0.5 * e, e, n, 1e-6);
    repetition_result b = repetition(1.0 - 2.0 * e, e, n, 1e-6);
    a.error_estimate = b.error_estimate = e;
    mc.cells.push_back(cell_at(n, {a, b}));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(mc)};
  const std::string page = render_results_markdown({}, tables);
  EXPECT_NE(page.find("## Error-estimate reliability"), std::string::npos) << page;
  EXPECT_NE(page.find("| plain_mc | analytic | 1 | 5 | 10 | 0.500 | 1.000 |"), std::string::npos)
      << page;
  expect_rectangular_tables(page);
  EXPECT_EQ(
      render_results_markdown({}, markdown_sample_tables()).find("Error-estimate reliability"),
      std::string::npos);
}

}  // namespace
}  // namespace quadmc
