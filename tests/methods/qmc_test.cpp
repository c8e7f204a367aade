// Tests of the quasi-Monte Carlo methods (lib/src/methods/qmc.cpp): sizes and the N = 2^m rule
// with the nearest valid sizes, options and labels, the deterministic variant, replicate error
// bars, and the rates on integrands no other test names: Owen-scrambled Sobol' at −3/2 on a Genz
// Gaussian in s = 2, the baker's lattice at −2, the digital shift and the two anti-patterns
// clearly shallower than the scramble.
#include "method_error.hpp"
#include "quadmc/analysis/power_law_fit.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/estimators/replicate_estimator.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace quadmc {
namespace {

TEST(QmcMethods, MapNToThePowerOfTwoBelowUnlessAskedNotTo) {
  const auto sobol = make_method("sobol");
  EXPECT_EQ(sobol->size_for(1000, 3).size->evaluations, 512u);
  EXPECT_EQ(sobol->size_for(1024, 3).size->evaluations, 1024u);
  EXPECT_EQ(make_method("sobol", {{"allow_any_n", true}})->size_for(1000, 3).size->evaluations,
            1000u);
  EXPECT_EQ(make_method("halton")->size_for(1000, 3).size->evaluations, 1000u);
  const auto lattice = make_method("lattice");
  EXPECT_EQ(lattice->size_for(3000, 2).size->evaluations, 2048u);
  EXPECT_FALSE(lattice->size_for(std::uint64_t{1} << 21, 2).size) << "the vector stops at 2^20";
  EXPECT_FALSE(sobol->size_for(1024, 3668).size);
  EXPECT_TRUE(sobol->incompatibility({"genz_gaussian", 3668, false}).has_value());
  EXPECT_FALSE(make_method("halton")->incompatibility({"genz_gaussian", 1000, false}).has_value());
}

TEST(QmcMethods, ExplicitPointsMustBePowersOfTwoAndTheErrorNamesTheNearest) {
  const std::string e = error_of("sobol", {{"points", std::vector<double>{256, 1000}}});
  EXPECT_NE(e.find("points"), std::string::npos) << e;
  EXPECT_NE(e.find("1000"), std::string::npos) << e;
  EXPECT_NE(e.find("nearest valid sizes 512 and 1024"), std::string::npos) << e;
  EXPECT_NE(error_of("lattice", {{"points", 3000.0}}).find("2048 and 4096"), std::string::npos);
  EXPECT_EQ(error_of("sobol", {{"points", std::vector<double>{256, 1000}}, {"allow_any_n", true}}),
            "no error");
  EXPECT_EQ(error_of("halton", {{"points", 1000.0}}), "no error");
  EXPECT_NE(error_of("sobol", {{"points", std::vector<double>{512, 256}}}).find("increase"),
            std::string::npos);
  const auto m = make_method("sobol", {{"points", std::vector<double>{256, 4096}}});
  const auto sizes = m->explicit_sizes(2);
  ASSERT_EQ(sizes.size(), 2u);
  EXPECT_EQ(sizes[1].size->evaluations, 4096u);
}

TEST(QmcMethods, OptionsAreCheckedAndNamedInTheLabel) {
  EXPECT_NE(error_of("sobol", {{"randomization", "permutation"}}).find("owen, fast_owen"),
            std::string::npos)
      << "permutation is Halton's";
  EXPECT_NE(error_of("halton", {{"randomization", "lms_shift"}}).find("owen, permutation, none"),
            std::string::npos);
  EXPECT_NE(error_of("halton", {{"allow_any_n", true}}).find("unknown key"), std::string::npos);
  EXPECT_NE(error_of("sobol", {{"periodization", "baker"}}).find("unknown key"), std::string::npos);
  EXPECT_NE(error_of("lattice", {{"periodization", "tent"}}).find("none, baker"),
            std::string::npos);
  EXPECT_EQ(make_method("sobol")->label_suffix(), "");
  EXPECT_EQ(make_method("sobol", {{"randomization", "shift"}})->label_suffix(), "_shift");
  EXPECT_EQ(make_method("sobol", {{"drop_first_point", true}})->label_suffix(), "_drop_first");
  EXPECT_EQ(make_method("sobol", {{"allow_any_n", true}})->label_suffix(), "_any_n");
  EXPECT_EQ(make_method("lattice", {{"periodization", "baker"}})->label_suffix(), "_baker");
  EXPECT_EQ(make_method("lattice", {{"periodization", "c2sin"}})->label_suffix(), "_c2sin");
  const std::string bad = error_of("lattice", {{"periodization", "sidi"}});
  EXPECT_NE(bad.find("periodization"), std::string::npos) << bad;
  EXPECT_NE(bad.find("sidi"), std::string::npos) << bad;
  EXPECT_NE(bad.find("none, baker, c0, c1, c1sin, c2sin, c3sin"), std::string::npos) << bad;
}

TEST(QmcMethods, RandomizedSetsTakeTheirErrorBarsFromReplicates) {
  for (const char* name : {"sobol", "halton", "lattice"}) {
    const auto m = make_method(name);
    EXPECT_EQ(m->kind(), method_kind::randomized) << name;
    EXPECT_EQ(m->error_bars(), error_bars::replicates) << name;
    const auto fixed = make_method(name, {{"randomization", "none"}});
    EXPECT_EQ(fixed->kind(), method_kind::deterministic) << name;
  }
  EXPECT_EQ(make_method("importance", {{"warp", "power"}, {"point_set", "sobol"}})->error_bars(),
            error_bars::replicates);
  EXPECT_EQ(make_method("importance", {{"warp", "power"}})->error_bars(), error_bars::own);
}

integrand_params gaussian_params(std::size_t s) {
  integrand_params p;
  p.dimension = s;
  p.seed = 11;
  return p;
}

// One repetition of `m` on f at N points, stream r.
repetition_result run_once(const method& m, const any_integrand& f, const integrand_params& p,
                           std::uint64_t n, std::uint64_t r, unsigned threads = 1) {
  const cell_size size = *m.size_for(n, f.dimension()).size;
  const method_cell cell{f, p, size, cell_control::fixed_size, std::nan(""), r};
  return m.run(cell, {2026, threads});
}

TEST(QmcMethods, OneRunReportsNoOwnErrorAndIsBitwiseTheSameForAnyThreadCount) {
  const integrand_params p = gaussian_params(3);
  const any_integrand f = make_integrand("genz_gaussian", p);
  for (const char* name : {"sobol", "halton", "lattice"}) {
    const auto m = make_method(name);
    const repetition_result one = run_once(*m, f, p, 1 << 15, 4, 1);
    EXPECT_TRUE(std::isnan(one.std_error)) << name << ": σ̂²/N is never reported for QMC points";
    EXPECT_TRUE(std::isnan(one.error_estimate)) << name;
    EXPECT_EQ(one.evaluations, 1u << 15);
    for (unsigned t : {2u, 3u}) {
      const repetition_result other = run_once(*m, f, p, 1 << 15, 4, t);
      EXPECT_EQ(std::memcmp(&one.value, &other.value, sizeof(double)), 0) << name << ", " << t;
    }
    EXPECT_NE(run_once(*m, f, p, 1 << 15, 5).value, one.value) << name << ": another replicate";
  }
}

// The RMSE of `m` over R replicates at N = 2^lo … 2^hi and its fitted slope.
power_law_fit fitted_rate(const method& m, const any_integrand& f, const integrand_params& p,
                          unsigned lo, unsigned hi, int R) {
  std::vector<double> ns, rmse;
  for (unsigned k = lo; k <= hi; ++k) {
    const std::uint64_t n = std::uint64_t{1} << k;
    double sum = 0.0;
    for (int r = 0; r < R; ++r) {
      const double e = run_once(m, f, p, n, static_cast<std::uint64_t>(r)).value - f.info().exact;
      sum += e * e;
    }
    ns.push_back(static_cast<double>(n));
    rmse.push_back(std::sqrt(sum / R));
  }
  return fit_power_law(ns, rmse);
}

// Owen-scrambled Sobol' on a Genz Gaussian (analytic) in s = 2 over N = 2^6 … 2^16: −3/2 up to
// (log N)^(1/2) ([Owen 1997b]). Fixed seeds; R = 64 replicates put each RMSE within about
// 1/√(2R) ≈ 9% (a log error of 0.09), so the fitted slope's own sampling error is about
// 0.09/(sd(ln N)·√11) ≈ 0.013: the ±0.15 of the check is over ten of those (a false alarm far
// below 1e-4), the rest of it the log factor, which flattens the slope by ½/ln N̄ ≈ 0.07.
TEST(QmcRates, OwenScrambledSobolFallsAtMinusThreeHalves) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  const power_law_fit fit = fitted_rate(*make_method("sobol"), f, p, 6, 16, 64);
  EXPECT_NEAR(fit.slope, -1.5, 0.15) << "[" << fit.ci_low << ", " << fit.ci_high << "]";
}

