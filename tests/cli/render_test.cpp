// End-to-end tests of `quadmc render` (bench/quadmc/render_command.hpp): the plan printed before
// the work, every file of the folder (and none of the binary copy the pictures are drawn from),
// the same bytes on 1 and 3 threads, a foreign folder refused and untouched, one-line errors for
// bad arguments and bad scene keys, and the README's render key table against the parser.
// Images of 16 × 16 pixels keep it fast; the statistics are tested in
// tests/estimators/irradiance_image_test.cpp.
#include "quadmc/report/csv.hpp"
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace quadmc_cli_test {
namespace {

const std::string small_scene = R"(name = "small"
seed = 5
width = 16
height = 12
region = [-0.55, -0.6, 0.15, 0.1]
occluder_height = 0.15
point_sets = ["independent", "jittered", "zsobol"]
spp = [1, 4, 16]
images = IMAGES

[light_sampling]
samples = 4
)";

std::string scene_text(bool images) {
  std::string s = small_scene;
  s.replace(s.find("IMAGES"), 6, images ? "true" : "false");
  return s;
}

class RenderCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<scratch_folder>();
    write_text(*dir_ / "small.toml", scene_text(true));
    result_ = std::make_unique<command_result>(
        run_quadmc(*dir_, {"render", "small.toml", "--out", "r", "--threads", "3"}));
  }
  static void TearDownTestSuite() {
    result_.reset();
    dir_.reset();
  }
  static std::unique_ptr<scratch_folder> dir_;
  static std::unique_ptr<command_result> result_;
};
std::unique_ptr<scratch_folder> RenderCommand::dir_;
std::unique_ptr<command_result> RenderCommand::result_;

TEST_F(RenderCommand, PrintsThePlanFirstAndWritesEveryFile) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  EXPECT_EQ(result_->out.rfind("render: 16 × 12 pixels of the plane z = 0", 0), 0u)
      << describe(*result_);
  EXPECT_NE(result_->out.find("3 estimators × 3 point sets × spp 1, 4, 16 = 27 images"),
            std::string::npos)
      << result_->out;
  EXPECT_NE(result_->out.find("light sampling: 1 × 4 and 4 × 1"), std::string::npos);
  EXPECT_NE(result_->out.find("\nrender: 33 images of 16 × 12 pixels in "), std::string::npos)
      << result_->out;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(*dir_ / "r")) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  const std::vector<std::string> expected{"README.md",
                                          "comparison.png",
                                          "error_spectrum.csv",
                                          "error_spectrum.png",
                                          "errors_cosine_hemisphere.png",
                                          "errors_light_area.png",
                                          "errors_uniform_hemisphere.png",
                                          "exact.png",
                                          "light_sampling.csv",
                                          "light_sampling.png",
                                          "lowpass.csv",
                                          "meta.csv",
                                          "rmse.csv",
                                          "rmse.png",
                                          "slopes.csv"};
  EXPECT_EQ(names, expected);
  const quadmc::csv_table rmse = quadmc::parse_csv(read_text(*dir_ / "r" / "rmse.csv"), "rmse.csv");
  EXPECT_EQ(rmse.rows.size(), 3u * 3u * 3u);
  const quadmc::csv_table slopes =
      quadmc::parse_csv(read_text(*dir_ / "r" / "slopes.csv"), "slopes.csv");
  EXPECT_EQ(slopes.rows.size(), 3u * 3u);
  // Five low-pass widths and 32 spectrum rings per estimated image.
  const quadmc::csv_table lowpass =
      quadmc::parse_csv(read_text(*dir_ / "r" / "lowpass.csv"), "lowpass.csv");
  EXPECT_EQ(lowpass.rows.size(), 3u * 3u * 3u * 5u);
  const quadmc::csv_table spectrum =
      quadmc::parse_csv(read_text(*dir_ / "r" / "error_spectrum.csv"), "error_spectrum.csv");
  EXPECT_EQ(spectrum.rows.size(), 3u * 3u * 3u * 32u);
  const quadmc::csv_table light =
      quadmc::parse_csv(read_text(*dir_ / "r" / "light_sampling.csv"), "light_sampling.csv");
  EXPECT_EQ(light.rows.size(), 4u);
  const std::string readme = read_text(*dir_ / "r" / "README.md");
  for (const std::string link :
       {"(exact.png)", "(comparison.png)", "(rmse.png)", "(errors_light_area.png)",
        "(light_sampling.png)", "(error_spectrum.png)"}) {
    EXPECT_NE(readme.find(link), std::string::npos) << link;
  }
}

