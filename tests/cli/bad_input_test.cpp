// Bad scene files through `quadmc run`: each must fail with a non-zero exit status and ONE line
// on stderr, "quadmc: <file>:<line>:<col>: key '<key>': …" (scene/parse.hpp), and leave no
// results folder and no "<folder>.partial" behind (the command writes only after a successful
// run, bench/quadmc/main.cpp).
//
// Use these for what a user sees on a mistake; the parser's own tests (tests/scene) cover every
// rule with parse_scene in memory. Not for valid scenes (run_test.cpp).
#include "quadmc_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

// The valid remainder most cases below add one mistake to.
const std::string valid_tables = R"([[integrand]]
family = "exp"

[[method]]
name = "simpson"

[budget]
N = [8, 16]

[output]
plots = false
)";

// Runs `quadmc run scene.toml` (default output folder results/<name>, in the scratch folder) on
// `text` and checks the failure: exit status 1, one stderr line starting with the file and
// `line`, naming `key` when there is one, and nothing written beside the scene file.
void expect_scene_error(const std::string& text, int line, const std::optional<std::string>& key,
                        const std::string& also = "") {
  scratch_folder dir;
  const fs::path scene = dir / "scene.toml";
  write_text(scene, text);
  const command_result r = run_quadmc(dir, {"run", scene.string()});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_FALSE(r.err.empty()) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected\n"
                                                             << describe(r);
  EXPECT_EQ(r.err.back(), '\n') << describe(r);
  const std::string where = "quadmc: " + scene.string() + ":" + std::to_string(line) + ":";
  EXPECT_EQ(r.err.rfind(where, 0), 0u) << "expected the line to start with " << where << "\n"
                                       << describe(r);
  if (key) {
    EXPECT_NE(r.err.find("key '" + *key + "'"), std::string::npos) << "key " << *key << "\n"
                                                                   << describe(r);
  }
  if (!also.empty()) {
    EXPECT_NE(r.err.find(also), std::string::npos) << also << "\n" << describe(r);
  }
  // No results/<name>/, no results/<name>.partial/, no --out folder: only the scene file.
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.toml"}) << describe(r);
}

TEST(BadInputTest, EmptySceneFile) {
  expect_scene_error("", 1, std::nullopt, "empty scene");
}

TEST(BadInputTest, FileTruncatedInsideATable) {
  // A scene cut inside [budget]'s N array: the TOML parser reports where the file ended.
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n\n[[method]]\nname = \"simpson\"\n\n"
      "[budget]\nN = [8, 16,",
      8, std::nullopt, "end-of-file");
}

TEST(BadInputTest, FileTruncatedBeforeARequiredTable) {
  // Cut after [[method]]: valid TOML, but [budget] never came.
  expect_scene_error("[[integrand]]\nfamily = \"exp\"\n\n[[method]]\nname = \"simpson\"\n", 1,
                     "budget");
}

TEST(BadInputTest, UnknownTopLevelKey) {
  expect_scene_error("name = \"bad\"\nseed = 1\ncolour = \"blue\"\n" + valid_tables, 3, "colour",
                     "unknown key");
}

TEST(BadInputTest, UnknownKeyInMethod) {
  // Line 6: the key after [[method]] and its name (valid_tables' lines 4–5).
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n\n[[method]]\nname = \"simpson\"\n"
      "colour = 3\n\n[budget]\nN = [8, 16]\n",
      6, "method[1].colour", "unknown key");
}

TEST(BadInputTest, APeerMethodInTheCommandWithoutPeers) {
  // `quadmc` never links the GPL peers: a scene naming one fails before anything runs, with the
  // command that has them.
  expect_scene_error(
      "[[integrand]]\nfamily = \"genz_gaussian\"\ndimensions = [2]\n\n[[method]]\n"
      "name = \"peer_gsl_vegas\"\n\n[budget]\nN = [1000, 2000]\n",
      6, "method[1].name", "is a peer, not built into this quadmc");
}

TEST(BadInputTest, WrongTypeOfSeed) {
  expect_scene_error("seed = \"x\"\n" + valid_tables, 1, "seed", "\"x\"");
}

TEST(BadInputTest, NegativeRepetitions) {
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n\n[[method]]\nname = \"plain_mc\"\n"
      "repetitions = -3\n\n[budget]\nN = [8, 16]\n",
      6, "method[1].repetitions", "-3");
}

TEST(BadInputTest, NegativeThreads) {
  expect_scene_error("name = \"bad\"\nthreads = -1\n" + valid_tables, 2, "threads", "-1");
}

TEST(BadInputTest, SimpsonWithOddPanels) {
  // Composite Simpson pairs panels: n must be even (Burden & Faires §4.4).
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n\n[[method]]\nname = \"simpson\"\n"
      "panels = [4, 7]\n\n[budget]\nN = [8, 16]\n",
      6, "method[1].panels[2]", "7");
}

