// Tests of scene/plan.hpp: which cells a scene gives, which it skips and why, and the errors
// only the catalogue or the pairing of methods with integrands can reveal.
#include "quadmc/scene/plan.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/scene/parse.hpp"
#include "scene_text.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

namespace quadmc {
namespace {

plan plan_of(std::string_view text) {
  return make_plan(parse_scene(text, "scene.toml"));
}

using test_support::replace;

std::vector<plan_cell> cells_of(const plan& p, std::string_view label) {
  std::vector<plan_cell> out;
  for (const auto& c : p.cells) {
    if (p.source.methods[c.method].label == label) out.push_back(c);
  }
  return out;
}

const plan_skip* find_skip(const plan& p, std::string_view what) {
  for (const auto& s : p.skips) {
    if (s.what == what) return &s;
  }
  return nullptr;
}

using test_support::line_of;

void expect_plan_error(std::string_view text, std::uint32_t line, std::string_view key,
                       std::string_view fragment) {
  try {
    plan_of(text);
    ADD_FAILURE() << "no scene_error for:\n" << text;
  } catch (const scene_error& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.where().line, line) << m;
    EXPECT_EQ(e.key(), key) << m;
    EXPECT_NE(m.find(fmt::format("scene.toml:{}:", line)), std::string::npos) << m;
    EXPECT_NE(m.find(fragment), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(MakePlan, MinimalScene) {
  const plan p = make_plan(parse_scene_file(QUADMC_SOURCE_DIR "/bench/scenes/minimal.toml"));
  ASSERT_EQ(p.instances.size(), 1u);
  EXPECT_EQ(p.instances[0].seed, stream_id({42, name_id("genz_gaussian"), 3, 0}));
  // Simpson in s = 3: the largest even n with (n+1)^3 ≤ N for N = 4^3 … 4^10 (integer cube
  // roots 4, 6, 10, 16, 25, 40, 64, 101).
  const auto simpson = cells_of(p, "simpson");
  const std::uint64_t n[] = {2, 4, 8, 14, 24, 38, 62, 100};
  ASSERT_EQ(simpson.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(simpson[i].per_axis, n[i]) << "N = " << simpson[i].nominal_N;
    EXPECT_EQ(simpson[i].evaluations, (n[i] + 1) * (n[i] + 1) * (n[i] + 1));
    EXPECT_EQ(simpson[i].repetitions, 1u) << "a rule runs once per N";
    EXPECT_EQ(simpson[i].order, 4);
  }
  const auto mc = cells_of(p, "plain_mc");
  ASSERT_EQ(mc.size(), 8u);
  for (const auto& c : mc) {
    EXPECT_EQ(c.evaluations, c.nominal_N);
    EXPECT_EQ(c.repetitions, 64u);
    // Named by the integrand's name and the method's label, never by their positions.
    EXPECT_EQ(c.stream_parts, (std::array<std::uint64_t, 4>{name_id(p.source.integrands[0].name), 0,
                                                            name_id("plain_mc"), c.nominal_N}));
  }
  // 64 · 4^10 = 2^26 < 1e8: nothing is over budget, and no grid repeats.
  EXPECT_TRUE(p.skips.empty());
  EXPECT_TRUE(p.notes.empty());
  const std::string listing = format_plan(p);
  EXPECT_NE(listing.find("plan for scene 'example'"), std::string::npos) << listing;
  EXPECT_NE(listing.find("cells (16,"), std::string::npos) << listing;
  EXPECT_NE(listing.find("1030301"), std::string::npos) << listing;  // 101^3
}

// Every example scene shipped in bench/scenes parses and plans (the README points users there);
// one that names a peer (time_to_error.toml) needs quadmc_with_peers, so here, without the
// peers, it must fail exactly with the message that says so (tests/peers plans it with them).
// A render scene (its first line names `quadmc render`) has keys of its own; tests/cli/
// render_test.cpp runs it.
TEST(MakePlan, EveryBundledSceneIsValid) {
  std::size_t scenes = 0;
  for (const auto& file : std::filesystem::directory_iterator(QUADMC_SOURCE_DIR "/bench/scenes")) {
    if (file.path().extension() != ".toml") continue;
    ++scenes;
    std::ifstream in(file.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.rfind("# `quadmc render`", 0) == 0) continue;
    if (text.find("name = \"peer_") != std::string::npos) {
      try {
        make_plan(parse_scene_file(file.path()));
        ADD_FAILURE() << file.path() << ": planned without the peers";
      } catch (const scene_error& e) {
        EXPECT_NE(std::string(e.what()).find("is a peer, not built into this quadmc"),
                  std::string::npos)
            << e.what();
      }
      continue;
    }
    try {
      const plan p = make_plan(parse_scene_file(file.path()));
      EXPECT_FALSE(p.cells.empty()) << file.path();
      EXPECT_FALSE(format_plan(p).empty());
    } catch (const std::exception& e) {
      ADD_FAILURE() << file.path() << ": " << e.what();
    }
  }
  EXPECT_GE(scenes, 3u);
}

TEST(MakePlan, TensorVersusMcScene) {
  const plan p = make_plan(parse_scene_file(QUADMC_SOURCE_DIR "/bench/scenes/tensor_vs_mc.toml"));
  // Romberg and importance run on genz_gaussian_s1 only; in s = 8 the midpoint rule keeps one
  // grid per integer 8th root: N = 16·4^k ≤ 262144 = 2^18 gives q = 1, 1, 2, 2, 2, 3, 4 (65536
  // = 4^8 exactly), 4 → n = 1, 2, 3, 4, the rest skipped as repeats.
  std::size_t one_dimensional_only = 0;  // so that the loop cannot pass by finding none
  for (const auto& c : p.cells) {
    const std::string& method = p.source.methods[c.method].name;
    if (method == "romberg" || method == "importance") {
      EXPECT_EQ(c.dimension, 1u) << method;
      ++one_dimensional_only;
    }
  }
  EXPECT_GT(one_dimensional_only, 0u) << "no romberg or importance cell planned";
  std::vector<std::uint64_t> n;
  for (const auto& c : p.cells) {
    if (c.instance == 0 && c.dimension == 8 && p.source.methods[c.method].name == "midpoint") {
      n.push_back(c.per_axis);
    }
  }
  EXPECT_EQ(n, (std::vector<std::uint64_t>{1, 2, 3, 4}));
  ASSERT_NE(find_skip(p, "romberg × genz_gaussian_s8"), nullptr);
  ASSERT_NE(find_skip(p, "output plots"), nullptr);
}

constexpr std::string_view base = R"(seed = 3
[[integrand]]
family = "genz_gaussian"
dimension = 8
[[method]]
name = "midpoint"
repetitions = 10
[[method]]
name = "plain_mc"
repetitions = 100
[budget]
N = [256, 300, 6561, 65535]
max_evaluations = 1e6
)";

TEST(MakePlan, DeterministicRulesRunOncePerNAndSayTheyIgnoreRepetitions) {
  const plan p = plan_of(base);
  for (const auto& c : cells_of(p, "midpoint")) EXPECT_EQ(c.repetitions, 1u);
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("repetitions = 10 ignored"), std::string::npos) << p.notes[0];
  EXPECT_NE(p.notes[0].find("scene.toml:7"), std::string::npos) << p.notes[0];
}

TEST(MakePlan, DuplicateGridsAreSkippedWithTheReason) {
  // s = 8: 2^8 = 256 ≤ 300 < 3^8 = 6561 ≤ 65535 < 4^8 = 65536: N = 300 gives the grid of
  // N = 256 and N = 65535 the grid of N = 6561.
  const plan p = plan_of(base);
  const auto mid = cells_of(p, "midpoint");
  ASSERT_EQ(mid.size(), 2u);
  EXPECT_EQ(mid[0].per_axis, 2u);
  EXPECT_EQ(mid[1].per_axis, 3u);
  const plan_skip* s = find_skip(p, "midpoint × genz_gaussian_s8, N = 300");
  ASSERT_NE(s, nullptr) << format_plan(p);
  EXPECT_EQ(s->reason, "same grid as N = 256 (n = 2 per axis, 256 evaluations)");
  ASSERT_NE(find_skip(p, "midpoint × genz_gaussian_s8, N = 65535"), nullptr);
}

// The Smolyak method (with `rule`, when given) on the Genz Gaussian in s = 2, over the ladder `N`.
plan smolyak_plan_of(std::string_view rule, std::string_view N) {
  return plan_of(fmt::format(R"(
[[integrand]]
family = "genz_gaussian"
dimension = 2
[[method]]
name = "smolyak"
{}
[budget]
N = {}
)",
                             rule.empty() ? "" : fmt::format("rule = \"{}\"", rule), N));
}

TEST(MakePlan, SparseGridCellsCarryTheirLevelAndRepeatedLevelsAreSkipped) {
  // Clenshaw–Curtis Smolyak in s = 2 has 1, 5, 13, 29 nodes at L = 0 … 3: N = 13 and 20 give L = 2,
  // N = 29 gives L = 3; the listing shows the level where a rule shows its n per axis.
  const plan p = smolyak_plan_of("", "[13, 20, 29]");
  ASSERT_EQ(p.cells.size(), 2u);
  EXPECT_EQ(p.cells[0].level, 2);
  EXPECT_EQ(p.cells[0].evaluations, 13u);
  EXPECT_EQ(p.cells[1].level, 3);
  EXPECT_EQ(p.cells[1].size().level, 3);
  const plan_skip* s = find_skip(p, "smolyak × genz_gaussian_s2, N = 20");
  ASSERT_NE(s, nullptr) << format_plan(p);
  EXPECT_EQ(s->reason, "same grid as N = 13 (level 2, 13 evaluations)");
  const std::string listing = format_plan(p);
  EXPECT_NE(listing.find("L=2"), std::string::npos) << listing;
  EXPECT_NE(listing.find("L=3"), std::string::npos) << listing;
}

TEST(MakePlan, ASparseGridAtItsLastLevelSaysSo) {
  // Regression: Gauss–Patterson's tables end at level 7 (255 nodes), so every N past its grid
  // gave the same level-7 grid, and the plan said only "same grid" (and Clenshaw–Curtis "level
  // 14"), hiding the cap.
  const plan p = smolyak_plan_of("gauss_patterson", "[100000, 10000000]");
  ASSERT_EQ(p.cells.size(), 1u);
  EXPECT_EQ(p.cells[0].level, 7);
  const plan_skip* s = find_skip(p, "smolyak_gauss_patterson × genz_gaussian_s2, N = 10000000");
  ASSERT_NE(s, nullptr) << format_plan(p);
  EXPECT_EQ(s->reason,
            "same grid as N = 100000 (level 7, 1793 evaluations: level 7 is the last of the "
            "gauss_patterson tables)");
}

TEST(MakePlan, CellsOverTheBudgetAreSkippedWithTheReason) {
  // plain_mc: N × 100 repetitions; 6561·100 = 656100 ≤ 1e6 < 65535·100.
  const plan p = plan_of(base);
  const auto mc = cells_of(p, "plain_mc");
  ASSERT_EQ(mc.size(), 3u);
  const plan_skip* s = find_skip(p, "plain_mc × genz_gaussian_s8, N = 65535");
  ASSERT_NE(s, nullptr) << format_plan(p);
  EXPECT_EQ(s->reason,
            "65535 evaluations × 100 repetitions = 6553500 exceed budget.max_evaluations = "
            "1000000");
  // A tensor grid over the budget: trapezoid with (n+1)^8 points.
  std::string t(base);
  t.replace(t.find("\"midpoint\""), 10, "\"trapezoid\"");
  t.replace(t.find("max_evaluations = 1e6"), 21, "max_evaluations = 1000");
  const plan q = plan_of(t);
  const plan_skip* g = find_skip(q, "trapezoid × genz_gaussian_s8, N = 6561");
  ASSERT_NE(g, nullptr) << format_plan(q);
  EXPECT_EQ(g->reason, "6561 evaluations exceed budget.max_evaluations = 1000");
  EXPECT_EQ(cells_of(q, "trapezoid").size(), 1u);
}

TEST(MakePlan, TooSmallNForAnyGridIsSkipped) {
  std::string t(base);
  t.replace(t.find("\"midpoint\""), 10, "\"simpson\"");
  const plan p = plan_of(t);  // Simpson needs 3^8 = 6561 points in s = 8
  const plan_skip* s = find_skip(p, "simpson × genz_gaussian_s8, N = 256");
  ASSERT_NE(s, nullptr) << format_plan(p);
  EXPECT_EQ(s->reason, "N is below the smallest grid, 3^8 = 6561 evaluations");
}

TEST(MakePlan, JitteredCountsAreMappedToPerfectPowers) {
  std::string t(base);
  t.replace(t.find("\"plain_mc\""), 10, "\"jittered\"");
  t.replace(t.find("dimension = 8"), 13, "dimension = 3");
  t.replace(t.find("N = [256, 300, 6561, 65535]"), 27, "N = [4095, 4096, 4097]");
  const plan p = plan_of(t);
  const auto j = cells_of(p, "jittered");
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0].per_axis, 15u);
  EXPECT_EQ(j[0].evaluations, 3375u);
  EXPECT_EQ(j[1].per_axis, 16u);
  EXPECT_EQ(j[1].evaluations, 4096u);
  EXPECT_NE(find_skip(p, "jittered × genz_gaussian_s3, N = 4097"), nullptr);
}

