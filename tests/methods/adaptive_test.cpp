// Tests of the genz_malik method (lib/src/methods/adaptive.cpp): which integrands and sizes it
// takes, its controls and theory, and a run that is the kernel's with its error estimate.
#include "quadmc/methods/registry.hpp"
#include "quadmc/rules/adaptive_cubature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace quadmc {
namespace {

TEST(GenzMalikMethod, TakesTwoOrMoreDimensionsAndOneRegionAtLeast) {
  const auto m = make_method("genz_malik");
  EXPECT_TRUE(m->incompatibility({"exp", 1, false}).has_value());
  EXPECT_FALSE(m->incompatibility({"genz_gaussian", 2, false}).has_value());
  // One region in s = 3 is 2^3 + 2·9 + 2·3 + 1 = 33 evaluations.
  EXPECT_FALSE(m->size_for(32, 3).size);
  EXPECT_NE(m->size_for(32, 3).reason.find("33"), std::string::npos) << m->size_for(32, 3).reason;
  EXPECT_EQ(m->size_for(33, 3).size->evaluations, 33u);
  const method_descriptor* d = find_method("genz_malik");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->kind, method_kind::deterministic);
  EXPECT_EQ(d->controls.front(), cell_control::budget);
  EXPECT_TRUE(d->supports(cell_control::tolerance));
  EXPECT_FALSE(m->theory({smoothness::analytic, 3, std::nan("")}).slope.has_value());
}

TEST(GenzMalikMethod, RunIsTheKernelWithItsErrorEstimate) {
  integrand_params params;
  params.dimension = 3;
  params.vectors["a"] = {2.0, 3.0, 1.5};
  params.vectors["u"] = {0.4, 0.5, 0.6};
  const any_integrand f = make_integrand("genz_gaussian", params);
  const auto m = make_method("genz_malik");
  const cell_size size = *m->size_for(20'000, 3).size;
  const repetition_result r =
      m->run({f, params, size, cell_control::budget, std::nan(""), 0}, {0, 2});
  const adaptive_cubature_result direct = genz_malik_cubature(f, {.max_evaluations = 20'000});
  EXPECT_EQ(r.value, direct.value);
  EXPECT_EQ(r.error_estimate, direct.error_estimate);
  EXPECT_EQ(r.evaluations, direct.evaluations);
  EXPECT_LE(r.evaluations, 20'000u);
  EXPECT_TRUE(std::isnan(r.std_error)) << "a deterministic rule has no sampling error";

  const double tolerance = 1e-9;
  const cell_size cap = *m->size_for(std::uint64_t{1} << 22, 3).size;
  const repetition_result t =
      m->run({f, params, cap, cell_control::tolerance, tolerance, 0}, {0, 1});
  EXPECT_LE(t.error_estimate, tolerance);
  EXPECT_LE(std::abs(t.value - f.info().exact), tolerance);
}

}  // namespace
}  // namespace quadmc
