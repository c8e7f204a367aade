#include "quadmc/estimators/monte_carlo.hpp"

#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/padded_jittered_points.hpp"
#include "quadmc/sampling/unjittered_points.hpp"
#include "test_integrands.hpp"

#include <gtest/gtest.h>
#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace quadmc;
using test_support::make_integrand;

// ∫₀² x² dx = 8/3.
const auto square = make_integrand("x^2 on [0,2]", box{{0.0}, {2.0}}, 8.0 / 3.0,
                                   [](std::span<const double> x) { return x[0] * x[0]; });
// ∫∫ e^(x+y) over [0,1]² = (e − 1)².
const auto exponential =
    make_integrand("e^(x+y)", box::unit(2), (std::numbers::e - 1) * (std::numbers::e - 1),
                   [](std::span<const double> x) { return std::exp(x[0] + x[1]); });
// ∫ over [0,1]×[0,π]×[−1,1] of x·sin(y)·(1 + z) = ½ · 2 · 2 = 2.
const auto product =
    make_integrand("x sin(y) (1+z)", box{{0.0, 0.0, -1.0}, {1.0, std::numbers::pi, 1.0}}, 2.0,
                   [](std::span<const double> x) { return x[0] * std::sin(x[1]) * (1.0 + x[2]); });

// Mean of R independent estimates against the exact value: within 4 standard errors of the mean
// (sample SD of the R estimates / √R). False-alarm probability 7.5e-5 per check (Student's t with
// R − 1 = 399 degrees of freedom; the estimates are means of 64 bounded values, close to normal).
template <class F, class MakePoints>
void expect_unbiased(const F& f, MakePoints make_points, const std::string& method) {
  constexpr int runs = 400;
  welford w;
  for (int r = 0; r < runs; ++r) w.add(monte_carlo(f, make_points(f.dimension(), r)).value);
  const double exact = f.info().exact;
  EXPECT_NEAR(w.mean(), exact, 4.0 * w.std_error())
      << method << " on " << f.info().name << ": mean of " << runs << " runs";
}

// N = 64 = 64¹ = 8² = 4³ is a valid stratified size in 1, 2 and 3 dimensions.
constexpr std::uint64_t n = 64;

// Under either generator (core/rng.hpp): the statistics are the same, only the numbers differ.
class MonteCarloWithGenerator : public ::testing::TestWithParam<rng_kind> {};

TEST_P(MonteCarloWithGenerator, EveryPointSetIsUnbiasedOnThreeIntegrands) {
  const rng_kind g = GetParam();
  auto check = [g](const auto& f) {
    expect_unbiased(
        f, [g](std::size_t s, int r) { return independent_points(s, n, 1, r, g); }, "independent");
    expect_unbiased(
        f, [g](std::size_t s, int r) { return jittered_points(s, n, 2, r, g); }, "jittered");
    expect_unbiased(
        f, [g](std::size_t s, int r) { return unjittered_points(s, n, 3, r, g); },
        "shifted unjittered");
    expect_unbiased(
        f, [g](std::size_t s, int r) { return padded_jittered_points(s, n, 4, r, g); },
        "padded jittered");
    expect_unbiased(
        f, [g](std::size_t s, int r) { return latin_hypercube_points(s, n, 5, r, g); },
        "latin hypercube");
  };
  check(square);
  check(exponential);
  check(product);
}

