// Genz families: closed forms against nested Gauss–Kronrod (s = 2, 3) and separable tensor
// integration (s = 5); corner-peak accuracy against 50-digit arithmetic; parameter validation.
#include "quadmc/functions/genz.hpp"

#include "jump_metadata.hpp"
#include "reference_quadrature.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

namespace quadmc {
namespace {

using test::at;
using test::gauss_kronrod;
using test::relative_error;

// Closed forms must agree with the independent integration to 1e-10 relative
// (docs/design.md#accuracy-targets; GK at tolerance 1e-14 per level reaches ~1e-13 on these smooth
// pieces).
constexpr double tolerance = 1e-10;

// Each measured disagreement is printed for the report (grep "relative error vs").
void record(const std::string& name, double err) {
  std::printf("%-20s relative error vs independent integration %.2e\n", name.c_str(), err);
}

// Nested 2D Gauss–Kronrod of f over [0,1]², splitting each axis at `breaks`.
template <class F>
double nested_2d(const F& f, const std::vector<double>& b0, const std::vector<double>& b1) {
  return gauss_kronrod(
      [&](double x0) {
        return gauss_kronrod([&](double x1) { return at(f, {x0, x1}); }, 0.0, 1.0, b1);
      },
      0.0, 1.0, b0);
}

template <class F>
double nested_3d(const F& f, const std::vector<double>& b0, const std::vector<double>& b1,
                 const std::vector<double>& b2) {
  return gauss_kronrod(
      [&](double x0) {
        return gauss_kronrod(
            [&](double x1) {
              return gauss_kronrod([&](double x2) { return at(f, {x0, x1, x2}); }, 0.0, 1.0, b2);
            },
            0.0, 1.0, b1);
      },
      0.0, 1.0, b0);
}

template <class F>
void check_nested(genz_family fam, std::size_t s, std::uint64_t seed, bool split_at_u) {
  const auto p = genz_random_parameters(fam, s, seed);
  const F f(p.a, p.u);
  auto br = [&](std::size_t j) {
    return split_at_u ? std::vector<double>{p.u[j]} : std::vector<double>{};
  };
  const double exact = f.info().exact;
  const double numeric = s == 2 ? nested_2d(f, br(0), br(1)) : nested_3d(f, br(0), br(1), br(2));
  const double err = relative_error(numeric, exact);
  record(std::string(to_string(fam)), err);
  EXPECT_LT(err, tolerance) << to_string(fam) << " s = " << s << " seed = " << seed
                            << " exact = " << exact << " numeric = " << numeric;
}

TEST(Genz, ClosedFormsMatchNestedGaussKronrodInTwoAndThreeDimensions) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    check_nested<genz_oscillatory>(genz_family::oscillatory, 2, seed, false);
    check_nested<genz_product_peak>(genz_family::product_peak, 2, seed, true);
    check_nested<genz_corner_peak>(genz_family::corner_peak, 2, seed, false);
    check_nested<genz_gaussian>(genz_family::gaussian, 2, seed, true);
    check_nested<genz_continuous>(genz_family::continuous, 2, seed, true);
  }
  check_nested<genz_oscillatory>(genz_family::oscillatory, 3, 4, false);
  check_nested<genz_corner_peak>(genz_family::corner_peak, 3, 4, false);
  check_nested<genz_gaussian>(genz_family::gaussian, 3, 4, true);
}

