// A scene run from plain C++ (scene/run_scene.hpp, then report/write_results.hpp) writes the
// folder `quadmc run` writes: the same files, the same figures in every column but run time, the
// same page. What a library user (an outside project, the Python module) gets is then what the
// command's users get, and the command is a thin layer over the library.
#include "quadmc/report/provenance.hpp"
#include "quadmc/report/write_results.hpp"
#include "quadmc/scene/run_scene.hpp"
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

// Every kind of series the page treats apart: a deterministic rule (a slope and a prediction), a
// randomized method (replicates and coverage), a tolerance cell, an ensemble, a skipped cell.
const std::string library_scene = R"(name = "library"
description = "run from plain C++"
seed = 21
threads = 1

[[integrand]]
family = "genz_gaussian"
dimension = 2

[[integrand]]
family = "genz_product_peak"
dimension = 2
ensemble = 2

[[method]]
name = "simpson"

[[method]]
name = "plain_mc"
repetitions = 4

[[method]]
name = "genz_malik"
control = "tolerance"
tolerances = [1e-3, 1e-5]

[budget]
N = [9, 81, 729, 6561]
timing_min_seconds = 0

[output]
plots = false
)";

// The page with every number replaced by '#': what differs between two runs of one scene is the
// run time and the timing columns, and the figures the page shows are checked in the CSV files.
std::vector<std::string> page_without_numbers(const fs::path& file) {
  static const std::regex number(R"([0-9][0-9.eE+\-−×^⁰¹²³⁴⁵⁶⁷⁸⁹⁻]*)");
  std::istringstream in(read_text(file));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    lines.push_back(std::regex_replace(line, number, "#"));
  }
  return lines;
}

TEST(LibraryRun, RunSceneAndWriteResultsWriteWhatTheCommandWrites) {
  scratch_folder dir;
  write_text(dir / "library.toml", library_scene);
  const command_result r = run_quadmc(
      dir, {"run", (dir / "library.toml").string(), "--out", (dir / "command").string()});
  ASSERT_EQ(r.exit_status, 0) << describe(r);

  quadmc::run_options options;
  const quadmc::scene_results results = quadmc::run_scene(dir / "library.toml", options);
  quadmc::results_options written;
  // The build is the program's to say; the command's own, so that meta.csv can be compared too.
  written.build = quadmc::read_meta_csv(dir / "command" / "meta.csv");
  const std::string said = quadmc::write_results(dir / "library", results, written);
  EXPECT_EQ(said, "wrote " + (dir / "library").string());

  std::vector<std::string> command_files;
  std::vector<std::string> library_files;
  for (const auto& e : fs::directory_iterator(dir / "command")) {
    command_files.push_back(e.path().filename().string());
  }
  for (const auto& e : fs::directory_iterator(dir / "library")) {
    library_files.push_back(e.path().filename().string());
  }
  std::sort(command_files.begin(), command_files.end());
  std::sort(library_files.begin(), library_files.end());
  EXPECT_EQ(library_files, command_files);
  // plots = false: no figure, neither per series nor the summary ones (report/answer_first.hpp).
  EXPECT_EQ(library_files, (std::vector<std::string>{"README.md", "convergence.csv", "meta.csv",
                                                     "slopes.csv", "who_leads.csv"}));
  EXPECT_EQ(read_text(dir / "library" / "meta.csv"), read_text(dir / "command" / "meta.csv"));
  expect_same_results(dir / "command", dir / "library", "run_scene + write_results");
  EXPECT_EQ(page_without_numbers(dir / "library" / "README.md"),
            page_without_numbers(dir / "command" / "README.md"));
}

// A given and a computed reference: `quadmc plan` states each with its uncertainty and how it
// was obtained, the results page lists both above the tables, and the exact value's integrand
// is not listed.
TEST(LibraryRun, GivenAndComputedReferencesAreStatedInThePlanAndOnThePage) {
  scratch_folder dir;
  write_text(dir / "refs.toml", R"(name = "refs"
threads = 1
[[integrand]]
family = "exp"
reference = 1.71828
reference_uncertainty = 1e-5
[[integrand]]
family = "genz_gaussian"
dimension = 2
reference = "computed"
[[integrand]]
family = "sin"
[[method]]
name = "simpson"
[budget]
N = [8, 64, 512]
timing_min_seconds = 0
[output]
plots = false
)");
  const command_result plan = run_quadmc(dir, {"plan", (dir / "refs.toml").string()});
  ASSERT_EQ(plan.exit_status, 0) << describe(plan);
  EXPECT_NE(plan.out.find("reference = 1.71828 ± 1e-05 (given, uncertainty 1e-05)"),
            std::string::npos)
      << plan.out;
  EXPECT_NE(plan.out.find("(computed: Genz–Malik h-adaptive cubature, relative tolerance 1e-12, "),
            std::string::npos)
      << plan.out;
  EXPECT_NE(plan.out.find("exists and is not used"), std::string::npos) << plan.out;

  const command_result r =
      run_quadmc(dir, {"run", (dir / "refs.toml").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  const std::string page = read_text(dir / "out" / "README.md");
  EXPECT_NE(page.find("References without a closed form"), std::string::npos) << page;
  EXPECT_NE(page.find("- exp: reference = 1.71828 ± 1e-05 (given, uncertainty 1e-05)"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("- genz_gaussian_s2: reference = "), std::string::npos) << page;
  EXPECT_EQ(page.find("- sin: reference"), std::string::npos) << page;
}

}  // namespace
}  // namespace quadmc_cli_test