// The padded sets are the same nets in s = 2: pmj02 (a nested uniform scramble of a
// (0,2)-sequence in distribution, [Helmer et al. 2021]) and padded_sobol fit −3/2 on the same
// integrand and allowance as Owen-scrambled Sobol' above, over N = 2^6 … 2^14 (a quarter of the
// work: the slope's own sampling error grows to about 0.017, still a ninth of the allowance).
TEST(QmcRates, PaddedNetsFallAtMinusThreeHalvesInTwoDimensions) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  for (const char* name : {"pmj02", "padded_sobol"}) {
    const power_law_fit fit = fitted_rate(*make_method(name), f, p, 6, 14, 64);
    EXPECT_NEAR(fit.slope, -1.5, 0.15) << name << " [" << fit.ci_low << ", " << fit.ci_high << "]";
  }
}

// A randomly shifted lattice with the baker's transform on the same smooth integrand: −2 up to
// N^ε and log factors ([Hickernell 2002]; [Dick, Nuyens & Pillichshammer 2014]). The vector is
// built for N ≥ 2^10, so the ladder is 2^10 … 2^18. The same sampling error as above (≈ 0.02 on
// the slope with R = 32); the allowance of 0.3 is the N^ε and log factors of the bound.
TEST(QmcRates, BakersLatticeFallsAtMinusTwo) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  const power_law_fit baker =
      fitted_rate(*make_method("lattice", {{"periodization", "baker"}}), f, p, 10, 18, 32);
  EXPECT_NEAR(baker.slope, -2.0, 0.3) << "[" << baker.ci_low << ", " << baker.ci_high << "]";
  const power_law_fit plain = fitted_rate(*make_method("lattice"), f, p, 10, 18, 32);
  EXPECT_GT(plain.slope, baker.slope + 0.5) << "without the transform the shifted lattice is ≈ −1";
}