TEST(MakePlan, ExplicitPanelsReplaceTheLadder) {
  const plan p = plan_of(R"([[integrand]]
family = "genz_gaussian"
dimension = 2
[[method]]
name = "simpson"
panels = [2, 4, 6]
[budget]
N = [1000]
)");
  const auto c = cells_of(p, "simpson");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[2].per_axis, 6u);
  EXPECT_EQ(c[2].evaluations, 49u);
  EXPECT_EQ(c[2].nominal_N, 49u);
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("scene.toml:6: method[1] (simpson): explicit panels replace budget.N"),
            std::string::npos)
      << p.notes[0];
}

// A quasi-Monte Carlo method's explicit sizes are its `points` (point counts, not panels per
// axis): the plan's note names that key and its line, as the panels note does.
TEST(MakePlan, ExplicitPointsOfAQuasiMonteCarloMethodAreNamedAsPoints) {
  const plan p = plan_of(R"([[integrand]]
family = "genz_gaussian"
dimension = 2
[[method]]
name = "sobol"
points = [256, 1024]
[budget]
N = [1000]
)");
  const auto c = cells_of(p, "sobol");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[1].evaluations, 1024u);
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("scene.toml:6: method[1] (sobol): explicit points replace budget.N"),
            std::string::npos)
      << p.notes[0];
  EXPECT_EQ(p.notes[0].find("panels"), std::string::npos) << p.notes[0];
}

