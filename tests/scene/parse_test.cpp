// Tests of scene/parse.hpp: valid scenes → the expected struct; every class of mistake → one
// scene_error naming the file, the line of the offending key and the key.
#include "quadmc/scene/parse.hpp"

#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "scene_text.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <string_view>
#include <thread>

namespace quadmc {
namespace {

scene parse(std::string_view text) {
  return parse_scene(text, "scene.toml");
}

using test_support::line_of;

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

using test_support::replace;

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
  EXPECT_EQ(sc.budget.timing_min_seconds, 0.01);  // the default stable-timing minimum
  EXPECT_EQ(sc.budget.paired_timing_rounds, 5u);  // the default paired timing
  EXPECT_TRUE(sc.output.csv && sc.output.markdown && sc.output.plots);
}

TEST(ParseScene, DefaultsWhenOptionalKeysAreOmitted) {
  const scene sc = parse_scene(replace(valid, "name = \"t\"\nseed = 7\n", ""), "dir/my_run.toml");
  EXPECT_EQ(sc.name, "my_run");  // the file name without extension
  EXPECT_EQ(sc.seed, 0u);
  EXPECT_EQ(sc.threads, 0u);  // all cores
  EXPECT_EQ(sc.methods[0].repetitions, 32u);
  EXPECT_EQ(sc.methods[0].control, cell_control::fixed_size);
  EXPECT_TRUE(sc.methods[0].tolerances.empty());
  EXPECT_FALSE(sc.budget.max_evaluations.has_value());
  EXPECT_TRUE(sc.output.csv && sc.output.markdown && sc.output.plots);
}

// Regression: a scene without `name` whose file name was not portable got the name "scene", so
// "my results.toml" and "other-test+1.toml" wrote one results/scene/ over the other.
TEST(ParseScene, AFileNameThatIsNotPortableGivesAPortableNameOfItsOwn) {
  const std::string text = replace(valid, "name = \"t\"\n", "");
  const auto name_of = [&](std::string_view file) { return parse_scene(text, file).name; };
  const std::vector<std::string> names = {name_of("my results.toml"), name_of("my+results.toml"),
                                          name_of("other-test+1.toml"),
                                          name_of("r\xc3\xa9sum\xc3\xa9.toml")};
  const std::vector<std::string> prefixes = {"my_results-", "my_results-", "other-test_1-",
                                             "r__sum__-"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& n = names[i];
    EXPECT_TRUE(is_portable_name(n)) << n;
    ASSERT_EQ(n.rfind(prefixes[i], 0), 0u) << n;
    const std::string hash = n.substr(prefixes[i].size());
    EXPECT_EQ(hash.size(), 8u) << n;
    EXPECT_EQ(hash.find_first_not_of("0123456789abcdef"), std::string::npos) << n;
  }
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size())
      << "names that differ only in unportable bytes get folders of their own";
  EXPECT_EQ(name_of("dir/my results.toml"), names[0]) << "the same file name, the same folder";
  EXPECT_EQ(name_of("dir/my_run.toml"), "my_run") << "a portable file name is kept as it is";
  // "." and ".." are made of allowed characters: the message says they are not names.
  const std::string dots = replace(valid, "name = \"t\"", "name = \"..\"");
  const std::string m = expect_error(dots, line_of(dots, "name"), "name");
  EXPECT_NE(m.find("other than '.' and '..'"), std::string::npos) << m;
}

