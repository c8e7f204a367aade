// End-to-end tests of `quadmc gallery` (bench/quadmc/gallery_command.hpp): the plan printed
// before the work, every file of the folder, exactly one point per stratum wherever the gallery
// draws a stratum grid, the same bytes for the same seed, a second run replacing the first, and
// one-line errors for bad arguments and a folder the gallery may not replace.
#include "quadmc/report/csv.hpp"
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace quadmc_cli_test {
namespace {

const std::vector<std::string> gallery_files{"README.md",    "discrepancy.csv", "gallery.png",
                                             "meta.csv",     "scatter.csv",     "spectra.png",
                                             "spectrum.csv", "strata.csv"};

// One gallery with few realizations, shared by the tests that only read it.
class GalleryCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<scratch_folder>();
    result_ = std::make_unique<command_result>(run_quadmc(
        *dir_, {"gallery", "--out", "g", "--realizations", "3", "--seed", "5", "--threads", "3"}));
  }
  static void TearDownTestSuite() {
    result_.reset();
    dir_.reset();
  }
  static quadmc::csv_table table(const std::string& name) {
    return quadmc::parse_csv(read_text(*dir_ / "g" / name), name);
  }
  static std::unique_ptr<scratch_folder> dir_;
  static std::unique_ptr<command_result> result_;
};
std::unique_ptr<scratch_folder> GalleryCommand::dir_;
std::unique_ptr<command_result> GalleryCommand::result_;

TEST_F(GalleryCommand, PrintsThePlanFirstAndWritesEveryFile) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  EXPECT_EQ(result_->out.rfind("gallery: 8 point sets in s = 2 (seed 5), 3 threads", 0), 0u)
      << describe(*result_);
  EXPECT_NE(result_->out.find("over 3 realizations per set"), std::string::npos);
  EXPECT_NE(result_->out.find("jittered         strata: N = 16: 4 × 4 cells"), std::string::npos)
      << result_->out;
  EXPECT_NE(result_->out.find("\ngallery: 8 point sets in "), std::string::npos);
  EXPECT_NE(result_->out.find("wrote "), std::string::npos);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(*dir_ / "g")) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, gallery_files);
  const std::string readme = read_text(*dir_ / "g" / "README.md");
  EXPECT_NE(readme.find("![Scatter plots"), std::string::npos);
  EXPECT_NE(readme.find("3 realizations"), std::string::npos);
  const quadmc::csv_table spectrum = table("spectrum.csv");
  std::set<std::string> sets;
  for (const auto& row : spectrum.rows) {
    sets.insert(row[spectrum.column("set")]);
    EXPECT_EQ(row[spectrum.column("realizations")], "3");
    EXPECT_EQ(row[spectrum.column("n")], "1024");
  }
  EXPECT_EQ(sets.size(), 8u);
  EXPECT_EQ(spectrum.rows.size(), 8u * 64u);
}

// Every grid strata.csv lists is checked against the points of scatter.csv: `cells` means each
// of the columns × rows cells holds exactly one point, `rows_and_columns` each of the N columns
// and each of the N rows of width 1/N. The stratified sets must list their grids at every N, so
// the check cannot pass by listing none.
TEST_F(GalleryCommand, StratifiedSetsPutExactlyOnePointPerStratum) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  const quadmc::csv_table scatter = table("scatter.csv");
  std::map<std::pair<std::string, std::string>, std::vector<std::pair<double, double>>> points;
  for (const auto& row : scatter.rows) {
    points[{row[scatter.column("set")], row[scatter.column("n")]}].emplace_back(
        std::stod(row[scatter.column("x1")]), std::stod(row[scatter.column("x2")]));
  }
  const quadmc::csv_table strata = table("strata.csv");
  std::set<std::pair<std::string, std::string>> listed;
  for (const auto& row : strata.rows) {
    const std::string set = row[strata.column("set")];
    const std::string n = row[strata.column("n")];
    listed.insert({set, row[strata.column("kind")] + "@" + n});
    const auto& x = points.at({set, n});
    ASSERT_EQ(x.size(), std::stoul(n)) << set;
    const auto columns = std::stoul(row[strata.column("columns")]);
    const auto rows = std::stoul(row[strata.column("rows")]);
    auto cell = [](double t, unsigned long k) {
      return std::min(k - 1, static_cast<unsigned long>(std::floor(t * static_cast<double>(k))));
    };
    if (row[strata.column("kind")] == "cells") {
      ASSERT_EQ(columns * rows, x.size()) << set << " N = " << n;
      std::set<std::pair<unsigned long, unsigned long>> cells;
      for (const auto& [a, b] : x) cells.insert({cell(a, columns), cell(b, rows)});
      EXPECT_EQ(cells.size(), x.size()) << set << " N = " << n << ": a cell holds two points";
    } else {
      ASSERT_EQ(row[strata.column("kind")], "rows_and_columns");
      std::set<unsigned long> xs, ys;
      for (const auto& [a, b] : x) {
        xs.insert(cell(a, columns));
        ys.insert(cell(b, rows));
      }
      EXPECT_EQ(xs.size(), x.size()) << set << " N = " << n << ": a column holds two points";
      EXPECT_EQ(ys.size(), x.size()) << set << " N = " << n << ": a row holds two points";
    }
  }
  for (const std::string n : {"16", "64", "256"}) {
    for (const std::string set : {"jittered", "unjittered", "padded_jittered", "sobol"}) {
      EXPECT_TRUE(listed.count({set, "cells@" + n})) << set << " N = " << n;
    }
    for (const std::string set : {"latin_hypercube", "lattice"}) {
      EXPECT_TRUE(listed.count({set, "rows_and_columns@" + n})) << set << " N = " << n;
    }
  }
}