TEST(MakePlan, EnsembleInstancesHaveTheirOwnSeedsAndCells) {
  const plan p = plan_of(R"(seed = 9
[[integrand]]
family = "genz_gaussian"
dimensions = [1, 2]
ensemble = 3
[[method]]
name = "plain_mc"
[budget]
N = [10, 20]
)");
  ASSERT_EQ(p.instances.size(), 6u);
  for (const auto& inst : p.instances) {
    EXPECT_EQ(inst.seed,
              stream_id({9, name_id("genz_gaussian"), inst.integrand + 1, inst.instance}));
    // Neither a nor u is given: both are drawn, with the catalogue's rule (catalogue.hpp).
    const genz_parameters expected =
        genz_random_parameters(genz_family::gaussian, inst.function.dimension(), inst.seed);
    ASSERT_EQ(inst.drawn.size(), 2u);
    EXPECT_EQ(inst.drawn.at("a"), expected.a);
    EXPECT_EQ(inst.drawn.at("u"), expected.u);
    EXPECT_EQ(inst.params.dimension, inst.integrand + 1);
  }
  EXPECT_EQ(p.cells.size(), 2u * 3u * 2u);
  EXPECT_EQ(p.cells.back().stream_parts,
            (std::array<std::uint64_t, 4>{name_id(p.source.integrands[1].name), 2,
                                          name_id("plain_mc"), 20}));
  EXPECT_EQ(p.total_evaluations, 3u * 32u * (10 + 20) * 2u);
  EXPECT_NE(format_plan(p).find("drawn from seed"), std::string::npos);
}

