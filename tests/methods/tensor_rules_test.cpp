// Tests of the tensor-rule methods (lib/src/methods/tensor_rules.cpp): the exact N → grid mapping,
// explicit panels, the options' checks, and that a method runs its rule.
#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/rules/gauss_legendre_rule.hpp"
#include "quadmc/rules/midpoint_rule.hpp"
#include "quadmc/rules/rectangle_rule.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace quadmc {
namespace {

constexpr const char* rules[] = {"left_rectangle", "right_rectangle", "midpoint",
                                 "trapezoid",      "simpson",         "gauss_legendre"};

cell_size grid(std::string_view method, std::uint64_t N, std::size_t s,
               const option_table& options = {}) {
  const sizing size = make_method(method, options)->size_for(N, s);
  if (!size.size) throw std::runtime_error(std::string(method) + ": " + size.reason);
  return *size.size;
}

TEST(TensorRuleMethods, NearPerfectCubes) {
  // N = 4096 = 16^3 → n = 16 midpoint panels; N = 4095 → 15.
  EXPECT_EQ(grid("midpoint", 4096, 3).per_axis, 16u);
  EXPECT_EQ(grid("midpoint", 4095, 3).per_axis, 15u);
  EXPECT_EQ(grid("midpoint", 4095, 3).evaluations, 3375u);
  // Trapezoid: n + 1 nodes per axis, 16^3 nodes → n = 15.
  EXPECT_EQ(grid("trapezoid", 4096, 3).per_axis, 15u);
  EXPECT_EQ(grid("trapezoid", 4096, 3).evaluations, 4096u);
  // Simpson: n even and n + 1 ≤ 16 → n = 14 (15^3 = 3375 evaluations).
  EXPECT_EQ(grid("simpson", 4096, 3).per_axis, 14u);
  EXPECT_EQ(grid("simpson", 4096, 3).evaluations, 3375u);
  EXPECT_EQ(grid("simpson", 3375, 3).per_axis, 14u);
  EXPECT_EQ(grid("simpson", 3374, 3).per_axis, 12u);
  // Gauss–Legendre, m = 3: 3n ≤ 16 → n = 5, 15^3 evaluations; order 2m = 6.
  const cell_size gauss = grid("gauss_legendre", 4096, 3);
  EXPECT_EQ(gauss.per_axis, 5u);
  EXPECT_EQ(gauss.evaluations, 3375u);
  EXPECT_EQ(gauss.order, 6);
  EXPECT_EQ(grid("gauss_legendre", 4096, 3, {{"m", 5}}).per_axis, 3u);
  EXPECT_EQ(grid("gauss_legendre", 4096, 3, {{"m", 5}}).order, 10);
}

TEST(TensorRuleMethods, TooSmallNGivesNoGridWithTheReason) {
  const sizing none = make_method("simpson")->size_for(26, 3);  // needs 3^3
  EXPECT_FALSE(none.size);
  EXPECT_EQ(none.reason, "N is below the smallest grid, 3^3 = 27 evaluations");
  EXPECT_EQ(grid("simpson", 27, 3).per_axis, 2u);
  EXPECT_FALSE(make_method("trapezoid")->size_for(255, 8).size);  // needs 2^8
  EXPECT_EQ(grid("midpoint", 1, 8).per_axis, 1u);
}

// The rule's own node count p(n) (rule.nodes(n).size()) is what the grid arithmetic assumes, for
// every admissible n.
template <class Rule>
void expect_node_counts(std::string_view method, const Rule& rule,
                        const option_table& options = {}) {
  const auto m = make_method(method, options);
  for (std::uint64_t N = 1; N <= 400; ++N) {
    const sizing size = m->size_for(N, 1);
    if (!size.size) continue;
    EXPECT_EQ(size.size->points_per_axis, rule.nodes(size.size->per_axis).size())
        << method << " n = " << size.size->per_axis;
    EXPECT_EQ(size.size->order, rule.order()) << method;
  }
}

TEST(TensorRuleMethods, NodeCountsAreTheRulesOwn) {
  expect_node_counts("left_rectangle", rectangle_rule<rectangle_side::left>{});
  expect_node_counts("right_rectangle", rectangle_rule<rectangle_side::right>{});
  expect_node_counts("midpoint", midpoint_rule{});
  expect_node_counts("trapezoid", trapezoid_rule{});
  expect_node_counts("simpson", simpson_rule{});
  expect_node_counts("gauss_legendre", gauss_legendre_rule(3));
  expect_node_counts("gauss_legendre", gauss_legendre_rule(7), {{"m", 7}});
}

// Maximality by definition, independently of how the method computes it: the grid fits
// (p(n)^s ≤ N) and the next admissible n does not, for every tensor rule, s = 1…8 and N around
// perfect powers.
TEST(TensorRuleMethods, GridIsTheLargestAdmissibleForSUpTo8) {
  std::vector<std::uint64_t> Ns;
  for (std::uint64_t q = 2; q <= 70; ++q) {
    for (unsigned s = 1; s <= 8; ++s) {
      const auto p = checked_power(q, s);
      if (!p || *p > (std::uint64_t{1} << 53)) continue;
      Ns.insert(Ns.end(), {*p - 1, *p, *p + 1});
    }
  }
  for (const char* name : rules) {
    const auto m = make_method(name);
    for (unsigned s = 1; s <= 8; ++s) {
      for (std::uint64_t N : Ns) {
        const sizing size = m->size_for(N, s);
        if (!size.size) continue;
        const cell_size& g = *size.size;
        ASSERT_LE(g.evaluations, N) << name << " s = " << s << " N = " << N;
        EXPECT_EQ(checked_power(g.points_per_axis, s), g.evaluations);
        // The definition of p(n) (docs/theory.md#conventions), written here independently of
        // the method: n for the rectangles and midpoint, n + 1 for trapezoid and Simpson (n even
        // for Simpson), 3n for Gauss–Legendre with its default m = 3.
        const std::string_view rule = name;
        const std::uint64_t step = rule == "simpson" ? 2 : 1;
        auto points = [&](std::uint64_t n) -> std::uint64_t {
          if (rule == "trapezoid" || rule == "simpson") return n + 1;
          if (rule == "gauss_legendre") return 3 * n;
          return n;
        };
        EXPECT_EQ(g.points_per_axis, points(g.per_axis)) << name;
        if (step == 2) {
          EXPECT_EQ(g.per_axis % 2, 0u) << "Simpson n must be even";
        }
        const auto bigger = checked_power(points(g.per_axis + step), s);
        EXPECT_TRUE(!bigger || *bigger > N)
            << name << " s = " << s << " N = " << N << ": n = " << g.per_axis + step << " fits";
      }
    }
  }
}

TEST(TensorRuleMethods, ExplicitPanelsReplaceTheLadder) {
  const auto m = make_method("simpson", {{"panels", std::vector<double>{2, 4, 8}}});
  std::vector<std::uint64_t> n;
  for (const sizing& size : m->explicit_sizes(2)) n.push_back(size.size->per_axis);
  EXPECT_EQ(n, (std::vector<std::uint64_t>{2, 4, 8}));
  EXPECT_EQ(m->explicit_sizes(2)[2].size->evaluations, 81u);
  EXPECT_TRUE(make_method("simpson")->explicit_sizes(2).empty());
  // A grid that cannot be counted is a skip with its reason, not an overflow.
  const auto huge = make_method("midpoint", {{"panels", 4294967296.0}});
  const sizing too_big = huge->explicit_sizes(3).front();
  EXPECT_FALSE(too_big.size);
  EXPECT_NE(too_big.reason.find("do not fit in 64 bits"), std::string::npos) << too_big.reason;
}

std::string error_of(std::string_view method, const option_table& options) {
  try {
    make_method(method, options);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(TensorRuleMethods, OptionsAreCheckedWithTheirReasons) {
  EXPECT_NE(error_of("simpson", {{"panels", std::vector<double>{2, 3}}})
                .find("panels[2]: expected an even panel count between 2 and 2^53, got 3"),
            std::string::npos);
  EXPECT_NE(error_of("midpoint", {{"panels", std::vector<double>{4, 2}}})
                .find("panel counts must increase, got 2 after 4"),
            std::string::npos);
  EXPECT_NE(error_of("gauss_legendre", {{"m", 6}}).find("expected one of 2 3 4 5 7 10 15 20 25 30"),
            std::string::npos);
  EXPECT_NE(error_of("trapezoid", {{"accumulator", "kahan"}})
                .find("one of: pairwise, neumaier, naive, long_double"),
            std::string::npos);
  EXPECT_NE(error_of("trapezoid", {{"m", 3}}).find("unknown key in a 'trapezoid' method"),
            std::string::npos)
      << "m belongs to Gauss–Legendre only";
}

TEST(TensorRuleMethods, RunIsTheRulesIntegrate) {
  // The method runs integrate() with its rule, n and accumulator: the same bits.
  integrand_params params;
  const any_integrand f = make_integrand("exp", params);
  const cell_size size = grid("simpson", 1000, 1);
  const method_cell cell{f, params, size, cell_control::fixed_size, 0.0, 0};
  const repetition_result r = make_method("simpson", {{"accumulator", "naive"}})->run(cell, {0, 2});
  const rule_result direct = integrate(f, simpson_rule{}, size.per_axis, 2, summation::naive);
  EXPECT_EQ(r.value, direct.value);
  EXPECT_EQ(r.evaluations, direct.evaluations);
  EXPECT_TRUE(std::isnan(r.std_error)) << "a rule has no sampling error";
  EXPECT_TRUE(std::isnan(r.error_estimate));
}

}  // namespace
}  // namespace quadmc
