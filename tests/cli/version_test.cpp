// End-to-end tests of `quadmc --version` and of what a run records about the code that made it
// (bench/quadmc/version.hpp, report/provenance.hpp): the version, commit, compiler and SIMD
// levels of --version are the ones in the results folder's meta.csv and README.md, and a folder
// holding meta.csv is a results folder a later run may replace.
//
// Use these for the command's provenance contract. Not for the commit lookup itself, which
// tests/cmake/quadmc_commit_test.cmake runs against repositories of its own, nor for the
// installed layout (installed_layout_test.cpp).
#include "quadmc/core/simd_level.hpp"
#include "quadmc/report/provenance.hpp"
#include "quadmc_process.hpp"

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

// The "key: value" lines after the first, by key; the first line under "".
std::map<std::string, std::string> version_fields(const std::string& text) {
  std::map<std::string, std::string> fields;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  fields[""] = line;
  while (std::getline(lines, line)) {
    const auto colon = line.find(": ");
    if (colon == std::string::npos) {
      ADD_FAILURE() << "not a 'key: value' line: " << line;
      continue;
    }
    fields[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return fields;
}

// "scalar sse2 avx2 (in use: avx2; QUADMC_SIMD to choose)" → {"scalar", "sse2", "avx2"}, "avx2".
struct simd_field {
  std::vector<std::string> available;
  std::string in_use;
};
simd_field parse_simd_field(const std::string& text) {
  static const std::regex shape(R"(^([a-z0-9 ]+) \(in use: ([a-z0-9]+); QUADMC_SIMD to choose\)$)");
  std::smatch m;
  simd_field f;
  if (!std::regex_match(text, m, shape)) {
    ADD_FAILURE() << "SIMD levels line: " << text;
    return f;
  }
  std::istringstream levels(m[1].str());
  for (std::string level; levels >> level;) f.available.push_back(level);
  f.in_use = m[2];
  return f;
}

std::vector<std::string> levels_of_this_machine() {
  std::vector<std::string> out;
  for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
    out.emplace_back(quadmc::to_string(level));
  }
  return out;
}

TEST(VersionTest, PrintsVersionCommitCompilerSimdLevelsAndPlotScript) {
  scratch_folder dir;
  const command_result r = run_quadmc(dir, {"--version"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.err, "") << describe(r);
  const auto fields = version_fields(r.out);
  EXPECT_EQ(fields.at(""), std::string("quadmc ") + QUADMC_PROJECT_VERSION) << describe(r);
  ASSERT_TRUE(fields.contains("commit")) << describe(r);
  // A 40-digit hash, "-dirty" when the tree had changes, or "unknown" (no git, not a checkout).
  EXPECT_TRUE(std::regex_match(fields.at("commit"), std::regex("[0-9a-f]{40}(-dirty)?|unknown")))
      << fields.at("commit");
  ASSERT_TRUE(fields.contains("compiler")) << describe(r);
  EXPECT_TRUE(std::regex_match(fields.at("compiler"), std::regex(R"(\S.* \(\S+\))")))
      << "compiler, version and (build type): " << fields.at("compiler");
  ASSERT_TRUE(fields.contains("SIMD levels available")) << describe(r);
  const simd_field simd = parse_simd_field(fields.at("SIMD levels available"));
  EXPECT_EQ(simd.available, levels_of_this_machine());
  EXPECT_EQ(simd.in_use, std::string(quadmc::to_string(quadmc::detected_simd_level())))
      << "without QUADMC_SIMD the best level is used";
  // The build tree's binary uses the source tree's script (plot_script.hpp).
  EXPECT_EQ(fields.at("plot script"), (fs::path(QUADMC_SOURCE_DIR) / "bench" / "plot.py").string());
  EXPECT_EQ(fields.size(), 5u) << describe(r);
}

TEST(VersionTest, NamesTheLevelQuadmcSimdPins) {
  scratch_folder dir;
  const command_result r =
      run_quadmc_with(dir.path(), dir.path(), {"--version"}, {"QUADMC_SIMD=scalar"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(parse_simd_field(version_fields(r.out).at("SIMD levels available")).in_use, "scalar");
  // A level the CPU or build lacks, or no level at all: the one-line refusal of every command.
  const command_result bad =
      run_quadmc_with(dir.path(), dir.path(), {"--version"}, {"QUADMC_SIMD=avx1024"});
  EXPECT_EQ(bad.exit_status, 1) << describe(bad);
  EXPECT_EQ(line_count(bad.err), 1u) << describe(bad);
  EXPECT_NE(bad.err.find("QUADMC_SIMD"), std::string::npos) << describe(bad);
  EXPECT_EQ(bad.out, "") << describe(bad);
}

TEST(VersionTest, AFullStdoutIsAnError) {
  // Like every other output of the command, --version's is checked (a script reading it from a
  // closed pipe must not be told it succeeded).
  scratch_folder dir;
  process_options options;
  options.working_directory = dir.path();
  options.stdout_file = "/dev/full";
  options.stderr_file = dir / "err";
  const command_result r = child_process({QUADMC_CLI, "--version"}, options).wait();
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_NE(r.err.find("cannot write to standard output"), std::string::npos) << describe(r);
}

TEST(VersionTest, ResultsFolderRecordsWhatVersionPrints) {
  scratch_folder dir;
  write_text(dir / "s.toml", tiny_scene("traced", "provenance", false));
  const command_result version = run_quadmc(dir, {"--version"});
  ASSERT_EQ(version.exit_status, 0) << describe(version);
  const auto fields = version_fields(version.out);
  const simd_field simd = parse_simd_field(fields.at("SIMD levels available"));

  const command_result r = run_quadmc(dir, {"run", (dir / "s.toml").string(), "--out", "out"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  const quadmc::provenance meta = quadmc::read_meta_csv(dir / "out" / "meta.csv");
  EXPECT_EQ("quadmc " + meta.version, fields.at(""));
  EXPECT_EQ(meta.commit, fields.at("commit"));
  EXPECT_EQ(meta.compiler, fields.at("compiler"));
  EXPECT_EQ(meta.simd_levels_available, simd.available);
  EXPECT_EQ(meta.simd_level, simd.in_use);

  const std::string readme = read_text(dir / "out" / "README.md");
  EXPECT_NE(readme.find("- quadmc: " + meta.version + ", commit " + meta.commit + "\n"),
            std::string::npos)
      << readme;
  EXPECT_NE(readme.find("- compiler: " + meta.compiler + "\n"), std::string::npos) << readme;
  std::string levels;
  for (const std::string& level : meta.simd_levels_available) {
    levels += (levels.empty() ? "" : ", ") + level;
  }
  EXPECT_NE(readme.find("- SIMD levels available: " + levels + "\n"), std::string::npos) << readme;

  // The level a run pins is the one its folder records.
  const command_result pinned =
      run_quadmc_with(dir.path(), dir.path(), {"run", (dir / "s.toml").string(), "--out", "scalar"},
                      {"QUADMC_SIMD=scalar"});
  ASSERT_EQ(pinned.exit_status, 0) << describe(pinned);
  EXPECT_EQ(quadmc::read_meta_csv(dir / "scalar" / "meta.csv").simd_level, "scalar");
}

TEST(VersionTest, AFolderWithMetaCsvIsReplacedByTheNextRun) {
  // Regression guard: meta.csv is a file a run writes (report/results_folder.hpp), so the folder
  // rules (lib/include/quadmc/report/results_staging.hpp) must accept it in an old folder and
  // remove it with the old results, not refuse the folder as someone else's.
  scratch_folder dir;
  write_text(dir / "old.toml", tiny_scene("s", "old results", false));
  write_text(dir / "new.toml", tiny_scene("s", "new results", false));
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "old.toml").string(), "--out", "out"}).exit_status, 0);
  ASSERT_TRUE(fs::exists(dir / "out" / "meta.csv"));
  const command_result r = run_quadmc(dir, {"run", (dir / "new.toml").string(), "--out", "out"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_NE(read_text(dir / "out" / "README.md").find("new results"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / "meta.csv"));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"new.toml", "old.toml", "out"}))
      << "no staging or old copy left behind";
}

}  // namespace
}  // namespace quadmc_cli_test
