// An integrand family from outside the library (functions/catalogue.hpp, add_integrands), as a
// program built on quadmc::command adds it: found by scenes beside the built-in families, its
// name checked against theirs, and, without an exact value, measured from a reference the scene
// gives or the plan computes (docs/theory.md#references-without-a-closed-form).
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace quadmc {
namespace {

// g(x) = exp(−(x₁ + x₂)²/2) on [0,1]², with no exact value: its integral over the triangular
// density of t = x₁ + x₂ is ∫₀¹ t e^(−t²/2) dt + ∫₁² (2 − t) e^(−t²/2) dt
//   = (1 − e^(−1/2)) + 2√(π/2)(erf(√2) − erf(1/√2)) − (e^(−1/2) − e^(−2)),
// the closed form the computed reference is checked against.
struct outside_gaussian {
  std::size_t dimension() const { return 2; }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double t = x[2 * i] + x[2 * i + 1];
      y[i] = std::exp(-t * t / 2);
    }
  }
  integrand_info info() const {
    integrand_info out;
    out.name = "outside_gaussian";
    out.formula = "exp(−(x₁ + x₂)²/2) on [0,1]²";
    out.domain = box::unit(2);
    out.reference = "no closed form";
    return out;  // exact stays NaN
  }
};

double closed_form() {
  const double sqrt2 = std::numbers::sqrt2;
  return (1 - std::exp(-0.5)) +
         2 * std::sqrt(std::numbers::pi / 2) * (std::erf(sqrt2) - std::erf(1 / sqrt2)) -
         (std::exp(-0.5) - std::exp(-2.0));
}

any_integrand make_outside(const integrand_params&) {
  return any_integrand(outside_gaussian{});
}

const std::array<catalogue_entry, 1> outside{{
    {"outside_gaussian",
     "exp(−(x₁ + x₂)²/2) on [0,1]²",
     "analytic",
     {},
     {},
     "no parameters",
     make_outside,
     nullptr,
     false,
     false,
     2},
}};

// Once per process: a second add_integrands of the same name is refused (tested below).
void add_outside_once() {
  static const bool added = [] {
    add_integrands(outside);
    return true;
  }();
  (void)added;
}

constexpr std::string_view scene_head = R"(name = "outside"
[[integrand]]
family = "outside_gaussian"
)";

plan outside_plan_of(const std::string& text) {
  add_outside_once();
  return make_plan(parse_scene(text, "outside.toml"));
}

TEST(OutsideIntegrand, IsFoundBesideTheBuiltInFamilies) {
  add_outside_once();
  const catalogue_entry* e = find_family("outside_gaussian");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(integrand_catalogue().back().name, "outside_gaussian");
  EXPECT_NE(find_family("genz_gaussian"), nullptr);
  EXPECT_EQ(make_integrand("outside_gaussian", {}).dimension(), 2u);
}

TEST(OutsideIntegrand, ATakenNameOrAnIncompleteEntryIsRefused) {
  add_outside_once();
  EXPECT_THROW(add_integrands(outside), std::logic_error);
  catalogue_entry twin = outside[0];
  twin.name = "genz_gaussian";
  EXPECT_THROW(add_integrands(std::span<const catalogue_entry>(&twin, 1)), std::logic_error);
  catalogue_entry nameless = outside[0];
  nameless.name = "";
  EXPECT_THROW(add_integrands(std::span<const catalogue_entry>(&nameless, 1)), std::logic_error);
  catalogue_entry unmade = outside[0];
  unmade.name = "outside_unmade";
  unmade.make = nullptr;
  EXPECT_THROW(add_integrands(std::span<const catalogue_entry>(&unmade, 1)), std::logic_error);
  EXPECT_EQ(find_family("outside_unmade"), nullptr);
}

TEST(OutsideIntegrand, WithoutAnExactValueTheSceneMustGiveAReference) {
  const std::string text =
      std::string(scene_head) + "[[method]]\nname = \"simpson\"\n[budget]\nN = [64]\n";
  try {
    (void)outside_plan_of(text);
    FAIL() << "a family without an exact value was planned without a reference";
  } catch (const scene_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("outside.toml:2"), std::string::npos) << m;
    EXPECT_NE(m.find("has no exact integral (no closed form)"), std::string::npos) << m;
    EXPECT_NE(m.find("reference = \"computed\""), std::string::npos) << m;
  }
}

TEST(OutsideIntegrand, AComputedReferenceAgreesWithTheClosedFormAndMeasuresTheErrors) {
  const plan p = outside_plan_of(std::string(scene_head) +
                                 "reference = \"computed\"\n[[method]]\nname = \"simpson\"\n"
                                 "[budget]\nN = [64, 1024]\ntiming_min_seconds = 0\n");
  ASSERT_EQ(p.references.size(), 1u);
  const plan_reference& ref = p.references[0];
  EXPECT_EQ(ref.source, reference_source::computed);
  // Within its stated uncertainty (plus the closed form's few roundings), and that is tight.
  EXPECT_LE(std::abs(ref.value - closed_form()), ref.uncertainty + 4e-16) << ref.describe();
  EXPECT_LE(ref.uncertainty, 1e-12 * closed_form());
  EXPECT_EQ(p.reference_of(p.instances[0]), ref.value);
  EXPECT_TRUE(std::any_of(p.notes.begin(), p.notes.end(), [](const std::string& n) {
    return n.find("the family has no exact value (no closed form)") != std::string::npos;
  }));
  EXPECT_NE(format_plan(p).find("no exact value)"), std::string::npos);

  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 1u);
  EXPECT_EQ(out.series[0].reference, ref.value);
  EXPECT_EQ(out.series[0].reference_uncertainty, ref.uncertainty);
}

// tolerance_kind = "relative" asks for tolerance·|I|: with no exact value, I is the reference.
TEST(OutsideIntegrand, ARelativeToleranceIsAFractionOfTheGivenReference) {
  const plan p = outside_plan_of(std::string(scene_head) +
                                 "reference = 0.6036012066722646\nreference_uncertainty = 1e-15\n"
                                 "[[method]]\nname = \"genz_malik\"\ncontrol = \"tolerance\"\n"
                                 "tolerance_kind = \"relative\"\ntolerances = [1e-3, 1e-6]\n"
                                 "[budget]\nN = [100000]\ntiming_min_seconds = 0\n");
  const run_output out = run_plan(p);
  ASSERT_EQ(out.series.size(), 1u);
  ASSERT_EQ(out.series[0].cells.size(), 2u);
  for (const convergence_cell& c : out.series[0].cells) {
    ASSERT_EQ(c.repetitions.size(), 1u);
    EXPECT_EQ(c.repetitions[0].target, c.tolerance * 0.6036012066722646);
  }
}

}  // namespace
}  // namespace quadmc