TEST(Genz, DiscontinuousMatchesNestedGaussKronrodSplitAtTheCuts) {
  // The jump sits at x_c = u_c: integrating each cut axis over [0, u_c] and [u_c, 1] separately
  // leaves only smooth pieces, so 1e-10 holds for the discontinuous family too.
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const auto p = genz_random_parameters(genz_family::discontinuous, 2, seed);
    const genz_discontinuous f(p.a, p.u);
    const double numeric = nested_2d(f, {p.u[0]}, {p.u[1]});
    const double err = relative_error(numeric, f.info().exact);
    record("genz_discontinuous", err);
    EXPECT_LT(err, tolerance) << "seed " << seed;
  }
  // s = 3, default cut {1, 2}: x₃ is not cut.
  const auto p = genz_random_parameters(genz_family::discontinuous, 3, 5);
  const genz_discontinuous f(p.a, p.u);
  const double err = relative_error(nested_3d(f, {p.u[0]}, {p.u[1]}, {}), f.info().exact);
  record("genz_discontinuous", err);
  EXPECT_LT(err, tolerance);
  // Every-coordinate convention.
  const genz_discontinuous g(p.a, p.u, {1, 2, 3});
  const double err_all = relative_error(nested_3d(g, {p.u[0]}, {p.u[1]}, {p.u[2]}), g.info().exact);
  record("genz_discontinuous", err_all);
  EXPECT_LT(err_all, tolerance);
}

// Separable families in s = 5: the integral is the product of 1D integrals, each by GK.
TEST(Genz, SeparableFamiliesMatchTensorGaussKronrodInFiveDimensions) {
  const std::size_t s = 5;
  {
    const auto p = genz_random_parameters(genz_family::product_peak, s, 9);
    double prod = 1.0;
    for (std::size_t j = 0; j < s; ++j) {
      const double a = p.a[j], u = p.u[j];
      prod *= gauss_kronrod([&](double x) { return 1.0 / (1.0 / (a * a) + (x - u) * (x - u)); },
                            0.0, 1.0, {u});
    }
    const double err = relative_error(prod, genz_product_peak(p.a, p.u).info().exact);
    record("genz_product_peak", err);
    EXPECT_LT(err, tolerance);
  }
  {
    const auto p = genz_random_parameters(genz_family::continuous, s, 9);
    double prod = 1.0;
    for (std::size_t j = 0; j < s; ++j) {
      const double a = p.a[j], u = p.u[j];
      prod *=
          gauss_kronrod([&](double x) { return std::exp(-a * std::abs(x - u)); }, 0.0, 1.0, {u});
    }
    const double err = relative_error(prod, genz_continuous(p.a, p.u).info().exact);
    record("genz_continuous", err);
    EXPECT_LT(err, tolerance);
  }
  {
    // Oscillatory: Re[e^{i2πu₁} Π ∫₀¹ e^{iaⱼx} dx], each factor by GK on cos and sin.
    const auto p = genz_random_parameters(genz_family::oscillatory, s, 9);
    std::complex<double> prod = std::polar(1.0, 2.0 * std::numbers::pi * p.u[0]);
    for (std::size_t j = 0; j < s; ++j) {
      const double a = p.a[j];
      prod *= std::complex<double>(gauss_kronrod([&](double x) { return std::cos(a * x); }, 0, 1),
                                   gauss_kronrod([&](double x) { return std::sin(a * x); }, 0, 1));
    }
    const double err = relative_error(prod.real(), genz_oscillatory(p.a, p.u).info().exact);
    record("genz_oscillatory", err);
    EXPECT_LT(err, tolerance);
  }
}

TEST(Genz, DiscontinuousWithUEqualOneIsAProductOfExponentialIntegrals) {
  const std::vector<double> a = {0.7, 1.3, 2.1};
  const genz_discontinuous f(a, {1.0, 1.0, 0.4}, {1, 2});
  // ∫₀¹ e^{ax} dx = (e^a − 1)/a for the two cut-at-1 axes (no cut effectively), x₃ uncut.
  double expected = 1.0;
  for (double ai : a) expected *= std::expm1(ai) / ai;
  EXPECT_NEAR(f.info().exact, expected, 8 * std::numeric_limits<double>::epsilon() * expected);
  // And it equals the cut-free Genz discontinuous... i.e. exp(Σaᵢxᵢ) on the whole cube.
  const genz_discontinuous all_cut_at_one(a, {1.0, 1.0, 1.0}, {1, 2, 3});
  EXPECT_NEAR(all_cut_at_one.info().exact, expected,
              8 * std::numeric_limits<double>::epsilon() * expected);
}

