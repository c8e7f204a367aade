// Tests of scene/parse.hpp: valid scenes → the expected struct; every class of mistake → one
// scene_error naming the file, the line of the offending key and the key.
#include "quadmc/scene/parse.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace quadmc {
namespace {

scene parse(std::string_view text) {
  return parse_scene(text, "scene.toml");
}

// 1-based line of the first occurrence of `needle`: the line an error about that key must name.
std::uint32_t line_of(std::string_view text, std::string_view needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string_view::npos) << needle;
  std::uint32_t line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

// Parses `text`, expects a scene_error at `line` about `key`, and returns its message.
std::string expect_error(std::string_view text, std::uint32_t line, std::string_view key) {
  try {
    parse(text);
  } catch (const scene_error& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.where().file, "scene.toml") << message;
    EXPECT_EQ(e.where().line, line) << message;
    EXPECT_EQ(e.key(), key) << message;
    EXPECT_NE(message.find(fmt::format("scene.toml:{}:", line)), std::string::npos) << message;
    if (!key.empty()) {
      EXPECT_NE(message.find(fmt::format("key '{}'", key)), std::string::npos) << message;
    }
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    return message;
  }
  ADD_FAILURE() << "no scene_error for:\n" << text;
  return {};
}

// A valid scene the error tests modify one line at a time.
constexpr std::string_view valid = R"(name = "t"
seed = 7
[[integrand]]
family = "genz_gaussian"
dimension = 2
[[method]]
name = "simpson"
[[method]]
name = "plain_mc"
repetitions = 8
[budget]
N = [16, 64]
)";

std::string replace(std::string_view text, std::string_view from, std::string_view to) {
  std::string s(text);
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  s.replace(at, from.size(), to);
  return s;
}

TEST(ParseScene, MinimalSceneFileGivesTheExpectedStruct) {
  const scene sc = parse_scene_file(QUADMC_SOURCE_DIR "/bench/scenes/minimal.toml");
  EXPECT_EQ(sc.name, "example");
  EXPECT_EQ(sc.seed, 42u);
  EXPECT_EQ(sc.threads, 2u);
  ASSERT_EQ(sc.integrands.size(), 1u);
  const integrand_spec& f = sc.integrands[0];
  EXPECT_EQ(f.family, "genz_gaussian");
  EXPECT_EQ(f.name, "genz_gaussian_s3");
  EXPECT_EQ(f.dimension, 3u);
  EXPECT_EQ(f.ensemble, 1u);
  EXPECT_EQ(f.vectors.at("a"), (std::vector<double>{1.0, 2.0, 0.5}));
  EXPECT_EQ(f.vectors.at("u"), (std::vector<double>{0.3, 0.6, 0.45}));
  EXPECT_TRUE(f.scalars.empty());
  EXPECT_EQ(f.table.line, 7u);  // the [[integrand]] header of minimal.toml
  EXPECT_EQ(f.keys.at("a").line, 10u);
  ASSERT_EQ(sc.methods.size(), 2u);
  EXPECT_EQ(sc.methods[0].name, "simpson");
  EXPECT_EQ(sc.methods[0].label, "simpson");
  EXPECT_FALSE(sc.methods[0].repetitions_given);
  EXPECT_EQ(sc.methods[1].name, "plain_mc");
  EXPECT_EQ(sc.methods[1].repetitions, 64u);
  EXPECT_TRUE(sc.methods[1].repetitions_given);
  // 64·4^k ≤ 2^20: 2^6, 2^8, …, 2^20.
  EXPECT_EQ(sc.budget.N,
            (std::vector<std::uint64_t>{64, 256, 1024, 4096, 16384, 65536, 262144, 1048576}));
  EXPECT_EQ(sc.budget.max_evaluations, 100'000'000u);
  EXPECT_FALSE(sc.budget.max_seconds.has_value());
  EXPECT_TRUE(sc.output.csv && sc.output.markdown && sc.output.plots);
}

TEST(ParseScene, DefaultsWhenOptionalKeysAreOmitted) {
  const scene sc = parse_scene(replace(valid, "name = \"t\"\nseed = 7\n", ""), "dir/my_run.toml");
  EXPECT_EQ(sc.name, "my_run");  // the file name without extension
  EXPECT_EQ(sc.seed, 0u);
  EXPECT_EQ(sc.threads, 0u);  // all cores
  EXPECT_EQ(sc.methods[0].repetitions, 32u);
  EXPECT_EQ(sc.methods[0].m, 3u);
  EXPECT_FALSE(sc.budget.max_evaluations.has_value());
  EXPECT_TRUE(sc.output.csv && sc.output.markdown && sc.output.plots);
}

