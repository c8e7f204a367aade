// exact_effective_dimensions against an independent brute-force ANOVA (s = 4, every separable
// family: real and complex factors, kinks and jumps), against the closed form of identical factors
// at s = 1024 (where a naive product overflows), and on its edge cases; the pick-freeze estimate
// (effective_dimension_estimate.hpp) against the exact form.
#include "quadmc/functions/effective_dimension.hpp"

#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/effective_dimension_estimate.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/functions/geometric_asian.hpp"
#include "quadmc/functions/sobol_g.hpp"
#include "support/invalid_argument_message.hpp"

#include <gtest/gtest.h>
#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace quadmc;

constexpr std::size_t s = 4;

// A product rule on [0, 1] per axis: Gauss–Legendre (Boost.Math, not the rules layer), 16 nodes
// on [0, 1] for a smooth factor, 10 on each piece between the breakpoints of one with a kink or
// jump (an exponential on each piece, integrated to ~1e-15 by 10 nodes), so a kink or jump
// sits on a piece boundary. 16⁴ or 20⁴ grid points keep the brute force quick under ASan.
struct axis_rule {
  std::vector<double> nodes, weights;
};

template <class Gauss>
void add_piece(axis_rule& rule, double lo, double hi) {
  const double half = 0.5 * (hi - lo), mid = lo + half;
  for (std::size_t k = 0; k < Gauss::abscissa().size(); ++k) {
    const double t = Gauss::abscissa()[k], w = Gauss::weights()[k];
    rule.nodes.push_back(mid + half * t);
    rule.weights.push_back(half * w);
    if (t != 0.0) {
      rule.nodes.push_back(mid - half * t);
      rule.weights.push_back(half * w);
    }
  }
}

axis_rule pieces(std::vector<double> breaks) {
  axis_rule rule;
  if (breaks.empty()) {
    add_piece<boost::math::quadrature::gauss<double, 16>>(rule, 0.0, 1.0);
    return rule;
  }
  breaks.insert(breaks.begin(), 0.0);
  breaks.push_back(1.0);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    add_piece<boost::math::quadrature::gauss<double, 10>>(rule, breaks[i], breaks[i + 1]);
  }
  return rule;
}

// The ANOVA of f on the product rule, by brute force: V_v = Var E[f | x_v] for every v ⊆ {1..4}
// (the conditional means summed over the other axes of the full grid), σ²_u by inclusion–exclusion
// σ²_u = Σ_{v⊆u} (−1)^{|u|−|v|} V_v, then the shares as effective_dimensions defines them.
struct brute_force {
  double variance = 0.0;
  std::vector<double> truncation_shares, superposition_shares;
};

