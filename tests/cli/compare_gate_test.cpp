// End-to-end tests of `quadmc compare` as a CI gate when there is little or nothing to compare
// (report/compare.hpp, "Incomparable"): exit 3 with the reason on one stderr line, never a
// silent 0 "No slope regression".
//
// Use these for the exit status on real folders; the counting itself is tested on hand-made
// folders in tests/report/compare_test.cpp, the regression case in compare_test.cpp here.
#include "quadmc_process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// The fields of one CSV line, quotes kept (the slopes file quotes notes that hold commas).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string joined(const std::vector<std::string>& parts, char separator) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i ? std::string(1, separator) : "") + parts[i];
  return out;
}

// `file` of folder a with field `column` of data record `record` (2 = the first data line) set to
// `value`, or with that record appended again when `column` is empty.
std::string edited(const fs::path& file, std::size_t record, const std::string& column,
                   const std::string& value) {
  std::vector<std::string> lines = lines_of(read_text(file));
  if (column.empty()) {
    lines.push_back(lines[record - 1]);
  } else {
    const std::vector<std::string> header = csv_fields(lines[0]);
    const auto at = std::find(header.begin(), header.end(), column) - header.begin();
    std::vector<std::string> fields = csv_fields(lines[record - 1]);
    fields.at(static_cast<std::size_t>(at)) = value;
    lines[record - 1] = joined(fields, ',');
  }
  return joined(lines, '\n') + "\n";
}

TEST_F(CompareGateTest, MalformedCandidatesAreIncomparableNamingFileRecordAndColumn) {
  // Regression: compare read only the first row of a duplicated series (a regressed copy appended
  // to slopes.csv passed with exit 0), and took ci_low > ci_high (a negative half-width widened
  // the allowed difference), slope = -inf, an unknown verdict, a slope whose fit_status says it
  // was not fitted, and a NaN rmse reported without file or row.
  struct malformed {
    std::string file, column, value, says;
    std::size_t record;
  };
  const std::vector<malformed> cases = {
      {"slopes.csv", "", "", "slopes.csv: record 4, column 'method'", 2},  // a duplicate row
      {"slopes.csv", "ci_low", "1e9", "column 'ci_low' = '1e9': expected at most ci_high", 2},
      {"slopes.csv", "slope", "-inf", "column 'slope' = '-inf': expected a finite number", 2},
      {"slopes.csv", "verdict", "great", "column 'verdict' = 'great'", 3},
      {"slopes.csv", "fit_status", "too_few_points", "fit_status = 'too_few_points'", 2},
      {"convergence.csv", "rmse", "nan", "convergence.csv: record 3, column 'rmse' = 'nan'", 3},
  };
  for (const malformed& c : cases) {
    fs::remove_all(dir / "b");
    fs::copy(dir / "a", dir / "b");
    write_text(dir / "b" / c.file, edited(dir / "a" / c.file, c.record, c.column, c.value));
    const command_result r = run_quadmc(dir, {"compare", "a", "b"});
    EXPECT_EQ(r.exit_status, 3) << c.says << "\n" << describe(r);
    EXPECT_EQ(line_count(r.err), 1u) << describe(r);
    EXPECT_EQ(r.err.rfind("quadmc: compare: incomparable: ", 0), 0u) << describe(r);
    EXPECT_NE(r.err.find("b/" + c.file + ": record "), std::string::npos) << describe(r);
    EXPECT_NE(r.err.find(c.says), std::string::npos) << "expected '" << c.says << "'\n"
                                                     << describe(r);
  }
}

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