TEST(MakePlan, OmittedDimensionIsResolvedFromTheFamily) {
  const plan p = plan_of(R"([[integrand]]
family = "sqrt"
[[integrand]]
family = "irradiance_hemisphere"
[[method]]
name = "midpoint"
[budget]
N = [16]
)");
  EXPECT_EQ(p.source.integrands[0].dimension, 1u);
  EXPECT_EQ(p.source.integrands[1].dimension, 2u);
  EXPECT_EQ(p.source.integrands[1].name, "irradiance_hemisphere");
  ASSERT_EQ(p.cells.size(), 2u);
  EXPECT_EQ(p.cells[0].per_axis, 16u);
  EXPECT_EQ(p.cells[1].per_axis, 4u);  // 4^2 = 16
  EXPECT_TRUE(p.instances[0].drawn.empty()) << "sqrt draws nothing";
}

TEST(MakePlan, IrradianceEstimatorsOnlyOnRenderingIntegrands) {
  const plan p = plan_of(R"([[integrand]]
family = "irradiance_area"
[[integrand]]
family = "genz_gaussian"
dimension = 2
[[method]]
name = "irradiance_light_area"
[budget]
N = [16]
)");
  ASSERT_EQ(p.cells.size(), 1u);
  EXPECT_EQ(p.cells[0].integrand, 0u);
  const plan_skip* s = find_skip(p, "irradiance_light_area × genz_gaussian_s2");
  ASSERT_NE(s, nullptr) << format_plan(p);
  EXPECT_EQ(s->reason,
            "irradiance_light_area estimates irradiance; 'genz_gaussian' is not a rendering "
            "integrand");
}

TEST(MakePlan, AnEnsembleWithNothingToDrawIsNoted) {
  const plan p = plan_of(R"([[integrand]]
family = "genz_gaussian"
dimension = 1
a = [2.0]
u = [0.5]
ensemble = 3
[[method]]
name = "plain_mc"
[budget]
N = [16]
)");
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("scene.toml:6: integrand[1]"), std::string::npos) << p.notes[0];
  EXPECT_NE(p.notes[0].find("every instance is the same integrand"), std::string::npos);
}

constexpr std::string_view mixed = R"([[integrand]]
family = "genz_gaussian"
dimensions = [1, 3]
name = "g"
[[method]]
name = "romberg"
[[method]]
name = "importance"
warp = "exponential"
[budget]
N = [17]
[output]
plots = false
)";

TEST(MakePlan, ImplicitlyIncompatiblePairsAreSkipped) {
  const plan p = plan_of(mixed);
  ASSERT_EQ(p.cells.size(), 2u);  // romberg and importance on g_s1
  EXPECT_EQ(p.cells[0].per_axis, 16u);
  const plan_skip* r = find_skip(p, "romberg × g_s3");
  ASSERT_NE(r, nullptr) << format_plan(p);
  EXPECT_EQ(r->reason, "romberg is one-dimensional; the integrand has s = 3");
  const plan_skip* w = find_skip(p, "importance_exponential × g_s3");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->reason, "the 'exponential' warp is a 1D density; the integrand has s = 3");
  const plan_skip* o = find_skip(p, "output plots");
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(o->reason, "not asked for (output.plots = false)");
}

TEST(MakePlan, ExplicitlyImpossiblePairsAreErrors) {
  // Naming `g` covers g_s1, which romberg can integrate: fine. Naming g_s3 alone is impossible.
  EXPECT_NO_THROW(plan_of(
      std::string(mixed).insert(mixed.find("[[method]]\nname = \"imp"), "integrands = [\"g\"]\n")));
  std::string t(mixed);
  t.insert(t.find("[[method]]\nname = \"imp"), "integrands = [\"g_s3\"]\n");
  expect_plan_error(t, line_of(t, "integrands"), "method[1].integrands[1]",
                    "romberg cannot integrate 'g_s3': romberg is one-dimensional");
  t = mixed;
  t.insert(t.find("[budget]"), "integrands = [\"g_s3\"]\n");
  expect_plan_error(t, line_of(t, "integrands"), "method[2].integrands[1]",
                    "importance_exponential cannot integrate 'g_s3': the 'exponential' warp is "
                    "a 1D density");
}

TEST(MakePlan, CatalogueErrorsNameTheKey) {
  constexpr std::string_view ok = R"(
[[integrand]]
family = "genz_gaussian"
dimension = 2
a = [1.0, 2.0]
[[method]]
name = "midpoint"
[budget]
N = [16]
)";
  EXPECT_NO_THROW(plan_of(ok));
  std::string t(ok);
  t.replace(t.find("\"genz_gaussian\""), 15, "\"genz_gausian\"");
  expect_plan_error(t, line_of(t, "family"), "integrand[1].family", "unknown family");
  // A parameter the family does not take.
  t = ok;
  t.insert(t.find("[[method]]"), "colour = 3\n");
  expect_plan_error(t, line_of(t, "colour"), "integrand[1].colour", "not a parameter of");
  // A parameter the family takes, with a value it rejects (length ≠ s).
  t = ok;
  t.replace(t.find("a = [1.0, 2.0]"), 14, "a = [1.0, 2.0, 3.0]");
  expect_plan_error(t, line_of(t, "a = "), "integrand[1].a", "a");
}

