// Tests of scene/render_scene.hpp: the documented defaults, the keys it accepts and refuses, its
// bounds, and that every mistake is one scene_error line at the key, as scene files' are.
#include "quadmc/scene/render_scene.hpp"

#include "quadmc/scene/scene_error.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace quadmc {
namespace {

render_scene parse_render(std::string_view text) {
  return parse_render_scene(text, "r.toml");
}

// Parses `text`, expects a scene_error at `line` about `key`, and returns its message.
std::string render_error(std::string_view text, std::uint32_t line, std::string_view key) {
  try {
    parse_render(text);
  } catch (const scene_error& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.where().file, "r.toml") << message;
    EXPECT_EQ(e.where().line, line) << message;
    EXPECT_EQ(e.key(), key) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    return message;
  }
  ADD_FAILURE() << "no scene_error for:\n" << text;
  return {};
}

TEST(RenderScene, AnEmptySceneHasTheDocumentedDefaults) {
  const render_scene sc = parse_render("");
  EXPECT_EQ(sc.file, "r.toml");
  EXPECT_EQ(sc.name, "r");  // the file name without extension
  EXPECT_EQ(sc.seed, 0u);
  EXPECT_EQ(sc.threads, 0u);
  EXPECT_EQ(sc.width, 256u);
  EXPECT_EQ(sc.height, 256u);
  EXPECT_EQ(sc.region, (std::array<double, 4>{-0.55, -0.6, 0.15, 0.1}));
  EXPECT_TRUE(sc.occluder);
  EXPECT_EQ(sc.occluder_height, 0.5);
  EXPECT_EQ(sc.estimators,
            (std::vector<irradiance_sampling>{irradiance_sampling::uniform_hemisphere,
                                              irradiance_sampling::cosine_hemisphere,
                                              irradiance_sampling::light_area}));
  std::vector<std::string_view> sets;
  for (const point_set_entry* set : sc.point_sets) sets.push_back(set->name);
  EXPECT_EQ(sets, (std::vector<std::string_view>{"independent", "jittered", "padded_jittered",
                                                 "latin_hypercube", "sobol"}));
  EXPECT_EQ(sc.spp, (std::vector<std::uint64_t>{1, 4, 16, 64}));
  EXPECT_TRUE(sc.images);
  EXPECT_FALSE(sc.light_sampling);
  // 3 estimators × 5 sets × 4 spp, and the exact image and its pixel means.
  EXPECT_EQ(sc.image_count(), 3u * 5u * 4u + 2u);
}

TEST(RenderScene, ReadsEveryKey) {
  const render_scene sc = parse_render(R"(name = "pic"
description = "d"
seed = 3
threads = 2
width = 16
height = 12
region = [0, 0, 1, 0.5]
occluder = false
estimators = ["light_area", "cosine_hemisphere"]
point_sets = ["sobol"]
spp = [2, 8]
images = false
[light_sampling]
samples = 4
point_set = "independent"
)");
  EXPECT_EQ(sc.name, "pic");
  EXPECT_EQ(sc.description, "d");
  EXPECT_EQ(sc.seed, 3u);
  EXPECT_EQ(sc.threads, 2u);
  EXPECT_EQ(sc.width, 16u);
  EXPECT_EQ(sc.height, 12u);
  EXPECT_EQ(sc.region, (std::array<double, 4>{0.0, 0.0, 1.0, 0.5}));
  EXPECT_FALSE(sc.occluder);
  // In the order given, not the catalogue's.
  EXPECT_EQ(sc.estimators,
            (std::vector<irradiance_sampling>{irradiance_sampling::light_area,
                                              irradiance_sampling::cosine_hemisphere}));
  ASSERT_EQ(sc.point_sets.size(), 1u);
  EXPECT_EQ(sc.point_sets[0]->name, "sobol");
  EXPECT_EQ(sc.spp, (std::vector<std::uint64_t>{2, 8}));
  EXPECT_FALSE(sc.images);
  EXPECT_TRUE(sc.light_sampling);
  EXPECT_EQ(sc.light_samples, 4u);
  EXPECT_EQ(sc.light_sampling_set->name, "independent");
  EXPECT_EQ(sc.image_count(), 2u * 1u * 2u + 2u + 4u);
  const irradiance_plane plane = sc.plane();
  EXPECT_EQ(plane.width, 16u);
  EXPECT_EQ(plane.height, 12u);
}

TEST(RenderScene, AnUnknownKeyIsRefusedWithTheKeysItTakes) {
  const std::string message = render_error("seed = 1\nseeds = 5\n", 2, "seeds");
  EXPECT_EQ(message.rfind("r.toml:2:1: key 'seeds': unknown key in a render scene; expected one "
                          "of: ",
                          0),
            0u)
      << message;
  for (const std::string_view key : render_scene_keys()) {
    EXPECT_NE(message.find(key), std::string::npos) << key << " in " << message;
  }
  const std::string inner =
      render_error("[light_sampling]\nsample = 4\n", 2, "light_sampling.sample");
  EXPECT_NE(inner.find(fmt::format("unknown key in [light_sampling]; expected one of: {}, {}",
                                   light_sampling_keys()[0], light_sampling_keys()[1])),
            std::string::npos)
      << inner;
}

