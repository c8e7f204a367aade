// The geometric Asian call: its closed form [Kemna & Vorst 1990] against integrals computed here
// without it, the three path constructions against the covariance min(tᵢ, tⱼ) they must
// reproduce (and the pca one against a numeric eigen-decomposition), plain Monte Carlo against
// the exact mean and variance, and the errors of the catalogue's keys
// (docs/theory.md#the-geometric-asian-option).
#include "quadmc/functions/geometric_asian.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "reference_quadrature.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>
#include <boost/math/special_functions/erf.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace quadmc {
namespace {

using test::at;
using test::gauss_kronrod;

constexpr path_construction all_constructions[] = {
    path_construction::standard, path_construction::bridge, path_construction::pca};

double phi(double z) {
  return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
}

// log G at the normals z by the test's own standard path (cumulative sums), as the definition
// reads: no closed form, no library code.
double log_g(const geometric_asian_parameters& p, std::span<const double> z) {
  const std::size_t s = z.size();
  const double dt = p.maturity / static_cast<double>(s);
  double w = 0.0, log_sum = 0.0;
  for (std::size_t i = 0; i < s; ++i) {
    w += std::sqrt(dt) * z[i];
    const double t = dt * static_cast<double>(i + 1);
    log_sum +=
        std::log(p.spot) + (p.rate - 0.5 * p.volatility * p.volatility) * t + p.volatility * w;
  }
  return log_sum / static_cast<double>(s);
}

double payoff(const geometric_asian_parameters& p, std::span<const double> z) {
  return std::exp(-p.rate * p.maturity) * std::max(std::exp(log_g(p, z)) - p.strike, 0.0);
}

// E payoff(Z) over Z ~ N(0, I_s) by nested Gauss–Kronrod on [−L, L]^s. φ(10) ≈ 8e-23 and the
// payoff grows at most like e^(σ√T·|z|): the tails beyond L = 10 are below 1e-18 of the price
// for these parameters. The innermost integral splits at the kink, where the last z makes
// log G = log K: along the standard path log G is affine in z_s with slope σ√Δt/s.
double nested_expectation(const geometric_asian_parameters& p, std::size_t s) {
  constexpr double L = 10.0;
  std::vector<double> z(s, 0.0);
  const double slope =
      p.volatility * std::sqrt(p.maturity / static_cast<double>(s)) / static_cast<double>(s);
  std::function<double(std::size_t)> level = [&](std::size_t j) -> double {
    std::vector<double> breaks;
    if (j + 1 == s) {
      z[j] = 0.0;
      breaks.push_back((std::log(p.strike) - log_g(p, z)) / slope);
    }
    return gauss_kronrod(
        [&, j](double v) {
          z[j] = v;
          return phi(v) * (j + 1 == s ? payoff(p, z) : level(j + 1));
        },
        -L, L, breaks);
  };
  return level(0);
}

// E payoff by one integral over log G ~ N(μ, v), with μ and v summed from their definitions
// (μ = log S₀ + (r − σ²/2)·mean tᵢ, v = σ²·(1/s²)ΣᵢΣⱼ min(tᵢ, tⱼ)) rather than taken from the
// closed sums, and the lognormal payoff integrated numerically from the kink y = log K: this
// checks the Black–Scholes-like formula and the two sums at any s.
double lognormal_expectation(const geometric_asian_parameters& p, std::size_t s) {
  const double dt = p.maturity / static_cast<double>(s);
  double mean_t = 0.0, covariance_sum = 0.0;
  for (std::size_t i = 1; i <= s; ++i) {
    mean_t += dt * static_cast<double>(i);
    for (std::size_t j = 1; j <= s; ++j) covariance_sum += dt * static_cast<double>(std::min(i, j));
  }
  const double sd = static_cast<double>(s);
  const double mu = std::log(p.spot) + (p.rate - 0.5 * p.volatility * p.volatility) * (mean_t / sd);
  const double root_v = p.volatility * std::sqrt(covariance_sum) / sd;
  // y = μ + √v·u with u ≥ (log K − μ)/√v, up to 12 standard deviations (φ(12) ≈ 5e-32).
  const double u0 = (std::log(p.strike) - mu) / root_v;
  const double integral =
      gauss_kronrod([&](double u) { return phi(u) * (std::exp(mu + root_v * u) - p.strike); },
                    std::max(u0, -12.0), std::max(u0, -12.0) + 24.0);
  return std::exp(-p.rate * p.maturity) * integral;
}

geometric_asian_parameters with(double spot, double strike, double rate, double volatility,
                                double maturity) {
  geometric_asian_parameters p;
  p.spot = spot;
  p.strike = strike;
  p.rate = rate;
  p.volatility = volatility;
  p.maturity = maturity;
  return p;
}

const geometric_asian_parameters cases[] = {
    with(100, 100, 0.05, 0.2, 1.0),   // the catalogue's default
    with(100, 120, 0.02, 0.35, 2.0),  // out of the money
    with(100, 80, -0.01, 0.1, 0.5),   // in the money, negative rate
};

TEST(GeometricAsian, DefaultAtOneMonitoringTimeIsTheBlackScholesCall) {
  // s = 1: G = S(T), the European call. 10.450583572185591 is the Black–Scholes formula for
  // S₀ = K = 100, r = 5 %, σ = 20 %, T = 1 evaluated in Python (math.erfc), apart from this code.
  EXPECT_LE(test::relative_error(geometric_asian(1, {}).info().exact, 10.450583572185591), 1e-14);
  const any_integrand f = make_integrand("geometric_asian", integrand_params{});
  EXPECT_EQ(f.dimension(), 1u);
  EXPECT_EQ(f.info().exact, geometric_asian::exact_value(1, {}));
  EXPECT_EQ(to_string(f.info().regularity), std::string("C0"));
}

TEST(GeometricAsian, ClosedFormAgreesWithNestedGaussKronrodOverTheNormals) {
  for (const geometric_asian_parameters& p : cases) {
    for (std::size_t s : {1u, 2u, 3u}) {
      const double exact = geometric_asian::exact_value(s, p);
      const double nested = nested_expectation(p, s);
      EXPECT_LE(test::relative_error(nested, exact), 1e-13)
          << "s = " << s << ", K = " << p.strike << ": nested " << nested << ", closed form "
          << exact;
    }
  }
}

TEST(GeometricAsian, ClosedFormAgreesWithTheLognormalIntegral) {
  for (const geometric_asian_parameters& p : cases) {
    for (std::size_t s : {1u, 2u, 4u, 16u, 100u, 1024u}) {
      const double exact = geometric_asian::exact_value(s, p);
      const double integral = lognormal_expectation(p, s);
      EXPECT_LE(test::relative_error(integral, exact), 1e-13)
          << "s = " << s << ", K = " << p.strike << ": integral " << integral << ", closed form "
          << exact;
    }
  }
}

// The closed form evaluated again in 50-digit arithmetic (Boost.Multiprecision, erfc of Boost.Math
// at that precision), from the formula written out here. The double code's own rounding is a few
// units in the last place, more where e^(μ+v/2)·Φ(d₁) − K·Φ(d₂) cancels (far out of the money):
// 1e-13 relative, as against the quadratures above, holds for these three cases.
TEST(GeometricAsian, ClosedFormAgreesWithA50DigitEvaluation) {
  using big = boost::multiprecision::cpp_bin_float_50;
  for (const geometric_asian_parameters& p : cases) {
    for (std::size_t s : {1u, 16u, 256u, 1024u}) {
      const big n = s, spot = p.spot, strike = p.strike, rate = p.rate, sigma = p.volatility,
                maturity = p.maturity;
      const big mu = log(spot) + (rate - sigma * sigma / 2) * maturity * (n + 1) / (2 * n);
      const big v = sigma * sigma * maturity * (n + 1) * (2 * n + 1) / (6 * n * n);
      const big d2 = (mu - log(strike)) / sqrt(v), d1 = d2 + sqrt(v);
      const auto phi = [](const big& x) {
        return boost::math::erfc(-x / boost::multiprecision::sqrt(big(2))) / 2;
      };
      const big price = exp(-rate * maturity) * (exp(mu + v / 2) * phi(d1) - strike * phi(d2));
      const double exact = geometric_asian::exact_value(s, p);
      EXPECT_LE(test::relative_error(exact, static_cast<double>(price)), 1e-13)
          << "s = " << s << ", K = " << p.strike << ": " << exact << " against " << price.str(20);
    }
  }
}

// The matrix A with W = A·z, column k the path of the k-th unit vector (every construction is
// linear in z).
std::vector<double> path_matrix(const geometric_asian& f) {
  const std::size_t s = f.dimension();
  std::vector<double> a(s * s), e(s, 0.0), w(s);
  for (std::size_t k = 0; k < s; ++k) {
    e[k] = 1.0;
    f.path(e, w);
    e[k] = 0.0;
    for (std::size_t i = 0; i < s; ++i) a[i * s + k] = w[i];
  }
  return a;
}

TEST(GeometricAsian, EveryConstructionReproducesTheBrownianCovariance) {
  for (path_construction c : all_constructions) {
    for (double maturity : {1.0, 2.5}) {
      for (std::size_t s : {1u, 2u, 3u, 5u, 8u, 17u, 64u, 100u}) {
        geometric_asian_parameters p;
        p.maturity = maturity;
        p.construction = c;
        const geometric_asian f(s, p);
        const std::vector<double> a = path_matrix(f);
        const double dt = maturity / static_cast<double>(s);
        double worst = 0.0;
        for (std::size_t i = 0; i < s; ++i) {
          for (std::size_t j = 0; j < s; ++j) {
            double c_ij = 0.0;
            for (std::size_t k = 0; k < s; ++k) c_ij += a[i * s + k] * a[j * s + k];
            const double expected = dt * static_cast<double>(std::min(i, j) + 1);
            worst = std::max(worst, std::abs(c_ij - expected));
          }
        }
        EXPECT_LE(worst, 1e-13 * maturity) << to_string(c) << ", s = " << s << ", T = " << maturity;
      }
    }
  }
}

TEST(GeometricAsian, BridgeFixesTheEndPointFirstAndPcaOrdersTheVariance) {
  geometric_asian_parameters p;
  p.construction = path_construction::bridge;
  const std::size_t s = 16;
  const std::vector<double> bridge = path_matrix(geometric_asian(s, p));
  // z₁ alone sets W(T) = √T·z₁, and W(T/2) = W(T)/2 + √(T/4)·z₂: the dyadic midpoints.
  EXPECT_NEAR(bridge[(s - 1) * s + 0], 1.0, 1e-15);
  for (std::size_t k = 1; k < s; ++k) EXPECT_EQ(bridge[(s - 1) * s + k], 0.0) << k;
  EXPECT_NEAR(bridge[(s / 2 - 1) * s + 0], 0.5, 1e-15);
  EXPECT_NEAR(bridge[(s / 2 - 1) * s + 1], 0.5, 1e-15);
  // pca: column norms² are the eigenvalues, in decreasing order.
  p.construction = path_construction::pca;
  const std::vector<double> pca = path_matrix(geometric_asian(s, p));
  double previous = INFINITY;
  for (std::size_t k = 0; k < s; ++k) {
    double norm2 = 0.0;
    for (std::size_t i = 0; i < s; ++i) norm2 += pca[i * s + k] * pca[i * s + k];
    EXPECT_LT(norm2, previous) << "column " << k;
    previous = norm2;
  }
}

// Eigenvalues of a symmetric matrix by cyclic Jacobi rotations, sorted in decreasing order: a
// numeric decomposition, apart from the closed form it checks.
std::vector<double> jacobi_eigenvalues(std::vector<double> m, std::size_t n) {
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) off += m[i * n + j] * m[i * n + j];
    if (off < 1e-40) break;
    for (std::size_t p = 0; p < n; ++p) {
      for (std::size_t q = p + 1; q < n; ++q) {
        if (m[p * n + q] == 0.0) continue;
        const double theta = (m[q * n + q] - m[p * n + p]) / (2.0 * m[p * n + q]);
        const double t = std::copysign(1.0, theta) / (std::abs(theta) + std::hypot(theta, 1.0));
        const double c = 1.0 / std::hypot(t, 1.0), sn = t * c;
        for (std::size_t k = 0; k < n; ++k) {  // columns p, q
          const double mkp = m[k * n + p], mkq = m[k * n + q];
          m[k * n + p] = c * mkp - sn * mkq;
          m[k * n + q] = sn * mkp + c * mkq;
        }
        for (std::size_t k = 0; k < n; ++k) {  // rows p, q
          const double mpk = m[p * n + k], mqk = m[q * n + k];
          m[p * n + k] = c * mpk - sn * mqk;
          m[q * n + k] = sn * mpk + c * mqk;
        }
      }
    }
  }
  std::vector<double> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = m[i * n + i];
  std::sort(d.begin(), d.end(), std::greater<>());
  return d;
}