// coefficient_decay (genz.hpp): the drawn a follows it, and the catalogue's key rule refuses a bad
// choice, a number, and the key beside an explicit a, each at the line of the key.
TEST(MakePlan, GenzCoefficientDecayShapesTheDrawnAAndBadUsesAreRefusedAtTheKey) {
  constexpr std::string_view ok = R"(seed = 5
[[integrand]]
family = "genz_product_peak"
dimension = 6
coefficient_decay = "quadratic"
ensemble = 2
[[method]]
name = "plain_mc"
[budget]
N = [16]
)";
  const plan p = plan_of(ok);
  ASSERT_EQ(p.instances.size(), 2u);
  for (const auto& inst : p.instances) {
    const genz_parameters expected =
        genz_random_parameters(genz_family::product_peak, 6, inst.seed, genz_decay::quadratic);
    EXPECT_EQ(inst.drawn.at("a"), expected.a);
    EXPECT_EQ(inst.drawn.at("u"), expected.u);
    // The seed is (seed, family, s, k) as without a decay: only the weights change.
    EXPECT_EQ(inst.seed, stream_id({5, name_id("genz_product_peak"), 6, inst.instance}));
    EXPECT_NE(expected.a,
              genz_random_parameters(genz_family::product_peak, 6, inst.seed, genz_decay::none).a);
  }
  EXPECT_NE(format_plan(p).find(fmt::format("    a = [{:.17g}]  (drawn from seed",
                                            fmt::join(p.instances[0].drawn.at("a"), ", "))),
            std::string::npos)
      << format_plan(p);
  // "none" is the default: the same plan as without the key.
  const plan none = plan_of(replace(ok, "\"quadratic\"", "\"none\""));
  const plan omitted = plan_of(replace(ok, "coefficient_decay = \"quadratic\"\n", ""));
  EXPECT_EQ(none.instances[1].drawn, omitted.instances[1].drawn);

  std::string t = replace(ok, "\"quadratic\"", "\"cubic\"");
  expect_plan_error(t, line_of(t, "coefficient_decay"), "integrand[1].coefficient_decay",
                    "expected one of \"none\", \"quadratic\", \"exponential\", got \"cubic\"");
  t = replace(ok, "\"quadratic\"", "2");
  expect_plan_error(t, line_of(t, "coefficient_decay"), "integrand[1].coefficient_decay",
                    "expected a string, one of \"none\", \"quadratic\", \"exponential\"");
  t = replace(ok, "dimension = 6\n", "dimension = 6\na = [1, 2, 3, 4, 5, 6]\n");
  expect_plan_error(t, line_of(t, "coefficient_decay"), "integrand[1].coefficient_decay",
                    "invalid coefficient_decay = \"quadratic\": expected no explicit a beside it");
  // A string where the family takes an array.
  t = replace(ok, "coefficient_decay = \"quadratic\"", "u = \"centre\"");
  expect_plan_error(t, line_of(t, "u = "), "integrand[1].u",
                    "expected an array of numbers for genz_product_peak, got \"centre\"");
}

// ---------------------------------------------------------------------------------------------
// What a run would refuse is refused by make_plan, before any work, at the key concerned.

// The issue's three examples of an exact value that is inf or NaN: `plan` listed them (exact =
// inf, exact = -nan, 3.14e+300 with f = inf at x = u) and `run` failed after the plan. The
// families refuse the parameter now, and make_plan reports it at its key.
TEST(PlanChecks, ReferencesBeyondDoubleAreRefusedAtTheParameter) {
  const std::string exp_scene = R"([[integrand]]
family = "exp"
lower = 0.0
upper = 1000.0
[[method]]
name = "simpson"
[budget]
N = [8, 16]
)";
  expect_plan_error(exp_scene, line_of(exp_scene, "upper"), "integrand[1].upper", "upper ≤ 709.78");
  std::string t =
      replace(replace(exp_scene, "\"exp\"", "\"poly\""), "lower = 0.0", "lower = -1e100");
  t = replace(t, "upper = 1000.0", "upper = 1e100");
  expect_plan_error(t, line_of(t, "lower"), "integrand[1].lower", "|lower| ≤ 1e51");
  const std::string peak = R"([[integrand]]
family = "genz_product_peak"
dimension = 1
a = [1e300]
u = [0.5]
[[method]]
name = "plain_mc"
[budget]
N = [8, 16]
)";
  expect_plan_error(peak, line_of(peak, "a = "), "integrand[1].a", "aᵢ² must stay finite");
}

// The generic check behind the families' own: an exact value or a largest value max|f| that is
// not finite. A radiance near DBL_MAX makes the hemisphere integrand's 2π·L overflow.
TEST(PlanChecks, NonFiniteExactOrLargestValueIsAnError) {
  const std::string t = R"([[integrand]]
family = "irradiance_hemisphere"
radiance = 1.7e308
[[method]]
name = "irradiance_hemisphere_uniform"
[budget]
N = [8, 16]
)";
  expect_plan_error(t, line_of(t, "[[integrand]]"), "integrand[1]", "overflow double");
}

