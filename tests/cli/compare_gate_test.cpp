// End-to-end tests of `quadmc compare` as a CI gate when there is little or nothing to compare
// (report/compare.hpp, "Incomparable"): exit 3 with the reason on one stderr line, never a
// silent 0 "No slope regression".
//
// Use these for the exit status on real folders; the counting itself is tested on hand-made
// folders in tests/report/compare_test.cpp, the regression case in compare_test.cpp here.
#include "quadmc_process.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

// Two rules on eˣ, N = 16…1024: both fitted (4 points each).
std::string gate_scene(const std::string& integrand, const std::string& ladder,
                       const std::string& extra_method = "") {
  return "name = \"gate\"\nseed = 5\n[[integrand]]\nname = \"" + integrand +
         "\"\nfamily = \"exp\"\n[[method]]\nname = \"midpoint\"\n[[method]]\nname = \"simpson\"\n" +
         extra_method + "[budget]\nN = " + ladder + "\n[output]\nplots = false\n";
}

void expect_incomparable(const command_result& r, const std::string& reason) {
  EXPECT_EQ(r.exit_status, 3) << describe(r);
  EXPECT_EQ(line_count(r.err), 1u) << describe(r);
  EXPECT_EQ(r.err.rfind("quadmc: compare: incomparable: ", 0), 0u) << describe(r);
  EXPECT_NE(r.err.find(reason), std::string::npos) << "expected '" << reason << "'\n"
                                                   << describe(r);
  EXPECT_NE(r.out.find("**INCOMPARABLE**"), std::string::npos) << describe(r);
  EXPECT_EQ(r.out.find("No slope regression"), std::string::npos) << describe(r);
}

class CompareGateTest : public ::testing::Test {
 protected:
  void SetUp() override {
    write_text(dir / "a.toml", gate_scene("e", "[16, 64, 256, 1024]"));
    ASSERT_EQ(run_quadmc(dir, {"run", (dir / "a.toml").string(), "--out", "a"}).exit_status, 0);
  }
  command_result run_b_and_compare(const std::string& scene) {
    write_text(dir / "b.toml", scene);
    const command_result b = run_quadmc(dir, {"run", (dir / "b.toml").string(), "--out", "b"});
    EXPECT_EQ(b.exit_status, 0) << describe(b);
    return run_quadmc(dir, {"compare", "a", "b"});
  }
  scratch_folder dir;
};

TEST_F(CompareGateTest, HeaderOnlyCandidateIsIncomparable) {
  // What an all-skipped or emptied run leaves: both CSV files with their header only.
  fs::create_directory(dir / "b");
  for (const std::string file : {"convergence.csv", "slopes.csv"}) {
    const std::string text = read_text(dir / "a" / file);
    write_text(dir / "b" / file, text.substr(0, text.find('\n') + 1));
  }
  expect_incomparable(run_quadmc(dir, {"compare", "a", "b"}), "2 series of A missing in B");
}

TEST_F(CompareGateTest, AnotherSceneIsIncomparable) {
  expect_incomparable(run_b_and_compare(gate_scene("other", "[16, 64, 256, 1024]")),
                      "no series is fitted in both");
}

TEST_F(CompareGateTest, LostFitsAreIncomparable) {
  // Two N per series: too few points for a fit in B, where A had four.
  expect_incomparable(run_b_and_compare(gate_scene("e", "[16, 64]")),
                      "2 series fitted in A without a fit in B (first: e (s = 1) midpoint)");
}

TEST_F(CompareGateTest, NewSeriesInTheCandidateAreFine) {
  const command_result r = run_b_and_compare(
      gate_scene("e", "[16, 64, 256, 1024]", "[[method]]\nname = \"trapezoid\"\n"));
  EXPECT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.err, "") << describe(r);
  EXPECT_NE(r.out.find("No slope regression in 2 series"), std::string::npos) << describe(r);
}

}  // namespace
}  // namespace quadmc_cli_test