TEST(GeometricAsian, PcaColumnsAreTheNumericEigenpairsOfTheCovariance) {
  for (std::size_t s : {2u, 5u, 12u, 33u}) {
    geometric_asian_parameters p;
    p.maturity = 1.5;
    p.construction = path_construction::pca;
    const std::vector<double> a = path_matrix(geometric_asian(s, p));
    const double dt = p.maturity / static_cast<double>(s);
    std::vector<double> c(s * s);
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j)
        c[i * s + j] = dt * static_cast<double>(std::min(i, j) + 1);
    const std::vector<double> lambda = jacobi_eigenvalues(c, s);
    // AᵀA = Λ: the columns √λₖ·vₖ are orthogonal, with norms² the numeric eigenvalues.
    for (std::size_t k = 0; k < s; ++k) {
      for (std::size_t l = 0; l < s; ++l) {
        double g = 0.0;
        for (std::size_t i = 0; i < s; ++i) g += a[i * s + k] * a[i * s + l];
        if (k == l) {
          EXPECT_LE(std::abs(g - lambda[k]), 1e-13 * lambda[0]) << "s = " << s << ", λ" << k + 1;
        } else {
          EXPECT_LE(std::abs(g), 1e-13 * lambda[0])
              << "s = " << s << ", columns " << k << ", " << l;
        }
      }
    }
  }
}