// A run of Monte Carlo on eˣ over [0, 700] failed with "invalid error[0] = -nan": values up to
// 700·e^700 ≈ 7e306 made the sums of squared deviations inf. 8·M²·N ≤ DBL_MAX is the bound.
TEST(PlanChecks, ValuesTooLargeForTheRunsSumsAreAnError) {
  const std::string t = R"([[integrand]]
family = "exp"
lower = 0.0
upper = 700.0
[[method]]
name = "plain_mc"
[budget]
N = [8, 16]
)";
  expect_plan_error(
      t, line_of(t, "[[integrand]]"), "integrand[1]",
      "values up to 7.1e+306 (max(|I|, max|f|·volume)) are too large for plain_mc at N = 8");
  // A rule only needs its error est − I finite: Simpson on [0, 700] plans (and runs,
  // run_test.cpp).
  EXPECT_NO_THROW(plan_of(replace(t, "plain_mc", "simpson")));
  // At the boundary: M = e^350·350 ≈ 3.5e154 is above √(DBL_MAX/64) ≈ 1.7e153 for N = 8, and
  // e^340·340 ≈ 7.2e149 is below √(DBL_MAX/128) ≈ 1.2e153 for N = 16.
  expect_plan_error(replace(t, "upper = 700.0", "upper = 350.0"), 1, "integrand[1]",
                    "too large for plain_mc at N = 8");
  EXPECT_NO_THROW(plan_of(replace(t, "upper = 700.0", "upper = 340.0")));
}

// Point sets need N·s ≤ 2^62 (sampling/point_set.hpp): the run refused N = 2^53 at s = 1024
// after printing the plan. It is an error at budget.N, unless the budget skips the cell.
TEST(PlanChecks, RandomCellsNeedNTimesSWithinTheStreamsCounters) {
  const std::string t = R"([[integrand]]
family = "genz_gaussian"
dimension = 1024
[[method]]
name = "plain_mc"
repetitions = 1
[budget]
N = [4503599627370496, 4503599627370497]
)";
  // 2^52·1024 = 2^62 is the largest allowed; one more point is too many.
  expect_plan_error(t, line_of(t, "N = "), "budget.N",
                    "N = 4503599627370497: plain_mc × genz_gaussian_s1024 would draw "
                    "4503599627370497 points in s = 1024");
  const plan p = plan_of(replace(t, "[4503599627370496, 4503599627370497]", "[4503599627370496]"));
  EXPECT_EQ(p.cells.size(), 1u);
  // Skipped by the budget, the cell never runs and is no error.
  EXPECT_NO_THROW(
      plan_of(replace(t, "4503599627370497]", "4503599627370497]\nmax_evaluations = 1e8")));
}

// ensemble = 1000000 at dimension = 1024 built instances until memory ran out. The plan's size is
// estimated from the scene and bounded before anything is built.
TEST(PlanChecks, InstancesAndCoordinatesAreBounded) {
  const std::string t = R"([[integrand]]
family = "genz_gaussian"
dimension = 1024
ensemble = 1000000
[[method]]
name = "plain_mc"
[budget]
N = [64]
)";
  expect_plan_error(t, line_of(t, "ensemble"), "integrand[1].ensemble",
                    "1000000 integrand instances; at most 65536");
  // 1025 × 1024 coordinates is one instance too many; 1024 × 1024 = 2^20 is the limit.
  expect_plan_error(replace(t, "ensemble = 1000000", "ensemble = 1025"), line_of(t, "ensemble"),
                    "integrand[1].ensemble",
                    "1049600 instance coordinates (Σ ensemble × s); at most 1048576");
  EXPECT_EQ(plan_of(replace(t, "ensemble = 1000000", "ensemble = 1024")).instances.size(), 1024u);
}

TEST(PlanChecks, CellsAndRepetitionsAreBounded) {
  std::string ladder = "N = [";
  for (int k = 1; k <= 256; ++k) ladder += fmt::format("{}{}", k == 1 ? "" : ", ", k);
  ladder += "]";
  // 4097 instances × 256 N values = 1048832 cells, 256 more than the limit.
  const std::string many = R"([[integrand]]
family = "genz_gaussian"
dimension = 1
ensemble = 4097
[[method]]
name = "plain_mc"
repetitions = 1
[budget]
)" + ladder + "\n";
  expect_plan_error(many, line_of(many, "ensemble"), "integrand[1].ensemble",
                    "bring the scene to 1048832 cells; at most 1048576");
  // Without an ensemble the error names budget.N: 5 integrands × 820 methods × 256 N values.
  std::string wide;
  for (int k = 1; k <= 5; ++k)
    wide += fmt::format("[[integrand]]\nfamily = \"exp\"\nname = \"e{}\"\n", k);
  for (int k = 1; k <= 820; ++k) {
    wide += fmt::format("[[method]]\nname = \"plain_mc\"\nlabel = \"m{}\"\nrepetitions = 1\n", k);
  }
  wide += "[budget]\n" + ladder + "\n";
  expect_plan_error(wide, line_of(wide, "N = "), "budget.N",
                    "e5: 209920 (method, N) pairs × 1 instances bring the scene to 1049600 cells");
  // The runner keeps one result per repetition: 2^25 in all.
  const std::string reps = R"([[integrand]]
family = "exp"
[[method]]
name = "plain_mc"
repetitions = 1000000000
[budget]
N = [1]
)";
  expect_plan_error(
      reps, line_of(reps, "repetitions"), "method[1].repetitions",
      "1000000000 repetitions; the runner keeps a result per repetition, at most 33554432");
}