TEST_F(GalleryCommand, SameSeedGivesTheSameNumbersOnAnyThreadCountAndReplacesItsOwnFolder) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  // On one thread instead of all cores (the fixture's run): the same bytes.
  const command_result again = run_quadmc(
      *dir_, {"gallery", "--out", "g2", "--realizations", "3", "--seed", "5", "--threads", "1"});
  ASSERT_EQ(again.exit_status, 0) << describe(again);
  for (const std::string file : {"scatter.csv", "spectrum.csv", "discrepancy.csv", "strata.csv"}) {
    EXPECT_EQ(read_text(*dir_ / "g2" / file), read_text(*dir_ / "g" / file)) << file;
  }
  // A second gallery into a folder of the first replaces it (its files are the gallery's own).
  const command_result replaced =
      run_quadmc(*dir_, {"gallery", "--out", "g2", "--realizations", "2", "--seed", "6"});
  ASSERT_EQ(replaced.exit_status, 0) << describe(replaced);
  EXPECT_NE(read_text(*dir_ / "g2" / "scatter.csv"), read_text(*dir_ / "g" / "scatter.csv"));
}

void expect_one_line_error(const std::vector<std::string>& args, int status,
                           const std::string& names) {
  scratch_folder dir;
  write_text(dir / "mine.txt", "keep me");
  fs::create_directory(dir / "notes");
  write_text(dir / "notes" / "todo.txt", "keep me too");
  const command_result r = run_quadmc(dir, args);
  EXPECT_EQ(r.exit_status, status) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find(names), std::string::npos) << describe(r);
  EXPECT_TRUE(r.out.empty()) << describe(r);
  EXPECT_EQ(read_text(dir / "notes" / "todo.txt"), "keep me too");
  EXPECT_FALSE(fs::exists(dir / "results"));
}

TEST(GalleryErrors, BadArgumentsGetOneLine) {
  expect_one_line_error({"gallery", "--realizations", "1"}, 2, "--realizations");
  expect_one_line_error({"gallery", "--realizations", "many"}, 2, "--realizations");
  expect_one_line_error({"gallery", "--realizations", "100001"}, 2, "--realizations");
  expect_one_line_error(
      {"gallery", "--seed", "-3"}, 2,
      "--seed: expected an integer K with 0 ≤ K ≤ 2^64 − 1 = 18446744073709551615, got -3");
  expect_one_line_error({"gallery", "--threads", "5000"}, 2, "--threads");
  expect_one_line_error({"gallery", "extra"}, 2, "extra");
  expect_one_line_error({"gallery", "--out"}, 2, "--out");
}

TEST(GalleryErrors, RefusesAFolderThatIsNotItsOwn) {
  // A folder with somebody's file in it is not replaced, before anything is computed.
  expect_one_line_error({"gallery", "--out", "notes", "--realizations", "2"}, 1,
                        "--out 'notes': not a results folder: it holds 'todo.txt'");
  // A `run` results folder is not the gallery's either (convergence.csv is not a gallery file).
  scratch_folder dir;
  fs::create_directory(dir / "r");
  write_text(dir / "r" / "convergence.csv", "x\n");
  const command_result r = run_quadmc(dir, {"gallery", "--out", "r", "--realizations", "2"});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_NE(r.err.find("it holds 'convergence.csv'"), std::string::npos) << describe(r);
  EXPECT_EQ(read_text(dir / "r" / "convergence.csv"), "x\n");
}

}  // namespace
}  // namespace quadmc_cli_test
