// Tests of point_set_catalogue.hpp: every set's estimators by name, bitwise the same for any
// thread count at every SIMD level, the count rules, each set's own keys, theory and strata, and
// importance sampling over a set.
#include "quadmc/estimators/point_set_catalogue.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/simd_level.hpp"
#include "quadmc/core/welford.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/functions/geometric_asian.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "test_integrands.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <set>
#include <string>
#include <vector>

namespace quadmc {
namespace {

const any_integrand gaussian(test_support::make_integrand(
    "e^-(x²+y²) on [0,1]²", box::unit(2), 0.25 * std::numbers::pi * std::pow(std::erf(1.0), 2),
    [](std::span<const double> x) { return std::exp(-(x[0] * x[0] + x[1] * x[1])); }));

bool bitwise_equal(const estimate& a, const estimate& b) {
  return std::memcmp(&a.value, &b.value, sizeof(double)) == 0 &&
         (std::memcmp(&a.std_error, &b.std_error, sizeof(double)) == 0 ||
          (std::isnan(a.std_error) && std::isnan(b.std_error))) &&
         a.evaluations == b.evaluations;
}

// N = 40 000 = 200² (4 chunks), or 2^15 = 32 768 (3 chunks) for the sets that need N = 2^m: 1, 2,
// 3 and 8 threads agree bitwise, under either generator, at every SIMD level of this CPU (the level
// changes the last bits of exp/cos, never the dependence on the thread count), and for every
// randomization of a quasi-Monte Carlo set. The value lies within 6 standard errors of the integral
// (a false alarm of 2e-9 per check under the CLT; for the sets whose error one run cannot estimate,
// a bound: 1e-3 for a 2^15-point QMC set, whose error on these smooth f is far less, O((log N)²/N)
// = O(3e-3)·V_HK with V_HK ≤ 1 here; and for the unjittered 200² grid shifted by Δ modulo 1, whose
// points are (i + u_j)h on each axis, Euler–Maclaurin's first term h·(½ − u_j)·∫(f|x_j=1 − f|x_j=0)
// per axis: |error| ≤ s·h/2 = 5e-3 for these f with values in [0, 1], plus O(h²) ≈ 2.5e-5, so
// 5.1e-3. A shift is not the midpoint rule: the grid wraps, and the O(h²) of the centres holds only
// for a periodic f.)
TEST(PointSetCatalogue, EverySetIsBitwiseIdenticalForAnyThreadCount) {
  const simd_level saved = active_simd_level();
  for (simd_level level : available_simd_levels()) {
    set_simd_level(level);
    integrand_params p;
    p.dimension = 2;
    const any_integrand genz = make_integrand("genz_gaussian", p);
    for (const any_integrand* f : {&gaussian, &genz}) {
      for (const point_set_entry& set : point_set_catalogue()) {
        const std::uint64_t n = largest_point_count(set.counts, 40000, 2).points;
        std::vector<point_set_options> configurations{point_set_options{}};
        for (const randomization r : set.randomizations) {
          configurations.push_back(point_set_options{r});
        }
        for (const point_set_options& o : configurations) {
          // Under either generator (core/rng.hpp): the same counter layout.
          for (const rng_kind g : {rng_kind::philox4x32_10, rng_kind::ars4x32_7}) {
            const std::string what =
                fmt::format("{} {}, {}, {}", set.name,
                            o.random ? to_string(*o.random) : std::string_view("default"),
                            f->info().name, to_string(g));
            const estimate one = set.monte_carlo(*f, {42, 7, g}, n, 1, o);
            const double bound = !std::isnan(one.std_error) ? 6 * one.std_error
                                 : set.name == "unjittered" ? 2 * 0.5 / 200 + 2.5e-5
                                                            : 1e-3;
            EXPECT_NEAR(one.value, f->info().exact, bound) << what;
            for (unsigned t : {2u, 3u, 8u}) {
              EXPECT_TRUE(bitwise_equal(one, set.monte_carlo(*f, {42, 7, g}, n, t, o)))
                  << what << ", " << t << " threads, level " << to_string(level);
            }
          }
        }
      }
    }
  }
  set_simd_level(saved);
  const irradiance_setup setup = default_irradiance_setup(true);
  const point_set_entry& jittered = *find_point_set("jittered");
  for (auto technique : {irradiance_sampling::uniform_hemisphere,
                         irradiance_sampling::cosine_hemisphere, irradiance_sampling::light_area}) {
    const estimate one = jittered.irradiance(technique, setup, {1, 2}, 40000, 1);
    for (unsigned t : {2u, 3u, 8u}) {
      EXPECT_TRUE(bitwise_equal(one, jittered.irradiance(technique, setup, {1, 2}, 40000, t)));
    }
  }
}

TEST(PointSetCatalogue, NamesAreUniqueAndFound) {
  for (const point_set_entry& set : point_set_catalogue()) {
    EXPECT_EQ(find_point_set(set.name), &set);
    EXPECT_FALSE(set.description.empty()) << set.name;
    EXPECT_NE(point_set_names().find(set.name), std::string::npos);
  }
  EXPECT_EQ(find_point_set("owen"), nullptr) << "owen is a randomization of sobol and halton";
  EXPECT_EQ(find_point_set("plain"), nullptr) << "plain_mc is a method; its set is independent";
}

TEST(PointSetCatalogue, AcceptsSizeFollowsTheStratificationPolicy) {
  const point_set_entry& jittered = *find_point_set("jittered");
  EXPECT_TRUE(accepts_size(jittered, 2, 400));
  EXPECT_FALSE(accepts_size(jittered, 2, 401));
  EXPECT_FALSE(accepts_size(*find_point_set("unjittered"), 3, 100));
  EXPECT_TRUE(accepts_size(*find_point_set("latin_hypercube"), 3, 101));
  EXPECT_FALSE(accepts_size(*find_point_set("independent"), 0, 10));
  EXPECT_FALSE(accepts_size(*find_point_set("independent"), 2, 0));
  EXPECT_THROW(jittered.monte_carlo(gaussian, {1, 1}, 401, 1), invalid_argument);
  EXPECT_THROW(find_point_set("independent")->monte_carlo(gaussian, {1, 1}, 0, 1),
               invalid_argument);
}

// The planner maps N to the largest k² for padded_jittered (largest_point_count); the set itself
// holds exactly those counts, so `quadmc points` and the methods agree on which N exist.
TEST(PointSetCatalogue, PaddedJitteredHoldsSquaresInTwoOrMoreDimensions) {
  const point_set_entry& padded = *find_point_set("padded_jittered");
  EXPECT_TRUE(accepts_size(padded, 2, 100));
  EXPECT_TRUE(accepts_size(padded, 5, 961));
  EXPECT_TRUE(accepts_size(padded, 1, 96));
  EXPECT_FALSE(accepts_size(padded, 2, 96));
  EXPECT_FALSE(accepts_size(padded, 3, 13));
  EXPECT_NE(size_problem(padded, 2, 96).find("nearest valid sizes 81 and 100"), std::string::npos)
      << size_problem(padded, 2, 96);
}

// cmj holds the near squares k² and k(k + 1) in s ≥ 2 (largest_point_count maps N to the larger
// below it) and names the nearest otherwise; padded_sobol has no unrandomized form.
TEST(PointSetCatalogue, CmjHoldsNearSquaresAndPaddedSobolIsAlwaysRandomized) {
  const point_set_entry& cmj = *find_point_set("cmj");
  EXPECT_TRUE(accepts_size(cmj, 2, 100));
  EXPECT_TRUE(accepts_size(cmj, 4, 110));
  EXPECT_TRUE(accepts_size(cmj, 1, 101));
  EXPECT_FALSE(accepts_size(cmj, 3, 105));
  EXPECT_NE(size_problem(cmj, 2, 105).find("nearest valid sizes 100 and 110"), std::string::npos)
      << size_problem(cmj, 2, 105);
  EXPECT_EQ(largest_point_count(point_count::near_square, 119, 2).points, 110u);
  EXPECT_EQ(largest_point_count(point_count::near_square, 109, 2).points, 100u);
  EXPECT_EQ(largest_point_count(point_count::near_square, 109, 1).points, 109u);
  const point_set_entry& padded = *find_point_set("padded_sobol");
  EXPECT_FALSE(padded.has(randomization::none));
  point_set_options none;
  none.random = randomization::none;
  try {
    (void)padded.monte_carlo(gaussian, {1, 1}, 64, 1, none);
    ADD_FAILURE() << "padded_sobol ran unrandomized";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("one of owen, fast_owen, lms_shift, shift for the "
                                         "padded_sobol points"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(accepts_size(padded, 2, 96)) << "a net needs N = 2^m";
}

// The dimension check alone (quadmc points blames --s with it), and size_problem begins with it.
TEST(PointSetCatalogue, DimensionProblemNamesTheSetsLastDimension) {
  const point_set_entry& sobol = *find_point_set("sobol");
  ASSERT_NE(sobol.max_dimension, 0u);
  EXPECT_EQ(dimension_problem(sobol, sobol.max_dimension), "");
  const std::string beyond = dimension_problem(sobol, sobol.max_dimension + 1);
  EXPECT_NE(beyond.find(fmt::format("s ≤ {} for the sobol points", sobol.max_dimension)),
            std::string::npos)
      << beyond;
  EXPECT_EQ(size_problem(sobol, sobol.max_dimension + 1, 8), beyond);
  EXPECT_EQ(dimension_problem(*find_point_set("independent"), 100000), "");
}

TEST(PointSetCatalogue, LargestCountIsAPerfectPowerOrSquare) {
  EXPECT_EQ(largest_point_count(point_count::perfect_power, 4096, 3).per_axis, 16u);
  EXPECT_EQ(largest_point_count(point_count::perfect_power, 4095, 3).points, 3375u);
  EXPECT_EQ(largest_point_count(point_count::perfect_power, 255, 8).points, 1u);
  EXPECT_EQ(largest_point_count(point_count::perfect_square, 1000, 5).points, 961u);
  EXPECT_EQ(largest_point_count(point_count::perfect_square, 1000, 1).points, 1000u);
  EXPECT_EQ(largest_point_count(point_count::any, 1000, 7).points, 1000u);
  EXPECT_EQ(largest_point_count(point_count::any, 1000, 7).per_axis, 0u);
  for (const point_set_entry& set : point_set_catalogue()) {
    for (std::size_t s : {1u, 2u, 3u}) {
      for (std::uint64_t N : {1u, 17u, 400u, 1000u}) {
        EXPECT_TRUE(accepts_size(set, s, largest_point_count(set.counts, N, s).points))
            << set.name << " s = " << s << " N = " << N;
      }
    }
  }
}

// Each set's keys: unique, documented, a choice's default first; the `randomization` key offers
// exactly the set's randomizations; the values given configure the options the estimators take.
TEST(PointSetCatalogue, EachSetReadsItsOwnKeys) {
  for (const point_set_entry& set : point_set_catalogue()) {
    std::vector<std::string_view> keys;
    for (const point_set_option& o : set.options) {
      EXPECT_EQ(std::count(keys.begin(), keys.end(), o.key), 0) << set.name << "." << o.key;
      keys.push_back(o.key);
      EXPECT_FALSE(o.meaning.empty()) << set.name << "." << o.key;
      EXPECT_EQ(o.is_flag(), !o.flag_label.empty()) << set.name << "." << o.key;
      EXPECT_EQ(set.option(o.key), &o);
    }
    const point_set_option* r = set.option("randomization");
    ASSERT_EQ(r != nullptr, !set.randomizations.empty()) << set.name;
    if (r == nullptr) continue;
    ASSERT_EQ(r->choices.size(), set.randomizations.size()) << set.name;
    for (std::size_t i = 0; i < r->choices.size(); ++i) {
      EXPECT_EQ(r->choices[i], to_string(set.randomizations[i])) << set.name;
      std::vector<std::string_view> values(set.options.size());
      values[static_cast<std::size_t>(r - set.options.data())] = r->choices[i];
      EXPECT_EQ(set.options_of(values).random, set.randomizations[i]) << set.name;
    }
  }
  const point_set_entry& sobol = *find_point_set("sobol");
  const std::vector<std::string_view> none{"", "", "", ""};
  EXPECT_EQ(sobol.options_of(none).random, std::nullopt);
  EXPECT_EQ(sobol.options_of(none).interlacing, 1u);
  const std::vector<std::string_view> flags{"shift", "true", "true", ""};
  const point_set_options o = sobol.options_of(flags);
  EXPECT_EQ(o.random, randomization::shift);
  EXPECT_TRUE(o.allow_any_n);
  EXPECT_TRUE(o.drop_first_point);
  EXPECT_EQ(max_point_count(sobol, o), (std::uint64_t{1} << 32) - 1);
  const std::vector<std::string_view> baker{"", "baker"};
  EXPECT_EQ(find_point_set("lattice")->options_of(baker).periodic, periodization::baker);
  // Every periodization by its name, which to_string gives back.
  const point_set_option& periodic = *find_point_set("lattice")->option("periodization");
  ASSERT_EQ(periodic.choices.size(), 7u);
  for (const std::string_view name : periodic.choices) {
    const std::vector<std::string_view> values{"", name};
    EXPECT_EQ(to_string(find_point_set("lattice")->options_of(values).periodic), name);
  }
  EXPECT_EQ(find_point_set("jittered")->option("randomization"), nullptr);
}

// Sobol's integer key `interlacing` as `quadmc points` and the Python module give it (text
// checked against its choices), and the randomizations and dimensions it refuses.
TEST(PointSetCatalogue, SobolInterlacingIsCheckedByItsChoices) {
  const point_set_entry& sobol = *find_point_set("sobol");
  const point_set_option* key = sobol.option("interlacing");
  ASSERT_NE(key, nullptr);
  EXPECT_TRUE(key->integer);
  EXPECT_EQ(key->choices.front(), "1") << "the default first";
  auto parameter = [](std::string_view k) { return std::string(k); };
  for (const std::string_view alpha : {"1", "2", "3"}) {
    const std::vector<named_option> given{{"interlacing", alpha}};
    EXPECT_EQ(checked_options(sobol, given, parameter).interlacing,
              static_cast<unsigned>(alpha[0] - '0'));
  }
  for (const std::string_view bad : {"0", "4", "two"}) {
    const std::vector<named_option> given{{"interlacing", bad}};
    try {
      (void)checked_options(sobol, given, parameter);
      ADD_FAILURE() << "interlacing = " << bad << " accepted";
    } catch (const invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("one of 1, 2, 3"), std::string::npos) << e.what();
    }
  }
  const std::vector<named_option> fast{{"interlacing", "2"}, {"randomization", "fast_owen"}};
  EXPECT_THROW((void)checked_options(sobol, fast, parameter), invalid_argument);
  point_set_options o;
  o.interlacing = 2;
  o.random = randomization::lms_shift;
  EXPECT_NE(interlacing_problem(sobol, o).find("owen, shift or none"), std::string::npos);
  EXPECT_THROW((void)sobol.monte_carlo(gaussian, {1, 1}, 64, 1, o), invalid_argument);
  o.random = std::nullopt;
  EXPECT_EQ(interlacing_problem(sobol, o), "");
  // α·s ≤ 3667: s = 1833 with α = 2 fits, 1834 does not, and the message names s, α and the
  // limit (size_problem begins with it).
  EXPECT_EQ(dimension_problem(sobol, 1833, o), "");
  const std::string beyond = dimension_problem(sobol, 1834, o);
  for (const std::string_view part : {"α·s ≤ 3667", "α = 2", "s = 1834"}) {
    EXPECT_NE(beyond.find(part), std::string::npos) << beyond;
  }
  EXPECT_EQ(size_problem(sobol, 1834, 8, o), beyond);
  // The threaded sample mean of the catalogue: 1 and 3 threads agree bitwise (N = 2^15, 3 chunks).
  for (const randomization r : {randomization::owen, randomization::shift, randomization::none}) {
    o.random = r;
    const estimate one = sobol.monte_carlo(gaussian, {42, 7}, std::uint64_t{1} << 15, 1, o);
    EXPECT_TRUE(
        bitwise_equal(one, sobol.monte_carlo(gaussian, {42, 7}, std::uint64_t{1} << 15, 3, o)))
        << to_string(r);
    // A 2^15-point order-2 net on this analytic f errs far below the 1e-3 allowance of
    // EverySetIsBitwiseIdenticalForAnyThreadCount (its error there is O((log N)²/N)·V_HK).
    EXPECT_NEAR(one.value, gaussian.info().exact, 1e-3) << to_string(r);
  }
}

// The theory the quasi-Monte Carlo sets state, per option (the methods turn it into a rate:
// tests/methods/qmc_test.cpp); the other sets' methods state theirs.
TEST(PointSetCatalogue, QuasiMonteCarloSetsStateTheirTheory) {
  const point_set_entry& sobol = *find_point_set("sobol");
  EXPECT_EQ(sobol.theory_of({})->basis, rate_basis::scrambled_net);
  EXPECT_EQ(sobol.theory_of({randomization::fast_owen})->basis, rate_basis::unproven);
  EXPECT_EQ(sobol.theory_of({randomization::none})->basis, rate_basis::low_discrepancy);
  point_set_options dropped;
  dropped.drop_first_point = true;
  EXPECT_EQ(sobol.theory_of(dropped)->basis, rate_basis::broken_net);
  point_set_options interlaced;
  interlaced.interlacing = 3;
  const point_set_theory order3 = *sobol.theory_of(interlaced);
  EXPECT_EQ(order3.basis, rate_basis::interlaced_net);
  EXPECT_EQ(order3.interlacing, 3u);
  EXPECT_TRUE(order3.scrambled);
  interlaced.random = randomization::shift;
  EXPECT_FALSE(sobol.theory_of(interlaced)->scrambled);
  interlaced.drop_first_point = true;
  EXPECT_EQ(sobol.theory_of(interlaced)->basis, rate_basis::broken_net);
  const point_set_theory halton = *find_point_set("halton")->theory_of({randomization::owen});
  EXPECT_EQ(halton.basis, rate_basis::low_discrepancy);
  EXPECT_NE(halton.note.find("owen-randomized"), std::string::npos) << halton.note;
  point_set_options baker;
  baker.periodic = periodization::baker;
  const point_set_theory lattice = *find_point_set("lattice")->theory_of(baker);
  EXPECT_EQ(lattice.basis, rate_basis::shifted_lattice);
  EXPECT_EQ(lattice.periodization, "baker");
  EXPECT_EQ(lattice.periodic_order, 0) << "f∘φ continuous and periodic";
  EXPECT_FALSE(lattice.weighted);
  EXPECT_TRUE(lattice.note.empty()) << "shifted by default";
  EXPECT_EQ(find_point_set("lattice")->theory_of({})->periodic_order, -1) << "f itself";
  // A weighted periodization: g periodic through order m − 1, m the order of φ''s zeros.
  const std::vector<std::pair<periodization, int>> orders{{periodization::c0, 0},
                                                          {periodization::c1, 1},
                                                          {periodization::c1sin, 1},
                                                          {periodization::c2sin, 2},
                                                          {periodization::c3sin, 3}};
  for (const auto& [p, k] : orders) {
    point_set_options o;
    o.periodic = p;
    const point_set_theory t = *find_point_set("lattice")->theory_of(o);
    EXPECT_EQ(t.periodization, to_string(p));
    EXPECT_EQ(t.periodic_order, k) << to_string(p);
    EXPECT_TRUE(t.weighted) << to_string(p);
  }
  EXPECT_FALSE(find_point_set("jittered")->theory_of({}));
}

// The strata each set states, counted here in 2D and for the Latin hypercube in 3D: every stratum
// holds exactly one point (the gallery draws and counts the same in 2D,
// tests/cli/gallery_test.cpp).
// none and baker keep their path through the catalogue: the same bits as monte_carlo over
// rank1_lattice_points itself.
TEST(PointSetCatalogue, LatticeWithoutWeightsIsMonteCarloOverItsPoints) {
  const point_set_entry& lattice = *find_point_set("lattice");
  const std::uint64_t n = std::uint64_t{1} << 14;
  point_set_options baker;
  baker.periodic = periodization::baker;
  EXPECT_TRUE(
      bitwise_equal(lattice.monte_carlo(gaussian, {3, 4}, n, 2),
                    monte_carlo(gaussian, rank1_lattice_points<no_periodization>(2, n, 3, 4), 2)));
  EXPECT_TRUE(
      bitwise_equal(lattice.monte_carlo(gaussian, {3, 4}, n, 2, baker),
                    monte_carlo(gaussian, rank1_lattice_points<baker_transform>(2, n, 3, 4), 2)));
}

// A weighted periodization has no equal-weight points to give: `quadmc points` and the Python
// module (checked_options), the points, importance and irradiance estimators refuse it, saying
// why and what they take; an unknown value lists the values the points take.
TEST(PointSetCatalogue, PointsRefuseTheWeightedPeriodizations) {
  const point_set_entry& lattice = *find_point_set("lattice");
  const auto quoted_flag = [](std::string_view key) { return "--" + std::string(key); };
  const auto message = [&](std::string_view value) {
    const std::vector<named_option> given{{"periodization", value}};
    try {
      (void)checked_options(lattice, given, quoted_flag);
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.parameter(), "--periodization");
      return std::string(e.what());
    }
    return std::string("no error");
  };
  for (const std::string_view weighted : {"c0", "c1", "c1sin", "c2sin", "c3sin"}) {
    const std::string e = message(weighted);
    EXPECT_NE(e.find("one of none, baker for lattice's points"), std::string::npos) << e;
    EXPECT_NE(e.find(weighted), std::string::npos) << e;
    EXPECT_NE(e.find("weights each point"), std::string::npos) << e;
  }
  EXPECT_NE(message("tent").find("one of none, baker for lattice"), std::string::npos);
  EXPECT_EQ(message("baker"), "no error");
  point_set_options o;
  o.periodic = periodization::c1sin;
  const auto sink = [](std::uint64_t, std::span<const double>) {};
  EXPECT_THROW(lattice.points(2, 64, {1, 2}, sink, o), invalid_argument);
  const any_integrand line(test_support::make_integrand(
      "x on [0,1]", box::unit(1), 0.5, [](std::span<const double> x) { return x[0]; }));
  EXPECT_THROW(lattice.importance(line, {unit_warp_kind::power, 1.0}, {1, 2}, 64, 1, o),
               invalid_argument);
  try {
    lattice.points(2, 64, {1, 2}, sink, o);
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.parameter(), "periodization");
    EXPECT_NE(std::string(e.what()).find("none or baker"), std::string::npos) << e.what();
  }
}

TEST(PointSetCatalogue, StrataHoldOnePointEach) {
  for (const point_set_entry& set : point_set_catalogue()) {
    for (const std::size_t s : {2u, 3u}) {
      for (const std::uint64_t n : {16u, 27u, 64u, 256u}) {
        const auto strata = set.strata_of(s, n);
        if (!strata || !accepts_size(set, s, n)) continue;
        std::vector<double> x;
        set.points(s, n, {3, 1}, [&](std::uint64_t, std::span<const double> b) {
          x.insert(x.end(), b.begin(), b.end());
        });
        const std::uint64_t k = strata->per_axis;
        auto cell = [k](double t) {
          return std::min<std::uint64_t>(k - 1,
                                         static_cast<std::uint64_t>(t * static_cast<double>(k)));
        };
        const std::string what = fmt::format("{} s = {} N = {}", set.name, s, n);
        if (strata->kind == strata_kind::cells) {
          std::set<std::vector<std::uint64_t>> cells;
          for (std::uint64_t i = 0; i < n; ++i) {
            std::vector<std::uint64_t> c;
            for (std::size_t j = 0; j < s; ++j) c.push_back(cell(x[i * s + j]));
            cells.insert(c);
          }
          EXPECT_EQ(cells.size(), n) << what;
        } else {
          for (std::size_t j = 0; j < s; ++j) {
            std::set<std::uint64_t> rows;
            for (std::uint64_t i = 0; i < n; ++i) rows.insert(cell(x[i * s + j]));
            EXPECT_EQ(rows.size(), n) << what << " axis " << j;
          }
        }
      }
    }
  }
  EXPECT_EQ(find_point_set("jittered")->strata_of(3, 64)->per_axis, 4u);
  EXPECT_FALSE(find_point_set("jittered")->strata_of(3, 63));
  EXPECT_FALSE(find_point_set("sobol")->strata_of(2, 32)) << "2^5 is no square";
  EXPECT_FALSE(find_point_set("halton")->strata_of(2, 64));
  EXPECT_EQ(find_point_set("latin_hypercube")->strata_of(3, 27)->kind,
            strata_kind::rows_and_columns);
}

// e^x on [1, 2] with the truncated exponential warp of rate 1 carried to [1, 2]: p ∝ f, so the
// estimate is exact to rounding (∫₁² eˣ dx = e² − e).
TEST(PointSetCatalogue, ImportanceMapsTheWarpToTheInterval) {
  const any_integrand f(
      test_support::make_integrand("e^x on [1,2]", box{{1.0}, {2.0}}, std::exp(2.0) - std::exp(1.0),
                                   [](std::span<const double> x) { return std::exp(x[0]); }));
  const estimate e =
      find_point_set("latin_hypercube")
          ->importance(f, {unit_warp_kind::truncated_exponential, 1.0}, {3, 4}, 1000, 2);
  EXPECT_NEAR(e.value, f.info().exact, 16 * std::numeric_limits<double>::epsilon() * e.value);
  // Within 5 standard errors: a false alarm of 6e-7 under the CLT.
  const estimate p =
      find_point_set("independent")->importance(f, {unit_warp_kind::power, 1.0}, {3, 4}, 100000, 2);
  EXPECT_NEAR(p.value, f.info().exact, 5 * p.std_error);
  EXPECT_THROW(find_point_set("independent")
                   ->importance(gaussian, {unit_warp_kind::power, 1.0}, {1, 1}, 10, 1),
               invalid_argument);
}

// The geometric Asian option's closed form [Kemna & Vorst 1990] against 2^22 evaluations on
// Owen-scrambled Sobol' points (16 independent scrambles of 2^18 points, s = 4, the bridge
// construction), computed apart from the closed form: the mean of the 16 estimates lies within
// t·sd/√16 of it, t the Student-t quantile of 15 degrees of freedom for a two-sided false alarm
// of 1e-4. The bound itself is checked to be below 1e-4 of the price, so that it says something.
TEST(PointSetCatalogue, ScrambledSobolAgreesWithTheGeometricAsianClosedForm) {
  geometric_asian_parameters p;
  p.construction = path_construction::bridge;
  const any_integrand f(geometric_asian(4, p));
  const point_set_entry* sobol = find_point_set("sobol");
  ASSERT_NE(sobol, nullptr);
  constexpr std::size_t replicates = 16;
  welford estimates;
  for (std::size_t r = 0; r < replicates; ++r) {
    estimates.add(sobol->monte_carlo(f, {20261205, r}, std::uint64_t{1} << 18, 2).value);
  }
  const double t = boost::math::quantile(
      boost::math::complement(boost::math::students_t_distribution<double>(replicates - 1), 5e-5));
  const double bound = t * estimates.std_error();  // t·sd/√16
  const double exact = geometric_asian::exact_value(4, p);
  EXPECT_LE(std::abs(estimates.mean() - exact), bound)
      << "mean " << estimates.mean() << ", closed form " << exact;
  EXPECT_LT(bound, 1e-4 * exact) << "sd " << std::sqrt(estimates.variance());
}

}  // namespace
}  // namespace quadmc
