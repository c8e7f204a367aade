// Tests for results_folder.hpp: the files appear together and agree.
#include "quadmc/report/results_folder.hpp"

#include "../analysis/series_builder.hpp"
#include "../analysis/time_to_error_sample.hpp"

#include "quadmc/report/csv.hpp"
#include "quadmc/report/provenance.hpp"
#include "quadmc/report/results_csv.hpp"
#include "support/temporary_directory.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

namespace quadmc {
namespace {

using test::cell_at;
using test::monte_carlo_theory;
using test::repetition;
using test::rule_theory;
using test::series_of;

namespace fs = std::filesystem;

using test_support::temporary_directory;

TEST(ResultsFolder, WritesThreeAgreeingFiles) {
  const temporary_directory dir{"quadmc_results_folder"};
  convergence_series s =
      series_of("f", 2, "simpson", smoothness::smooth, 1.0, rule_theory(4, smoothness::smooth, 2));
  for (std::uint64_t n : {9u, 25u, 81u, 289u}) {
    s.cells.push_back(cell_at(
        n, {repetition(1.0 + 1.0 / (n * n), std::numeric_limits<double>::quiet_NaN(), n, 1e-6)}));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(s)};
  run_info info;
  info.scene = "unit";
  info.build.version = "9.8.7";
  info.build.commit = "unknown";
  info.build.compiler = "GNU 12.2.0 (RelWithDebInfo)";
  info.build.simd_levels_available = {"scalar", "sse2"};
  info.build.simd_level = "scalar";
  const fs::path folder = dir.path / "results" / "unit";  // nested: created on demand
  write_results_folder(folder, info, tables);
  EXPECT_TRUE(fs::exists(folder / "README.md"));
  // What made the CSV files is recorded beside them, and the page says the same.
  const provenance meta = read_meta_csv(folder / "meta.csv");
  EXPECT_EQ(meta.version, "9.8.7");
  EXPECT_EQ(meta.commit, "unknown");
  EXPECT_EQ(meta.compiler, "GNU 12.2.0 (RelWithDebInfo)");
  EXPECT_EQ(meta.simd_levels_available, (std::vector<std::string>{"scalar", "sse2"}));
  EXPECT_EQ(meta.simd_level, "scalar");
  std::ifstream readme(folder / "README.md");
  const std::string page((std::istreambuf_iterator<char>(readme)),
                         std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("- quadmc: 9.8.7, commit unknown\n"), std::string::npos) << page;
  EXPECT_EQ(read_convergence_csv(folder / "convergence.csv").size(), 4u);
  const auto slopes = read_slopes_csv(folder / "slopes.csv");
  ASSERT_EQ(slopes.size(), 1u);
  EXPECT_EQ(slopes[0].scene, "unit");
  // Error N⁻²; the theory for Simpson in s = 2 is −4/2 = −2: agrees. The errors are read off
  // 1 + N⁻² (rounded to ε/2 ≈ 1e-16 against e ≥ 1.2e-5, relative ≤ 1e-11), so the slope is −2
  // to ~1e-11, not to ε.
  EXPECT_NEAR(slopes[0].slope, -2.0, 1e-10);
  EXPECT_EQ(slopes[0].verdict, "agrees");
  // One method per family: who_leads.csv is its header alone (no "Who leads" table).
  EXPECT_EQ(read_csv_file(folder / "who_leads.csv").rows.size(), 0u);
  // No paired timing: no pairs file (a scene without peers writes what it always wrote).
  EXPECT_FALSE(fs::exists(folder / "time_to_error_pairs.csv"));
}

// A run that paired time-to-error winners writes time_to_error_pairs.csv beside the other CSV
// files, one row per pair, and the page shows the pair's median; without csv, no file.
TEST(ResultsFolder, WritesThePairsOfAPairedTiming) {
  const temporary_directory dir{"quadmc_results_folder"};
  const std::vector<convergence_table> tables = test::time_to_error_sample_tables();
  run_info info;
  info.scene = "paired";
  info.paired_timing.rounds = 5;
  info.paired_timing.pairs.push_back(
      test::sample_pair({3.0, 2.0, 4.0, 3.0, 3.0}, {2.0, 2.0, 2.0, 2.0, 2.0}));
  write_results_folder(dir.path / "with", info, tables);
  const csv_table pairs = read_csv_file(dir.path / "with" / "time_to_error_pairs.csv");
  ASSERT_EQ(pairs.rows.size(), 1u);
  EXPECT_EQ(pairs.rows[0][pairs.column("scene")], "paired");
  EXPECT_EQ(pairs.rows[0][pairs.column("ratio_median")], "1.5");
  std::ifstream readme(dir.path / "with" / "README.md");
  const std::string page((std::istreambuf_iterator<char>(readme)),
                         std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("| 1.5 (1–2 over 5 alternating runs) |"), std::string::npos) << page;
  write_results_folder(dir.path / "without", info, tables, {.csv = false, .markdown = true});
  EXPECT_FALSE(fs::exists(dir.path / "without" / "time_to_error_pairs.csv"));
}

// End to end from a series to the files: a rule on a jump whose flat ladder (slope 0 against the
// theory −1, which the slope verdict calls shallower) stays under its envelope: slopes.csv and the
// README both say within_envelope, and the cells' envelopes reach convergence.csv.
TEST(ResultsFolder, EnvelopeVerdictReachesSlopesCsvAndTheReadme) {
  const temporary_directory dir{"quadmc_results_folder"};
  const double c = 0.93750095367431640625;  // 1/2 + 1/4 + 1/8 + 1/16 + 2⁻²⁰
  convergence_series s = series_of("step", 1, "midpoint", smoothness::discontinuous, 1.0 - c,
                                   rule_theory(2, smoothness::discontinuous));
  for (std::uint64_t n = 16; n <= 4096; n *= 2) {
    s.cells.push_back(cell_at(n,
                              {repetition(1.0 - c + std::ldexp(1.0, -20),
                                          std::numeric_limits<double>::quiet_NaN(), n, 1e-6)},
                              n, 0.5 / static_cast<double>(n)));
  }
  const std::vector<convergence_table> tables = {analyse_convergence(s)};
  run_info info;
  info.scene = "jumps";
  write_results_folder(dir.path, info, tables);
  const auto slopes = read_slopes_csv(dir.path / "slopes.csv");
  ASSERT_EQ(slopes.size(), 1u);
  EXPECT_EQ(slopes[0].verdict, "within_envelope");
  EXPECT_EQ(slopes[0].slope, 0.0) << "the slope stays in the file beside the verdict";
  EXPECT_EQ(slopes[0].theory, -1.0);
  const auto cells = read_convergence_csv(dir.path / "convergence.csv");
  ASSERT_EQ(cells.size(), 9u);
  EXPECT_EQ(cells.front().envelope, 0.5 / 16.0);
  std::ifstream readme(dir.path / "README.md");
  const std::string page((std::istreambuf_iterator<char>(readme)),
                         std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("| step | 1 | midpoint | 0.000 ± 0.000 | -1.000 | within_envelope |"),
            std::string::npos)
      << page;
}

TEST(ResultsFolder, WritesOnlyTheOutputsAskedFor) {
  const temporary_directory dir{"quadmc_results_folder"};
  convergence_series s = series_of("f", 1, "plain_mc", smoothness::smooth, 1.0,
                                   monte_carlo_theory(smoothness::smooth));
  s.cells.push_back(cell_at(16, {repetition(1.1, 0.1, 16, 1e-6)}));
  const std::vector<convergence_table> tables = {analyse_convergence(s)};
  run_info info;
  info.scene = "unit";
  write_results_folder(dir.path, info, tables, {.csv = false, .markdown = true});
  EXPECT_TRUE(fs::exists(dir.path / "README.md"));
  EXPECT_FALSE(fs::exists(dir.path / "convergence.csv"));
  EXPECT_FALSE(fs::exists(dir.path / "slopes.csv"));
  EXPECT_FALSE(fs::exists(dir.path / "who_leads.csv"));
  // meta.csv is written with any output: it is what a later run checks before it replaces the
  // folder (lib/include/quadmc/report/results_staging.hpp).
  EXPECT_TRUE(fs::exists(dir.path / "meta.csv"));
}

TEST(ResultsFolder, PlotCommandLine) {
  const auto argv = plot_command_line("bench/plot.py", "results/default");
  ASSERT_EQ(argv.size(), 3u);
  EXPECT_EQ(argv[0], "/usr/bin/python3");
  EXPECT_EQ(argv[1], "bench/plot.py");
  EXPECT_EQ(argv[2], "results/default");
}

TEST(ResultsFolder, ResultsFileNamesAreWhatARunWrites) {
  for (const char* name :
       {"convergence.csv", "slopes.csv", "meta.csv", "README.md", "error_exp_s=1.svg", "exp_s1.svg",
        "work_precision_gaussian_s3.svg", "who_leads.csv", "who_leads.png",
        "slope_against_theory.png", "time_to_error_pairs.csv"}) {
    EXPECT_TRUE(is_results_file_name(name)) << name;
  }
  // Near misses: other cases, other files, a bare extension (a hidden file, not a plot).
  for (const char* name : {"readme.md", "README.txt", "notes.txt", "thesis.tex", ".svg", "svg",
                           "plot.svg.bak", "convergence.csv~", "meta.csv.bak", "Meta.csv", ""}) {
    EXPECT_FALSE(is_results_file_name(name)) << name;
  }
}

}  // namespace
}  // namespace quadmc
