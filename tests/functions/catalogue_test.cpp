// The catalogue: every member builds from default parameters, batch evaluation (the vector path)
// agrees with point-by-point evaluation (the scalar path) to a stated ulp bound at every SIMD
// level of this CPU, and bad names/keys/values are named in the error.
#include "quadmc/functions/catalogue.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/core/ulp_distance.hpp"
#include "quadmc/functions/genz.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace quadmc {
namespace {

integrand_params params_for(const catalogue_entry& e) {
  integrand_params p;
  // Variable-dimension families get s = 3 (the default 0 means 1, or 2 for irradiance).
  const std::string_view n = e.name;
  if (n.starts_with("genz_") || n == "disk_indicator" || n == "half_space" || n == "sobol_g" ||
      n == "keister" || n == "geometric_asian") {
    p.dimension = 3;
  }
  p.seed = 5;
  return p;
}

// The bound between the two paths: glibc documents libmvec's vector exp/cos to within 4 ulp of
// the exact value (glibc 2.22 NEWS, "maximum 4 ulp error") and its scalar exp/cos to within
// 1 ulp, so the two differ by at most 5 ulp; the arithmetic around them is the same code in the
// same order, so the integrand inherits that bound. Measured on this suite's points: ≤ 4
// (tests/core/vector_math_test.cpp). At the scalar level both paths are the same code: 0.
constexpr std::uint64_t vector_vs_scalar_ulp = 5;

TEST(Catalogue, EveryMemberBatchAgreesWithPointByPointAtEverySimdLevel) {
  const simd_level saved = active_simd_level();
  for (simd_level level : available_simd_levels()) {
    set_simd_level(level);
    const std::uint64_t bound = level == simd_level::scalar ? 0 : vector_vs_scalar_ulp;
    for (const catalogue_entry& e : integrand_catalogue()) {
      for (double occluder : {0.0, 1.0}) {
        integrand_params p = params_for(e);
        if (std::string_view(e.name).starts_with("irradiance")) {
          p.scalars["occluder"] = occluder;
        } else if (occluder == 1.0) {
          continue;
        }
        const any_integrand f = make_integrand(e.name, p);
        const integrand_info& info = f.info();
        EXPECT_EQ(info.name, e.name);
        EXPECT_TRUE(std::isfinite(info.exact)) << e.name;
        EXPECT_TRUE(std::string_view(e.smoothness).starts_with(to_string(info.regularity)) ||
                    occluder == 1.0)
            << e.name << ": catalogue says " << e.smoothness << ", info says "
            << to_string(info.regularity);
        const std::size_t s = f.dimension();
        const std::size_t n = 300;  // a full vector body and a padded tail at every level
        std::vector<double> x(n * s), y(n), y1(n);
        const random_stream rng(11, 0);
        rng.fill_uniform(0, x);
        for (std::size_t i = 0; i < n; ++i) {
          for (std::size_t j = 0; j < s; ++j) {
            const double lo = info.domain.lower[j], hi = info.domain.upper[j];
            x[i * s + j] = lo + (hi - lo) * x[i * s + j];
          }
        }
        f.evaluate(x, y);
        for (std::size_t i = 0; i < n; ++i) {
          f.evaluate(std::span<const double>(x).subspan(i * s, s),
                     std::span<double>(y1).subspan(i, 1));
        }
        for (std::size_t i = 0; i < n; ++i) {
          EXPECT_LE(ulp_distance(y[i], y1[i]), bound)
              << e.name << " at level " << to_string(level) << ", point " << i << ": batch " << y[i]
              << ", alone " << y1[i];
          EXPECT_TRUE(std::isfinite(y[i])) << e.name << " point " << i;
        }
        check_finite_batch(info.name, x, y, s);
        // A value must not depend on where in a batch it falls: the same points, shifted by
        // one, give the same bits (the vector path pads its tail instead of going scalar).
        std::vector<double> y_shifted(n - 1);
        f.evaluate(std::span<const double>(x).subspan(s), y_shifted);
        for (std::size_t i = 1; i < n; ++i) {
          EXPECT_EQ(y_shifted[i - 1], y[i]) << e.name << " at level " << to_string(level);
        }
      }
    }
  }
  set_simd_level(saved);
}

TEST(Catalogue, KeysAreDocumentedAndNamesUnique) {
  std::set<std::string_view> names;
  for (const catalogue_entry& e : integrand_catalogue()) {
    EXPECT_TRUE(names.insert(e.name).second) << e.name;
    for (std::string_view key : e.vector_keys)
      EXPECT_NE(e.parameters.find(key), std::string_view::npos) << e.name << " " << key;
    for (std::string_view key : e.scalar_keys)
      EXPECT_NE(e.parameters.find(key), std::string_view::npos) << e.name << " " << key;
    for (const string_key& key : e.string_keys) {
      EXPECT_NE(e.parameters.find(key.key), std::string_view::npos) << e.name << " " << key.key;
      EXPECT_FALSE(key.choices.empty()) << e.name << " " << key.key;
    }
  }
  EXPECT_EQ(names.size(), 31u);
}

// The planner draws an instance from (seed, family, s, k) before building it, so it needs the
// s that dimension = 0 will build: resolved_dimension must be what every factory resolves.
TEST(Catalogue, ResolvedDimensionIsWhatEveryFactoryBuilds) {
  for (const catalogue_entry& e : integrand_catalogue()) {
    const any_integrand f = make_integrand(e.name, integrand_params{});
    EXPECT_EQ(resolved_dimension(e, 0), f.dimension()) << e.name;
    EXPECT_EQ(resolved_dimension(e, 5), 5u) << e.name;
  }
}

std::string message_of(std::string_view name, const integrand_params& p) {
  try {
    make_integrand(name, p);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "no exception";
}

TEST(Catalogue, BadNamesKeysAndValuesAreNamed) {
  integrand_params p;
  EXPECT_NE(message_of("genz_wavy", p).find("invalid integrand = genz_wavy"), std::string::npos);
  p.scalars["radius"] = 0.3;
  EXPECT_NE(message_of("disk_indicator", p)
                .find("invalid radius: unknown key: not a parameter of disk_indicator (its "
                      "parameters: arrays: center; numbers: r)"),
            std::string::npos);
  p = {};
  p.scalars["a"] = 1.0;  // a is a vector for Genz
  EXPECT_NE(message_of("genz_gaussian", p)
                .find("invalid a: expected an array of numbers for genz_gaussian, got 1"),
            std::string::npos);
  p = {};
  p.vectors["r"] = {0.3};  // r is a number for the ball
  EXPECT_NE(message_of("disk_indicator", p)
                .find("invalid r: expected a number for disk_indicator, got an array"),
            std::string::npos);
  p = {};
  p.dimension = 3;
  p.vectors["a"] = {1.0, 2.0};
  EXPECT_NE(message_of("genz_gaussian", p).find("invalid a = [1, 2]"), std::string::npos);
  p.vectors["a"] = {1.0, 2.0, 3.0};
  p.vectors["u"] = {0.5, 1.5, 0.5};
  EXPECT_NE(message_of("genz_gaussian", p).find("invalid u = 1.5"), std::string::npos);
  p = {};
  p.dimension = 2;
  EXPECT_NE(message_of("sqrt", p).find("invalid dimension = 2"), std::string::npos);
  p.dimension = 1;
  EXPECT_NE(message_of("irradiance_area", p).find("invalid dimension = 1"), std::string::npos);
  p = {};
  p.scalars["occluder"] = 0.5;
  EXPECT_NE(message_of("irradiance_hemisphere", p).find("invalid occluder = 0.5"),
            std::string::npos);
  p.scalars["occluder"] = 1.0;
  p.scalars["radiance"] = -2.0;
  EXPECT_NE(message_of("irradiance_hemisphere", p).find("invalid radiance = -2"),
            std::string::npos);
  p = {};
  p.dimension = 2;
  p.vectors["cut"] = {1.5};
  EXPECT_NE(message_of("genz_discontinuous", p).find("invalid cut = 1.5"), std::string::npos);
  p.vectors["cut"] = {3};
  EXPECT_NE(message_of("genz_discontinuous", p).find("invalid cut = 3"), std::string::npos);
  p = {};
  p.scalars["r"] = -0.1;
  EXPECT_NE(message_of("disk_indicator", p).find("invalid r = -0.1"), std::string::npos);
}

TEST(Catalogue, GenzParametersFromSeedOrGiven) {
  integrand_params p;
  p.dimension = 4;
  p.seed = 9;
  const auto drawn = genz_random_parameters(genz_family::oscillatory, 4, 9);
  const any_integrand f = make_integrand("genz_oscillatory", p);
  EXPECT_EQ(f.info().exact, genz_oscillatory(drawn.a, drawn.u).info().exact);
  // Given a, drawn u.
  p.vectors["a"] = {1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(make_integrand("genz_oscillatory", p).info().exact,
            genz_oscillatory({1.0, 2.0, 3.0, 4.0}, drawn.u).info().exact);
  // Every-coordinate cut.
  integrand_params q;
  q.dimension = 3;
  q.vectors["cut"] = {1, 2, 3};
  const auto d = genz_random_parameters(genz_family::discontinuous, 3, 0);
  EXPECT_EQ(make_integrand("genz_discontinuous", q).info().exact,
            genz_discontinuous(d.a, d.u, {1, 2, 3}).info().exact);
}

// coefficient_decay, the one string key: it shapes the drawn a (genz_random_parameters), is
// checked in find_key_problem with the other keys, and is refused beside an explicit a.
TEST(Catalogue, GenzCoefficientDecayShapesTheDrawnAAndIsChecked) {
  integrand_params p;
  p.dimension = 5;
  p.seed = 9;
  for (const genz_decay d : {genz_decay::none, genz_decay::quadratic, genz_decay::exponential}) {
    p.strings["coefficient_decay"] = std::string(to_string(d));
    const auto drawn = genz_random_parameters(genz_family::gaussian, 5, 9, d);
    EXPECT_EQ(make_integrand("genz_gaussian", p).info().exact,
              genz_gaussian(drawn.a, drawn.u).info().exact)
        << to_string(d);
    const drawn_parameters shown = find_catalogue_entry("genz_gaussian").drawn(p);
    EXPECT_EQ(shown.at("a"), drawn.a) << to_string(d);
    EXPECT_EQ(shown.at("u"), drawn.u) << to_string(d);
  }
  p.strings["coefficient_decay"] = "cubic";
  EXPECT_NE(message_of("genz_gaussian", p)
                .find("invalid coefficient_decay: expected one of \"none\", \"quadratic\", "
                      "\"exponential\", got \"cubic\""),
            std::string::npos)
      << message_of("genz_gaussian", p);
  p.strings["coefficient_decay"] = "quadratic";
  p.vectors["a"] = {1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_NE(message_of("genz_gaussian", p)
                .find("invalid coefficient_decay = \"quadratic\": expected no explicit a"),
            std::string::npos)
      << message_of("genz_gaussian", p);
  p = {};
  p.scalars["coefficient_decay"] = 2.0;
  EXPECT_NE(message_of("genz_product_peak", p)
                .find("invalid coefficient_decay: expected a string, one of \"none\", "
                      "\"quadratic\", \"exponential\", for genz_product_peak, got 2"),
            std::string::npos)
      << message_of("genz_product_peak", p);
  p = {};
  p.strings["a"] = "quadratic";
  EXPECT_NE(message_of("genz_product_peak", p)
                .find("invalid a: expected an array of numbers for genz_product_peak, got "
                      "\"quadratic\""),
            std::string::npos)
      << message_of("genz_product_peak", p);
  p = {};
  p.strings["coefficient_decay"] = "none";
  EXPECT_NE(message_of("sqrt", p).find("invalid coefficient_decay: unknown key: not a parameter "
                                       "of sqrt"),
            std::string::npos)
      << message_of("sqrt", p);
}

}  // namespace
}  // namespace quadmc