// The same scene and seed on one thread (the fixture used three): the same bytes in every CSV,
// the fingerprints of every image included, and in every PNG.
TEST_F(RenderCommand, SameBytesOnOneAndThreeThreadsAndReplacesItsOwnFolder) {
  ASSERT_EQ(result_->exit_status, 0) << describe(*result_);
  const command_result again =
      run_quadmc(*dir_, {"render", "small.toml", "--out", "r1", "--threads", "1"});
  ASSERT_EQ(again.exit_status, 0) << describe(again);
  for (const std::string file :
       {"rmse.csv", "slopes.csv", "light_sampling.csv", "lowpass.csv", "error_spectrum.csv",
        "exact.png", "comparison.png", "error_spectrum.png", "errors_light_area.png", "rmse.png",
        "light_sampling.png"}) {
    EXPECT_EQ(read_text(*dir_ / "r1" / file), read_text(*dir_ / "r" / file)) << file;
  }
  // Another seed into the folder of the first: replaced (its files are the render's own), and
  // the images differ.
  const command_result replaced =
      run_quadmc(*dir_, {"render", "small.toml", "--out", "r1", "--threads", "1", "--seed", "6"});
  ASSERT_EQ(replaced.exit_status, 0) << describe(replaced);
  EXPECT_NE(read_text(*dir_ / "r1" / "rmse.csv"), read_text(*dir_ / "r" / "rmse.csv"));
}

