// End-to-end tests of the plot file names (report/markdown_report.hpp): distinct for distinct
// integrands, the same in bench/plot.py as in the library, and linked from README.md.
//
// Use these for the contract between the two sides; the rule itself is tested in
// tests/report/markdown_report_test.cpp.
#include "quadmc/report/answer_first.hpp"
#include "quadmc/report/markdown_report.hpp"
#include "quadmc_process.hpp"

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

TEST(PlotNamesTest, CollidingIntegrandNamesGetTheirOwnPlots) {
  // Regression: `x` and `x_s1` (s = 1) both drew "x_s1.svg", and `y`'s work-precision plot was
  // "work_precision_y_s1.svg", the error plot of an integrand named `work_precision_y`: two of
  // the eight plots overwrote others and the README linked the survivors twice.
  const std::vector<std::string> names{"x", "x_s1", "y", "work_precision_y"};
  std::string scene = "name = \"collide\"\nseed = 1\n";
  const std::vector<std::string> families{"exp", "sin", "poly", "inverse_quadratic"};
  for (std::size_t k = 0; k < names.size(); ++k) {
    scene += "[[integrand]]\nname = \"" + names[k] + "\"\nfamily = \"" + families[k] + "\"\n";
  }
  scene += "[[method]]\nname = \"midpoint\"\n[budget]\nN = [16, 64, 256]\n";
  scratch_folder dir;
  write_text(dir / "collide.toml", scene);
  const command_result r =
      run_quadmc(dir, {"run", (dir / "collide.toml").string(), "--out", "out"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);

  std::set<std::string> svgs;
  for (const auto& e : fs::directory_iterator(dir / "out")) {
    if (e.path().extension() == ".svg") svgs.insert(e.path().filename().string());
  }
  std::set<std::string> expected;
  for (const auto& name : names) {
    expected.insert(quadmc::convergence_plot_file(name, 1));
    expected.insert(quadmc::work_precision_plot_file(name, 1));
  }
  ASSERT_EQ(expected.size(), 8u) << "the library's names are distinct";
  // And the two summary figures (report/answer_first.hpp): `x` and `x_s1` in s = 1 are one
  // family, `x` (report/who_leads.hpp), so the page has a "Who leads" table.
  expected.insert(std::string(quadmc::slope_figure_stem) + ".svg");
  expected.insert(std::string(quadmc::who_leads_figure_stem) + ".svg");
  EXPECT_EQ(svgs, expected) << describe(r);
  const std::string readme = read_text(dir / "out" / "README.md");
  for (const auto& svg : svgs) {
    const std::string link = "](" + svg + ")";
    const auto first = readme.find(link);
    EXPECT_NE(first, std::string::npos) << svg << " is not linked";
    EXPECT_EQ(readme.find(link, first + 1), std::string::npos) << svg << " is linked twice";
  }
}

TEST(PlotNamesTest, PlotScriptWritesTheNamesTheLibraryLinks) {
  // bench/plot.py's plot_files against quadmc's functions on names a scene cannot hold (spaces,
  // '/', '~', '=', non-ASCII) as well as ones it can.
  const std::vector<std::pair<std::string, std::size_t>> cases{{"genz_gaussian_s3", 3},
                                                               {"genz_gaussian_s3", 4},
                                                               {"x", 1},
                                                               {"x_s1", 1},
                                                               {"x_s01", 1},
                                                               {"x_s12", 2},
                                                               {"a b/c", 2},
                                                               {"a~b", 1},
                                                               {"a_s=1", 1},
                                                               {"é", 1},
                                                               {"work_precision_y", 1}};
  scratch_folder logs;
  std::string script = "import sys\nsys.path.insert(0, '" + std::string(QUADMC_SOURCE_DIR) +
                       "/bench')\nimport plot\ncases = [\n";
  for (const auto& [name, s] : cases) {
    std::string quoted;
    for (const unsigned char c : name) {
      quoted += "\\x" + std::string(1, "0123456789abcdef"[c >> 4]) + "0123456789abcdef"[c & 15];
    }
    script += "    (b'" + quoted + "'.decode('utf-8'), " + std::to_string(s) + "),\n";
  }
  script += "]\nfor name, s in cases:\n    print(*plot.plot_files(name, s))\n";
  script += "print(plot.SLOPE_FIGURE, plot.WHO_LEADS_FIGURE)\n";
  write_text(logs / "names.py", script);
  process_options options;
  options.stdout_file = logs / "out";
  options.stderr_file = logs / "err";
  const command_result r =
      child_process({"/usr/bin/python3", (logs / "names.py").string()}, options).wait();
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  std::istringstream lines(r.out);
  for (const auto& [name, s] : cases) {
    std::string error_file;
    std::string work_precision_file;
    lines >> error_file >> work_precision_file;
    EXPECT_EQ(error_file, quadmc::convergence_plot_file(name, s)) << name << ", s = " << s;
    EXPECT_EQ(work_precision_file, quadmc::work_precision_plot_file(name, s))
        << name << ", s = " << s;
  }
  // The summary figures' names (report/answer_first.hpp).
  std::string slope_figure;
  std::string who_leads_figure;
  lines >> slope_figure >> who_leads_figure;
  EXPECT_EQ(slope_figure, quadmc::slope_figure_stem);
  EXPECT_EQ(who_leads_figure, quadmc::who_leads_figure_stem);
}

}  // namespace
}  // namespace quadmc_cli_test