TEST(BadInputTest, UnknownFamily) {
  expect_scene_error(
      "[[integrand]]\nfamily = \"expo\"\n\n[[method]]\nname = \"simpson\"\n\n"
      "[budget]\nN = [8, 16]\n",
      2, "integrand[1].family", "expo");
}

// reference / reference_uncertainty (docs/theory.md#references-without-a-closed-form): each
// mistake is one line at its key, from the command as from the parser.
TEST(BadInputTest, BadReferenceKeys) {
  const std::string head = "[[integrand]]\nfamily = \"exp\"\n";
  const std::string tail = "\n[[method]]\nname = \"simpson\"\n\n[budget]\nN = [8, 16]\n";
  expect_scene_error(head + "reference = \"exactly\"\n" + tail, 3, "integrand[1].reference",
                     "expected a finite number or \"computed\", got \"exactly\"");
  expect_scene_error(head + "reference = -inf\n" + tail, 3, "integrand[1].reference", "-inf");
  expect_scene_error(head + "reference = 1.5\nreference_uncertainty = -0.1\n" + tail, 4,
                     "integrand[1].reference_uncertainty", "expected a finite number ≥ 0");
  expect_scene_error(head + "reference_uncertainty = 0.1\n" + tail, 3,
                     "integrand[1].reference_uncertainty", "only with a number `reference`");
  expect_scene_error(head + "reference = 1.5\nensemble = 3\n" + tail, 3, "integrand[1].reference",
                     "not with ensemble = 3");
}

TEST(BadInputTest, NonexistentSceneFile) {
  // CLI11's ExistingFile check answers before quadmc does (its own message and exit code).
  scratch_folder dir;
  const command_result r = run_quadmc(dir, {"run", (dir / "missing.toml").string()});
  EXPECT_NE(r.exit_status, 0) << describe(r);
  EXPECT_NE(r.err.find("missing.toml"), std::string::npos) << describe(r);
  EXPECT_TRUE(dir.entries().empty()) << describe(r);
}

// QUADMC_SIMD picks the kernels' instruction set (core/simd_level.hpp); a misspelt level is one
// line naming the variable and the levels, before any work and with no folder written.
TEST(BadInputTest, UnknownSimdLevelInTheEnvironment) {
  scratch_folder dir;
  const fs::path scene = dir / "scene.toml";
  write_text(scene, valid_tables);
  ::setenv("QUADMC_SIMD", "avx3", 1);
  const command_result r = run_quadmc(dir, {"run", scene.string()});
  ::unsetenv("QUADMC_SIMD");
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(r.err,
            "quadmc: invalid QUADMC_SIMD = avx3: expected one of scalar, sse2, avx2, avx512\n")
      << describe(r);
  EXPECT_TRUE(r.out.empty()) << describe(r);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.toml"}) << describe(r);
}

// --- Inputs that crashed, hung or ran before failing: refused before any work ------------------

std::string repeated(const std::string& part, std::size_t count, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) out += (i > 0 ? separator : "") + part;
  return out;
}

// A dotted key of 40,000 parts (80 KB) and a header of 50,000 parts made toml++ recurse until
// the stack overflowed: exit status 139 (SIGSEGV), no message.
TEST(BadInputTest, DeepDottedKeysAreAnErrorNotACrash) {
  expect_scene_error(repeated("a", 40000, ".") + " = 1\n" + valid_tables, 1, std::nullopt,
                     "nesting deeper than 64 levels");
  expect_scene_error(valid_tables + "[" + repeated("a", 50000, ".") + "]\n", 12, std::nullopt,
                     "nesting deeper than 64 levels");
}

// factor = 1.0000000001 ran the ladder loop for minutes before the plan was printed.
TEST(BadInputTest, AGeometricLadderOfTooManySteps) {
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"simpson\"\n[budget]\n"
      "N = { from = 1, to = 1e6, factor = 1.0000000001 }\n",
      6, "budget.N.factor", "at most 4096");
}

// /dev/zero was read until memory ran out: it is no regular file, and is refused unread.
TEST(BadInputTest, ADeviceIsNoSceneFile) {
  scratch_folder dir;
  const command_result r = run_quadmc(dir, {"run", "/dev/zero"});
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find("/dev/zero"), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << describe(r);
  EXPECT_TRUE(dir.entries().empty()) << describe(r);
}