TEST(Genz, DefaultCutIsFirstTwoCoordinatesAndOnlyTheFirstInOneDimension) {
  EXPECT_EQ(genz_discontinuous({1.0}, {0.5}).cut(), (std::vector<std::size_t>{1}));
  EXPECT_EQ(genz_discontinuous({1.0, 1.0, 1.0}, {0.5, 0.5, 0.5}).cut(),
            (std::vector<std::size_t>{1, 2}));
  // 1D: ∫₀^{u} e^{ax} dx.
  EXPECT_NEAR(genz_discontinuous({2.0}, {0.5}).info().exact, std::expm1(1.0) / 2.0, 1e-15);
}

TEST(Genz, DiscontinuousCarriesOneFactorPerAxisWithTheCutsAsJumps) {
  // 1D: a jump of size e^{a·u} at u (f(u) the left limit), M_k = |a|ᵏ·e^{max(0, a·u)}.
  {
    const genz_discontinuous f({2.5}, {0.6});
    test::expect_factors_describe(f, {0.0}, {1.0});
    const integrand_info info = f.info();
    const piecewise_smooth_factor& g = info.separable_factors.at(0);
    ASSERT_EQ(g.jumps.size(), 1u);
    EXPECT_EQ(g.jumps[0].location, 0.6);
    EXPECT_DOUBLE_EQ(g.jumps[0].size, std::exp(1.5));
    for (std::size_t k = 0; k < g.derivative_bound.size(); ++k) {
      // max over [0, 0.6] of |(e^{2.5x})⁽ᵏ⁾| = 2.5ᵏ e^{1.5}, at the cut.
      EXPECT_DOUBLE_EQ(*g.derivative_bound[k], std::pow(2.5, k) * std::exp(1.5)) << "k = " << k;
    }
  }
  // A negative a: the largest derivative is at x = 0.
  {
    const genz_discontinuous f({-3.0}, {0.7});
    test::expect_factors_describe(f, {0.0}, {1.0});
    EXPECT_DOUBLE_EQ(*f.info().separable_factors.at(0).derivative_bound[2], 9.0);
  }
  // u = 1: no jump. (u = 0 would make f zero almost everywhere, ∫f = 0: the family refuses it,
  // since a zero reference leaves no relative error to measure.)
  EXPECT_TRUE(genz_discontinuous({1.0}, {1.0}).info().separable_factors.at(0).jumps.empty());
  // s = 3 with Genz's default cut {1, 2}: axes 1 and 2 jump, axis 3 is e^{a₃x} on [0, 1]. With
  // the other coordinates at 0 each other factor is e⁰ = 1.
  const genz_discontinuous f3({0.7, 1.3, 2.1}, {0.4, 0.55, 0.3});
  test::expect_factors_describe(f3, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  const integrand_info info = f3.info();
  ASSERT_EQ(info.separable_factors.size(), 3u);
  EXPECT_EQ(info.separable_factors[0].jumps.size(), 1u);
  EXPECT_EQ(info.separable_factors[1].jumps.size(), 1u);
  EXPECT_TRUE(info.separable_factors[2].jumps.empty());
  // Other families carry no factors.
  EXPECT_TRUE(genz_gaussian({1.0}, {0.5}).info().separable_factors.empty());
}

TEST(Genz, NormalisationMakesTheSumOfAEqualTheDifficulty) {
  const genz_family families[] = {genz_family::oscillatory, genz_family::product_peak,
                                  genz_family::corner_peak, genz_family::gaussian,
                                  genz_family::continuous,  genz_family::discontinuous};
  const double b[] = {9.0, 7.25, 1.85, 7.03, 20.4, 4.3};  // docs/theory.md#genz-difficulty
  for (int k = 0; k < 6; ++k) {
    const auto p = genz_random_parameters(families[k], 7, 42);
    double sum = 0.0;
    for (double ai : p.a) {
      EXPECT_GT(ai, 0.0);
      sum += ai;
    }
    EXPECT_NEAR(sum, b[k], 8 * std::numeric_limits<double>::epsilon() * b[k])
        << to_string(families[k]);
    for (double ui : p.u) {
      EXPECT_GE(ui, 0.0);
      EXPECT_LT(ui, 1.0);
    }
    // Deterministic in the seed, different across seeds.
    EXPECT_EQ(p.a, genz_random_parameters(families[k], 7, 42).a);
    EXPECT_NE(p.u, genz_random_parameters(families[k], 7, 43).u);
  }
  const std::vector<double> w = {1.0, 3.0};
  EXPECT_EQ(genz_normalise(genz_family::gaussian, w),
            (std::vector<double>{7.03 / 4, 3 * 7.03 / 4}));
}

// The draw as it was before coefficient_decay existed, copied here so that "none" is held to it
// bit for bit: every committed result was computed with these parameters.
genz_parameters draw_without_decay(genz_family f, std::size_t s, std::uint64_t seed) {
  const random_stream rng(seed, stream_id({static_cast<std::uint64_t>(f)}));
  std::vector<double> w(s), u(s);
  for (std::size_t j = 0; j < s; ++j) {
    w[j] = 1.0 - rng.uniform(j);
    u[j] = rng.uniform(s + j);
  }
  return {genz_normalise(f, w), std::move(u)};
}

constexpr genz_family all_genz_families[] = {genz_family::oscillatory, genz_family::product_peak,
                                             genz_family::corner_peak, genz_family::gaussian,
                                             genz_family::continuous,  genz_family::discontinuous};

TEST(GenzDecay, NoneIsBitForBitTheDrawWithoutADecay) {
  for (const genz_family f : all_genz_families) {
    for (const std::size_t s : {1u, 2u, 3u, 7u, 16u, 20u}) {
      for (const std::uint64_t seed : {0ull, 1ull, 42ull, 0x9e3779b97f4a7c15ull}) {
        const genz_parameters old = draw_without_decay(f, s, seed);
        const genz_parameters none = genz_random_parameters(f, s, seed, genz_decay::none);
        EXPECT_EQ(none.a, old.a) << to_string(f) << " s = " << s << " seed = " << seed;
        EXPECT_EQ(none.u, old.u) << to_string(f) << " s = " << s << " seed = " << seed;
        EXPECT_EQ(genz_random_parameters(f, s, seed).a, old.a) << "the default is none";
      }
    }
  }
}

// aⱼ = b·wⱼ·dⱼ/Σ wₖdₖ with wⱼ = 1 − Uⱼ regenerated here from the stream and dⱼ = j⁻² or 2⁻ʲ
// (1-based j), in long double; Σa = b to 1e-15 relative; u as without a decay.
TEST(GenzDecay, QuadraticAndExponentialScaleTheWeightsAndKeepTheDifficulty) {
  for (const genz_decay decay : {genz_decay::quadratic, genz_decay::exponential}) {
    for (const genz_family f : all_genz_families) {
      for (const std::size_t s : {1u, 2u, 5u, 12u, 20u}) {
        for (const std::uint64_t seed : {3ull, 2026ull}) {
          const genz_parameters p = genz_random_parameters(f, s, seed, decay);
          const random_stream rng(seed, stream_id({static_cast<std::uint64_t>(f)}));
          std::vector<long double> scaled(s);
          long double total = 0.0L;
          for (std::size_t j = 0; j < s; ++j) {
            const long double index = static_cast<long double>(j + 1);
            const long double d = decay == genz_decay::quadratic
                                      ? 1.0L / (index * index)
                                      : std::ldexp(1.0L, -static_cast<int>(j + 1));
            scaled[j] = (1.0L - rng.uniform(j)) * d;
            total += scaled[j];
          }
          const std::string context =
              fmt::format("{} {} s = {} seed = {}", to_string(decay), to_string(f), s, seed);
          long double sum = 0.0L;
          for (std::size_t j = 0; j < s; ++j) {
            const long double expected = genz_difficulty(f) * scaled[j] / total;
            EXPECT_LE(std::abs(p.a[j] - expected),
                      4 * std::numeric_limits<double>::epsilon() * expected)
                << context << " j = " << j + 1;
            sum += p.a[j];
          }
          EXPECT_LE(std::abs(sum - genz_difficulty(f)), 1e-15 * genz_difficulty(f)) << context;
          EXPECT_EQ(p.u, draw_without_decay(f, s, seed).u) << context;
          // Lower effective dimension: the first coefficient carries more of b than without.
          if (s > 1) {
            EXPECT_GT(p.a[0], draw_without_decay(f, s, seed).a[0]) << context;
          }
        }
      }
    }
  }
}

TEST(GenzDecay, NamesAreParsedAndABadOneNamesTheChoices) {
  for (const genz_decay d : {genz_decay::none, genz_decay::quadratic, genz_decay::exponential}) {
    EXPECT_EQ(genz_decay_from(to_string(d)), d);
  }
  const std::string m = test_support::message_of([] { genz_decay_from("cubic"); });
  EXPECT_NE(m.find("invalid coefficient_decay = \"cubic\": expected one of \"none\", "
                   "\"quadratic\", \"exponential\""),
            std::string::npos)
      << m;
}

// The corner-peak closed form in 100 significant digits, the reference for the rounding study.
double corner_peak_100_digits(const std::vector<double>& a) {
  using big = boost::multiprecision::cpp_bin_float_100;
  const std::size_t s = a.size();
  big sum = 0;
  for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << s); ++mask) {
    big t = 1;
    int parity = 0;
    for (std::size_t j = 0; j < s; ++j) {
      if ((mask >> j) & 1U) {
        t += big(a[j]);
        parity ^= 1;
      }
    }
    sum += parity ? -1 / t : 1 / t;
  }
  big denominator = 1;
  for (std::size_t j = 0; j < s; ++j) denominator *= big(j + 1) * big(a[j]);
  return static_cast<double>(sum / denominator);
}

