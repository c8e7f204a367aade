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
// (sample SD of the R estimates / √R). False-alarm probability ≈ 6e-5 per check (normal tail;
// the estimates are means of 64 bounded values, close to normal).
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

TEST(MonteCarlo, EveryPointSetIsUnbiasedOnThreeIntegrands) {
  auto check = [](const auto& f) {
    expect_unbiased(
        f, [](std::size_t s, int r) { return independent_points(s, n, 1, r); }, "independent");
    expect_unbiased(
        f, [](std::size_t s, int r) { return jittered_points(s, n, 2, r); }, "jittered");
    expect_unbiased(
        f, [](std::size_t s, int r) { return unjittered_points(s, n, 3, r); },
        "shifted unjittered");
    expect_unbiased(
        f, [](std::size_t s, int r) { return padded_jittered_points(s, n, 4, r); },
        "padded jittered");
    expect_unbiased(
        f, [](std::size_t s, int r) { return latin_hypercube_points(s, n, 5, r); },
        "latin hypercube");
  };
  check(square);
  check(exponential);
  check(product);
}

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

// Theory (docs/theory.md#jittered; [Mitchell 1996]): RMSE ∝ N^(−1/2 − 1/s) = N^−1 for a smooth f in
// s = 2. 9 values of N from 16 to 4096, 64 repetitions each: the RMSE of each N is known to ≈ 9%
// (relative SD of a root mean square of 64 squares ≈ 1/√(2·64)), which puts the slope's
// standard error near 0.02. Tolerance ±0.12 around −1 (≈ 6 of those standard errors, and room
// for the pre-asymptotic curvature at N = 16); the fitted 95% interval must exclude −1/2.
TEST(MonteCarlo, JitteredRmseSlopeOnASmoothIntegrandIsMinusOne) {
  const slope_fit fit = jittered_slope(exponential, {4, 6, 8, 12, 16, 24, 32, 48, 64}, 64, 11);
  std::cout << "[ measured ] jittered, e^(x+y): slope " << fit.slope << " ± " << fit.half_width
            << " (95%), theory −1\n";
  EXPECT_NEAR(fit.slope, -1.0, 0.12);
  EXPECT_LT(fit.slope + fit.half_width, -0.5);
}

// Indicator of the disk of radius 0.4 centred in the unit square, area 0.16π. Theory:
// N^(−1/2 − 1/(2s)) = N^−0.75 (only the ≈ 4·0.4·π·k strata cut by the circle contribute).
// 9 values of N from 64 to 16384, 64 repetitions each; tolerance ±0.12 as above, and the 95%
// interval must exclude both −1/2 (plain MC) and −1 (the smooth rate).
TEST(MonteCarlo, JitteredRmseSlopeOnADiskIndicatorIsMinusThreeQuarters) {
  const auto disk = make_integrand("disk r=0.4", box::unit(2), std::numbers::pi * 0.16,
                                   [](std::span<const double> x) {
                                     const double dx = x[0] - 0.5, dy = x[1] - 0.5;
                                     return dx * dx + dy * dy < 0.16 ? 1.0 : 0.0;
                                   });
  const slope_fit fit = jittered_slope(disk, {8, 11, 16, 23, 32, 45, 64, 90, 128}, 64, 12);
  std::cout << "[ measured ] jittered, disk indicator: slope " << fit.slope << " ± "
            << fit.half_width << " (95%), theory −0.75\n";
  EXPECT_NEAR(fit.slope, -0.75, 0.12);
  EXPECT_LT(fit.slope + fit.half_width, -0.5);
  EXPECT_GT(fit.slope - fit.half_width, -1.0);
}

// An additive integrand f = Σⱼ xⱼ² in s = 5: Latin hypercube sampling removes the additive part
// from the variance (Stein 1987), leaving only the O(1/N²)-order within-row part. Variances over
// 64 runs at N = 1024; for equal true variances the ratio would follow F(63, 63), whose 1e-4
// upper quantile is ≈ 2.6: we assert plain/LHS > 100 (false alarm far below 1e-4).
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
  EXPECT_NEAR(lhs.mean(), 5.0 / 3.0, 4 * lhs.std_error());
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