template <class F>
brute_force anova(const F& f, const std::array<axis_rule, s>& rules) {
  std::array<std::size_t, s> n{};
  std::size_t total = 1;
  for (std::size_t j = 0; j < s; ++j) total *= n[j] = rules[j].nodes.size();
  std::vector<double> x(total * s), y(total), w(total);
  for (std::size_t i = 0; i < total; ++i) {
    std::size_t rest = i;
    w[i] = 1.0;
    for (std::size_t j = s; j-- > 0;) {
      const std::size_t k = rest % n[j];
      rest /= n[j];
      x[i * s + j] = rules[j].nodes[k];
      w[i] *= rules[j].weights[k];
    }
  }
  f.evaluate(x, y);
  double mean = 0.0;
  for (std::size_t i = 0; i < total; ++i) mean += w[i] * y[i];
  std::array<double, 1U << s> closed{};  // V_v, v as a bit mask
  for (unsigned v = 1; v < (1U << s); ++v) {
    // E[f | x_v] on the v-grid: sum w·f over the other axes, divided by the v-axes' weights.
    std::vector<double> conditional(total, 0.0), weight(total, 0.0);
    for (std::size_t i = 0; i < total; ++i) {
      std::size_t rest = i, key = 0, stride = 1;
      for (std::size_t j = s; j-- > 0;) {
        const std::size_t k = rest % n[j];
        rest /= n[j];
        if (v & (1U << j)) {
          key += k * stride;
          stride *= n[j];
        }
      }
      conditional[key] += w[i] * y[i];
      weight[key] += w[i];
    }
    double second = 0.0;
    for (std::size_t key = 0; key < total; ++key) {
      if (weight[key] > 0.0) second += conditional[key] * conditional[key] / weight[key];
    }
    closed[v] = second - mean * mean;
  }
  std::array<double, 1U << s> sigma{};
  for (unsigned u = 1; u < (1U << s); ++u) {
    for (unsigned v = u;; v = (v - 1) & u) {
      const int sign = (__builtin_popcount(u) - __builtin_popcount(v)) % 2 == 0 ? 1 : -1;
      sigma[u] += sign * (v == 0 ? 0.0 : closed[v]);
      if (v == 0) break;
    }
  }
  brute_force out;
  out.variance = closed[(1U << s) - 1];
  for (std::size_t d = 1; d <= s; ++d) {
    out.truncation_shares.push_back(closed[(1U << d) - 1] / out.variance);
  }
  for (std::size_t k = 1; k <= s; ++k) {
    double sum = 0.0;
    for (unsigned u = 1; u < (1U << s); ++u) {
      if (static_cast<std::size_t>(__builtin_popcount(u)) <= k) sum += sigma[u];
    }
    out.superposition_shares.push_back(sum / out.variance);
  }
  return out;
}

template <class F>
void expect_brute_force(const F& f, const std::array<axis_rule, s>& rules,
                        const std::string& label) {
  const integrand_info info = f.info();
  ASSERT_TRUE(info.moments.has_value()) << label;
  const std::optional<effective_dimensions> exact = exact_effective_dimensions(*info.moments);
  ASSERT_TRUE(exact.has_value()) << label;
  const brute_force reference = anova(f, rules);
  // The rule integrates every piece to ~1e-15 and the shares are ratios of O(1) sums: 1e-10
  // leaves room for the inclusion–exclusion's cancellation.
  EXPECT_NEAR(exact->variance / reference.variance, 1.0, 1e-10) << label;
  for (std::size_t d = 0; d < s; ++d) {
    EXPECT_NEAR(exact->truncation_shares[d], reference.truncation_shares[d], 1e-10)
        << label << ", truncation d = " << d + 1;
    EXPECT_NEAR(exact->superposition_shares[d], reference.superposition_shares[d], 1e-10)
        << label << ", superposition k = " << d + 1;
  }
}

std::array<axis_rule, s> smooth() {
  return {pieces({}), pieces({}), pieces({}), pieces({})};
}
std::array<axis_rule, s> split_at(const std::vector<double>& u) {
  return {pieces({u[0]}), pieces({u[1]}), pieces({u[2]}), pieces({u[3]})};
}

// |aⱼ| ≤ 2: product peak's poles u ± i/a stay ≥ 0.5 from [0, 1], where 16 Gauss nodes reach
// ~1e-12 (the ellipse through the pole has ρ = 1 + √2: error ~ ρ^−32).
const std::vector<double> a{1.5, 1.0, 0.5, 2.0};
const std::vector<double> u{0.3, 0.7, 0.45, 0.2};

TEST(EffectiveDimension, SeparableFamiliesAgreeWithABruteForceAnova) {
  expect_brute_force(genz_gaussian(a, u), smooth(), "genz_gaussian");
  expect_brute_force(genz_product_peak(a, u), smooth(), "genz_product_peak");
  expect_brute_force(genz_oscillatory({3.0, 1.5, 5.0, 0.7}, {0.2, 0, 0, 0}), smooth(),
                     "genz_oscillatory");
  expect_brute_force(genz_continuous(a, u), split_at(u), "genz_continuous");
  // Jumps at u₁, u₂ (the cut axes); the other two factors are smooth.
  expect_brute_force(genz_discontinuous({1.0, -2.0, 0.5, 3.0}, {0.6, 0.35, 0.5, 0.5}),
                     {pieces({0.6}), pieces({0.35}), pieces({}), pieces({})}, "genz_discontinuous");
  expect_brute_force(sobol_g({0.0, 1.0, 4.5, 9.0}), split_at({0.5, 0.5, 0.5, 0.5}), "sobol_g");
}