// bench/scenes/render.toml (which tests/scene/plan_test.cpp leaves to this test) runs, at 8 × 8
// pixels and without pictures so that it is quick: every other key is the bundled scene's.
TEST(RenderCommandWithoutImages, BundledSceneRuns) {
  scratch_folder dir;
  std::string text = read_text(fs::path(QUADMC_SOURCE_DIR) / "bench" / "scenes" / "render.toml");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"width = 256", "width = 8"},
                                 {"height = 256", "height = 8"},
                                 {"images = true", "images = false"}}) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  }
  write_text(dir / "render.toml", text);
  const command_result r = run_quadmc(dir, {"render", "render.toml"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_NE(r.out.find("3 estimators × 9 point sets × spp 1, 4, 16, 64 = 108 images"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(fs::exists(dir / "results" / "render" / "light_sampling.csv"));
}

TEST(RenderCommandWithoutImages, WritesTheTablesOnly) {
  scratch_folder dir;
  write_text(dir / "s.toml", scene_text(false));
  const command_result r = run_quadmc(dir, {"render", "s.toml"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "results" / "small")) {
    names.insert(e.path().filename().string());
  }
  EXPECT_EQ(names, (std::set<std::string>{"README.md", "error_spectrum.csv", "light_sampling.csv",
                                          "lowpass.csv", "meta.csv", "rmse.csv", "slopes.csv"}));
}

void expect_render_error(const std::vector<std::string>& args, int status, const std::string& names,
                         const std::string& scene = scene_text(false)) {
  scratch_folder dir;
  write_text(dir / "s.toml", scene);
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

TEST(RenderErrors, BadArgumentsGetOneLine) {
  expect_render_error({"render"}, 2, "scene");
  expect_render_error(
      {"render", "s.toml", "--seed", "-3"}, 2,
      "--seed: expected an integer K with 0 ≤ K ≤ 2^64 − 1 = 18446744073709551615, got -3");
  expect_render_error({"render", "s.toml", "--threads", "5000"}, 2, "--threads");
  expect_render_error({"render", "s.toml", "extra"}, 2, "extra");
  expect_render_error({"render", "s.toml", "--out"}, 2, "--out");
  expect_render_error({"render", "missing.toml"}, 1, "missing.toml:0:0: cannot open");
}

TEST(RenderErrors, BadScenesGetOneLineNamingTheKey) {
  auto with = [](const std::string& from, const std::string& to) {
    std::string s = scene_text(false);
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const std::vector<std::string> args{"render", "s.toml"};
  expect_render_error(args, 1, "s.toml:2:1: key 'seeds': unknown key in a render scene",
                      with("seed = 5", "seeds = 5"));
  expect_render_error(args, 1, "key 'spp[2]': spp must increase, got 1 after 4",
                      with("spp = [1, 4, 16]", "spp = [4, 1]"));
  expect_render_error(args, 1,
                      "key 'spp': the jittered points cannot hold 2 samples per pixel in 2D",
                      with("spp = [1, 4, 16]", "spp = [1, 2]"));
  expect_render_error(args, 1, "key 'point_sets[1]': expected a point set",
                      with("\"independent\", ", "\"random\", "));
  expect_render_error(args, 1, "key 'width': expected a width between 1 and 4096 pixels, got 0",
                      with("width = 16", "width = 0"));
  expect_render_error(args, 1, "key 'region': expected [x_min, y_min, x_max, y_max]",
                      with("[-0.55, -0.6, 0.15, 0.1]", "[1, 0, 0, 1]"));
  // Regression: a region this far out squared distances past DBL_MAX, and the render exited 0
  // with rmse = nan for every estimator.
  expect_render_error(args, 1,
                      "key 'region': ", with("[-0.55, -0.6, 0.15, 0.1]", "[0, 0, 1e155, 1e155]"));
  expect_render_error(args, 1, "|x| ≤ 1e100",
                      with("[-0.55, -0.6, 0.15, 0.1]", "[0, 0, 1e155, 1e155]"));
  expect_render_error(
      args, 1, "key 'occluder_height': ", with("occluder_height = 0.15", "occluder_height = 1.5"));
  expect_render_error(args, 1, "key 'images': expected true or false, got \"yes\"",
                      with("images = false", "images = \"yes\""));
  expect_render_error(args, 1,
                      "key 'light_sampling.samples': ", with("samples = 4", "samples = 5"));
}

TEST(RenderErrors, RefusesAFolderThatIsNotItsOwn) {
  expect_render_error({"render", "s.toml", "--out", "notes"}, 1,
                      "--out 'notes': not a results folder: it holds 'todo.txt'");
  // A `run` results folder is not the render's either (convergence.csv is not a render file).
  scratch_folder dir;
  write_text(dir / "s.toml", scene_text(false));
  fs::create_directory(dir / "r");
  write_text(dir / "r" / "convergence.csv", "x\n");
  const command_result r = run_quadmc(dir, {"render", "s.toml", "--out", "r"});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_NE(r.err.find("it holds 'convergence.csv'"), std::string::npos) << describe(r);
  EXPECT_EQ(read_text(dir / "r" / "convergence.csv"), "x\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"r", "s.toml"}));
}

// README.md's table headed | render key | documents exactly the keys the parser accepts: the
// parser names them in its unknown-key message, which is read back here.
std::set<std::string> keys_in_message(const std::string& err) {
  const std::string marker = "expected one of: ";
  std::set<std::string> keys;
  std::stringstream list(err.substr(err.find(marker) + marker.size()));
  for (std::string k; std::getline(list, k, ',');) {
    k.erase(0, k.find_first_not_of(' '));
    k.erase(k.find_last_not_of(" \n") + 1);
    keys.insert(k);
  }
  return keys;
}

TEST(RenderReadme, KeyTableDocumentsEveryRenderKey) {
  scratch_folder dir;
  write_text(dir / "s.toml", "bogus = 1\n");
  const command_result top = run_quadmc(dir, {"render", "s.toml"});
  write_text(dir / "s.toml", "[light_sampling]\nbogus = 1\n");
  const command_result inner = run_quadmc(dir, {"render", "s.toml"});
  std::set<std::string> accepted = keys_in_message(top.err);
  for (const std::string& k : keys_in_message(inner.err)) accepted.insert("light_sampling." + k);
  accepted.erase("light_sampling");
  ASSERT_GE(accepted.size(), 10u) << top.err;

  std::ifstream readme(fs::path(QUADMC_SOURCE_DIR) / "README.md");
  std::set<std::string> documented;
  bool in_table = false;
  int tables = 0;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("| render key |", 0) == 0) {
      in_table = true;
      ++tables;
      continue;
    }
    if (in_table && line.rfind("|", 0) != 0) in_table = false;
    if (!in_table || line.rfind("|---", 0) == 0) continue;
    const auto a = line.find('`');
    const auto b = line.find('`', a + 1);
    ASSERT_NE(b, std::string::npos) << line;
    documented.insert(line.substr(a + 1, b - a - 1));
  }
  EXPECT_EQ(tables, 1) << "README.md should have one table headed | render key |";
  EXPECT_EQ(documented, accepted);
}

}  // namespace
}  // namespace quadmc_cli_test