// The same closed form summed in double or long double: docs/theory.md#corner-peak-cancellation.
template <class Real>
double corner_peak_in(const std::vector<double>& a) {
  const std::size_t s = a.size();
  Real sum = 0.0, denominator = 1.0;
  for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << s); ++mask) {
    Real t = 1.0;
    int parity = 0;
    for (std::size_t j = 0; j < s; ++j) {
      if ((mask >> j) & 1U) {
        t += a[j];
        parity ^= 1;
      }
    }
    sum += parity ? -1 / t : 1 / t;
  }
  for (std::size_t j = 0; j < s; ++j) denominator *= static_cast<Real>(j + 1) * a[j];
  return static_cast<double>(sum / denominator);
}

TEST(Genz, CornerPeakClosedFormAccuracyAgainstOneHundredDigits) {
  // Genz difficulty Σa = 1.85 (the hard case for the alternating sum: small aᵢ). The library
  // sums in 50 digits; double and long double are printed to show what that buys (the figures
  // quoted in genz.hpp and inclusion_exclusion.hpp).
  for (std::size_t s = 1; s <= 14; ++s) {
    const auto p = genz_random_parameters(genz_family::corner_peak, s, 11);
    const double reference = corner_peak_100_digits(p.a);
    const auto [value, bound] = genz_corner_peak::closed_form(p.a);
    const double err = relative_error(value, reference);
    std::printf(
        "corner peak s = %2zu: 50-digit error %.2e (bound %.2e), long double %.2e, "
        "double %.2e\n",
        s, err, bound, relative_error(corner_peak_in<long double>(p.a), reference),
        relative_error(corner_peak_in<double>(p.a), reference));
    // The 50-digit sum is exact to double precision: only the final rounding (ε/2) remains.
    EXPECT_LE(err, std::numeric_limits<double>::epsilon()) << "s = " << s;
    EXPECT_LE(bound, 1e-30) << "s = " << s;
    EXPECT_NO_THROW(genz_corner_peak(p.a, p.u)) << "s = " << s;
  }
}