// genz_corner_peak sums 2^s vertices in 50-digit arithmetic (~1.4 µs each) per drawn instance:
// an ensemble of 17 at s = 20 would be 25 s of planning. Families that draw nothing are built
// once, so their ensembles cost one reference.
TEST(PlanChecks, ReferenceTermsAreBoundedAndSharedInstancesAreBuiltOnce) {
  const std::string t = R"([[integrand]]
family = "genz_corner_peak"
dimension = 20
ensemble = 17
[[method]]
name = "plain_mc"
[budget]
N = [64]
)";
  expect_plan_error(t, line_of(t, "ensemble"), "integrand[1].ensemble",
                    "17 instance(s) of genz_corner_peak at s = 20 need 17825792 terms");
  // half_space draws nothing: 300 instances at s = 16 are one sum of 2^16 terms, not 300.
  const plan p = plan_of(R"([[integrand]]
family = "half_space"
dimension = 16
ensemble = 300
[[method]]
name = "plain_mc"
[budget]
N = [64]
)");
  ASSERT_EQ(p.instances.size(), 300u);
  EXPECT_EQ(p.instances[299].function.info().exact, p.instances[0].function.info().exact);
  EXPECT_NE(p.instances[299].seed, p.instances[0].seed);
  EXPECT_EQ(p.cells.size(), 300u);
}

// Ī, the series' reference, is computed once by the plan (run.hpp uses it).
TEST(PlanChecks, MeanReferenceOfAnEnsemble) {
  const plan p = plan_of(R"(seed = 5
[[integrand]]
family = "genz_gaussian"
dimension = 2
ensemble = 3
[[method]]
name = "plain_mc"
[budget]
N = [64]
)");
  ASSERT_EQ(p.mean_reference.size(), 1u);
  double sum = 0.0;
  for (const auto& inst : p.instances) sum += inst.function.info().exact;
  EXPECT_EQ(p.mean_reference[0], sum / 3.0);
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// tolerance_kind = "relative" needs every instance's I to be a number other than 0: the target
// tolerance·|I| would otherwise be 0 (never reached) or no number.
TEST(PlanTolerance, ARelativeToleranceOnAZeroIntegralIsRefusedAtItsKey) {
  const std::string text = R"(name = "t"
[[integrand]]
family = "poly"
lower = -1.0
upper = 1.0
[[method]]
name = "romberg"
control = "tolerance"
tolerance_kind = "relative"
tolerances = [1e-3, 1e-6]
[budget]
N = [16, 64]
)";
  expect_plan_error(text, line_of(text, "tolerance_kind"), "method[1].tolerance_kind",
                    "\"relative\" needs I ≠ 0, but integrand 'poly' has I = 0");
  // The same on [0, 1] (I = 1/6) plans, and the plan says the tolerances are relative.
  const plan p = make_plan(parse_scene(replace(text, "lower = -1.0", "lower = 0.0"), "scene.toml"));
  ASSERT_EQ(p.cells.size(), 2u);
  EXPECT_EQ(p.cells[0].tolerance, 1e-3) << "the cell keeps the scene's (relative) tolerance";
  EXPECT_NE(format_plan(p).find("control = tolerance (relative: each tolerance times |I|)"),
            std::string::npos)
      << format_plan(p);
}

// control = "tolerance": one cell per tolerance, spending at most the budget per repetition
// (budget.max_evaluations, else plan_limits::default_tolerance_budget), each on its own stream.
// budget.paired_timing_rounds of a scene built in C++ is checked by make_plan as the parser checks
// a file's: 0 or 5…1000, refused naming the key, the value and the range, before any work.
TEST(PlanChecks, PairedTimingRoundsOfASceneBuiltInCppAreChecked) {
  scene sc = parse_scene(R"(name = "t"
[[integrand]]
family = "exp"
[[method]]
name = "midpoint"
[budget]
N = [16, 64]
)",
                         "scene.toml");
  for (const std::uint64_t rounds : {1u, 4u, 1001u}) {
    sc.budget.paired_timing_rounds = rounds;
    try {
      (void)make_plan(sc);
      ADD_FAILURE() << "paired_timing_rounds = " << rounds << " was planned";
    } catch (const scene_error& e) {
      EXPECT_EQ(e.key(), "budget.paired_timing_rounds") << e.what();
      EXPECT_NE(std::string(e.what()).find(fmt::format(
                    "expected 0 (off) or a whole number of rounds from 5 to 1000, got {}", rounds)),
                std::string::npos)
          << e.what();
    }
  }
  for (const std::uint64_t rounds : {0u, 5u, 1000u}) {
    sc.budget.paired_timing_rounds = rounds;
    EXPECT_NO_THROW((void)make_plan(sc)) << rounds;
  }
}