TEST(GeometricAsian, StandardPathIsTheDefinitionAndFacesAreZero) {
  const geometric_asian_parameters p = cases[0];
  const std::size_t s = 4;
  const geometric_asian f(s, p);
  const random_stream rng(3, 0);
  std::vector<double> x(s), z(s);
  for (std::uint64_t n = 0; n < 50; ++n) {
    rng.fill_uniform(n * s, x);
    for (std::size_t j = 0; j < s; ++j) {
      z[j] = -std::numbers::sqrt2 * boost::math::erfc_inv(2.0 * x[j]);
    }
    const double expected = payoff(p, z);
    EXPECT_NEAR(at(f, x), expected, 1e-12 * (1.0 + expected)) << "point " << n;
  }
  EXPECT_EQ(at(f, {0.0, 0.5, 0.5, 0.5}), 0.0);
  EXPECT_EQ(at(f, {0.9, 0.9, 1.0, 0.9}), 0.0);
  EXPECT_TRUE(std::isnan(at(f, {0.5, 1.5, 0.5, 0.5})));
  EXPECT_TRUE(std::isnan(at(f, {0.5, 0.5, NAN, 0.5})));
  // Every value at a double next to a face is finite, even at s = 1024 (the constructor's bound).
  for (path_construction c : all_constructions) {
    geometric_asian_parameters q;
    q.construction = c;
    const geometric_asian g(1024, q);
    std::vector<double> high(1024, 1.0 - 0x1p-53), low(1024, 0x1p-1074);
    EXPECT_TRUE(std::isfinite(at(g, high))) << to_string(c);
    EXPECT_EQ(at(g, low), 0.0) << to_string(c);
  }
}