INSTANTIATE_TEST_SUITE_P(BothGenerators, MonteCarloWithGenerator,
                         ::testing::Values(rng_kind::philox4x32_10, rng_kind::ars4x32_7),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(MonteCarlo, UnshiftedCentresAreTheMidpointRule) {
  // Midpoint rule on 64 panels for x² on [0,2]: exact − M = (b−a)h²f″/24 = 2·(1/32)²·2/24.
  const estimate e = monte_carlo(square, unjittered_points(1, 64));
  EXPECT_NEAR(square.info().exact - e.value, 2.0 * std::pow(1.0 / 32, 2) * 2.0 / 24.0, 1e-14);
  EXPECT_TRUE(std::isnan(e.std_error));
}

// Least-squares slope of log RMSE against log N, with a 95% confidence interval from the
// residuals (Student t with points − 2 degrees of freedom).
struct slope_fit {
  double slope, half_width;
};
slope_fit fit_slope(const std::vector<double>& n_values, const std::vector<double>& rmse) {
  const std::size_t m = n_values.size();
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < m; ++i) {
    mx += std::log(n_values[i]) / double(m);
    my += std::log(rmse[i]) / double(m);
  }
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < m; ++i) {
    sxx += std::pow(std::log(n_values[i]) - mx, 2);
    sxy += (std::log(n_values[i]) - mx) * (std::log(rmse[i]) - my);
  }
  const double b = sxy / sxx;
  double ssr = 0;
  for (std::size_t i = 0; i < m; ++i) {
    ssr += std::pow(std::log(rmse[i]) - my - b * (std::log(n_values[i]) - mx), 2);
  }
  const double se = std::sqrt(ssr / double(m - 2) / sxx);
  const double t =
      boost::math::quantile(boost::math::complement(boost::math::students_t(double(m - 2)), 0.025));
  return {b, t * se};
}

// RMSE over `reps` jittered runs at N = k² for each k.
template <class F>
slope_fit jittered_slope(const F& f, const std::vector<std::uint64_t>& ks, int reps,
                         std::uint64_t seed) {
  std::vector<double> ns, rmse;
  for (std::uint64_t k : ks) {
    double sq = 0;
    for (int r = 0; r < reps; ++r) {
      const double err =
          monte_carlo(f, jittered_points(2, k * k, seed, k * 1000 + r)).value - f.info().exact;
      sq += err * err;
    }
    ns.push_back(double(k * k));
    rmse.push_back(std::sqrt(sq / reps));
  }
  return slope_fit(fit_slope(ns, rmse));
}

// How far a fitted slope can stray by chance. The R = 64 errors at each N are independent and
// close to N(0, σ_N²) (sums of N independent stratum terms), so RMSE_N² = σ_N²·χ²_R/R and the
// OLS slope of ln RMSE on x = ln N is b + S, b the slope of the exact ln σ_N over the ladder and
//   S = Σ_i w_i·½ln(χ²_{R,i}/R),  w_i = (x_i − x̄)/Sxx,  E e^{λS} = Π_i (2/R)^{λw_i/2}·Γ(R/2 +
//   λw_i/2)/Γ(R/2)
// exactly (Σ w_i = 0 cancels the mean of the log). Chernoff's bound, P(S ≥ c) ≤ min_{λ>0}
// e^{−λc}·E e^{λS} and the same for −S, gives the false-alarm probabilities below. Both ladders
// have Sxx ≈ 28.9, so sd S = √(ψ′(32)/(4·Sxx)) = 0.0166 and P(|S| ≥ 0.0746) ≤ 1e-4.

// Theory (docs/theory.md#jittered; [Mitchell 1996]): RMSE ∝ N^(−1/2 − 1/s) = N^−1 for a smooth f in
// s = 2. 9 values of N from 16 to 4096, 64 repetitions each. Exact σ_N (cell variances of e^x·e^y
// in closed form, E_cell[g²] and E_cell[g]² per axis) has slope −0.99938 over this ladder, a bias
// of 6e-4, so |slope + 1| ≤ 0.08 fails by chance with probability ≤ 2.8e-5 (the stratum sums have
// negative excess kurtosis, ≈ −1.2/N, which only narrows S). The band excludes plain MC's −1/2:
// jittering that gained nothing, or a pre-asymptotic slope off by 0.1, fails.
TEST(MonteCarlo, JitteredRmseSlopeOnASmoothIntegrandIsMinusOne) {
  const slope_fit fit = jittered_slope(exponential, {4, 6, 8, 12, 16, 24, 32, 48, 64}, 64, 11);
  std::cout << "[ measured ] jittered, e^(x+y): slope " << fit.slope << " ± " << fit.half_width
            << " (95%), theory −1\n";
  EXPECT_NEAR(fit.slope, -1.0, 0.08);
}