// Every periodization of the shifted lattice on the same smooth, non-periodic integrand (a Genz
// Gaussian in s = 2) over N = 2^8 … 2^16, R = 16 replicates each; the slopes are printed with
// their 95% intervals. Theory (docs/theory.md#lattice-periodizations): none −1, baker and c0 −2,
// c1 and c1sin −3, c2sin −4, c3sin −5, each up to N^ε — upper bounds on the error, so what the
// test asserts is the gain over none, and only half of the proven gain (m/2 for φ' vanishing to
// order m, 1/2 for the baker's map): the rest is allowance for N^ε and log factors and for the
// lattice's own scatter from one N to the next (the fixed vector is better at some N than at
// others: the fits' residual intervals are ±0.4 to ±0.5). The replicates' part of a slope's
// error is far smaller: each RMSE within 1/√(2R) ≈ 18% (a log error of 0.18), so a slope within
// 0.18/(sd(ln N)·√9) ≈ 0.035 and a difference of two within 0.05; the smallest margin asserted
// (c0: measured gain ≈ 1.1 against 0.5) is over ten of those, a false alarm far below 1e-4.
// Points whose RMSE is within 64ε·|I| of the rounding floor are left out of the fit (c3sin's
// error reaches it by N = 2^14, so its fit covers fewer, noisier points: measured, not asserted).
TEST(QmcRates, LatticePeriodizationsSteepenTheSlope) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  const double floor = 64 * std::numeric_limits<double>::epsilon() * std::abs(f.info().exact);
  std::map<std::string, double> slope;
  for (const char* name : {"none", "baker", "c0", "c1", "c1sin", "c2sin", "c3sin"}) {
    const auto m = make_method("lattice", {{"periodization", name}});
    std::vector<double> ns, rmse;
    for (unsigned k = 8; k <= 16; ++k) {
      const std::uint64_t n = std::uint64_t{1} << k;
      double sum = 0.0;
      for (int r = 0; r < 16; ++r) {
        const double e =
            run_once(*m, f, p, n, static_cast<std::uint64_t>(r)).value - f.info().exact;
        sum += e * e;
      }
      if (std::sqrt(sum / 16) <= floor) continue;
      ns.push_back(static_cast<double>(n));
      rmse.push_back(std::sqrt(sum / 16));
    }
    const power_law_fit fit = fit_power_law(ns, rmse);
    ASSERT_TRUE(fit.ok()) << name;
    slope[name] = fit.slope;
    std::printf("lattice %-6s slope %.2f, 95%% interval [%.2f, %.2f], N = 2^8 … 2^%d\n", name,
                fit.slope, fit.ci_low, fit.ci_high, static_cast<int>(std::log2(ns.back())));
  }
  EXPECT_LT(slope["baker"], slope["none"] - 0.5);
  EXPECT_LT(slope["c0"], slope["none"] - 0.5);
  EXPECT_LT(slope["c1"], slope["none"] - 1.0);
  EXPECT_LT(slope["c1sin"], slope["none"] - 1.0);
  EXPECT_LT(slope["c2sin"], slope["none"] - 1.5);
}

