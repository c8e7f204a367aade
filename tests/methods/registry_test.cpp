// Tests of registry.hpp and option_map.hpp: the one table of methods, configured from C++.
#include "quadmc/methods/registry.hpp"
#include "method_error.hpp"

#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <iterator>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {
namespace {

// The one hard-coded list of names in the tests: the methods and peers scenes have always named
// (scene/parse.hpp's reference), in listing order, so that none disappears unnoticed. Every other
// test that walks the methods or peers reads the tables (method_registry, peers::known).
struct named_method {
  std::string_view name;
  method_kind kind;
};
constexpr method_kind rule_kind = method_kind::deterministic;
constexpr method_kind random_kind = method_kind::randomized;
constexpr named_method expected_methods[] = {
    {"left_rectangle", rule_kind},
    {"right_rectangle", rule_kind},
    {"midpoint", rule_kind},
    {"trapezoid", rule_kind},
    {"simpson", rule_kind},
    {"gauss_legendre", rule_kind},
    {"romberg", rule_kind},
    {"plain_mc", random_kind},
    {"jittered", random_kind},
    {"unjittered", random_kind},
    {"padded_jittered", random_kind},
    {"cmj", random_kind},
    {"latin_hypercube", random_kind},
    {"importance", random_kind},
    {"irradiance_hemisphere_uniform", random_kind},
    {"irradiance_hemisphere_cosine", random_kind},
    {"irradiance_light_area", random_kind},
    {"smolyak", rule_kind},
    {"adaptive_sparse_grid", rule_kind},
    {"genz_malik", rule_kind},
    {"vegas", random_kind},
    {"sobol", random_kind},
    {"halton", random_kind},
    {"padded_sobol", random_kind},
    {"pmj02", random_kind},
    {"lattice", random_kind},
    {"external_points", random_kind},
    {"external_rule", random_kind},
};
constexpr std::string_view expected_peers[] = {
    "peer_hcubature", "peer_pcubature",       "peer_gsl_plain",           "peer_gsl_miser",
    "peer_gsl_vegas", "peer_boost_tanh_sinh", "peer_boost_gauss_kronrod", "peer_scipy_qmc_quad"};

// Each with its kind: the deterministic methods are the rules.
TEST(MethodRegistry, NamesEveryMethodOnceWithAKindAndAControl) {
  std::vector<std::string_view> names;
  for (const method_descriptor* d : method_registry()) {
    names.push_back(d->name);
    EXPECT_EQ(find_method(d->name), d);
    EXPECT_FALSE(d->description.empty()) << d->name;
    ASSERT_FALSE(d->controls.empty()) << d->name;
    EXPECT_TRUE(d->supports(d->controls.front())) << d->name;
    std::set<std::string_view> keys;
    for (const option_doc& o : d->options) {
      EXPECT_TRUE(keys.insert(o.key).second) << d->name << " documents " << o.key << " twice";
      EXPECT_FALSE(o.meaning.empty()) << d->name << "." << o.key;
    }
  }
  std::vector<std::string_view> expected;
  for (const named_method& m : expected_methods) {
    expected.push_back(m.name);
    const method_descriptor* d = find_method(m.name);
    if (d != nullptr) {
      EXPECT_EQ(d->kind, m.kind) << m.name;
    }
  }
  EXPECT_EQ(names, expected);
  EXPECT_EQ(find_method("simpsons"), nullptr);
  EXPECT_NE(method_names().find("irradiance_light_area"), std::string::npos);
}

TEST(MethodRegistry, MakeMethodChecksNameAndKeys) {
  EXPECT_NE(error_of("simpsons", {}).find("invalid method = simpsons: expected one of: "),
            std::string::npos);
  EXPECT_NE(error_of("plain_mc", {{"panels", 3}}).find("unknown key in a 'plain_mc' method"),
            std::string::npos);
  EXPECT_NE(error_of("importance", {}).find("missing required key for importance"),
            std::string::npos);
  EXPECT_NE(error_of("importance", {{"warp", "gaussian"}}).find("one of: power, exponential"),
            std::string::npos);
  EXPECT_NE(error_of("importance", {{"warp", option_table{{"name", "power"}, {"rate", 2.0}}}})
                .find("unknown key in warp 'power'; expected one of: name, exponent"),
            std::string::npos);
  EXPECT_NE(
      error_of("importance", {{"warp", option_table{{"name", "exponential"}, {"rate", 1e308}}}})
          .find("expected a rate 0 < |l| <= 700"),
      std::string::npos);
  EXPECT_NE(error_of("jittered", {{"point_set", "sobol"}}).find("unknown key"), std::string::npos)
      << "a method named after its point set takes no point_set";
  EXPECT_NE(error_of("importance", {{"warp", "power"}, {"point_set", "niederreiter"}})
                .find("one of: independent, jittered"),
            std::string::npos);
}

TEST(MethodRegistry, APeerOutsideItsBuildSaysHowToGetIt) {
  // The peers (bench/peers/) are not linked into this test: the library alone knows their names
  // and says where they are built, instead of "expected one of" a list without them.
  std::vector<std::string_view> known;
  for (const known_peer& p : peers::known) known.push_back(p.name);
  EXPECT_EQ(known,
            std::vector<std::string_view>(std::begin(expected_peers), std::end(expected_peers)));
  for (const known_peer& p : peers::known) {
    const std::string peer(p.name);
    EXPECT_EQ(find_method(peer), nullptr) << peer;
    const std::optional<std::string> why = unavailable_method(peer);
    ASSERT_TRUE(why.has_value()) << peer;
    EXPECT_NE(why->find(std::string("method '") + peer + "'"), std::string::npos) << *why;
    EXPECT_NE(why->find("quadmc_with_peers"), std::string::npos) << *why;
    const std::string m = error_of(peer, {});
    EXPECT_NE(m.find(std::string("invalid method = ") + peer), std::string::npos) << m;
    EXPECT_NE(m.find("is a peer, not built into this quadmc"), std::string::npos) << m;
    EXPECT_EQ(m.find("expected one of"), std::string::npos) << m;
  }
  EXPECT_FALSE(unavailable_method("simpson").has_value()) << "present";
  EXPECT_FALSE(unavailable_method("simpsons").has_value()) << "unknown";
}

TEST(MethodRegistry, AddMethodsRefusesATakenName) {
  // A second "simpson" would make find_method's answer depend on the order of registration.
  static const method_descriptor twin{"simpson", "a duplicate", method_kind::deterministic, {},
                                      {},        nullptr};
  const std::size_t before = method_registry().size();
  EXPECT_THROW(add_methods(std::span<const method_descriptor>(&twin, 1)), std::logic_error);
  EXPECT_EQ(method_registry().size(), before);
}

TEST(MethodRegistry, LabelSuffixesSayWhatWasConfigured) {
  EXPECT_EQ(make_method("simpson")->label_suffix(), "");
  EXPECT_EQ(make_method("simpson", {{"accumulator", "naive"}})->label_suffix(), "_naive");
  EXPECT_EQ(make_method("importance", {{"warp", "exponential"}})->label_suffix(), "_exponential");
  EXPECT_EQ(
      make_method("importance", {{"warp", "power"}, {"point_set", "jittered"}})->label_suffix(),
      "_power_jittered");
  EXPECT_EQ(
      make_method("irradiance_light_area", {{"point_set", "latin_hypercube"}})->label_suffix(),
      "_latin_hypercube");
}

TEST(MethodRegistry, PairingsAreTheMethodsOwn) {
  const integrand_traits disk{"disk_indicator", 2, false};
  const integrand_traits light{"irradiance_area", 2, true};
  EXPECT_FALSE(make_method("plain_mc")->incompatibility(disk));
  EXPECT_TRUE(make_method("irradiance_light_area")->incompatibility(disk));
  EXPECT_FALSE(make_method("irradiance_light_area")->incompatibility(light));
  const auto why = make_method("importance", {{"warp", "power"}})->incompatibility(disk);
  ASSERT_TRUE(why);
  EXPECT_EQ(*why, "the 'power' warp is a 1D density; the integrand has s = 2");
}

TEST(OptionMap, TypesAndRangesAreCheckedAtTheirKey) {
  option_map options({{"n", 2.5}, {"s", "text"}, {"b", true}, {"list", std::vector<double>{1, -2}}},
                     "test");
  EXPECT_THROW(options.count("n", 1, 10, "a count"), invalid_argument);
  EXPECT_EQ(options.number("n", "a number"), 2.5);
  EXPECT_THROW(options.number("s", "a number"), invalid_argument);
  EXPECT_EQ(options.string("s", "a string"), "text");
  EXPECT_EQ(options.boolean("b"), true);
  EXPECT_EQ(options.count("absent", 1, 10, "a count"), std::nullopt);
  try {
    options.counts("list", 0, 10, 8, "a count");
    FAIL() << "−2 is not a count";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "test.list[2]: expected a count, got -2");
    EXPECT_EQ(e.parameter(), "test.list[2]");
  }
  option_map unread({{"typo", 1}}, "t");
  const std::array<std::string_view, 1> accepted{"m"};
  EXPECT_THROW(unread.reject_unread("a 'x' method", accepted), invalid_argument);
}

}  // namespace
}  // namespace quadmc
