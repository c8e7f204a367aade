// Tests of compute_reference (scene/computed_reference.hpp): on catalogue integrands whose exact
// integral is known, the computed value is within its stated uncertainty of it, and that
// uncertainty is tight (below 1e-9 of the magnitude), on eleven families: 1D smooth,
// 1D endpoint-singular, 1D with a kink or a jump, and Genz and Sobol' g integrands in s = 2 and 3.
#include "quadmc/scene/computed_reference.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/catalogue.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace quadmc {
namespace {

struct family_case {
  std::string family;
  std::size_t s;
  // The largest stated uncertainty accepted, relative to max(|I|, 1e-3): the tolerance asked for
  // (1e-12 for both) with a margin of 10³ for the estimates' own slack.
  double tight;
};

class ComputedReference : public ::testing::TestWithParam<family_case> {};

TEST_P(ComputedReference, AgreesWithTheExactValueWithinItsStatedUncertainty) {
  const family_case& c = GetParam();
  integrand_params params;
  params.dimension = c.s;
  params.seed = 20261205;  // drawn Genz parameters: any fixed instance
  const any_integrand f = make_integrand(c.family, params);
  const double exact = f.info().exact;
  ASSERT_TRUE(std::isfinite(exact)) << c.family;
  const computed_reference r = compute_reference(f);
  const double off = std::abs(r.value - exact);
  // Printed for the record (the achieved accuracy against the stated uncertainty).
  std::printf("%s s=%zu: |computed - exact| = %.3g, uncertainty = %.3g, %llu evaluations, %s\n",
              c.family.c_str(), c.s, off, r.uncertainty,
              static_cast<unsigned long long>(r.evaluations), r.method.c_str());
  EXPECT_TRUE(r.converged) << r.describe();
  EXPECT_LE(off, r.uncertainty) << c.family << ": " << r.describe() << ", exact " << exact;
  EXPECT_GT(r.uncertainty, 0.0);
  EXPECT_LE(r.uncertainty, c.tight * std::max(std::abs(exact), 1e-3)) << r.describe();
  EXPECT_GT(r.evaluations, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Families, ComputedReference,
    ::testing::Values(family_case{"exp", 1, 1e-10}, family_case{"inverse_sqrt", 1, 1e-10},
                      family_case{"inverse_quadratic", 1, 1e-10},
                      family_case{"genz_gaussian", 2, 1e-9},
                      family_case{"genz_oscillatory", 3, 1e-9},
                      family_case{"genz_product_peak", 2, 1e-9},
                      family_case{"genz_continuous", 2, 1e-9},
                      family_case{"genz_discontinuous", 2, 1e-9}, family_case{"abs_kink", 1, 1e-10},
                      family_case{"step", 1, 1e-10}, family_case{"sobol_g", 3, 1e-9}),
    [](const auto& info) { return info.param.family + "_s" + std::to_string(info.param.s); });

TEST(ComputedReferenceLimits, RefusesDimensionsAboveTheLimit) {
  integrand_params params;
  params.dimension = max_computed_reference_dimension + 1;
  const any_integrand f = make_integrand("genz_gaussian", params);
  EXPECT_THROW(compute_reference(f), invalid_argument);
}

TEST(ComputedReferenceLimits, DescribeNamesMethodToleranceEvaluationsAndUncertainty) {
  integrand_params params;
  params.dimension = 1;
  const computed_reference r = compute_reference(make_integrand("exp", params));
  const std::string text = r.describe();
  EXPECT_NE(text.find("tanh-sinh"), std::string::npos) << text;
  EXPECT_NE(text.find("relative tolerance 1e-12"), std::string::npos) << text;
  EXPECT_NE(text.find(std::to_string(r.evaluations) + " evaluations"), std::string::npos) << text;
  EXPECT_NE(text.find("uncertainty"), std::string::npos) << text;
}

}  // namespace
}  // namespace quadmc
