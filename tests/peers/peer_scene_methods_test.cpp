// Tests of the peers as scene methods (bench/peers/peer_scene_methods.cpp): each adapter counts
// exactly the integrand calls its library makes, honours its control (budget, the library's own
// tolerance), reports its own error estimate, turns a non-finite value into the suite's error, and
// a seed gives the same result again. Built only where GSL and cubature are installed.
#include "peer_scene_methods.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadmc {
namespace {

// A catalogue integrand that counts the points it is asked for (the peers call it from one
// thread; atomic so that the count cannot be wrong if one ever did not).
struct counting_integrand {
  any_integrand inner;
  std::shared_ptr<std::atomic<std::uint64_t>> points =
      std::make_shared<std::atomic<std::uint64_t>>(0);

  std::size_t dimension() const noexcept { return inner.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    points->fetch_add(y.size());
    inner.evaluate(x, y);
  }
  integrand_info info() const { return inner.info(); }
};

// NaN on the right half of x₁, for the error path.
struct nan_on_right_half {
  integrand_info meta;
  explicit nan_on_right_half(std::size_t s) {
    meta.name = "nan_on_right_half";
    meta.domain = box::unit(s);
    meta.exact = 0.0;
  }
  std::size_t dimension() const noexcept { return meta.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = dimension();
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[i * s] > 0.5 ? std::nan("") : 1.0;
  }
  integrand_info info() const { return meta; }
};

integrand_params gaussian_params(std::size_t s) {
  integrand_params p;
  p.dimension = s;
  p.vectors["a"] = std::vector<double>(s, 3.0);
  p.vectors["u"] = std::vector<double>(s, 0.4);
  return p;
}

// Every peer the library knows (registry.hpp's peers::known, whose names registry_test.cpp
// guards) is registered here under its name, in its order.
TEST(PeerSceneMethods, AreRegisteredUnderTheirNames) {
  std::vector<std::string_view> registered;
  for (const method_descriptor& d : peers::peer_scene_methods()) {
    registered.push_back(d.name);
    EXPECT_EQ(find_method(d.name), &d) << d.name;
    EXPECT_FALSE(unavailable_method(d.name).has_value()) << d.name;
  }
  std::vector<std::string_view> known;
  for (const known_peer& p : peers::known) known.push_back(p.name);
  EXPECT_EQ(registered, known);
}

struct peer_case {
  const char* name;
  std::size_t s;
  cell_control control;
  double tolerance;
  std::uint64_t budget;
};

TEST(PeerSceneMethods, CountedEvaluationsAreTheIntegrandCalls) {
  const peer_case cases[] = {
      {"peer_hcubature", 3, cell_control::budget, NAN, 5000},
      {"peer_hcubature", 1, cell_control::budget, NAN, 500},
      {"peer_hcubature", 3, cell_control::tolerance, 1e-6, 1u << 20},
      {"peer_pcubature", 3, cell_control::budget, NAN, 5000},
      {"peer_pcubature", 2, cell_control::tolerance, 1e-8, 1u << 20},
      {"peer_gsl_plain", 2, cell_control::budget, NAN, 3000},
      {"peer_gsl_miser", 4, cell_control::budget, NAN, 30000},
      {"peer_gsl_vegas", 4, cell_control::budget, NAN, 30000},
      {"peer_boost_tanh_sinh", 1, cell_control::tolerance, 1e-10, 1u << 20},
      {"peer_boost_gauss_kronrod", 1, cell_control::tolerance, 1e-10, 1u << 20},
  };
  for (const peer_case& c : cases) {
    SCOPED_TRACE(std::string(c.name) + " s = " + std::to_string(c.s));
    const integrand_params params = gaussian_params(c.s);
    const counting_integrand counting{make_integrand("genz_gaussian", params)};
    const any_integrand f(counting);
    const auto m = make_method(c.name);
    const cell_size size = *m->size_for(c.budget, c.s).size;
    const repetition_result r = m->run({f, params, size, c.control, c.tolerance, 3}, {11, 1});
    EXPECT_EQ(r.evaluations, counting.points->load());
    EXPECT_GT(r.evaluations, 0u);
    EXPECT_TRUE(std::isfinite(r.error_estimate)) << "each peer reports its own error estimate";
    if (c.control == cell_control::tolerance) {
      // The library's own stopping test: its error estimate is at the tolerance (Boost's is
      // relative to ∫|f|, passed as tolerance / ∫|f|, so within rounding of it).
      EXPECT_LE(r.error_estimate, c.tolerance * (1.0 + 1e-9)) << r.error_estimate;
    }
  }
}

TEST(PeerSceneMethods, ATighterToleranceSpendsMore) {
  const integrand_params params = gaussian_params(3);
  const any_integrand f = make_integrand("genz_gaussian", params);
  for (const char* name : {"peer_hcubature", "peer_pcubature"}) {
    const auto m = make_method(name);
    const cell_size cap = *m->size_for(1u << 22, 3).size;
    const repetition_result loose = m->run({f, params, cap, cell_control::tolerance, 1e-3, 0}, {});
    const repetition_result tight = m->run({f, params, cap, cell_control::tolerance, 1e-9, 0}, {});
    EXPECT_LT(loose.evaluations, tight.evaluations) << name;
    EXPECT_LE(std::abs(tight.value - f.info().exact), 1e-8) << name;
  }
}

TEST(PeerSceneMethods, SizesBelowTheFirstRoundAreSkipsWithAReason) {
  // One Genz–Malik region in s = 3: 2^3 + 2·9 + 2·3 + 1 = 33; pcubature's first grid 3^3 = 27.
  EXPECT_FALSE(make_method("peer_hcubature")->size_for(32, 3).size);
  EXPECT_NE(make_method("peer_hcubature")->size_for(32, 3).reason.find("33"), std::string::npos);
  EXPECT_TRUE(make_method("peer_hcubature")->size_for(33, 3).size);
  EXPECT_FALSE(make_method("peer_pcubature")->size_for(26, 3).size);
  EXPECT_TRUE(make_method("peer_boost_tanh_sinh")->incompatibility({"genz_gaussian", 2, false}));
  EXPECT_FALSE(make_method("peer_boost_tanh_sinh")->incompatibility({"exp", 1, false}));
}

TEST(PeerSceneMethods, ANonFiniteValueIsTheSuitesErrorNamingThePoint) {
  for (const known_peer& peer : peers::known) {
    const std::string name(peer.name);
    // scipy's qmc_quad evaluates the catalogue's instance in its own process, never this test's
    // integrand (ScipyQmcQuadRunsTheSameInstanceInPython).
    if (name == peers::scipy_qmc_quad.name) continue;
    SCOPED_TRACE(name);
    const auto m = make_method(name);
    const bool one_d = std::string(name).find("boost") != std::string::npos;
    const std::size_t s = one_d ? 1 : 2;
    const any_integrand f{nan_on_right_half(s)};
    const integrand_params params;
    const cell_size size = *m->size_for(4000, s).size;
    const cell_control control = one_d ? cell_control::tolerance : m->descriptor().controls.front();
    try {
      m->run({f, params, size, control, 1e-6, 0}, {1, 1});
      ADD_FAILURE() << "no error";
    } catch (const non_finite_value& e) {
      EXPECT_NE(std::string(e.what()).find("nan_on_right_half"), std::string::npos) << e.what();
    }
  }
}

TEST(PeerSceneMethods, ASeedAndStreamGiveTheSameResultAgain) {
  const integrand_params params = gaussian_params(3);
  const any_integrand f = make_integrand("genz_gaussian", params);
  for (const char* name : {"peer_gsl_plain", "peer_gsl_miser", "peer_gsl_vegas"}) {
    const auto m = make_method(name);
    const cell_size size = *m->size_for(4000, 3).size;
    const repetition_result a = m->run({f, params, size, cell_control::budget, NAN, 5}, {9, 1});
    const repetition_result b = m->run({f, params, size, cell_control::budget, NAN, 5}, {9, 2});
    const repetition_result other = m->run({f, params, size, cell_control::budget, NAN, 6}, {9, 1});
    EXPECT_EQ(a.value, b.value) << name << ": threads must not matter";
    EXPECT_EQ(a.std_error, b.std_error) << name;
    EXPECT_NE(a.value, other.value) << name << ": another stream is another sample";
  }
}

// scipy's qmc_quad in its Python process: N = 8·2^m, the instance rebuilt there from the cell's
// parameters (a different one is refused), the integral within its standard error's reach, and the
// same result for a seed and stream on any thread count.
TEST(PeerSceneMethods, ScipyQmcQuadRunsTheSameInstanceInPython) {
  const auto m = make_method("peer_scipy_qmc_quad");
  EXPECT_EQ(m->size_for(100000, 3).size->evaluations, 8u * 8192u);
  EXPECT_FALSE(m->size_for(15, 3).size);
  EXPECT_EQ(*m->theory({smoothness::analytic, 3}).slope, -1.5);
  const integrand_params params = gaussian_params(3);
  const any_integrand f = make_integrand("genz_gaussian", params);
  const cell_size size = *m->size_for(8192, 3).size;
  const repetition_result a = m->run({f, params, size, cell_control::fixed_size, NAN, 3}, {11, 1});
  // 8·1024 points, and the three qmc_quad evaluates to check the integrand (its centroid and its
  // two corners), counted where they happen.
  EXPECT_EQ(a.evaluations, 8192u + 3u);
  EXPECT_GT(a.std_error, 0.0);
  EXPECT_EQ(a.error_estimate, a.std_error);
  // The mean of 8 independent estimates over its standard error is Student's t with 7 degrees of
  // freedom: beyond 8 with probability 9e-5 (the false alarm).
  EXPECT_LE(std::abs(a.value - f.info().exact), 8.0 * a.std_error)
      << a.value << " ± " << a.std_error << " against " << f.info().exact;
  const repetition_result b = m->run({f, params, size, cell_control::fixed_size, NAN, 3}, {11, 3});
  EXPECT_EQ(a.value, b.value) << "threads must not matter";
  const repetition_result other =
      m->run({f, params, size, cell_control::fixed_size, NAN, 4}, {11, 1});
  EXPECT_NE(a.value, other.value) << "another stream is another sample";
  // Parameters that build another instance than the cell's are caught by its exact value.
  integrand_params moved = params;
  moved.vectors["u"][0] = 0.7;  // not 0.6: u and 1 − u give the Gaussian the same integral
  try {
    m->run({f, moved, size, cell_control::fixed_size, NAN, 3}, {11, 1});
    ADD_FAILURE() << "another instance was not noticed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("built another genz_gaussian"), std::string::npos)
        << e.what();
  }
}

// The bundled scene that names the peers plans with them, with cells for every peer it names.
TEST(PeerSceneMethods, TheTimeToErrorScenePlansWithThePeers) {
  const plan p = make_plan(parse_scene_file(QUADMC_SOURCE_DIR "/bench/scenes/time_to_error.toml"));
  std::vector<std::string> with_cells;
  for (const plan_cell& c : p.cells) {
    const std::string& name = p.source.methods[c.method].name;
    if (name.rfind("peer_", 0) == 0 &&
        std::find(with_cells.begin(), with_cells.end(), name) == with_cells.end()) {
      with_cells.push_back(name);
    }
  }
  std::sort(with_cells.begin(), with_cells.end());
  EXPECT_EQ(with_cells,
            (std::vector<std::string>{"peer_gsl_miser", "peer_gsl_plain", "peer_gsl_vegas",
                                      "peer_hcubature", "peer_pcubature"}));
}

}  // namespace
}  // namespace quadmc