TEST(Genz, CornerPeakRejectsParametersWhereTheClosedFormIsUntrustworthy) {
  // aᵢ = 1e-6, s = 12: the sum is ~10^-70 of its terms; 50 digits cannot hold that.
  const std::vector<double> tiny(12, 1e-6), u(12, 0.5);
  try {
    genz_corner_peak f(tiny, u);
    FAIL() << "aᵢ = 1e-6 at s = 12 should be rejected";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.parameter(), "a");
    EXPECT_NE(std::string(e.what()).find("relative rounding bound"), std::string::npos) << e.what();
  }
  const auto q = genz_random_parameters(genz_family::corner_peak, 21, 11);
  try {
    genz_corner_peak f(q.a, q.u);
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.parameter(), "dimension");
  }
}

using test_support::message_of;

TEST(Genz, BadParametersAreNamed) {
  EXPECT_NE(message_of([] { genz_gaussian({}, {}); }).find("invalid a"), std::string::npos);
  EXPECT_NE(message_of([] { genz_gaussian({1.0}, {1.5}); }).find("invalid u = 1.5"),
            std::string::npos);
  EXPECT_NE(message_of([] { genz_gaussian({1.0}, {-0.1}); }).find("invalid u"), std::string::npos);
  EXPECT_NE(message_of([] {
              genz_gaussian({1.0, 2.0}, {0.5});
            }).find("invalid u"),
            std::string::npos);
  EXPECT_NE(message_of([] { genz_product_peak({0.0}, {0.5}); }).find("invalid a = 0"),
            std::string::npos);
  EXPECT_NE(message_of([] { genz_oscillatory({NAN}, {0.5}); }).find("invalid a = nan"),
            std::string::npos);
  EXPECT_NE(message_of([] { genz_discontinuous({1.0}, {0.5}, {2}); }).find("invalid cut = 2"),
            std::string::npos);
  // Regression: u₁ = 0 on a cut coordinate makes the integral 0, and the refusal named a.
  EXPECT_NE(message_of([] {
              genz_discontinuous({1.0, 1.0}, {0.0, 0.5});
            }).find("invalid u = 0"),
            std::string::npos)
      << message_of([] {
           genz_discontinuous({1.0, 1.0}, {0.0, 0.5});
         });
  // A coordinate that is not cut may have uᵢ = 0 (it is not used).
  EXPECT_NO_THROW(genz_discontinuous({1.0, 1.0, 1.0}, {0.5, 0.5, 0.0}));
  EXPECT_NE(message_of([] {
              genz_discontinuous({1.0, 1.0}, {0.5, 0.5}, {1, 1});
            }).find("distinct"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              genz_random_parameters(genz_family::gaussian, 0, 1);
            }).find("invalid dimension = 0"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              genz_normalise(genz_family::gaussian, std::vector<double>{-1.0});
            }).find("invalid w"),
            std::string::npos);
  // Oscillatory and discontinuous accept any finite a, including 0 and negative values.
  EXPECT_NEAR(genz_oscillatory({0.0}, {0.0}).info().exact, 1.0, 1e-16);
  EXPECT_NEAR(genz_discontinuous({0.0, -1.0}, {0.5, 1.0}).info().exact, 0.5 * -std::expm1(-1.0),
              1e-16);
}