// The digital shift moves every point together: the net's error on smooth f stays about N^−1
// ([Dick & Pillichshammer 2010]); dropping the first point or taking N ≠ 2^m loses the net
// ([Owen 2022]). Each is clearly shallower than Owen's scramble over the same ladder
// N ≈ 2^6 … 2^16: the anti-patterns by more than 0.3, the shift (still pre-asymptotic here,
// measured −1.22 against −1.44) by more than 0.15, against a sampling error of the difference
// of two slopes of about √2·0.013 ≈ 0.02 (R = 64, as above): over seven of those for the shift,
// a false alarm far below 1e-4.
TEST(QmcRates, DigitalShiftAndTheAntiPatternsAreShallowerThanOwen) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  const double owen = fitted_rate(*make_method("sobol"), f, p, 6, 16, 64).slope;
  const double shift =
      fitted_rate(*make_method("sobol", {{"randomization", "shift"}}), f, p, 6, 16, 64).slope;
  const double dropped =
      fitted_rate(*make_method("sobol", {{"drop_first_point", true}}), f, p, 6, 16, 64).slope;
  EXPECT_GT(shift, owen + 0.15) << "owen " << owen << ", shift " << shift;
  EXPECT_GT(dropped, owen + 0.3) << "owen " << owen << ", dropped " << dropped;
  // N ≠ 2^m: 2^k + 1 points of the sequence (the one point past the net alone adds
  // (f(x) − I)/N, O(N^−1)).
  const auto any_n = make_method("sobol", {{"allow_any_n", true}});
  std::vector<double> ns, rmse;
  for (unsigned k = 6; k <= 16; ++k) {
    const std::uint64_t n = (std::uint64_t{1} << k) + 1;
    double sum = 0.0;
    for (int r = 0; r < 64; ++r) {
      const double e =
          run_once(*any_n, f, p, n, static_cast<std::uint64_t>(r)).value - f.info().exact;
      sum += e * e;
    }
    ns.push_back(static_cast<double>(n));
    rmse.push_back(std::sqrt(sum / 64));
  }
  const double off_grid = fit_power_law(ns, rmse).slope;
  EXPECT_GT(off_grid, owen + 0.3) << "owen " << owen << ", N = 2^k + 1 " << off_grid;
}

