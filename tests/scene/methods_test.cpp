// Tests of scene/methods.hpp: the method table and the exact N → grid arithmetic.
#include "quadmc/scene/methods.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

namespace quadmc {
namespace {

const method_info& method(std::string_view name) {
  const method_info* m = find_method(name);
  EXPECT_NE(m, nullptr) << name;
  return *m;
}

TEST(MethodCatalogue, NamesEveryMethodTheSceneFormatPromises) {
  // The list of parse.hpp's reference block plus the irradiance estimators.
  for (std::string_view name :
       {"left_rectangle", "right_rectangle", "midpoint", "trapezoid", "simpson", "gauss_legendre",
        "romberg", "plain_mc", "jittered", "unjittered", "padded_jittered", "latin_hypercube",
        "importance", "irradiance_hemisphere_uniform", "irradiance_hemisphere_cosine",
        "irradiance_light_area"}) {
    const method_info* m = find_method(name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_FALSE(m->description.empty()) << name;
    const auto& o = m->options;
    EXPECT_NE(std::find(o.begin(), o.end(), "name"), o.end()) << name;
  }
  EXPECT_EQ(find_method("simpsons"), nullptr);
  EXPECT_EQ(method_catalogue().size(), 16u);
}

TEST(MethodCatalogue, KindsAndOrdersMatchTheTheoryTable) {
  // docs/theory.md#newton-cotes-errors: r = 1 rectangle, 2 midpoint/trapezoid, 4 Simpson.
  EXPECT_EQ(method("left_rectangle").order, 1);
  EXPECT_EQ(method("right_rectangle").order, 1);
  EXPECT_EQ(method("midpoint").order, 2);
  EXPECT_EQ(method("trapezoid").order, 2);
  EXPECT_EQ(method("simpson").order, 4);
  for (const auto& m : method_catalogue()) {
    const bool rule = m.counts == count_constraint::tensor_grid;
    EXPECT_EQ(m.kind == method_kind::deterministic_rule, rule) << m.name;
    EXPECT_EQ(m.tensor_product, rule && m.name != "romberg") << m.name;
  }
  EXPECT_EQ(method("jittered").counts, count_constraint::perfect_power);
  EXPECT_EQ(method("romberg").applies_to, integrand_requirement::one_dimensional);
  EXPECT_EQ(method("irradiance_light_area").applies_to, integrand_requirement::irradiance);
}

TEST(CheckedPower, ExactUpToTheLimitAndNulloptBeyond) {
  EXPECT_EQ(checked_power(2, 63), std::uint64_t{1} << 63);
  EXPECT_EQ(checked_power(2, 64), std::nullopt);
  EXPECT_EQ(checked_power(4294967295u, 2), 18446744065119617025u);  // (2^32 − 1)^2
  EXPECT_EQ(checked_power(4294967296u, 2), std::nullopt);
  EXPECT_EQ(checked_power(0, 5), 0u);
  EXPECT_EQ(checked_power(7, 0), 1u);
}

TEST(IntegerRoot, ExactAroundEveryPerfectPowerForSUpTo8) {
  for (unsigned s = 1; s <= 8; ++s) {
    for (std::uint64_t q = 1; q <= 200; ++q) {
      const auto p = checked_power(q, s);
      if (!p) break;
      EXPECT_EQ(integer_root(*p, s), q) << "s = " << s << ", N = " << q << "^" << s;
      EXPECT_EQ(integer_root(*p - 1, s), q - 1) << "s = " << s << ", N = " << q << "^s − 1";
      // q^s + 1 < (q+1)^s for s ≥ 2; for s = 1 it is (q+1)^1.
      EXPECT_EQ(integer_root(*p + 1, s), s == 1 ? q + 1 : q)
          << "s = " << s << ", N = " << q << "^s + 1";
    }
  }
  // The largest 64-bit value: its square root is 2^32 − 1 exactly (pow would round to 2^32).
  EXPECT_EQ(integer_root(18446744073709551615u, 2), 4294967295u);
  EXPECT_EQ(integer_root(18446744073709551615u, 64), 1u);
}

TEST(LargestTensorGrid, NearPerfectCubes) {
  // Exact integer grids: N = 4096 = 16^3 → n = 16 midpoint panels; N = 4095 → 15.
  EXPECT_EQ(largest_tensor_grid(method("midpoint"), 4096, 3, 1)->panels, 16u);
  EXPECT_EQ(largest_tensor_grid(method("midpoint"), 4095, 3, 1)->panels, 15u);
  EXPECT_EQ(largest_tensor_grid(method("midpoint"), 4095, 3, 1)->evaluations, 3375u);
  // Trapezoid: n + 1 nodes per axis, 16^3 nodes → n = 15.
  EXPECT_EQ(largest_tensor_grid(method("trapezoid"), 4096, 3, 1)->panels, 15u);
  EXPECT_EQ(largest_tensor_grid(method("trapezoid"), 4096, 3, 1)->evaluations, 4096u);
  // Simpson: n even and n + 1 ≤ 16 → n = 14 (15^3 = 3375 evaluations).
  const auto simpson = largest_tensor_grid(method("simpson"), 4096, 3, 1);
  EXPECT_EQ(simpson->panels, 14u);
  EXPECT_EQ(simpson->evaluations, 3375u);
  EXPECT_EQ(largest_tensor_grid(method("simpson"), 3375, 3, 1)->panels, 14u);
  EXPECT_EQ(largest_tensor_grid(method("simpson"), 3374, 3, 1)->panels, 12u);
  // Gauss–Legendre, m = 3: 3n ≤ 16 → n = 5, (15)^3 evaluations; order 2m = 6.
  const auto gauss = largest_tensor_grid(method("gauss_legendre"), 4096, 3, 3);
  EXPECT_EQ(gauss->panels, 5u);
  EXPECT_EQ(gauss->evaluations, 3375u);
  EXPECT_EQ(gauss->order, 6);
}

TEST(LargestTensorGrid, RombergUsesPowersOfTwoPanels) {
  // 2^k + 1 nodes: N = 17 → 16 panels (order 2·4 + 2 = 10), N = 16 → 8 panels.
  EXPECT_EQ(largest_tensor_grid(method("romberg"), 17, 1, 1)->panels, 16u);
  EXPECT_EQ(largest_tensor_grid(method("romberg"), 17, 1, 1)->order, 10);
  EXPECT_EQ(largest_tensor_grid(method("romberg"), 16, 1, 1)->panels, 8u);
  EXPECT_EQ(largest_tensor_grid(method("romberg"), 3, 1, 1)->panels, 2u);
  EXPECT_FALSE(largest_tensor_grid(method("romberg"), 2, 1, 1).has_value());
}

TEST(LargestTensorGrid, TooSmallNGivesNoGrid) {
  EXPECT_FALSE(largest_tensor_grid(method("simpson"), 26, 3, 1).has_value());  // needs 3^3
  EXPECT_EQ(largest_tensor_grid(method("simpson"), 27, 3, 1)->panels, 2u);
  EXPECT_FALSE(largest_tensor_grid(method("trapezoid"), 255, 8, 1).has_value());  // needs 2^8
  EXPECT_EQ(largest_tensor_grid(method("midpoint"), 1, 8, 1)->panels, 1u);
}

// Maximality by definition, independently of how largest_tensor_grid computes it: the grid fits
// (p(n)^s ≤ N) and the next admissible n does not, for every tensor rule, s = 1…8 and N around
// perfect powers.
TEST(LargestTensorGrid, IsTheLargestAdmissibleGridForSUpTo8) {
  std::vector<std::uint64_t> Ns;
  for (std::uint64_t q = 2; q <= 70; ++q) {
    for (unsigned s = 1; s <= 8; ++s) {
      const auto p = checked_power(q, s);
      if (!p || *p > (std::uint64_t{1} << 53)) continue;
      Ns.insert(Ns.end(), {*p - 1, *p, *p + 1});
    }
  }
  for (const auto& m : method_catalogue()) {
    if (m.counts != count_constraint::tensor_grid) continue;
    for (unsigned s = 1; s <= 8; ++s) {
      if (m.name == "romberg" && s > 1) continue;
      for (std::uint64_t N : Ns) {
        const std::uint64_t nodes = 3;  // Gauss–Legendre m
        const auto g = largest_tensor_grid(m, N, s, nodes);
        if (!g) continue;
        ASSERT_LE(g->evaluations, N) << m.name << " s = " << s << " N = " << N;
        EXPECT_EQ(checked_power(points_per_axis(m, g->panels, nodes), s), g->evaluations);
        std::uint64_t next = g->panels + 1;
        if (m.name == "simpson") next = g->panels + 2;
        if (m.name == "romberg") next = 2 * g->panels;
        if (m.name == "simpson") {
          EXPECT_EQ(g->panels % 2, 0u) << "Simpson n must be even";
        }
        const auto bigger = checked_power(points_per_axis(m, next, nodes), s);
        EXPECT_TRUE(!bigger || *bigger > N)
            << m.name << " s = " << s << " N = " << N << ": n = " << next << " also fits";
      }
    }
  }
}

TEST(StratifiedCount, PerfectPowersAndSquares) {
  EXPECT_EQ(stratified_count_for(count_constraint::perfect_power, 4096, 3).per_axis, 16u);
  EXPECT_EQ(stratified_count_for(count_constraint::perfect_power, 4095, 3).evaluations, 3375u);
  EXPECT_EQ(stratified_count_for(count_constraint::perfect_power, 255, 8).evaluations, 1u);
  EXPECT_EQ(stratified_count_for(count_constraint::perfect_square, 1000, 5).evaluations, 961u);
  EXPECT_EQ(stratified_count_for(count_constraint::perfect_square, 1000, 1).evaluations, 1000u);
  EXPECT_EQ(stratified_count_for(count_constraint::any, 1000, 7).evaluations, 1000u);
}

TEST(WarpAndPointSetCatalogues, KnowTheirNames) {
  EXPECT_NE(find_warp("power"), nullptr);
  EXPECT_NE(find_warp("exponential"), nullptr);
  EXPECT_EQ(find_warp("gaussian"), nullptr);
  EXPECT_EQ(find_point_set("jittered")->counts, count_constraint::perfect_power);
  EXPECT_EQ(find_point_set("independent")->counts, count_constraint::any);
  EXPECT_NE(method_names().find("irradiance_light_area"), std::string::npos);
}

}  // namespace
}  // namespace quadmc