// Regression: a name with a newline was shown as "a b" (another name than the one refused), and
// max_evaluations = 1e300 was refused as "expected a positive number", which it is.
TEST(SceneErrors, MessagesShowTheValueAsWrittenAndTheRealRange) {
  const std::string newline = replace(valid, "name = \"t\"", "name = \"a\\nb\"");
  std::string m = expect_error(newline, line_of(newline, "name"), "name");
  EXPECT_NE(m.find("got \"a\\nb\""), std::string::npos) << m;
  const std::string huge = std::string(valid) + "max_evaluations = 1e300\n";
  m = expect_error(huge, line_of(huge, "max_evaluations"), "budget.max_evaluations");
  EXPECT_NE(m.find("a whole number of evaluations from 1 to 2^63 − 1"), std::string::npos) << m;
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
  // A string is a string parameter; which strings a key takes is the catalogue's rule (make_plan).
  const scene st =
      parse(replace(valid, "dimension = 2", "dimension = 2\ncoefficient_decay = \"cubic\""));
  EXPECT_EQ(st.integrands[0].strings.at("coefficient_decay"), "cubic");
  EXPECT_TRUE(st.integrands[0].scalars.empty());
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
max_seconds = 60
timing_min_seconds = 0.25)"));
  ASSERT_EQ(sc.methods.size(), 4u);
  // The options reached the configured methods: m = 5 is order 10; the panels replace the
  // ladder with n = 1, 2, 4 (5, 10, 20 nodes per axis).
  const method& gauss = *sc.methods[2].configured;
  EXPECT_EQ(gauss.theory({smoothness::smooth, 1}).slope, -10.0);
  std::vector<std::uint64_t> panels, nodes;
  for (const sizing& size : gauss.explicit_sizes(1)) {
    ASSERT_TRUE(size.size) << size.reason;
    panels.push_back(size.size->per_axis);
    nodes.push_back(size.size->points_per_axis);
  }
  EXPECT_EQ(panels, (std::vector<std::uint64_t>{1, 2, 4}));
  EXPECT_EQ(nodes, (std::vector<std::uint64_t>{5, 10, 20}));
  // The warp's exponent and the point set: the same estimates as the method configured from C++
  // with them (and not as with another exponent).
  const method& importance = *sc.methods[3].configured;
  EXPECT_EQ(sc.methods[3].label, "importance_power_jittered");
  const integrand_params params;
  const any_integrand f = make_integrand("exp", params);
  const cell_size size{1024, 32, 0, 0};
  const method_cell cell{
      f, params, size, cell_control::fixed_size, std::numeric_limits<double>::quiet_NaN(), 3};
  const run_context context{7, 1};
  const double value = importance.run(cell, context).value;
  auto warp = [](double exponent) {
    return option_table{{"warp", option_table{{"name", "power"}, {"exponent", exponent}}},
                        {"point_set", "jittered"}};
  };
  EXPECT_EQ(make_method("importance", warp(2.0))->run(cell, context).value, value);
  EXPECT_NE(make_method("importance", warp(3.0))->run(cell, context).value, value);
  EXPECT_EQ(sc.methods[3].integrands, (std::vector<std::string>{"genz_gaussian_s2"}));
  EXPECT_FALSE(sc.output.plots);
  EXPECT_TRUE(sc.output.csv);
  EXPECT_EQ(sc.budget.max_seconds, 60.0);
  EXPECT_EQ(sc.budget.timing_min_seconds, 0.25);
}