// A scene whose page can pair time-to-error winners (a tolerance method, a `peer_*` one and one
// of quadmc's) says in its plan what the run will do after its cells; other scenes say nothing.
TEST(PlanTolerance, APlanThatCanPairWinnersSaysSo) {
  const std::string text = R"(name = "t"
[[integrand]]
family = "genz_gaussian"
dimension = 2
[[method]]
name = "genz_malik"
control = "tolerance"
tolerances = [1e-3]
[[method]]
name = "genz_malik"
label = "peer_twin"
control = "tolerance"
tolerances = [1e-3]
[budget]
N = [16, 64]
)";
  auto note_of = [](const plan& p) {
    const auto it = std::find_if(p.notes.begin(), p.notes.end(), [](const std::string& n) {
      return n.starts_with("time to error:");
    });
    return it == p.notes.end() ? std::string() : *it;
  };
  const std::string paired = note_of(plan_of(text));
  EXPECT_NE(paired.find("budget.paired_timing_rounds = 5 rounds"), std::string::npos) << paired;
  const std::string off =
      note_of(plan_of(replace(text, "N = [16, 64]", "N = [16, 64]\npaired_timing_rounds = 0")));
  EXPECT_NE(off.find("paired_timing_rounds = 0: the ratios"), std::string::npos) << off;
  // Without the peer there is nothing to pair.
  EXPECT_EQ(note_of(plan_of(replace(text, "label = \"peer_twin\"", "label = \"twin\""))), "");
}

TEST(PlanTolerance, OneCellPerToleranceWithinTheBudget) {
  const std::string text = R"(name = "t"
[[integrand]]
family = "exp"
[[method]]
name = "romberg"
control = "tolerance"
tolerances = [1e-3, 1e-6]
[budget]
N = [16, 64]
max_evaluations = 1000
)";
  const plan p = make_plan(parse_scene(text, "scene.toml"));
  ASSERT_EQ(p.cells.size(), 2u);
  for (const plan_cell& c : p.cells) {
    EXPECT_EQ(c.control, cell_control::tolerance);
    EXPECT_EQ(c.nominal_N, 0u);
    EXPECT_EQ(c.evaluations, 513u) << "the largest 2^k + 1 ≤ 1000";
  }
  EXPECT_EQ(p.cells[0].tolerance, 1e-3);
  EXPECT_EQ(p.cells[1].tolerance, 1e-6);
  EXPECT_NE(p.cells[0].stream_parts, p.cells[1].stream_parts);
  const std::string listing = format_plan(p);
  EXPECT_NE(listing.find("tol 1e-06"), std::string::npos) << listing;
  EXPECT_NE(listing.find("control = tolerance: one cell per tolerance"), std::string::npos)
      << listing;
  // Without max_evaluations the default budget applies: 2^29 + 1 ≤ 2^30.
  const plan unbounded = make_plan(parse_scene(
      std::string(text).replace(text.find("max_evaluations = 1000\n"), 23, ""), "scene.toml"));
  EXPECT_EQ(unbounded.cells[0].evaluations, (std::uint64_t{1} << 29) + 1);
}

}  // namespace
}  // namespace quadmc

namespace quadmc {
namespace {

// A given or computed reference replaces the exact value in mean_reference, is stated in the
// listing with its uncertainty and how it was obtained, and a note says the exact value exists.
constexpr std::string_view referenced = R"(name = "ref"
[[integrand]]
family = "exp"
name = "given"
reference = 1.7
reference_uncertainty = 1e-3
[[integrand]]
family = "genz_gaussian"
dimension = 2
reference = "computed"
[[integrand]]
family = "sin"
[[method]]
name = "midpoint"
[budget]
N = [4, 16]
)";

TEST(MakePlan, GivenAndComputedReferencesReplaceTheExactValue) {
  const plan p = plan_of(referenced);
  ASSERT_EQ(p.references.size(), 3u);
  EXPECT_EQ(p.references[0].source, reference_source::given);
  EXPECT_EQ(p.mean_reference[0], 1.7);
  EXPECT_EQ(p.references[0].uncertainty, 1e-3);
  EXPECT_EQ(p.references[1].source, reference_source::computed);
  ASSERT_TRUE(p.references[1].computed.has_value());
  EXPECT_EQ(p.mean_reference[1], p.references[1].computed->value);
  EXPECT_EQ(p.references[1].uncertainty, p.references[1].computed->uncertainty);
  const double exact = p.instances[1].function.info().exact;
  EXPECT_LE(std::abs(p.mean_reference[1] - exact), p.references[1].uncertainty);
  EXPECT_EQ(p.references[2].source, reference_source::exact);
  EXPECT_EQ(p.mean_reference[2], p.instances[2].function.info().exact);
  EXPECT_EQ(p.references[2].uncertainty, 0.0);

  const std::string listing = format_plan(p);
  EXPECT_NE(listing.find("reference = 1.7 ± 0.001 (given, uncertainty 0.001)"), std::string::npos)
      << listing;
  EXPECT_NE(listing.find("(computed: Genz–Malik h-adaptive cubature, relative tolerance 1e-12, "),
            std::string::npos)
      << listing;
  int notes = 0;
  for (const std::string& n : p.notes) {
    if (n.find("exists and is not used") != std::string::npos) ++notes;
  }
  EXPECT_EQ(notes, 2) << listing;
  EXPECT_NE(listing.find(fmt::format("scene.toml:{}: integrand[1] (given): errors are measured "
                                     "from the given reference 1.7",
                                     line_of(referenced, "reference = 1.7"))),
            std::string::npos)
      << listing;
}

TEST(MakePlan, AComputedReferenceAboveItsDimensionLimitIsAnErrorAtTheKey) {
  const std::string t =
      replace(referenced, "dimension = 2\nreference", "dimension = 11\nreference");
  expect_plan_error(t, line_of(t, "reference = \"computed\""), "integrand[2].reference",
                    "\"computed\" is for s ≤ 10");
}

}  // namespace
}  // namespace quadmc