// E Yʲ for Y = e^(−rT)·max(G − K, 0), log G ~ N(μ, v): Σₘ C(j, m)(−K)^(j−m)·E[Gᵐ; G > K] with
// E[Gᵐ; G > K] = e^(mμ + m²v/2)·Φ(d₂ + m√v) (the lognormal's partial moments).
double raw_moment(std::size_t s, const geometric_asian_parameters& p, int j) {
  const double sd = static_cast<double>(s);
  const double mu = std::log(p.spot) +
                    (p.rate - 0.5 * p.volatility * p.volatility) * p.maturity * (sd + 1) / (2 * sd);
  const double v =
      p.volatility * p.volatility * p.maturity * (sd + 1) * (2 * sd + 1) / (6 * sd * sd);
  const double d2 = (mu - std::log(p.strike)) / std::sqrt(v);
  double sum = 0.0, binomial = 1.0;
  for (int m = 0; m <= j; ++m) {
    const double partial = std::exp(m * mu + m * m * v / 2) * 0.5 *
                           std::erfc(-(d2 + m * std::sqrt(v)) / std::numbers::sqrt2);
    sum += binomial * std::pow(-p.strike, j - m) * partial;
    binomial = binomial * (j - m) / (m + 1);
  }
  return std::pow(std::exp(-p.rate * p.maturity), j) * sum;
}