TEST(ParseScene, ListAndRangeFormsOfN) {
  EXPECT_EQ(parse(valid).budget.N, (std::vector<std::uint64_t>{16, 64}));
  const auto range = [](std::string_view r) {
    return parse(replace(valid, "N = [16, 64]", r)).budget.N;
  };
  EXPECT_EQ(range("N = { from = 10, to = 1000, factor = 10 }"),
            (std::vector<std::uint64_t>{10, 100, 1000}));
  EXPECT_EQ(range("N = { from = 3, to = 20, factor = 2 }"), (std::vector<std::uint64_t>{3, 6, 12}));
  // Fractional factor: round(10·1.5^k) = 10, 15, 22.5 → 23, 33.75 → 34, 50.6 → 51, 75.9 → 76.
  EXPECT_EQ(range("N = { from = 10, to = 100, factor = 1.5 }"),
            (std::vector<std::uint64_t>{10, 15, 23, 34, 51, 76}));
  EXPECT_EQ(range("N = [1e3, 4096]"), (std::vector<std::uint64_t>{1000, 4096}));
}

TEST(ParseScene, DimensionsShorthandExpandsOneIntegrandPerS) {
  const scene sc =
      parse(replace(valid, "dimension = 2", "dimensions = [1, 2, 4, 8]\nensemble = 5"));
  ASSERT_EQ(sc.integrands.size(), 4u);
  const std::size_t s[] = {1, 2, 4, 8};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(sc.integrands[i].dimension, s[i]);
    EXPECT_EQ(sc.integrands[i].name, fmt::format("genz_gaussian_s{}", s[i]));
    EXPECT_EQ(sc.integrands[i].base_name, "genz_gaussian");
    EXPECT_EQ(sc.integrands[i].table_index, 1u);
    EXPECT_EQ(sc.integrands[i].ensemble, 5u);
  }
}

TEST(ParseScene, OmittedDimensionMeansTheFamilyDefault) {
  // s = 0 is the catalogue's "family default" (1, or 2 for irradiance); make_plan resolves it.
  const scene sc = parse(replace(valid, "dimension = 2\n", ""));
  EXPECT_EQ(sc.integrands[0].dimension, 0u);
  EXPECT_EQ(sc.integrands[0].name, "genz_gaussian");
}