// n identical factors with r = v/μ²: Σ_{|u|=m} σ²_u ∝ C(n, m)·r^m, so T(d)/σ² =
// ((1 + r)^d − 1)/((1 + r)^n − 1) and S(k)/σ² = Σ_{m≤k} C(n, m) r^m / ((1 + r)^n − 1), evaluated
// here in logarithms (lgamma) term by term. At n = 1024 the terms C(1024, k)·r^k the exact form
// never forms reach C(1024, 512) ≈ 1e307 before the powers of r are applied.
TEST(EffectiveDimension, IdenticalFactorsAtS1024MatchTheBinomialForm) {
  const std::size_t n = 1024;
  for (const double a_value : {1.0, 3.0, 30.0}) {  // a = 0 would give a peak of 2^1024
    const std::vector<double> as(n, a_value);
    const double r = 1.0 / (3.0 * (1.0 + a_value) * (1.0 + a_value));  // Sobol' g: μ = 1
    const std::optional<effective_dimensions> e =
        exact_effective_dimensions(*sobol_g(as).info().moments);
    ASSERT_TRUE(e.has_value());
    const double log_total = std::log(std::expm1(static_cast<double>(n) * std::log1p(r)));
    double superposition = 0.0;
    for (std::size_t k = 1; k <= n; k += 37) {
      const double kd = static_cast<double>(k);
      const double truncation = std::exp(std::log(std::expm1(kd * std::log1p(r))) - log_total);
      EXPECT_NEAR(e->truncation_shares[k - 1] / truncation, 1.0, 1e-11)
          << "a = " << a_value << ", d = " << k;
    }
    for (std::size_t m = 1; m <= n; ++m) {
      const double md = static_cast<double>(m), nd = static_cast<double>(n);
      superposition += std::exp(std::lgamma(nd + 1) - std::lgamma(md + 1) -
                                std::lgamma(nd - md + 1) + md * std::log(r) - log_total);
      if (m % 41 == 1 && superposition > 1e-300) {
        EXPECT_NEAR(e->superposition_shares[m - 1] / superposition, 1.0, 1e-9)
            << "a = " << a_value << ", k = " << m;
      }
    }
    // Monotone shares up to 1, and the dimensions where they first reach 0.99.
    for (std::size_t d = 1; d < n; ++d) {
      EXPECT_LE(e->truncation_shares[d - 1], e->truncation_shares[d] + 1e-15);
      EXPECT_LE(e->superposition_shares[d - 1], e->superposition_shares[d] + 1e-15);
    }
    EXPECT_GE(e->truncation_shares[e->truncation - 1], 0.99 - 1e-12);
    if (e->truncation > 1) {
      EXPECT_LT(e->truncation_shares[e->truncation - 2], 0.99);
    }
    EXPECT_GE(e->superposition_shares[e->superposition - 1], 0.99 - 1e-12);
    if (e->superposition > 1) {
      EXPECT_LT(e->superposition_shares[e->superposition - 2], 0.99);
    }
  }
}

// Decaying coefficients concentrate the variance in the first coordinates: Sobol' g with
// aⱼ = j² (r_j = 1/(3(1 + j²)²)) has d_T small and d_S = 1 or 2 at s = 256, while equal
// coefficients spread it over every axis (d_T = s).
TEST(EffectiveDimension, DecayingCoefficientsLowerTheTruncationDimension) {
  std::vector<double> decaying, equal(256, 0.0);
  for (std::size_t j = 1; j <= 256; ++j) decaying.push_back(static_cast<double>(j * j));
  const auto low = exact_effective_dimensions(*sobol_g(decaying).info().moments);
  const auto high = exact_effective_dimensions(*sobol_g(equal).info().moments);
  ASSERT_TRUE(low && high);
  EXPECT_LT(low->truncation, 10U);
  EXPECT_LE(low->superposition, 2U);
  EXPECT_EQ(high->truncation, 256U);
}