// interlacing = α is an integer key: 1, 2 or 3, named in the label as "_interlacing<α>"; a
// string, another integer, a randomization an interlaced net refuses or more than 3667 Sobol'
// dimensions fail at plan time, each naming what it expects.
TEST(QmcMethods, InterlacingIsAnIntegerOneTwoOrThree) {
  EXPECT_EQ(make_method("sobol", {{"interlacing", 2}})->label_suffix(), "_interlacing2");
  EXPECT_EQ(make_method("sobol", {{"interlacing", 3}, {"randomization", "shift"}})->label_suffix(),
            "_shift_interlacing3");
  EXPECT_EQ(make_method("sobol", {{"interlacing", 1}})->label_suffix(), "_interlacing1");
  for (const option_value& bad : {option_value(0), option_value(4), option_value(2.5)}) {
    const std::string e = error_of("sobol", {{"interlacing", bad}});
    EXPECT_NE(e.find("interlacing"), std::string::npos) << e;
    EXPECT_NE(e.find("an integer, one of 1, 2, 3"), std::string::npos) << e;
  }
  const std::string text = error_of("sobol", {{"interlacing", "2"}});
  EXPECT_NE(text.find("an integer, one of 1, 2, 3, got \"2\""), std::string::npos) << text;
  for (const char* r : {"fast_owen", "lms_shift"}) {
    const std::string e = error_of("sobol", {{"interlacing", 2}, {"randomization", r}});
    EXPECT_NE(e.find(fmt::format("randomization \"{}\" with interlacing = 2", r)),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("owen, shift or none"), std::string::npos) << e;
  }
  EXPECT_EQ(error_of("sobol", {{"interlacing", 1}, {"randomization", "fast_owen"}}), "no error");
  EXPECT_NE(error_of("halton", {{"interlacing", 2}}).find("unknown key"), std::string::npos);
  // α·s ≤ 3667: s = 1222 takes 3666 dimensions with α = 3, s = 1223 would take 3669.
  const auto three = make_method("sobol", {{"interlacing", 3}});
  EXPECT_TRUE(three->size_for(1024, 1222).size);
  const sizing beyond = three->size_for(1024, 1223);
  EXPECT_FALSE(beyond.size);
  EXPECT_NE(beyond.reason.find("α·s ≤ 3667"), std::string::npos) << beyond.reason;
  EXPECT_NE(beyond.reason.find("α = 3"), std::string::npos) << beyond.reason;
  EXPECT_NE(beyond.reason.find("s = 1223"), std::string::npos) << beyond.reason;
  EXPECT_TRUE(three->incompatibility({"genz_gaussian", 1223, false}).has_value());
  EXPECT_FALSE(three->incompatibility({"genz_gaussian", 1222, false}).has_value());
  EXPECT_EQ(three->size_for(1000, 2).size->evaluations, 512u) << "N = 2^m as without interlacing";
}

// The interlaced points by the method, 1 and 3 threads: bitwise the same value.
TEST(QmcMethods, InterlacedRunsAreBitwiseTheSameForAnyThreadCount) {
  const integrand_params p = gaussian_params(3);
  const any_integrand f = make_integrand("genz_gaussian", p);
  for (const char* r : {"owen", "shift", "none"}) {
    const auto m = make_method("sobol", {{"interlacing", 2}, {"randomization", r}});
    const repetition_result one = run_once(*m, f, p, 1 << 15, 4, 1);
    const repetition_result three = run_once(*m, f, p, 1 << 15, 4, 3);
    EXPECT_EQ(std::memcmp(&one.value, &three.value, sizeof(double)), 0) << r;
  }
}