// Indicator of the disk of radius 0.4 centred in the unit square, area 0.16π. Theory:
// N^(−1/2 − 1/(2s)) = N^−0.75 (only the ≈ 4·0.4·π·k strata cut by the circle contribute).
// 9 values of N from 64 to 16384, 64 repetitions each. The exact σ_N (Σ over the cut cells of
// p(1 − p)/N², p the area fraction of the disk in the cell, from the antiderivative of
// √(r² − x²); the areas sum to 0.16π within 1e-13) has slope −0.7457 over this ladder, a bias of
// 0.0043; the per-repetition errors have excess kurtosis ≤ 0.065 (at k = 8), which widens S by
// ≤ 2%. So |slope + 0.75| ≤ 0.09 fails by chance with probability ≤ 7.2e-6, and the band
// excludes both neighbouring rates, −1/2 (plain MC) and −1 (the smooth rate), by 0.16.
TEST(MonteCarlo, JitteredRmseSlopeOnADiskIndicatorIsMinusThreeQuarters) {
  const auto disk = make_integrand("disk r=0.4", box::unit(2), std::numbers::pi * 0.16,
                                   [](std::span<const double> x) {
                                     const double dx = x[0] - 0.5, dy = x[1] - 0.5;
                                     return dx * dx + dy * dy < 0.16 ? 1.0 : 0.0;
                                   });
  const slope_fit fit = jittered_slope(disk, {8, 11, 16, 23, 32, 45, 64, 90, 128}, 64, 12);
  std::cout << "[ measured ] jittered, disk indicator: slope " << fit.slope << " ± "
            << fit.half_width << " (95%), theory −0.75\n";
  EXPECT_NEAR(fit.slope, -0.75, 0.09);
}

// An additive integrand f = Σⱼ xⱼ² in s = 5: Latin hypercube sampling removes the additive part
// from the variance (Stein 1987), leaving only the within-row part. Exact variances at N = 1024:
// plain Var(Σx²)/N = 5·(4/45)/N = 4.3e-4; LHS Σ_j (1/N²)Σ_rows Var_row(x_j²) ≈ 5·(4/3)/(12N³) =
// 5.2e-10, a true ratio ρ ≈ 8e5. The observed ratio is ρ·F with F ~ F(63, 63) (normal values),
// whose 1e-4 lower quantile is ≈ 0.38, so "ratio > 100" fails by chance only if F < 1.2e-4:
// never in practice. It fails for any LHS that does not stratify every axis (ratio ≈ 1, and
// F(63, 63)'s 1e-4 upper quantile is ≈ 2.6). The mean check uses Student's t with 63 degrees
// of freedom: 4.5 standard errors, false alarm 3e-5.
TEST(MonteCarlo, LatinHypercubeBeatsPlainMonteCarloOnAnAdditiveIntegrand) {
  const auto additive =
      make_integrand("sum x_j^2", box::unit(5), 5.0 / 3.0, [](std::span<const double> x) {
        double s = 0;
        for (double v : x) s += v * v;
        return s;
      });
  welford plain, lhs;
  for (int r = 0; r < 64; ++r) {
    plain.add(monte_carlo(additive, independent_points(5, 1024, 21, r)).value);
    lhs.add(monte_carlo(additive, latin_hypercube_points(5, 1024, 22, r)).value);
  }
  std::cout << "[ measured ] additive s=5, N=1024: Var plain / Var LHS = "
            << plain.variance() / lhs.variance() << "\n";
  EXPECT_GT(plain.variance() / lhs.variance(), 100.0);
  EXPECT_NEAR(lhs.mean(), 5.0 / 3.0, 4.5 * lhs.std_error());
}

TEST(MonteCarlo, RejectsAPointSetOfTheWrongDimension) {
  try {
    monte_carlo(exponential, independent_points(3, 10, 1, 1));
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("point set dimension = 3"), std::string::npos) << e.what();
  }
}

TEST(MonteCarlo, ReportsTheIntegrandAndPointOfANonFiniteValue) {
  const auto singular = make_integrand("1/x", box::unit(1), NAN, [](std::span<const double> x) {
    return x[0] < 0.5 ? std::numeric_limits<double>::infinity() : 1.0;
  });
  try {
    monte_carlo(singular, unjittered_points(1, 4));
    FAIL();
  } catch (const non_finite_value& e) {
    EXPECT_STREQ(e.what(), "1/x returned inf at x = (0.125)");
  }
}

}  // namespace