TEST(ParseScene, FamilyParametersPassThrough) {
  const scene sc = parse(replace(valid, "dimension = 2", "dimension = 2\ncut = [1, 2]\nb = 3"));
  EXPECT_EQ(sc.integrands[0].vectors.at("cut"), (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(sc.integrands[0].scalars.at("b"), 3.0);
}

TEST(ParseScene, MethodOptions) {
  const scene sc = parse(replace(valid, "[budget]", R"([[method]]
name = "gauss_legendre"
m = 5
panels = [1, 2, 4]
[[method]]
name = "importance"
warp = { name = "power", exponent = 2.0 }
point_set = "jittered"
integrands = ["genz_gaussian_s2"]
[output]
plots = false
[budget]
max_seconds = 60)"));
  ASSERT_EQ(sc.methods.size(), 4u);
  EXPECT_EQ(sc.methods[2].m, 5u);
  EXPECT_EQ(sc.methods[2].panels, (std::vector<std::uint64_t>{1, 2, 4}));
  EXPECT_EQ(sc.methods[3].warp, "power");
  EXPECT_EQ(sc.methods[3].warp_parameter, 2.0);
  EXPECT_EQ(sc.methods[3].point_set, "jittered");
  EXPECT_EQ(sc.methods[3].label, "importance_power_jittered");
  EXPECT_EQ(sc.methods[3].integrands, (std::vector<std::string>{"genz_gaussian_s2"}));
  EXPECT_FALSE(sc.output.plots);
  EXPECT_TRUE(sc.output.csv);
  EXPECT_EQ(sc.budget.max_seconds, 60.0);
}

// `accumulator` on a tensor rule: parsed into enum summation, and the default label gets the
// accumulator's name so that the same rule with two accumulators gives two series.
TEST(ParseScene, AccumulatorKeyMakesItsOwnSeries) {
  const scene sc = parse(replace(valid, "[budget]", R"([[method]]
name = "simpson"
accumulator = "naive"
[[method]]
name = "gauss_legendre"
accumulator = "long_double"
[budget])"));
  ASSERT_EQ(sc.methods.size(), 4u);
  EXPECT_EQ(sc.methods[0].accumulator, summation::pairwise) << "the default";
  EXPECT_FALSE(sc.methods[0].accumulator_given);
  EXPECT_EQ(sc.methods[0].label, "simpson");
  EXPECT_EQ(sc.methods[2].accumulator, summation::naive);
  EXPECT_EQ(sc.methods[2].label, "simpson_naive");
  EXPECT_EQ(sc.methods[3].accumulator, summation::long_double);
  EXPECT_EQ(sc.methods[3].label, "gauss_legendre_long_double");
}

TEST(SceneErrors, AccumulatorValueTypeAndMethod) {
  std::string t =
      replace(valid, "name = \"simpson\"", "name = \"simpson\"\naccumulator = \"kahan\"");
  std::string m = expect_error(t, line_of(t, "accumulator"), "method[1].accumulator");
  EXPECT_NE(m.find("one of: pairwise, neumaier, naive, long_double"), std::string::npos) << m;
  t = replace(valid, "name = \"simpson\"", "name = \"simpson\"\naccumulator = 3");
  expect_error(t, line_of(t, "accumulator"), "method[1].accumulator");
  // Monte Carlo's accumulation is fixed (Neumaier + Welford): the key is unknown there.
  t = replace(valid, "repetitions = 8", "repetitions = 8\naccumulator = \"naive\"");
  m = expect_error(t, line_of(t, "accumulator"), "method[2].accumulator");
  EXPECT_NE(m.find("unknown key in a 'plain_mc' method"), std::string::npos) << m;
}

// Found by the scene fuzzer (tests/fuzz/regressions/): toml++ 3.3.0 has undefined behaviour on
// U+00A1…U+0499 and three other blocks (§, π, é…) in some positions. The parser hands toml++
// private-use stand-ins instead and maps them back: the error is toml++'s ordinary one, naming the
// original character at its line and column, and strings keep their characters.
TEST(SceneErrors, NonAsciiCharactersTomlPlusPlusCannotClassify) {
  std::string t = replace(valid, "name = \"plain_mc\"", "name = \"plain_mc\"\u00a7");
  std::string m = expect_error(t, line_of(t, "plain_mc"), "");
  EXPECT_NE(m.find(fmt::format("scene.toml:{}:18: ", line_of(t, "plain_mc"))), std::string::npos)
      << m;
  EXPECT_NE(m.find("saw '\u00a7'"), std::string::npos) << m;
  t = replace(valid, "seed = 7", "\u03c0 = 7");
  m = expect_error(t, line_of(t, "= 7"), "");
  EXPECT_NE(m.find("\u03c0"), std::string::npos) << m;
  // A quoted key keeps its π in the unknown-key message.
  t = replace(valid, "seed = 7", "\"\u03c0\" = 7");
  m = expect_error(t, line_of(t, "= 7"), "\u03c0");
  EXPECT_NE(m.find("key '\u03c0': unknown key"), std::string::npos) << m;
  // Private-use characters of the stand-in block are refused, by position.
  t = replace(valid, "seed = 7", "seed = 7 # \ue006");
  m = expect_error(t, line_of(t, "seed"), "");
  EXPECT_NE(m.find("private-use character U+E006"), std::string::npos) << m;
  // Inside strings of every kind and in comments they are kept as written.
  std::string ok = replace(valid, "name = \"t\"", R"(name = "t"  # σ·N ≈ 10⁻⁷ — § é fine
description = """π ≈ 3.14 "quoted" \"""
and "" more ’ ε """)");
  ok = replace(ok, "family = \"genz_gaussian\"", "family = 'genz_gaussian'  # § after a literal");
  const scene sc = parse(ok);
  EXPECT_EQ(sc.description, "π ≈ 3.14 \"quoted\" \"\"\"\nand \"\" more ’ ε ");
}

TEST(SceneErrors, TheIssuesExampleMessageExactly) {
  const std::string text = replace(valid, "repetitions = 8", "repetitions = -3");
  const std::string message = expect_error(text, 10, "method[2].repetitions");
  EXPECT_EQ(message,
            "scene.toml:10:1: key 'method[2].repetitions': expected a positive "
            "integer, got -3");
}

TEST(SceneErrors, EmptyAndCommentOnlyFiles) {
  expect_error("", 1, "");
  expect_error("# nothing but a comment\n\n", 1, "");
}

TEST(SceneErrors, TruncatedFileReportsTomlsPosition) {
  // Cut in the middle of a string: toml++ reports the line where the string began and ran out.
  const std::string text(valid.substr(0, valid.find("genz_gaussian") + 4));
  const std::string message = expect_error(text, line_of(text, "family"), "");
  EXPECT_NE(message.find("scene.toml:4:"), std::string::npos) << message;
  // Cut inside an array.
  const std::string array(valid.substr(0, valid.find("64]")));
  expect_error(array, line_of(array, "N = "), "");
}

TEST(SceneErrors, UnknownKeysAtEveryLevel) {
  std::string t = replace(valid, "seed = 7", "seed = 7\ncolour = 1");
  expect_error(t, line_of(t, "colour"), "colour");
  t = replace(valid, "repetitions = 8", "repetition = 8");
  expect_error(t, line_of(t, "repetition"), "method[2].repetition");
  t = replace(valid, "N = [16, 64]", "N = [16, 64]\nmax_evals = 5");
  expect_error(t, line_of(t, "max_evals"), "budget.max_evals");
  t = replace(valid, "N = [16, 64]", "N = { from = 1, to = 8, factr = 2 }");
  expect_error(t, line_of(t, "N = "), "budget.N.factr");
  t = std::string(valid) + "[output]\nhtml = true\n";
  expect_error(t, line_of(t, "html"), "output.html");
  // A key a method does not take: Simpson has no `m`.
  t = replace(valid, "name = \"simpson\"", "name = \"simpson\"\nm = 3");
  expect_error(t, line_of(t, "m = 3"), "method[1].m");
  // Unknown keys of an [[integrand]] are family parameters; the catalogue rejects them when
  // the plan is made (plan_test.cpp).
}

TEST(SceneErrors, WrongTypes) {
  std::string t = replace(valid, "seed = 7", "seed = 7\nthreads = \"two\"");
  const std::string m = expect_error(t, line_of(t, "threads"), "threads");
  EXPECT_NE(m.find("got \"two\""), std::string::npos) << m;
  t = replace(valid, "repetitions = 8", "repetitions = 2.5");
  expect_error(t, line_of(t, "repetitions"), "method[2].repetitions");
  t = replace(valid, "dimension = 2", "dimension = \"2\"");
  expect_error(t, line_of(t, "dimension"), "integrand[1].dimension");
  t = replace(valid, "dimension = 2", "dimension = 2\na = \"wide\"");
  expect_error(t, line_of(t, "a = "), "integrand[1].a");
  t = replace(valid, "N = [16, 64]", "N = 64");
  expect_error(t, line_of(t, "N = "), "budget.N");
  t = replace(valid, "N = [16, 64]", "N = [16, \"x\"]");
  expect_error(t, line_of(t, "N = "), "budget.N[2]");
  t = std::string(valid) + "[output]\ncsv = 1\n";
  expect_error(t, line_of(t, "csv"), "output.csv");
  t = replace(replace(valid, "[budget]\nN = [16, 64]\n", ""), "seed = 7", "seed = 7\nbudget = 3");
  expect_error(t, line_of(t, "budget = 3"), "budget");
}

TEST(SceneErrors, OutOfRangeValues) {
  std::string t = replace(valid, "dimension = 2", "dimension = 0");
  expect_error(t, line_of(t, "dimension"), "integrand[1].dimension");
  t = replace(valid, "seed = 7", "seed = -1");
  expect_error(t, line_of(t, "seed"), "seed");
  t = replace(valid, "N = [16, 64]", "N = [16, 0]");
  expect_error(t, line_of(t, "N = "), "budget.N[2]");
  t = replace(valid, "N = [16, 64]", "N = [64, 16]");
  expect_error(t, line_of(t, "N = "), "budget.N[2]");
  t = replace(valid, "N = [16, 64]", "N = { from = 64, to = 16, factor = 2 }");
  expect_error(t, line_of(t, "N = "), "budget.N.to");
  t = replace(valid, "N = [16, 64]", "N = { from = 1, to = 16, factor = 1 }");
  expect_error(t, line_of(t, "N = "), "budget.N.factor");
  t = replace(valid, "N = [16, 64]", "N = [16, 64]\nmax_evaluations = 0.5");
  expect_error(t, line_of(t, "max_eval"), "budget.max_evaluations");
  t = replace(valid, "N = [16, 64]", "N = [16, 64]\nmax_seconds = 0");
  expect_error(t, line_of(t, "max_sec"), "budget.max_seconds");
  t = replace(valid, "dimension = 2", "dimension = 2\nensemble = 0");
  expect_error(t, line_of(t, "ensemble"), "integrand[1].ensemble");
  t = replace(valid, "name = \"simpson\"", "name = \"gauss_legendre\"\nm = 6");  // no 6-point rule
  expect_error(t, line_of(t, "m = 6"), "method[1].m");
}

TEST(SceneErrors, SimpsonWithAnOddExplicitPanelCount) {
  std::string t = replace(valid, "name = \"simpson\"", "name = \"simpson\"\npanels = [2, 5]");
  const std::string m = expect_error(t, line_of(t, "panels"), "method[1].panels[2]");
  EXPECT_NE(m.find("even"), std::string::npos) << m;
  t = replace(valid, "name = \"simpson\"", "name = \"simpson\"\npanels = 3");
  expect_error(t, line_of(t, "panels"), "method[1].panels");
  // Even counts are fine, and the trapezoid rule takes odd ones.
  EXPECT_NO_THROW(parse(replace(valid, "name = \"simpson\"", "name = \"simpson\"\npanels = 4")));
  EXPECT_NO_THROW(
      parse(replace(valid, "name = \"simpson\"", "name = \"trapezoid\"\npanels = [3, 5]")));
}

TEST(SceneErrors, UnknownMethodNamesTheChoices) {
  const std::string t = replace(valid, "\"simpson\"", "\"simpsons\"");
  const std::string m = expect_error(t, line_of(t, "simpsons"), "method[1].name");
  EXPECT_NE(m.find("simpson, gauss_legendre"), std::string::npos) << m;
}

TEST(SceneErrors, MissingRequiredKeys) {
  std::string t = replace(valid, "family = \"genz_gaussian\"\n", "");
  expect_error(t, line_of(t, "[[integrand]]"), "integrand[1].family");
  t = replace(valid, "N = [16, 64]\n", "max_seconds = 5\n");
  expect_error(t, line_of(t, "[budget]"), "budget.N");
  t = std::string(valid.substr(0, valid.find("[budget]")));
  expect_error(t, 1, "budget");
  t = replace(valid, "name = \"simpson\"", "repetitions = 4");
  expect_error(t, line_of(t, "[[method]]"), "method[1].name");
  t = replace(valid, "name = \"plain_mc\"", "name = \"importance\"");
  expect_error(t, line_of(t, "importance") - 1, "method[2].warp");
}

TEST(SceneErrors, ImpossibleCombinationsTheParserSees) {
  std::string t = replace(valid, "dimension = 2", "dimension = 2\ndimensions = [1, 2]");
  expect_error(t, line_of(t, "dimensions"), "integrand[1].dimensions");
  // Two integrands with the same display name.
  t = replace(valid, "[[method]]",
              "[[integrand]]\nfamily = \"genz_gaussian\"\ndimension = 2\n"
              "[[method]]");
  expect_error(t, line_of(t, "dimension = 2\n[[method]]") - 2, "integrand[2].name");
  // Two methods with the same label.
  t = replace(valid, "name = \"plain_mc\"", "name = \"simpson\"");
  expect_error(t, line_of(t, "repetitions") - 2, "method[2].label");
  // A restriction naming no integrand of the scene.
  t = replace(valid, "repetitions = 8", "integrands = [\"genz_gaussian_s3\"]");
  expect_error(t, line_of(t, "integrands"), "method[2].integrands[1]");
  // Warp parameters out of range.
  t = replace(valid, "name = \"plain_mc\"",
              "name = \"importance\"\nwarp = { name = \"power\", exponent = -1 }");
  expect_error(t, line_of(t, "exponent"), "method[2].warp.exponent");
  t = replace(valid, "name = \"plain_mc\"", "name = \"importance\"\nwarp = \"gaussian\"");
  expect_error(t, line_of(t, "warp"), "method[2].warp");
}

TEST(SceneErrors, UnreadableFile) {
  try {
    parse_scene_file("/nonexistent/scene.toml");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const scene_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.toml:0:0:"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace quadmc