// A nearly constant factor (r = 2^−46 ≈ 1.4e-14, given exactly: E g² = 1 + 2^−46) keeps its
// digits: with one such axis first and a varying one second (r₂ = ½), the first axis carries
// r/(r + r₂ + r·r₂) of the variance, which 1 − (1 − r)-style cancellation would get wrong in the
// second digit.
TEST(EffectiveDimension, ANearlyConstantFactorKeepsItsDigits) {
  const double tiny = std::ldexp(1.0, -46);
  separable_moments f;
  f.factors.push_back({1.0, 1.0 + tiny, 1.0 + tiny});
  f.factors.push_back({1.0, 1.5, 1.5});
  const auto e = exact_effective_dimensions(f);
  ASSERT_TRUE(e.has_value());
  const double expected = tiny / (tiny + 0.5 + tiny * 0.5);
  EXPECT_NEAR(e->truncation_shares[0] / expected, 1.0, 1e-12);
  EXPECT_EQ(e->truncation, 2U);
  EXPECT_EQ(e->superposition, 1U);
}

TEST(EffectiveDimension, NoAnswerWithoutVarianceOrWithAZeroMean) {
  separable_moments constant;
  constant.factors.assign(3, {2.0, 4.0, 4.0});
  EXPECT_FALSE(exact_effective_dimensions(constant).has_value());
  // A factor of mean 0 (cos 2πx: E g = 0, E g² = ½): the normalised form cannot divide by it.
  separable_moments zero_mean;
  zero_mean.factors = {{0.0, 0.5, 0.5}, {1.0, 1.5, 1.5}};
  EXPECT_FALSE(exact_effective_dimensions(zero_mean).has_value());
  EXPECT_THROW(exact_effective_dimensions(*sobol_g({1.0}).info().moments, 0.0), invalid_argument);
  EXPECT_THROW(exact_effective_dimensions(*sobol_g({1.0}).info().moments, 1.5), invalid_argument);
}

// The pick-freeze estimate on a product family, whose exact shares are known: every interval
// covers its exact value. Each interval is at confidence 1 − 5e-6; the test reads three of them,
// and d_T's interval rests on the probes of three bisections over d ∈ [1, 6], at most 9 intervals:
// false alarm ≤ 12 × 5e-6 = 6e-5 (the delta method's normal approximation, n = 4096 rows).
TEST(EffectiveDimensionEstimate, CoversTheExactSharesOfAProductFamily) {
  const sobol_g g({0.0, 0.5, 1.0, 2.0, 4.0, 8.0});
  const auto exact = exact_effective_dimensions(*g.info().moments);
  ASSERT_TRUE(exact.has_value());
  effective_dimension_estimate_options o;
  o.confidence = 1.0 - 5e-6;
  const auto e = estimate_effective_dimensions(any_integrand(g), 20261205, o);
  ASSERT_TRUE(e.has_value() && e->first_order && e->mean_dimension);
  double mean_dimension = 0.0, below = 0.0;
  for (std::size_t k = 1; k <= 6; ++k) {
    mean_dimension += static_cast<double>(k) * (exact->superposition_shares[k - 1] - below);
    below = exact->superposition_shares[k - 1];
  }
  const auto covers = [](const estimated_share& i, double value, const char* what) {
    EXPECT_LE(i.low, value) << what << ": " << i.value << " [" << i.low << ", " << i.high << "]";
    EXPECT_GE(i.high, value) << what << ": " << i.value << " [" << i.low << ", " << i.high << "]";
    // Not vacuous: at 4.56 standard errors each side, a width of 0.3 is a 95 % half-width of
    // 0.064 (measured here: 0.16 to 0.26, standard errors of 0.018 to 0.028 at n = 4096).
    EXPECT_LT(i.high - i.low, 0.3) << what << ": an interval that says nothing";
  };
  covers(e->first_coordinate, exact->truncation_shares[0], "share of x₁");
  covers(*e->first_order, exact->superposition_shares[0], "share of order 1");
  covers(*e->mean_dimension, mean_dimension, "mean dimension");
  EXPECT_LE(e->truncation_low, exact->truncation);
  EXPECT_GE(e->truncation_high, exact->truncation);
  // d_S's range, from the order-1 interval, holds the exact d_S.
  EXPECT_LE(e->superposition_low, exact->superposition);
  EXPECT_TRUE(e->superposition_high == 0 || e->superposition_high >= exact->superposition);
  // A case where neither answer is trivial: d_T inside (1, s), order 1 below 99 %.
  EXPECT_GT(exact->truncation, 1U);
  EXPECT_LT(exact->truncation, 6U);
  EXPECT_LT(exact->superposition_shares[0], 0.99);
  EXPECT_EQ(e->samples, 4096U);
  EXPECT_EQ(e->first_order_samples, 4096U);
}