TEST(RenderScene, BoundsAreRefusedAtTheirKey) {
  EXPECT_NE(render_error("width = 4097\n", 1, "width")
                .find("expected a width between 1 and 4096 pixels, got 4097"),
            std::string::npos);
  EXPECT_NE(render_error("height = 0\n", 1, "height").find("got 0"), std::string::npos);
  // A render scene's counts are TOML integers: an integral float is refused, unlike a scene's.
  EXPECT_NE(render_error("width = 16.0\n", 1, "width").find("expected a width"), std::string::npos);
  EXPECT_NE(render_error("spp = [1, 4, 4097]\n", 1, "spp[3]")
                .find("expected samples per pixel between 1 and 4096, got 4097"),
            std::string::npos);
  // Each side within its bound, but the images together beyond 2^25 doubles: named at `width`.
  const std::uint64_t mib = (3u * 5u * 4u + 2u) * 4096u * 256u * 8u >> 20;
  EXPECT_NE(render_error("threads = 1\nwidth = 4096\n", 2, "width")
                .find(fmt::format("need {} MiB; at most 256 MiB", mib)),
            std::string::npos);
  // Within the bound: 62 images of 2048 × 256 pixels are just under 2^25 doubles.
  EXPECT_EQ(parse_render("width = 2048\n").width, 2048u);
}

TEST(RenderScene, ListsAreCheckedElementByElement) {
  EXPECT_NE(render_error("estimators = [\"light_area\", \"light_area\"]\n", 1, "estimators[2]")
                .find("'light_area' is listed twice"),
            std::string::npos);
  EXPECT_NE(render_error("spp = [4, 1]\n", 1, "spp[2]").find("spp must increase, got 1 after 4"),
            std::string::npos);
  EXPECT_NE(render_error("point_sets = []\n", 1, "point_sets")
                .find("expected a non-empty array of point-set names, got an array"),
            std::string::npos);
  EXPECT_NE(render_error("region = [0, 0, 1]\n", 1, "region")
                .find("expected [x_min, y_min, x_max, y_max]"),
            std::string::npos);
  EXPECT_NE(render_error("region = [0, \"a\", 1, 1]\n", 1, "region[2]")
                .find("expected a finite number, got \"a\""),
            std::string::npos);
}

// zsobol is the render's own set: accepted among the images' sets, refused for the light patterns
// (one integral's points), and its index range (4^⌈log₂ max(W, H)⌉ × spp ≤ 2^32) checked at plan
// time: 4096² pixels leave spp ≤ 2^8.
TEST(RenderScene, ZsobolIsAnImageSetWithItsIndexRangeCheckedAtPlanTime) {
  const render_scene sc = parse_render("point_sets = [\"zsobol\", \"sobol\"]\n");
  ASSERT_EQ(sc.point_sets.size(), 2u);
  EXPECT_EQ(sc.point_sets[0], &zsobol_render_set());
  EXPECT_EQ(sc.point_sets[1]->name, "sobol");
  EXPECT_NE(
      render_error("[light_sampling]\npoint_set = \"zsobol\"\n", 2, "light_sampling.point_set")
          .find("expected a point set, one of: independent"),
      std::string::npos);
  EXPECT_NE(render_error("point_sets = [\"zsobol\"]\nspp = [3]\n", 2, "spp")
                .find("the zsobol points cannot hold 3 samples per pixel"),
            std::string::npos);
  const std::string message = render_error(
      "threads = 1\nwidth = 4096\nheight = 4\nestimators = [\"light_area\"]\n"
      "point_sets = [\"zsobol\"]\nspp = [256, 512]\n",
      6, "spp");
  EXPECT_NE(message.find("cannot hold 512 samples per pixel"), std::string::npos) << message;
  EXPECT_NE(message.find("spp ≤ 2^8 for a 4096 × 4 image"), std::string::npos) << message;
}

TEST(RenderScene, ValuesAreShownOnOneLine) {
  // A string with a tab and a quote is shown escaped, as TOML writes it.
  const std::string message = render_error("images = \"a\\tb\\\"\"\n", 1, "images");
  EXPECT_NE(message.find(R"(expected true or false, got "a\tb\"")"), std::string::npos) << message;
  // A syntax error has no key and toml++'s own position.
  try {
    parse_render("width = \n");
    ADD_FAILURE() << "no scene_error";
  } catch (const scene_error& e) {
    EXPECT_EQ(e.key(), "");
    EXPECT_EQ(e.where().line, 1u);
  }
}

TEST(RenderScene, EstimatorNamesRoundTrip) {
  for (const auto t : {irradiance_sampling::uniform_hemisphere,
                       irradiance_sampling::cosine_hemisphere, irradiance_sampling::light_area}) {
    const render_scene sc = parse_render(fmt::format("estimators = [\"{}\"]\n", to_string(t)));
    ASSERT_EQ(sc.estimators.size(), 1u);
    EXPECT_EQ(sc.estimators[0], t);
  }
}

}  // namespace
}  // namespace quadmc