TEST(GeometricAsian, PlainMonteCarloMeanAndVarianceWithinStatisticalBounds) {
  // N = 2^16 Philox points (seed 17) per construction at s = 16 and 64. The mean is checked to
  // 4.9 standard errors (two-sided normal tail 1e-6), the sample variance to 4.9 of its own
  // standard error √((μ₄ − σ⁴)/N) (μ₄ the exact fourth central moment): 2 checks × 3
  // constructions × 2 dimensions = 12 checks, a false alarm with probability ≤ 12e-6 < 1e-4
  // (the sample means and variances are sums of 65536 terms with finite fourth (eighth) moments,
  // so the normal approximation holds to far better than these margins need).
  constexpr std::size_t n = 1u << 16;
  constexpr double z = 4.9;
  for (std::size_t s : {16u, 64u}) {
    const random_stream rng(17, s);
    std::vector<double> x(n * s), y(n);
    rng.fill_uniform(0, x);
    const geometric_asian_parameters p0 = cases[0];
    const double m1 = raw_moment(s, p0, 1), m2 = raw_moment(s, p0, 2);
    const double m3 = raw_moment(s, p0, 3), m4 = raw_moment(s, p0, 4);
    const double variance = m2 - m1 * m1;
    const double mu4 = m4 - 4 * m1 * m3 + 6 * m1 * m1 * m2 - 3 * m1 * m1 * m1 * m1;
    EXPECT_LE(test::relative_error(m1, geometric_asian::exact_value(s, p0)), 1e-13);
    for (path_construction c : all_constructions) {
      geometric_asian_parameters p = p0;
      p.construction = c;
      const geometric_asian f(s, p);
      f.evaluate(x, y);
      double mean = 0.0;
      for (double v : y) mean += v;
      mean /= n;
      double sample_variance = 0.0;
      for (double v : y) sample_variance += (v - mean) * (v - mean);
      sample_variance /= n - 1;
      const double nd = static_cast<double>(n);
      EXPECT_LE(std::abs(mean - m1), z * std::sqrt(variance / nd))
          << to_string(c) << ", s = " << s << ": mean " << mean << ", exact " << m1;
      EXPECT_LE(std::abs(sample_variance - variance),
                z * std::sqrt((mu4 - variance * variance) / nd))
          << to_string(c) << ", s = " << s << ": variance " << sample_variance << ", exact "
          << variance;
    }
  }
}

std::string asian_error_of(const integrand_params& p) {
  return test_support::message_of([&p] { make_integrand("geometric_asian", p); });
}

TEST(GeometricAsian, BadKeysAndValuesAreNamed) {
  integrand_params p;
  p.dimension = 4;
  p.strings["construction"] = "brownian";
  EXPECT_EQ(asian_error_of(p),
            "invalid construction: expected one of \"standard\", \"bridge\", \"pca\", got "
            "\"brownian\"");
  p = {};
  p.scalars["construction"] = 1.0;
  EXPECT_EQ(asian_error_of(p),
            "invalid construction: expected a string, one of \"standard\", \"bridge\", \"pca\", "
            "for geometric_asian, got 1");
  p = {};
  p.vectors["construction"] = {1.0};
  EXPECT_EQ(asian_error_of(p),
            "invalid construction: expected a string, one of \"standard\", \"bridge\", \"pca\", "
            "for geometric_asian, got an array");
  p = {};
  p.strings["spot"] = "high";
  EXPECT_EQ(asian_error_of(p), "invalid spot: expected a number for geometric_asian, got \"high\"");
  p = {};
  p.strings["kind"] = "call";
  EXPECT_EQ(asian_error_of(p),
            "invalid kind: unknown key: not a parameter of geometric_asian (its parameters: "
            "arrays: none; numbers: spot, strike, rate, volatility, maturity; strings: "
            "construction)");
  for (const char* key : {"spot", "strike", "volatility", "maturity"}) {
    for (double bad : {0.0, -1.0, double(INFINITY), double(NAN)}) {
      p = {};
      p.scalars[key] = bad;
      EXPECT_EQ(asian_error_of(p).rfind(std::string("invalid ") + key + " = ", 0), 0u)
          << key << " = " << bad << ": " << asian_error_of(p);
    }
  }
  p = {};
  p.scalars["rate"] = INFINITY;
  EXPECT_EQ(asian_error_of(p).rfind("invalid rate = inf", 0), 0u) << asian_error_of(p);
  p = {};
  p.dimension = 1025;
  EXPECT_EQ(asian_error_of(p), "invalid dimension = 1025: expected 1 ≤ s ≤ 1024");
  // σ = 1 at s = 1024: a node next to a face could overflow G, so it is refused up front.
  p.dimension = 1024;
  p.scalars["volatility"] = 1.0;
  EXPECT_EQ(asian_error_of(p).rfind("invalid volatility = 1: expected |log S₀", 0), 0u)
      << asian_error_of(p);
  // Every key taken, and a string key given the way a scene gives it.
  p = {};
  p.dimension = 8;
  p.scalars = {{"spot", 90}, {"strike", 95}, {"rate", 0.03}, {"volatility", 0.3}, {"maturity", 2}};
  p.strings["construction"] = "pca";
  const any_integrand f = make_integrand("geometric_asian", p);
  EXPECT_EQ(f.info().exact, geometric_asian::exact_value(8, with(90, 95, 0.03, 0.3, 2)));
}

}  // namespace
}  // namespace quadmc