// The order-2 interlaced Sobol' net on the Genz Gaussian of s = 2 (analytic: δ = ∞),
// Owen-scrambled before interlacing: RMSE N^−5/2 up to log factors ([Dick 2011]). R = 32
// replicates put each RMSE within about 1/√(2R) ≈ 12.5% for normal errors (a log error of 0.125),
// so a slope fitted over k ladder points spaced by ln 2 has a sampling error of about
// 0.125/(sd(ln N)·√k): ≈ 0.017 over 2^6 … 2^16, ≈ 0.06 over 2^12 … 2^17; the ±0.25 of the check
// is four of the latter (a false alarm below 1e-4 for normal errors), the rest the log factor.
// Over 2^6 … 2^16 the fit is not −5/2: the RMSE of the 4-dimensional Sobol' net stalls at
// m = 7–8 and 11–12, the same m for the shift and the scramble (so a property of the net's
// t-values, not of the randomization), and the fit there is about −1.9, pre-asymptotic
// (docs/theory.md#pre-asymptotic-ladders); it must still be clearly steeper than order 1's on the
// same ladder (−3/2 in theory), by more than 0.25, over ten times the difference's sampling error
// √2·0.017 ≈ 0.024.
TEST(QmcRates, InterlacedOrderTwoOwenFallsAtMinusFiveHalves) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  const auto order2 = make_method("sobol", {{"interlacing", 2}});
  const power_law_fit asymptotic = fitted_rate(*order2, f, p, 12, 17, 32);
  EXPECT_NEAR(asymptotic.slope, -2.5, 0.25)
      << "[" << asymptotic.ci_low << ", " << asymptotic.ci_high << "]";
  const power_law_fit whole = fitted_rate(*order2, f, p, 6, 16, 32);
  const power_law_fit order1 = fitted_rate(*make_method("sobol"), f, p, 6, 16, 32);
  EXPECT_LT(whole.slope, order1.slope - 0.25)
      << "order 2 [" << whole.ci_low << ", " << whole.ci_high << "], order 1 [" << order1.ci_low
      << ", " << order1.ci_high << "]";
}

// The digital shift of the order-2 net: N^−2 up to log factors ([Dick 2008]). "About −2" is
// −2 ± 0.3: the same sampling error as above (≈ 0.017) and the log factor, which here may also
// steepen the short ladder (the error of a shifted net is dominated by few dual-net Walsh
// coefficients and moves in steps with m); far from the Owen rate −2.5 and from order 1's −1.
TEST(QmcRates, InterlacedOrderTwoShiftFallsAtAboutMinusTwo) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  const power_law_fit fit = fitted_rate(
      *make_method("sobol", {{"interlacing", 2}, {"randomization", "shift"}}), f, p, 6, 16, 32);
  EXPECT_NEAR(fit.slope, -2.0, 0.3) << "[" << fit.ci_low << ", " << fit.ci_high << "]";
}