// --- Parameters at the edges of double: a finite, correct reference or a named refusal --------

// Every instance either has a finite exact value and finite values at the points that matter
// (the peak, the corners) or its constructor names the parameter.
TEST(GenzRange, ProductPeakIsEvaluatedWithoutOverflowOnTheWay) {
  // Π 1/(aᵢ⁻² + dᵢ²) reached 1e300·1e300 = inf after two factors at x = u although f(u) = 1;
  // now f = C·Π 1/(1 + aᵢ²dᵢ²) with C = Π aᵢ² = 1 (computed past the overflow of its prefix).
  const genz_product_peak f({1e150, 1e150, 1e-150, 1e-150}, {0.5, 0.5, 0.5, 0.5});
  EXPECT_NEAR(at(f, {0.5, 0.5, 0.5, 0.5}), 1.0, 1e-15);
  EXPECT_NEAR(f.info().derivative_bound[0].value(), 1.0, 1e-15);
  // ∫ = Π aᵢ[atan(aᵢ(1 − uᵢ)) + atan(aᵢuᵢ)] = (1e150·π)²·(1e-150·1e-150)² = π²·1e-300.
  const double expected = std::numbers::pi * std::numbers::pi * 1e-300;
  EXPECT_NEAR(f.info().exact, expected, 1e-14 * expected);
  // Ordinary parameters: the same values as the textbook form, to rounding.
  const genz_product_peak g({2.0, 5.0}, {0.3, 0.7});
  const double x = 0.1, y = 0.9;
  const double textbook = 1.0 / (0.25 + (x - 0.3) * (x - 0.3)) / (0.04 + (y - 0.7) * (y - 0.7));
  EXPECT_NEAR(at(g, {x, y}), textbook, 4e-16 * textbook);
}