TEST(ParseScene, PairedTimingRoundsAreReadWithTheirLine) {
  for (const std::uint64_t rounds : {0u, 5u, 9u, 1000u}) {
    const std::string t = replace(valid, "N = [16, 64]",
                                  fmt::format("N = [16, 64]\npaired_timing_rounds = {}", rounds));
    const scene sc = parse(t);
    EXPECT_EQ(sc.budget.paired_timing_rounds, rounds);
    EXPECT_EQ(sc.budget.paired_timing_rounds_location.line, line_of(t, "paired_timing"));
  }
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
  // (That the accumulator reaches the kernel: tests/scene/run_test.cpp.)
  EXPECT_EQ(sc.methods[0].label, "simpson") << "the default accumulator adds no suffix";
  EXPECT_EQ(sc.methods[2].label, "simpson_naive");
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

TEST(ParseScene, RngNamesTheGeneratorAndIsPhiloxByDefault) {
  EXPECT_EQ(parse_scene(valid, "scene.toml").rng, rng_kind::philox4x32_10);
  const std::string ars = replace(valid, "seed = 7", "seed = 7\nrng = \"ars4x32_7\"");
  EXPECT_EQ(parse_scene(ars, "scene.toml").rng, rng_kind::ars4x32_7);
  const std::string explicit_philox =
      replace(valid, "seed = 7", "seed = 7\nrng = \"philox4x32_10\"");
  EXPECT_EQ(parse_scene(explicit_philox, "scene.toml").rng, rng_kind::philox4x32_10);
  // A name it lacks: the line, the key, the value and the names it takes.
  std::string t = replace(valid, "seed = 7", "seed = 7\nrng = \"aes\"");
  std::string m = expect_error(t, line_of(t, "rng"), "rng");
  EXPECT_NE(m.find("\"aes\""), std::string::npos) << m;
  EXPECT_NE(m.find("philox4x32_10, ars4x32_7"), std::string::npos) << m;
  t = replace(valid, "seed = 7", "seed = 7\nrng = 7");
  m = expect_error(t, line_of(t, "rng"), "rng");
  EXPECT_NE(m.find("philox4x32_10, ars4x32_7"), std::string::npos) << m;
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
  // A family parameter is a number, an array of numbers or a string: a boolean is none of them.
  // (A string where the family takes an array is the catalogue's to refuse, at make_plan.)
  t = replace(valid, "dimension = 2", "dimension = 2\na = true");
  EXPECT_NE(expect_error(t, line_of(t, "a = "), "integrand[1].a")
                .find("a number, an array of numbers or a string"),
            std::string::npos);
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
  t = replace(valid, "N = [16, 64]", "N = [16, 64]\ntiming_min_seconds = -0.01");
  expect_error(t, line_of(t, "timing_min"), "budget.timing_min_seconds");
  t = replace(valid, "N = [16, 64]", "N = [16, 64]\ntiming_min_seconds = 61");
  expect_error(t, line_of(t, "timing_min"), "budget.timing_min_seconds");
  t = replace(valid, "N = [16, 64]", "N = [16, 64]\ntiming_min_seconds = \"fast\"");
  expect_error(t, line_of(t, "timing_min"), "budget.timing_min_seconds");
  t = replace(valid, "dimension = 2", "dimension = 2\nensemble = 0");
  expect_error(t, line_of(t, "ensemble"), "integrand[1].ensemble");
  // paired_timing_rounds: 0 (off) or 5…1000, a TOML integer; the message quotes the value and
  // the range.
  const std::pair<std::string_view, std::string_view> bad_rounds[] = {
      {"1", "1"},   {"4", "4"},   {"1001", "1001"},
      {"-1", "-1"}, {"5.0", "5"}, {"\"five\"", "\"five\""}};
  for (const auto& [written, shown] : bad_rounds) {
    t = replace(valid, "N = [16, 64]",
                fmt::format("N = [16, 64]\npaired_timing_rounds = {}", written));
    const std::string m =
        expect_error(t, line_of(t, "paired_timing"), "budget.paired_timing_rounds");
    EXPECT_NE(m.find(fmt::format(
                  "expected 0 (off) or a whole number of rounds from 5 to 1000, got {}", shown)),
              std::string::npos)
        << m;
  }
  t = replace(valid, "name = \"simpson\"", "name = \"gauss_legendre\"\nm = 6");  // no 6-point rule
  expect_error(t, line_of(t, "m = 6"), "method[1].m");
}

TEST(ParseScene, ReferenceKeysGiveTheirSource) {
  scene sc = parse(replace(valid, "dimension = 2",
                           "dimension = 2\nreference = 0.5\nreference_uncertainty = 1e-9"));
  EXPECT_EQ(sc.integrands[0].reference, reference_source::given);
  EXPECT_EQ(sc.integrands[0].reference_value, 0.5);
  EXPECT_EQ(sc.integrands[0].reference_uncertainty, 1e-9);
  sc = parse(replace(valid, "dimension = 2", "dimension = 2\nreference = 2"));
  EXPECT_EQ(sc.integrands[0].reference, reference_source::given);
  EXPECT_EQ(sc.integrands[0].reference_value, 2.0);
  EXPECT_EQ(sc.integrands[0].reference_uncertainty, 0.0);
  sc = parse(replace(valid, "dimension = 2", "dimension = 2\nreference = \"computed\""));
  EXPECT_EQ(sc.integrands[0].reference, reference_source::computed);
  sc = parse(valid);
  EXPECT_EQ(sc.integrands[0].reference, reference_source::exact);
}

TEST(SceneErrors, BadReferenceKeysAreOneLineErrorsAtTheKey) {
  struct bad {
    std::string_view added;
    std::string_view at;   // the text of the line the error points at
    std::string_view key;  // the key the message names
    std::string_view says;
  };
  const bad cases[] = {
      {"reference = \"exact\"", "reference", "integrand[1].reference",
       "expected a finite number or \"computed\", got \"exact\""},
      {"reference = inf", "reference", "integrand[1].reference",
       "expected a finite number or \"computed\", got inf"},
      {"reference = nan", "reference", "integrand[1].reference", "expected a finite number"},
      {"reference = true", "reference", "integrand[1].reference", "got true"},
      {"reference = 1.0\nreference_uncertainty = -1e-9", "reference_uncertainty",
       "integrand[1].reference_uncertainty", "expected a finite number ≥ 0"},
      {"reference = 1.0\nreference_uncertainty = inf", "reference_uncertainty",
       "integrand[1].reference_uncertainty", "got inf"},
      {"reference_uncertainty = 1e-9", "reference_uncertainty",
       "integrand[1].reference_uncertainty", "only with a number `reference`"},
      {"reference = \"computed\"\nreference_uncertainty = 1e-9", "reference_uncertainty",
       "integrand[1].reference_uncertainty", "not with reference = \"computed\""},
      {"reference = 1.0\nensemble = 4", "reference", "integrand[1].reference",
       "not with ensemble = 4"},
      {"reference = \"computed\"\nensemble = 2", "reference", "integrand[1].reference",
       "not with ensemble = 2"},
  };
  // A number for a `dimensions` list would be one value for several integrals; "computed" is
  // computed per s.
  const std::string listed =
      replace(valid, "dimension = 2", "dimensions = [2, 3]\nreference = 0.5");
  const std::string m =
      expect_error(listed, line_of(listed, "reference"), "integrand[1].reference");
  EXPECT_NE(m.find("not one for each of the 2 dimensions"), std::string::npos) << m;
  const scene sc =
      parse(replace(valid, "dimension = 2", "dimensions = [2, 3]\nreference = \"computed\""));
  ASSERT_EQ(sc.integrands.size(), 2u);
  EXPECT_EQ(sc.integrands[1].reference, reference_source::computed);
  for (const bad& b : cases) {
    const std::string t =
        replace(valid, "dimension = 2", std::string("dimension = 2\n") + std::string(b.added));
    const std::string m = expect_error(t, line_of(t, b.at), b.key);
    EXPECT_NE(m.find(b.says), std::string::npos) << m;
  }
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

TEST(SceneErrors, APeerWithoutThePeersBuildSaysHowToGetIt) {
  // The library alone (this test links no peer): naming one is an error at its `name`, saying
  // which library it needs and which command has it.
  const std::string t = replace(valid, "\"simpson\"", "\"peer_hcubature\"");
  const std::string m = expect_error(t, line_of(t, "peer_hcubature"), "method[1].name");
  EXPECT_NE(m.find("method 'peer_hcubature' (cubature's hcubature, libcubature-dev) is a peer"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("quadmc_with_peers"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
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

// ---------------------------------------------------------------------------------------------
// Bounds: whatever a small file asks for, parsing it takes bounded time and memory.

std::string repeated(std::string_view part, std::size_t count, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) out += separator;
    out += part;
  }
  return out;
}

// toml++ recursed once per part of a dotted key or table header and overflowed the stack (a
// segfault at 40,000 parts, an 80 KB file); the parser now measures the depth before toml++ sees
// the text. The error is at the first part beyond 64: column 2·64 + 1 of `a.a.a…`.
TEST(SceneLimits, DeepDottedKeysAndHeadersAreRefusedBeforeParsing) {
  const std::string key = repeated("a", 40000, ".") + " = 1\n" + std::string(valid);
  std::string m = expect_error(key, 1, "");
  EXPECT_NE(m.find("scene.toml:1:129: nesting deeper than 64 levels"), std::string::npos) << m;
  const std::string header = std::string(valid) + "[" + repeated("a", 50000, ".") + "]\n";
  m = expect_error(header, line_of(header, "[a.a"), "");
  EXPECT_NE(m.find(fmt::format("scene.toml:{}:130: nesting", line_of(header, "[a.a"))),
            std::string::npos)
      << m;
  // Inside an inline table the parts add to the table's own depth: 2 + 63 > 64.
  const std::string inline_key =
      "x = { " + repeated("b", 63, ".") + " = 1 }\n" + std::string(valid);
  expect_error(inline_key, 1, "");
}

TEST(SceneLimits, TheNestingLimitIsSixtyFourLevels) {
  // 64 parts is the limit, met exactly: the scene goes on to toml++ and to the key checks.
  const std::string at_limit = repeated("a", 64, ".") + " = 1\n" + std::string(valid);
  std::string m = expect_error(at_limit, 1, "a");
  EXPECT_NE(m.find("unknown key in the scene"), std::string::npos) << m;
  m = expect_error(repeated("a", 65, ".") + " = 1\n" + std::string(valid), 1, "");
  EXPECT_NE(m.find("nesting deeper than 64"), std::string::npos) << m;
  // Arrays: the key is level 1, so 63 brackets reach 64 and 64 brackets do not fit.
  m = expect_error(
      "x = " + repeated("[", 63, "") + repeated("]", 63, "") + "\n" + std::string(valid), 1, "x");
  EXPECT_NE(m.find("unknown key"), std::string::npos) << m;
  m = expect_error(
      "x = " + repeated("[", 64, "") + repeated("]", 64, "") + "\n" + std::string(valid), 1, "");
  EXPECT_NE(m.find("scene.toml:1:68: nesting deeper than 64"), std::string::npos) << m;
  // Nested 100,000 deep, arrays and inline tables stop at level 65 too.
  expect_error("x = " + repeated("[", 100000, "") + "\n", 1, "");
  expect_error("x = " + repeated("{b=", 100000, "") + "1" + repeated("}", 100000, "") + "\n", 1,
               "");
}

TEST(SceneLimits, DotsAndBracketsInStringsAndCommentsDoNotCount) {
  // 200 brackets and dots in a basic string and in a comment, and a quoted key of 100 dots: one
  // level each, so the scene reaches the key checks.
  std::string t =
      replace(valid, "name = \"t\"",
              "name = \"t\"\ndescription = \"" + repeated("[a.b{\\\"", 200, "") + "\"  # " +
                  repeated("[.{", 200, "") + "\n\"" + repeated("q", 100, ".") + "\" = 1");
  std::string m = expect_error(t, line_of(t, "\"q.q"), repeated("q", 100, "."));
  EXPECT_NE(m.find("unknown key"), std::string::npos) << m;
  // Multi-line strings of both kinds, with quotes and escapes inside, spanning lines.
  t = replace(valid, "name = \"t\"",
              "name = \"t\"\ndescription = \"\"\"" + repeated("[[{", 100, ".") +
                  " \\\"\"\" \"\" \n" + repeated("[", 100, "") + "\"\"\"\nx = '''" +
                  repeated("[.", 100, "") + " '' \n'''");
  m = expect_error(t, line_of(t, "x = '''"), "x");
  EXPECT_NE(m.find("unknown key"), std::string::npos) << m;
}

TEST(SceneLimits, ATextLargerThanOneMebibyteIsRefused) {
  const std::string padding = "# " + std::string(scene_limits::max_file_bytes, 'x') + "\n";
  const std::string m = expect_error(padding + std::string(valid), 0, "");
  EXPECT_NE(m.find("a scene file has at most 1048576"), std::string::npos) << m;
  // Exactly at the limit it is parsed.
  std::string exact = std::string(valid) + "# ";
  exact += std::string(scene_limits::max_file_bytes - exact.size() - 1, 'x') + "\n";
  ASSERT_EQ(exact.size(), scene_limits::max_file_bytes);
  EXPECT_NO_THROW(parse(exact));
}

// A scratch file or folder under the temp directory, removed at the end of the test.
struct scratch_path {
  std::filesystem::path path;
  explicit scratch_path(std::string_view name)
      : path(std::filesystem::temp_directory_path() /
             fmt::format("quadmc_parse_test_{}_{}", ::getpid(), name)) {
    std::filesystem::remove_all(path);
  }
  scratch_path(const scratch_path&) = delete;
  scratch_path& operator=(const scratch_path&) = delete;
  ~scratch_path() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

std::string file_error(const std::filesystem::path& path) {
  try {
    parse_scene_file(path);
  } catch (const scene_error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path.string() + ":0:0: ", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return m;
  }
  ADD_FAILURE() << "no scene_error for " << path;
  return {};
}

// /dev/zero was read with rdbuf() until memory ran out; a device, a folder or an oversized file
// is refused before (or while) reading, never read past the limit.
TEST(SceneLimits, SceneFilesMustBeRegularAndAtMostOneMebibyte) {
  std::string m = file_error("/dev/zero");
  EXPECT_NE(m.find("not a regular file (a character device)"), std::string::npos) << m;
  m = file_error(std::filesystem::temp_directory_path());
  EXPECT_NE(m.find("is a directory"), std::string::npos) << m;

  const scratch_path big("big.toml");
  {
    std::ofstream out(big.path, std::ios::binary);
    out << valid << "# " << std::string(scene_limits::max_file_bytes, 'x') << "\n";
  }
  m = file_error(big.path);
  EXPECT_NE(m.find("larger than 1048576 bytes"), std::string::npos) << m;

  const scratch_path small("small.toml");
  {
    std::ofstream out(small.path, std::ios::binary);
    out << valid;
  }
  EXPECT_EQ(parse_scene_file(small.path).name, "t");
}

// A pipe (`quadmc run <(generate-scene)`) is read like a file, with the same bound.
TEST(SceneLimits, APipeIsReadUpToTheLimit) {
  const scratch_path fifo("scene.fifo");
  ASSERT_EQ(::mkfifo(fifo.path.c_str(), 0600), 0) << std::strerror(errno);
  std::thread writer([&] {
    std::ofstream out(fifo.path, std::ios::binary);
    out << valid;
  });
  const scene sc = parse_scene_file(fifo.path);
  writer.join();
  EXPECT_EQ(sc.name, "t");
}

// factor = 1.0000000001 made the ladder loop run ~10^11 steps (minutes) before it had 256 values;
// the steps ⌈ln(to/from)/ln(factor)⌉ are now bounded by 4096 before the loop.
TEST(SceneLimits, GeometricLaddersTakeAtMost4096Steps) {
  std::string t =
      replace(valid, "N = [16, 64]", "N = { from = 1, to = 1e6, factor = 1.0000000001 }");
  const std::string m = expect_error(t, line_of(t, "N = "), "budget.N.factor");
  EXPECT_NE(m.find("needs 1.38e+11 steps from 1 to 1000000; at most 4096"), std::string::npos) << m;
  EXPECT_NE(m.find("a factor ≥ 1.00338"), std::string::npos) << m;
  // From 1 to 2: 2^(1/4095.5) takes ⌈4095.5⌉ = 4096 steps and gives {1, 2}; 2^(1/4096.5) needs
  // one step more.
  const auto ladder = [&](double factor) {
    return replace(valid, "N = [16, 64]",
                   fmt::format("N = {{ from = 1, to = 2, factor = {:.17g} }}", factor));
  };
  EXPECT_EQ(parse(ladder(std::pow(2.0, 1.0 / 4095.5))).budget.N,
            (std::vector<std::uint64_t>{1, 2}));
  t = ladder(std::pow(2.0, 1.0 / 4096.5));
  expect_error(t, line_of(t, "N = "), "budget.N.factor");
}

// The plots are drawn from convergence.csv: plots without the CSV failed only after the run.
TEST(SceneLimits, PlotsNeedTheCsv) {
  std::string t = std::string(valid) + "[output]\ncsv = false\nplots = true\n";
  std::string m = expect_error(t, line_of(t, "plots"), "output.plots");
  EXPECT_NE(m.find("plots need the CSV"), std::string::npos) << m;
  // plots defaults to true: the error is then at the [output] table.
  t = std::string(valid) + "[output]\ncsv = false\n";
  expect_error(t, line_of(t, "[output]"), "output.plots");
  EXPECT_NO_THROW(parse(std::string(valid) + "[output]\ncsv = false\nplots = false\n"));
}

// The warps' own bounds (sampling/inversion_warps.hpp), at parse time: a rate of 1e308 used to
// reach the run, where the truncated exponential refused it after the plan was printed.
TEST(SceneLimits, WarpParametersWithinTheWarpsBounds) {
  const auto warp = [](std::string_view table) {
    return replace(valid, "name = \"plain_mc\"",
                   fmt::format("name = \"importance\"\nwarp = {}", table));
  };
  for (const char* ok :
       {"{ name = \"exponential\", rate = 700.0 }", "{ name = \"exponential\", rate = -700.0 }",
        "{ name = \"power\", exponent = 1e5 }", "{ name = \"power\", exponent = -0.999 }"}) {
    EXPECT_NO_THROW(parse(warp(ok))) << ok;
  }
  for (const char* bad : {"{ name = \"exponential\", rate = 1e308 }",
                          "{ name = \"exponential\", rate = 700.0000000001 }",
                          "{ name = \"exponential\", rate = -700.0000000001 }",
                          "{ name = \"exponential\", rate = 0.0 }"}) {
    const std::string t = warp(bad);
    const std::string m = expect_error(t, line_of(t, "warp"), "method[2].warp.rate");
    EXPECT_NE(m.find("|l| <= 700"), std::string::npos) << m;
  }
  for (const char* bad : {"{ name = \"power\", exponent = 1.00000000001e5 }",
                          "{ name = \"power\", exponent = -1 }"}) {
    const std::string t = warp(bad);
    const std::string m = expect_error(t, line_of(t, "warp"), "method[2].warp.exponent");
    EXPECT_NE(m.find("-1 < k <= 100000"), std::string::npos) << m;
  }
}

// Every key of an [[integrand]] table is copied into each of up to 1024 `dimensions` expansions,
// so tables, names and parameter arrays are bounded.
TEST(SceneLimits, IntegrandTablesAreBounded) {
  std::string keys;
  for (int k = 0; k < 31; ++k) keys += fmt::format("p{} = 1\n", k);  // + family, dimension
  std::string t = replace(valid, "dimension = 2", "dimension = 2\n" + keys);
  const std::string m = expect_error(t, line_of(t, "[[integrand]]"), "integrand[1]");
  EXPECT_NE(m.find("33 keys in one [[integrand]] table; at most 32"), std::string::npos) << m;
  // 32 keys parse; the catalogue refuses the unknown parameters later (plan_test.cpp).
  EXPECT_NO_THROW(parse(replace(valid, "dimension = 2", "dimension = 2\n" + keys.substr(7))));
  t = replace(valid, "dimension = 2", "dimension = 2\nname = \"" + std::string(129, 'n') + "\"");
  expect_error(t, line_of(t, "name = \"nn"), "integrand[1].name");
  EXPECT_NO_THROW(parse(
      replace(valid, "dimension = 2", "dimension = 2\nname = \"" + std::string(128, 'n') + "\"")));
  // The scene's own name is one folder name: the command checks its length, not the parser.
  EXPECT_EQ(
      parse(replace(valid, "name = \"t\"", "name = \"" + std::string(200, 's') + "\"")).name.size(),
      200u);
  t = replace(valid, "dimension = 2", "dimension = 2\na = [" + repeated("1.0", 1025, ", ") + "]");
  expect_error(t, line_of(t, "a = "), "integrand[1].a");
  t = replace(valid, "family = \"genz_gaussian\"", "family = \"" + std::string(129, 'f') + "\"");
  expect_error(t, line_of(t, "family"), "integrand[1].family");
}

TEST(SceneLimits, AtMost4096IntegrandsAnd1024Methods) {
  std::string all_s = "dimensions = [";
  for (int s = 1; s <= 1024; ++s) all_s += fmt::format("{}{}", s == 1 ? "" : ", ", s);
  all_s += "]";
  std::string tables;
  for (int k = 1; k <= 4; ++k) {
    tables +=
        fmt::format("[[integrand]]\nfamily = \"genz_gaussian\"\nname = \"g{}\"\n{}\n", k, all_s);
  }
  const std::string rest = "[[method]]\nname = \"plain_mc\"\n[budget]\nN = [16]\n";
  EXPECT_EQ(parse(tables + rest).integrands.size(), 4096u);
  const std::string five = tables + "[[integrand]]\nfamily = \"exp\"\n" + rest;
  std::string m = expect_error(five, line_of(five, "family = \"exp\"") - 1, "integrand[5]");
  EXPECT_NE(m.find("4097 integrands"), std::string::npos) << m;

  std::string methods;
  for (int k = 1; k <= 1025; ++k) {
    methods += fmt::format("[[method]]\nname = \"plain_mc\"\nlabel = \"m{}\"\n", k);
  }
  const std::string t = "[[integrand]]\nfamily = \"exp\"\n" + methods + "[budget]\nN = [16]\n";
  m = expect_error(t, line_of(t, "\"m1025\"") - 2, "method[1025]");
  EXPECT_NE(m.find("1025 [[method]] tables; at most 1024"), std::string::npos) << m;
}

TEST(SceneLimits, PanelListsAndIntegrandListsAreBounded) {
  std::string panels;
  for (int n = 1; n <= 257; ++n) panels += fmt::format("{}{}", n == 1 ? "" : ", ", 2 * n);
  std::string t =
      replace(valid, "name = \"simpson\"", "name = \"simpson\"\npanels = [" + panels + "]");
  expect_error(t, line_of(t, "panels"), "method[1].panels");
  t = replace(valid, "repetitions = 8",
              "integrands = [" + repeated("\"genz_gaussian_s2\"", 4097, ", ") + "]");
  expect_error(t, line_of(t, "integrands"), "method[2].integrands");
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// `control` and `tolerances` (methods/method.hpp): a method supports some controls; tolerances
// come with control = "tolerance" only, positive and decreasing.
constexpr std::string_view romberg_scene = R"(name = "t"
[[integrand]]
family = "exp"
[[method]]
name = "romberg"
control = "tolerance"
tolerances = [1e-3, 1e-6, 1e-9]
[budget]
N = [16, 64]
)";

TEST(ParseScene, ControlAndTolerances) {
  const scene sc = parse(romberg_scene);
  EXPECT_EQ(sc.methods[0].control, cell_control::tolerance);
  EXPECT_EQ(sc.methods[0].tolerances, (std::vector<double>{1e-3, 1e-6, 1e-9}));
  const scene budget = parse(replace(replace(romberg_scene, "\"tolerance\"", "\"budget\""),
                                     "tolerances = [1e-3, 1e-6, 1e-9]\n", ""));
  EXPECT_EQ(budget.methods[0].control, cell_control::budget);
  EXPECT_TRUE(budget.methods[0].tolerances.empty());
}

TEST(ParseScene, ToleranceKindIsAbsoluteUnlessRelative) {
  EXPECT_FALSE(parse(romberg_scene).methods[0].relative_tolerance);
  const std::string relative = replace(romberg_scene, "control = \"tolerance\"\n",
                                       "control = \"tolerance\"\ntolerance_kind = \"relative\"\n");
  EXPECT_TRUE(parse(relative).methods[0].relative_tolerance);
  EXPECT_FALSE(
      parse(replace(relative, "\"relative\"", "\"absolute\"")).methods[0].relative_tolerance);
}

TEST(SceneErrors, BadToleranceKinds) {
  std::string t = replace(romberg_scene, "control = \"tolerance\"\n",
                          "control = \"tolerance\"\ntolerance_kind = \"percent\"\n");
  std::string m = expect_error(t, line_of(t, "tolerance_kind"), "method[1].tolerance_kind");
  EXPECT_NE(m.find("one of: absolute (the tolerances are errors), relative (fractions of |I|), "
                   "got \"percent\""),
            std::string::npos)
      << m;
  t = replace(t, "\"percent\"", "true");
  expect_error(t, line_of(t, "tolerance_kind"), "method[1].tolerance_kind");
  // Without control = "tolerance" there is nothing for it to qualify.
  t = replace(valid, "name = \"simpson\"", "name = \"simpson\"\ntolerance_kind = \"relative\"");
  m = expect_error(t, line_of(t, "tolerance_kind"), "method[1].tolerance_kind");
  EXPECT_NE(m.find("only with control = \"tolerance\""), std::string::npos) << m;
}

TEST(SceneErrors, ControlsAMethodDoesNotSupportAndBadTolerances) {
  std::string t = replace(valid, "name = \"simpson\"", "name = \"simpson\"\ncontrol = \"budget\"");
  std::string m = expect_error(t, line_of(t, "control"), "method[1].control");
  EXPECT_NE(m.find("expected one of: fixed (simpson supports these), got \"budget\""),
            std::string::npos)
      << m;
  t = replace(romberg_scene, "tolerances = [1e-3, 1e-6, 1e-9]", "tolerances = [1e-3, 1e-2]");
  m = expect_error(t, line_of(t, "tolerances"), "method[1].tolerances[2]");
  EXPECT_NE(m.find("tolerances must decrease, got 0.01 after 0.001"), std::string::npos) << m;
  t = replace(romberg_scene, "tolerances = [1e-3, 1e-6, 1e-9]", "tolerances = [0.0]");
  expect_error(t, line_of(t, "tolerances"), "method[1].tolerances[1]");
  t = replace(romberg_scene, "tolerances = [1e-3, 1e-6, 1e-9]\n", "");
  m = expect_error(t, line_of(t, "[[method]]"), "method[1].tolerances");
  EXPECT_NE(m.find("missing required key for control = \"tolerance\""), std::string::npos) << m;
  t = replace(romberg_scene, "control = \"tolerance\"\n", "");
  m = expect_error(t, line_of(t, "tolerances"), "method[1].tolerances");
  EXPECT_NE(m.find("only with control = \"tolerance\""), std::string::npos) << m;
}

}  // namespace
}  // namespace quadmc