TEST(QmcTheory, RatesOfTheTable) {
  auto slope = [](std::string_view name, option_table o, smoothness c, std::size_t s) {
    return make_method(name, o)->theory(integrand_class{c, s, std::nan("")}).slope;
  };
  EXPECT_DOUBLE_EQ(*slope("sobol", {}, smoothness::analytic, 2), -1.5);
  EXPECT_DOUBLE_EQ(*slope("sobol", {{"randomization", "lms_shift"}}, smoothness::smooth, 8), -1.5);
  EXPECT_DOUBLE_EQ(*slope("sobol", {}, smoothness::discontinuous, 2), -0.5 - 1.0 / 6.0);
  EXPECT_FALSE(slope("sobol", {}, smoothness::c0, 2).has_value());
  EXPECT_FALSE(slope("sobol", {{"randomization", "fast_owen"}}, smoothness::smooth, 2));
  EXPECT_DOUBLE_EQ(*slope("sobol", {{"randomization", "shift"}}, smoothness::smooth, 2), -1.0);
  EXPECT_DOUBLE_EQ(*slope("sobol", {{"drop_first_point", true}}, smoothness::smooth, 2), -1.0);
  EXPECT_DOUBLE_EQ(*slope("sobol", {{"allow_any_n", true}}, smoothness::smooth, 2), -1.0);
  EXPECT_DOUBLE_EQ(*slope("halton", {}, smoothness::analytic, 4), -1.0);
  EXPECT_FALSE(slope("halton", {}, smoothness::discontinuous, 2).has_value());
  EXPECT_DOUBLE_EQ(*slope("lattice", {}, smoothness::smooth, 2), -1.0);
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "baker"}}, smoothness::smooth, 2), -2.0);
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "baker"}}, smoothness::c0, 2), -1.0);
  // The weighted periodizations: −(m + 1) on smooth f, m the order of φ''s zeros; −1 on kinks.
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "c0"}}, smoothness::analytic, 2), -2.0);
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "c1"}}, smoothness::smooth, 2), -3.0);
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "c1sin"}}, smoothness::smooth, 2), -3.0);
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "c2sin"}}, smoothness::smooth, 2), -4.0);
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "c3sin"}}, smoothness::analytic, 8), -5.0);
  EXPECT_DOUBLE_EQ(*slope("lattice", {{"periodization", "c3sin"}}, smoothness::c0, 2), -1.0);
  EXPECT_FALSE(slope("lattice", {{"periodization", "c1sin"}}, smoothness::discontinuous, 2));
  EXPECT_FALSE(slope("lattice", {{"periodization", "c1sin"}}, smoothness::singular, 1));
  EXPECT_FALSE(slope("lattice", {}, smoothness::discontinuous, 2).has_value());
  // Padded sets: the pairs' net rate in s ≤ 2, plain Monte Carlo's beyond.
  EXPECT_DOUBLE_EQ(*slope("pmj02", {}, smoothness::smooth, 2), -1.5);
  EXPECT_DOUBLE_EQ(*slope("pmj02", {}, smoothness::smooth, 4), -0.5);
  EXPECT_DOUBLE_EQ(*slope("padded_sobol", {}, smoothness::analytic, 2), -1.5);
  EXPECT_DOUBLE_EQ(*slope("padded_sobol", {{"randomization", "shift"}}, smoothness::smooth, 2),
                   -1.0);
  EXPECT_DOUBLE_EQ(*slope("padded_sobol", {}, smoothness::smooth, 3), -0.5);
  EXPECT_DOUBLE_EQ(*slope("cmj", {}, smoothness::smooth, 2), -0.75);
  EXPECT_DOUBLE_EQ(*slope("cmj", {}, smoothness::discontinuous, 2), -0.75);
  EXPECT_DOUBLE_EQ(*slope("cmj", {}, smoothness::smooth, 1), -1.5);
  EXPECT_DOUBLE_EQ(*slope("cmj", {}, smoothness::smooth, 6), -0.5);
  // Interlaced order-α nets: −(α + 1/2) Owen-scrambled, −α shifted or deterministic, on f smooth
  // enough (δ ≥ α); no rate on kinks or jumps; the broken net's −1 without a net.
  EXPECT_DOUBLE_EQ(*slope("sobol", {{"interlacing", 2}}, smoothness::analytic, 2), -2.5);
  EXPECT_DOUBLE_EQ(*slope("sobol", {{"interlacing", 3}}, smoothness::smooth, 4), -3.5);
  EXPECT_DOUBLE_EQ(
      *slope("sobol", {{"interlacing", 2}, {"randomization", "shift"}}, smoothness::smooth, 2),
      -2.0);
  EXPECT_DOUBLE_EQ(
      *slope("sobol", {{"interlacing", 3}, {"randomization", "none"}}, smoothness::analytic, 2),
      -3.0);
  EXPECT_FALSE(slope("sobol", {{"interlacing", 2}}, smoothness::c0, 2).has_value());
  EXPECT_FALSE(slope("sobol", {{"interlacing", 2}}, smoothness::discontinuous, 2).has_value());
  EXPECT_FALSE(slope("sobol", {{"interlacing", 2}}, smoothness::singular, 1).has_value());
  EXPECT_DOUBLE_EQ(
      *slope("sobol", {{"interlacing", 2}, {"drop_first_point", true}}, smoothness::smooth, 2),
      -1.0);
  EXPECT_DOUBLE_EQ(
      *slope("sobol", {{"interlacing", 2}, {"allow_any_n", true}}, smoothness::smooth, 2), -1.0);
  EXPECT_DOUBLE_EQ(*slope("sobol", {{"interlacing", 1}}, smoothness::smooth, 2), -1.5);
  const theoretical_rate owen =
      make_method("sobol", {{"interlacing", 2}})->theory(integrand_class{smoothness::smooth, 2});
  EXPECT_NE(owen.source.find("[Dick 2011]"), std::string::npos) << owen.source;
  EXPECT_NE(owen.source.find("docs/theory.md#interlaced-nets"), std::string::npos);
  const theoretical_rate shift =
      make_method("sobol", {{"interlacing", 2}, {"randomization", "shift"}})
          ->theory(integrand_class{smoothness::smooth, 2});
  EXPECT_NE(shift.source.find("[Dick 2008]"), std::string::npos) << shift.source;
}