TEST(GenzRange, HugeOrTinyAAreRefusedWithTheParameterNamed) {
  // a = 1e300: a² = inf (and the integral π·1e300 the plan used to print as finite, with f = inf
  // at x = u).
  std::string m = message_of([] { genz_product_peak({1e300}, {0.5}); });
  EXPECT_NE(m.find("invalid a = 1.0000000000000001e+300"), std::string::npos) << m;
  // The peak Π aᵢ² = 1e320 overflows although each aᵢ² is finite.
  m = message_of([] { genz_product_peak({1e80, 1e80}, {0.5, 0.5}); });
  EXPECT_NE(m.find("peak Π aᵢ² at x = u is a normal double"), std::string::npos) << m;
  // The Gaussian's aᵢ² = inf would give inf·0 = NaN at x = u.
  m = message_of([] { genz_gaussian({1e155}, {0.5}); });
  EXPECT_NE(m.find("invalid a = 1e+155: expected aᵢ ≤ 1.3e154"), std::string::npos) << m;
  EXPECT_NEAR(genz_gaussian({1e150}, {0.5}).info().exact, std::sqrt(std::numbers::pi) * 1e-150,
              1e-15 * 1.8e-150);
  // Oscillatory: 2π + Σ|aᵢ| = inf, so cos of the phase is NaN.
  m = message_of([] { genz_oscillatory({1.7e308, 1.7e308}, {0.0, 0.0}); });
  EXPECT_NE(m.find("finite 2π + Σ|aᵢ|"), std::string::npos) << m;
  // 1e308 − 1e307 is finite, but a phase of 5e307 cannot be carried to a fraction of a period.
  m = message_of([] { genz_oscillatory({1e308, -1e307}, {0.0, 0.0}); });
  EXPECT_NE(m.find("accurate to 1e-12 of its amplitude"), std::string::npos) << m;
  // Discontinuous: e^(Σ aᵢ) overflows at the corner.
  m = message_of([] { genz_discontinuous({400.0, 400.0}, {1.0, 1.0}); });
  EXPECT_NE(m.find("above ln(DBL_MAX)"), std::string::npos) << m;
  // Subnormal aᵢ: the closed forms divide by them.
  m = message_of([] { genz_continuous({1e-310}, {0.5}); });
  EXPECT_NE(m.find("not subnormal"), std::string::npos) << m;
  // Integrals below the normal range: a relative error is no longer measurable.
  m = message_of([] { genz_continuous({1e300, 1e300}, {0.5, 0.5}); });
  EXPECT_NE(m.find("integral of genz_continuous is a normal double (it is about 1e-600, below"),
            std::string::npos)
      << m;
  // s = 12, aᵢ = 1e27: the closed form is accurate (bound ≈ 1e-17) but 1/(12!·Π aᵢ) ≈ 1e-333.
  m = message_of(
      [] { genz_corner_peak(std::vector<double>(12, 1e27), std::vector<double>(12, 0.5)); });
  EXPECT_NE(m.find("integral of genz_corner_peak is a normal double"), std::string::npos) << m;
}