// Each of these planned (with an exact value of inf or NaN, or a cell the run refuses) and
// failed only when the run reached it; now `run` stops at the plan, naming the key.
TEST(BadInputTest, ReferencesTheRunCannotUseAreRefusedAtPlanTime) {
  const std::string tail = "[[method]]\nname = \"plain_mc\"\n[budget]\nN = [8, 16]\n";
  expect_scene_error("[[integrand]]\nfamily = \"exp\"\nlower = 0.0\nupper = 1000.0\n" + tail, 4,
                     "integrand[1].upper", "709.78");
  expect_scene_error("[[integrand]]\nfamily = \"poly\"\nlower = -1e100\nupper = 1e100\n" + tail, 3,
                     "integrand[1].lower", "1e51");
  expect_scene_error(
      "[[integrand]]\nfamily = \"genz_product_peak\"\ndimension = 1\na = [1e300]\nu = [0.5]\n" +
          tail,
      4, "integrand[1].a", "aᵢ² must stay finite");
  // Finite, but too large for the statistics: this one ended with "invalid error[0] = -nan".
  expect_scene_error("[[integrand]]\nfamily = \"exp\"\nlower = 0.0\nupper = 700.0\n" + tail, 1,
                     "integrand[1]", "too large for plain_mc at N = 8");
}

TEST(BadInputTest, CellsTheRunWouldRefuseAreRefusedAtPlanTime) {
  // N·s > 2^62: the point set refused it after the plan was printed.
  expect_scene_error(
      "[[integrand]]\nfamily = \"genz_gaussian\"\ndimension = 1024\n[[method]]\n"
      "name = \"plain_mc\"\nrepetitions = 1\n[budget]\nN = [9007199254740992]\n",
      8, "budget.N", "N·s ≤ 2^62");
  // A warp rate whose e^λ overflows: the warp refused it after the plan was printed.
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"importance\"\n"
      "warp = { name = \"exponential\", rate = 1e308 }\n[budget]\nN = [8, 16]\n",
      5, "method[1].warp.rate", "|l| <= 700");
  // Plots without the CSV they are drawn from: the plot script failed after the run.
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"simpson\"\n[budget]\nN = [8, 16]\n"
      "[output]\ncsv = false\n",
      7, "output.plots", "plots need the CSV");
  // An ensemble of a million instances at s = 1024 grew until memory ran out.
  expect_scene_error(
      "[[integrand]]\nfamily = \"genz_gaussian\"\ndimension = 1024\nensemble = 1000000\n"
      "[[method]]\nname = \"plain_mc\"\n[budget]\nN = [64]\n",
      4, "integrand[1].ensemble", "at most 65536");
}

TEST(BadInputTest, ExternalPointFilesAreCheckedAtPlanTime) {
  // A relative path is read from the scene file's folder; none of its files exists.
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"external_points\"\n"
      "path = \"pts/{N}_{r}.csv\"\nrepetitions = 1\n[budget]\nN = [8]\n",
      5, "method[1].path", "pts/8_0.csv = missing");
  // A coordinate outside [0, 1) in a file elsewhere (absolute path): its row and column.
  scratch_folder points;
  write_text(points / "4_0.csv", "x1\n0.125\n0.5\n1.5\n0.75\n");
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"external_points\"\n"
      "path = \"" +
          (points / "{N}_{r}.csv").string() + "\"\nrepetitions = 1\n[budget]\nN = [4]\n",
      5, "method[1].path", "4_0.csv row 3 column 1 = 1.5");
}

TEST(BadInputTest, ExternalPointSetFilesMustFitTheMethodAtPlanTime) {
  // importance warps one uniform per sample: a 2-column file is refused before any work.
  scratch_folder points;
  write_text(points / "4_0.csv", "x1,x2\n0.125,0.5\n0.375,0.25\n0.625,0.75\n0.875,0.0\n");
  write_text(points / "u_4_0.csv", "x1\n0.125\n0.375\n0.625\n0.875\n");
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"importance\"\n"
      "warp = \"power\"\npoint_set = \"external_points\"\npath = \"" +
          (points / "{N}_{r}.csv").string() + "\"\nrepetitions = 1\n[budget]\nN = [4]\n",
      7, "method[1].path",
      "4_0.csv = 2 columns: expected 1 (importance warps one uniform per sample: "
      "point_set = \"external_points\" needs s = 1)");
  // An irradiance method maps two: a 1-column file is refused the same way.
  expect_scene_error(
      "[[integrand]]\nfamily = \"irradiance_area\"\n[[method]]\n"
      "name = \"irradiance_light_area\"\npoint_set = \"external_points\"\npath = \"" +
          (points / "u_{N}_{r}.csv").string() + "\"\nrepetitions = 1\n[budget]\nN = [4]\n",
      6, "method[1].path", "u_4_0.csv = 1 columns: expected 2 (irradiance_light_area");
  // The files' keys without the files' point set.
  expect_scene_error(
      "[[integrand]]\nfamily = \"exp\"\n[[method]]\nname = \"importance\"\n"
      "warp = \"power\"\npath = \"pts/{N}_{r}.csv\"\n[budget]\nN = [8]\n",
      6, "method[1].path",
      "expected only with point_set = \"external_points\" (the files' rows as the "
      "uniforms), got it with no point_set (independent points)");
}

}  // namespace
}  // namespace quadmc_cli_test