// replicate_estimator: N is spent on k randomizations of n = N/k points (n the largest 2^m the
// set holds), the label says which, the error bars are the estimate's own, and the keys are
// refused where they mean nothing, naming them.
TEST(QmcReplicateEstimator, SizesLabelsAndRefusals) {
  const auto median = make_method("sobol", {{"replicate_estimator", "median"}});
  // 100000/11 = 9090 → n = 8192, 11·8192 evaluations.
  EXPECT_EQ(median->size_for(100000, 2).size->evaluations, 11u * 8192u);
  EXPECT_FALSE(median->size_for(10, 2).size) << "fewer evaluations than randomizations";
  EXPECT_EQ(median->label_suffix(), "_median");
  EXPECT_EQ(median->error_bars(), error_bars::own);
  EXPECT_EQ(median->kind(), method_kind::randomized);
  EXPECT_FALSE(median->shares_chunks()) << "k runs computed whole on every process";
  const auto mean = make_method(
      "halton", {{"replicate_estimator", "mean"}, {"replicate_count", 4.0}, {"points", 1000.0}});
  EXPECT_EQ(mean->label_suffix(), "_mean4");
  EXPECT_EQ(mean->explicit_sizes(3)[0].size->evaluations, 4000u) << "points: n of one of them";
  EXPECT_EQ(make_method("sobol")->label_suffix(), "") << "absent: one randomization, as before";

  const std::string even =
      error_of("sobol", {{"replicate_estimator", "median"}, {"replicate_count", 10.0}});
  EXPECT_NE(even.find("replicate_count"), std::string::npos) << even;
  EXPECT_NE(even.find("odd k ≥ 3"), std::string::npos) << even;
  const std::string alone = error_of("sobol", {{"replicate_count", 5.0}});
  EXPECT_NE(alone.find("expected only with replicate_estimator"), std::string::npos) << alone;
  const std::string fixed =
      error_of("sobol", {{"replicate_estimator", "mean"}, {"randomization", "none"}});
  EXPECT_NE(fixed.find("nothing to combine"), std::string::npos) << fixed;
  EXPECT_NE(error_of("lattice", {{"replicate_estimator", "mode"}}).find("mean, median"),
            std::string::npos);
  const auto refusal = median->refuses(cell_control::tolerance);
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->key, "replicate_estimator");
  EXPECT_FALSE(median->refuses(cell_control::fixed_size));
}

// One combined estimate is the median (or mean) of the k single runs of n points on the streams
// stream_id({cell stream, r}) — the same values bit for bit — on any thread count, with its error
// bar from replicate_estimator.hpp.
TEST(QmcReplicateEstimator, CombinesTheSingleRunsOfItsStreams) {
  const integrand_params p = gaussian_params(2);
  const any_integrand f = make_integrand("genz_gaussian", p);
  const auto one = make_method("sobol", {{"randomization", "lms_shift"}});
  for (const char* how : {"mean", "median"}) {
    const auto combined = make_method(
        "sobol",
        {{"randomization", "lms_shift"}, {"replicate_estimator", how}, {"replicate_count", 5.0}});
    std::vector<double> singles;
    for (std::uint64_t r = 0; r < 5; ++r) {
      singles.push_back(run_once(*one, f, p, 1024, stream_id({7, r})).value);
    }
    const combined_replicates expected =
        combine_replicates(singles, std::string(how) == "mean" ? replicate_estimator::mean
                                                               : replicate_estimator::median);
    for (unsigned threads : {1u, 3u}) {
      const repetition_result got = run_once(*combined, f, p, 5 * 1024, 7, threads);
      EXPECT_EQ(got.evaluations, 5u * 1024u) << how;
      EXPECT_EQ(std::memcmp(&got.value, &expected.value, sizeof(double)), 0) << how << threads;
      EXPECT_EQ(got.error_estimate, expected.error_estimate) << how;
      EXPECT_GT(got.error_estimate, 0.0) << how;
    }
  }
}

}  // namespace
}  // namespace quadmc