// Regression: the phase 2πu₁ + Σaᵢ/2 was summed in one double, so the exact value lost the
// fraction of a period it needs (relative error 8e-8 at a₁ = 1e10, 1e-3 at 1e14, the wrong sign at
// 1e16). The reference is the same closed form in 50 significant digits of the same doubles
// (Boost.Multiprecision), with the error measured against the amplitude Π|sin(aᵢ/2)/(aᵢ/2)|, the
// scale of the integrand's integral whatever its phase (cos of the phase may be near 0).
TEST(GenzRange, OscillatoryPhaseKeepsItsFractionOfAPeriod) {
  using big = boost::multiprecision::cpp_bin_float_50;
  const auto check = [](std::vector<double> a, std::vector<double> u) {
    big phase = big(2.0 * std::numbers::pi * u[0]);
    big amplitude = 1;
    for (const double ai : a) {
      const big half = big(ai) / 2;
      phase += half;
      amplitude *= sin(half) / half;
    }
    const big exact = cos(phase) * amplitude;
    const double value = genz_oscillatory(a, u).info().exact;
    EXPECT_LT(static_cast<double>(abs((big(value) - exact) / amplitude)), 1e-14)
        << "a₁ = " << a[0] << ", value " << value;
  };
  for (const double a1 : {1e10, 1e14, 1e16, 1e19}) check({a1}, {0.3});
  check({1e15, 3.0, 7e14}, {0.7, 0.1, 0.9});
  check({1e16, 3.0}, {0.25, 0.5});  // the ulp of 5e15 is 1: lo carries 2πu₁'s and 1.5's fractions
  // Past about 2e19 the two-double phase is no longer within 1e-12 of a period: refused.
  for (const double a1 : {1e21, 1e300}) {
    const std::string m = message_of([a1] { genz_oscillatory({a1}, {0.3}); });
    EXPECT_NE(m.find("accurate to 1e-12 of its amplitude"), std::string::npos) << m;
  }
}

TEST(GenzRange, DiscontinuousProductSurvivesAnUnderflowOnTheWay) {
  // Factors 1e-200, 1e-200 (a = −1e200: ∫₀¹e^{ax} = 1/|a|) and (e^700 − 1)/700: the product of
  // the first two underflows in double, the whole is 1e-400·e^700/700 ≈ 1.4e-99. The expected
  // value divides in an order that never leaves the normal range: four correctly rounded steps
  // and exp's < 1 ulp, so within 3e-16 relative (not exp(700 − 400·ln 10), whose argument alone
  // carries 921·ε ≈ 1e-13 of rounding).
  const genz_discontinuous f({-1e200, -1e200, 700.0}, {1.0, 1.0, 1.0}, {1});
  const double expected = std::exp(700.0) / 700.0 / 1e200 / 1e200;
  EXPECT_NEAR(f.info().exact, expected, 1e-14 * expected);
}

TEST(GenzRange, DerivativeBoundsThatOverflowAreLeftEmpty) {
  const auto info = genz_gaussian({1e100}, {0.5}).info();
  EXPECT_FALSE(info.derivative_bound[4].has_value()) << "12a⁴ = 1.2e401";
  EXPECT_TRUE(info.derivative_bound[2].has_value());
  // The oscillatory family's aᵢ stop near 2e19 (its phase), where aᵢ⁴ ≈ 1.6e77 is far from
  // overflowing: its largest accepted a has every bound.
  const auto osc = genz_oscillatory({1e19}, {0.0}).info();
  EXPECT_TRUE(osc.derivative_bound[4].has_value());
  EXPECT_EQ(osc.derivative_bound[0], 1.0);
}

}  // namespace
}  // namespace quadmc
