// End-to-end tests of `quadmc compare`: exit 0 when no slope regresses, 1 when one does, so it
// can gate CI (report/compare.hpp states the regression rule).
//
// Use these to check the command's exit status and what it prints. Not for the rule's
// arithmetic (tests/report covers compare_results on hand-made folders).
#include "quadmc/report/results_csv.hpp"
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

// Two deterministic series and one random one; plots off.
const std::string compare_scene = R"(name = "cmp"
seed = 5
[[integrand]]
name = "exp"
family = "exp"
[[method]]
name = "midpoint"
[[method]]
name = "simpson"
[[method]]
name = "plain_mc"
repetitions = 8
[budget]
N = [16, 64, 256, 1024]
[output]
plots = false
)";

// Makes `series`' slope in slopes.csv shallower by `change` (a text edit of the one field),
// leaving its CI columns as they were.
void make_slope_shallower(const fs::path& slopes_csv, const std::string& method, double change) {
  std::istringstream in(read_text(slopes_csv));
  std::string line;
  std::string doctored;
  bool found = false;
  std::getline(in, line);
  doctored = line + "\n";  // header: scene,integrand,s,method,slope,…
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream row(line);
    for (int i = 0; i < 5 && std::getline(row, field, ','); ++i) fields.push_back(field);
    std::string rest;
    std::getline(row, rest, '\0');
    if (fields.size() == 5 && fields[3] == method) {
      fields[4] = std::to_string(std::stod(fields[4]) + change);
      found = true;
    }
    std::string rebuilt;
    for (const auto& f : fields) rebuilt += f + ",";
    doctored += rebuilt + rest + "\n";
  }
  ASSERT_TRUE(found) << method << " not in " << slopes_csv;
  write_text(slopes_csv, doctored);
}

TEST(CompareTest, FolderAgainstItselfIsNoRegression) {
  scratch_folder dir;
  write_text(dir / "cmp.toml", compare_scene);
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "cmp.toml").string(), "--out", "a"}).exit_status, 0);
  const command_result r = run_quadmc(dir, {"compare", "a", "a"});
  EXPECT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_EQ(r.err, "") << describe(r);
  for (const std::string series : {"midpoint", "simpson", "plain_mc"}) {
    EXPECT_NE(r.out.find(series), std::string::npos) << series << "\n" << describe(r);
  }
  // render_compare_markdown marks a regressed series' status "**regression**" and opens with
  // "**REGRESSION**" when any did.
  EXPECT_EQ(r.out.find("regression**"), std::string::npos) << describe(r);
  EXPECT_EQ(r.out.find("REGRESSION"), std::string::npos) << describe(r);
}

TEST(CompareTest, MuchShallowerSlopeIsARegressionNamingTheSeries) {
  scratch_folder dir;
  write_text(dir / "cmp.toml", compare_scene);
  ASSERT_EQ(run_quadmc(dir, {"run", (dir / "cmp.toml").string(), "--out", "a"}).exit_status, 0);
  fs::copy(dir / "a", dir / "b", fs::copy_options::recursive);
  // Simpson's ≈ −4 made ≈ −2: far beyond the allowed loss max(tolerance 0.1, √(h_A² + h_B²))
  // (compare.hpp), ≈ 0.15 here: the doctored row keeps A's CI, half-width h ≈ 0.1 on this
  // ladder of 4 N.
  make_slope_shallower(dir / "b" / "slopes.csv", "simpson", 2.0);
  const auto doctored = quadmc::read_slopes_csv(dir / "b" / "slopes.csv");  // still a valid file
  ASSERT_EQ(doctored.size(), 3u);

  const command_result r = run_quadmc(dir, {"compare", "a", "b"});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  bool named = false;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("| simpson |") != std::string::npos &&
        line.find("**regression**") != std::string::npos) {
      named = true;
    }
    if (line.find("midpoint") != std::string::npos || line.find("plain_mc") != std::string::npos) {
      EXPECT_EQ(line.find("**regression**"), std::string::npos)
          << "only simpson regressed: " << line;
    }
  }
  EXPECT_TRUE(named) << "no line names simpson as a regression\n" << describe(r);
  EXPECT_NE(r.out.find("REGRESSION"), std::string::npos) << describe(r);

  // The other direction is a steeper slope in B: not a regression.
  const command_result back = run_quadmc(dir, {"compare", "b", "a"});
  EXPECT_EQ(back.exit_status, 0) << describe(back);
}

}  // namespace
}  // namespace quadmc_cli_test