TEST(EffectiveDimensionEstimate, SameSeedSameBitsAndBadOptionsAreNamed) {
  const any_integrand f(genz_corner_peak({1.0, 2.0, 0.5}, {0.0, 0.0, 0.0}));
  const auto one = estimate_effective_dimensions(f, 7);
  const auto two = estimate_effective_dimensions(f, 7);
  const auto other = estimate_effective_dimensions(f, 8);
  ASSERT_TRUE(one && two && other);
  EXPECT_EQ(one->first_coordinate.value, two->first_coordinate.value);
  EXPECT_EQ(one->first_order->value, two->first_order->value);
  EXPECT_EQ(one->evaluations, two->evaluations);
  EXPECT_NE(one->first_coordinate.value, other->first_coordinate.value);
  effective_dimension_estimate_options bad;
  bad.samples = 1;
  EXPECT_NE(test_support::message_of([&] {
              (void)estimate_effective_dimensions(f, 7, bad);
            }).find("samples"),
            std::string::npos);
  bad = {};
  bad.confidence = 1.0;
  EXPECT_NE(test_support::message_of([&] {
              (void)estimate_effective_dimensions(f, 7, bad);
            }).find("confidence"),
            std::string::npos);
  // One dimension has nothing to split.
  EXPECT_FALSE(estimate_effective_dimensions(any_integrand(genz_corner_peak({1.0}, {0.0})), 7));
}

// The geometric Asian option at s = 64 (not a product: the estimate is its only answer): the
// PCA construction puts the largest share of the variance on x₁, the bridge the next, the
// standard construction little (x₁ moves the whole path by √Δt only). Three intervals at
// confidence 1 − 5e-6: false alarm ≤ 1.5e-5.
TEST(EffectiveDimensionEstimate, PcaPutsTheLargestShareOnTheFirstCoordinate) {
  effective_dimension_estimate_options o;
  o.confidence = 1.0 - 5e-6;
  o.first_order_coordinates = 0;  // the truncation part only
  std::vector<estimated_share> first;
  for (const path_construction c :
       {path_construction::standard, path_construction::bridge, path_construction::pca}) {
    geometric_asian_parameters p;
    p.construction = c;
    const auto e = estimate_effective_dimensions(any_integrand(geometric_asian(64, p)), 11, o);
    ASSERT_TRUE(e.has_value()) << to_string(c);
    EXPECT_FALSE(e->first_order.has_value());
    first.push_back(e->first_coordinate);
  }
  EXPECT_LT(first[0].high, first[1].low)
      << "standard " << first[0].value << ", bridge " << first[1].value;
  EXPECT_LT(first[1].high, first[2].low)
      << "bridge " << first[1].value << ", pca " << first[2].value;
}

}  // namespace
