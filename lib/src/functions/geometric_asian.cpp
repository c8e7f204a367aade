// The geometric-average Asian call (geometric_asian.hpp): path constructions, evaluation and the
// closed form of [Kemna & Vorst 1990] (docs/theory.md#the-geometric-asian-option).
#include "quadmc/functions/geometric_asian.hpp"

#include "quadmc/core/errors.hpp"

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/erf.hpp>

#include <fmt/format.h>

#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <utility>

namespace quadmc {
namespace {

// Φ(x) = erfc(−x/√2)/2, accurate in both tails (1 − Φ would cancel for x ≫ 0).
double normal_cdf(double x) {
  return 0.5 * boost::math::erfc(-x / std::numbers::sqrt2);
}

// The largest |Φ⁻¹(x)| over doubles x in (0, 1): at the smallest subnormal, ≈ 38.47 (the other
// side stops at 1 − 2⁻⁵³, ≈ 8.3). It bounds every path, hence every value (see the constructor).
double largest_normal() {
  return std::numbers::sqrt2 *
         boost::math::erfc_inv(2.0 * std::numeric_limits<double>::denorm_min());
}

}  // namespace

std::string_view to_string(path_construction c) noexcept {
  return path_construction_names[static_cast<std::size_t>(c)];
}

path_construction parse_path_construction(std::string_view text) {
  for (std::size_t i = 0; i < path_construction_names.size(); ++i) {
    if (text == path_construction_names[i]) return static_cast<path_construction>(i);
  }
  throw invalid_argument("construction", fmt::format("\"{}\"", text),
                         "one of \"standard\", \"bridge\", \"pca\"");
}

double geometric_asian::exact_value(std::size_t s, const geometric_asian_parameters& p) {
  const double sd = static_cast<double>(s);
  const double mean = std::log(p.spot) + (p.rate - 0.5 * p.volatility * p.volatility) * p.maturity *
                                             (sd + 1.0) / (2.0 * sd);
  const double variance =
      p.volatility * p.volatility * p.maturity * (sd + 1.0) * (2.0 * sd + 1.0) / (6.0 * sd * sd);
  const double root = std::sqrt(variance);
  const double d2 = (mean - std::log(p.strike)) / root;
  return std::exp(-p.rate * p.maturity) *
         (std::exp(mean + 0.5 * variance) * normal_cdf(d2 + root) - p.strike * normal_cdf(d2));
}

geometric_asian::geometric_asian(std::size_t s, const geometric_asian_parameters& p)
    : s_(s), p_(p) {
  require(s >= 1 && s <= max_dimension, "dimension", s, "1 ≤ s ≤ 1024");
  require(std::isfinite(p.spot) && p.spot > 0.0, "spot", p.spot, "a finite number > 0");
  require(std::isfinite(p.strike) && p.strike > 0.0, "strike", p.strike, "a finite number > 0");
  require(std::isfinite(p.rate), "rate", p.rate, "a finite number");
  require(std::isfinite(p.volatility) && p.volatility > 0.0, "volatility", p.volatility,
          "a finite number > 0");
  require(std::isfinite(p.maturity) && p.maturity > 0.0, "maturity", p.maturity,
          "a finite number > 0");
  const double sd = static_cast<double>(s);
  const double dt = p.maturity / sd;
  sqrt_dt_ = std::sqrt(dt);
  log_drift_ = std::log(p.spot) +
               (p.rate - 0.5 * p.volatility * p.volatility) * p.maturity * (sd + 1.0) / (2.0 * sd);
  discount_ = std::exp(-p.rate * p.maturity);
  // Every construction writes W(tᵢ) = aᵢ·z with ‖aᵢ‖² = tᵢ ≤ T, so |W(tᵢ)| ≤ √T·‖z‖ ≤ √(sT)·z_max
  // (Cauchy–Schwarz) and |log G − μ| ≤ σ√(sT)·z_max: when e^(that + |μ| − rT) is finite, so is
  // every value f can take at a double in (0, 1)^s, and a rule's node next to a face cannot
  // overflow. The default at s = 1024 uses 251 of the 709.78 available.
  const double z_max = largest_normal();
  const double log_bound = std::abs(log_drift_) + p.volatility * std::sqrt(sd * p.maturity) * z_max;
  require(std::isfinite(discount_) && discount_ > 0.0 &&
              log_bound - p.rate * p.maturity < std::log(std::numeric_limits<double>::max()),
          "volatility", p.volatility,
          fmt::format("|log S₀ + (r − σ²/2)T(s+1)/(2s)| + σ·√(sT)·{:.4g} − rT < 709.78 (every "
                      "value finite), here {:.4g}",
                      z_max, log_bound - p.rate * p.maturity));

  if (p.construction == path_construction::bridge) {
    // Breadth first over the intervals of time indices (0 stands for W(0) = 0, j for tⱼ): each
    // interval's midpoint, the floor of it when the interval is odd, takes the next z, so the
    // coarse shape of the path comes first whatever s is [Caflisch, Morokoff & Owen 1997].
    // Given W at times l < m < r, W(m) is normal with mean ((r − m)W(l) + (m − l)W(r))/(r − l)
    // and variance Δt·(m − l)(r − m)/(r − l).
    std::deque<std::pair<std::size_t, std::size_t>> intervals{{0, s}};
    while (!intervals.empty()) {
      const auto [l, r] = intervals.front();
      intervals.pop_front();
      if (r - l < 2) continue;
      const std::size_t m = l + (r - l) / 2;
      const double width = static_cast<double>(r - l);
      const double a = static_cast<double>(m - l), b = static_cast<double>(r - m);
      bridge_.push_back({l, r, m, b / width, a / width, std::sqrt(dt * a * b / width)});
      intervals.emplace_back(l, m);
      intervals.emplace_back(m, r);
    }
  } else if (p.construction == path_construction::pca) {
    // The covariance Δt·min(i, j) has the eigenpairs (docs/theory.md#the-geometric-asian-option)
    //   vₖ(i) = 2/√(2s+1)·sin((2k−1)iπ/(2s+1)),  λₖ = Δt/(4 sin²((2k−1)π/(2(2s+1)))),
    // k = 1..s, λ₁ the largest; the column k of V·Λ^(1/2) is √λₖ·vₖ.
    pca_.resize(s * s);
    const double n = 2.0 * sd + 1.0;
    for (std::size_t k = 1; k <= s; ++k) {
      const double odd = static_cast<double>(2 * k - 1);
      const double half_angle = std::sin(odd * std::numbers::pi / (2.0 * n));
      const double scale = 2.0 / std::sqrt(n) * sqrt_dt_ / (2.0 * half_angle);
      for (std::size_t i = 1; i <= s; ++i) {
        pca_[(i - 1) * s + (k - 1)] =
            scale * std::sin(odd * static_cast<double>(i) * std::numbers::pi / n);
      }
    }
  }
  exact_ = exact_value(s, p);
}

void geometric_asian::path(std::span<const double> z, std::span<double> w) const noexcept {
  switch (p_.construction) {
    case path_construction::standard: {
      double sum = 0.0;
      for (std::size_t i = 0; i < s_; ++i) w[i] = sum += sqrt_dt_ * z[i];
      return;
    }
    case path_construction::bridge: {
      // w[j − 1] = W(tⱼ); time index 0 reads as W(0) = 0.
      const auto at = [&](std::size_t j) { return j == 0 ? 0.0 : w[j - 1]; };
      w[s_ - 1] = std::sqrt(p_.maturity) * z[0];
      for (std::size_t k = 0; k < bridge_.size(); ++k) {
        const bridge_step& b = bridge_[k];
        w[b.index - 1] =
            b.left_weight * at(b.left) + b.right_weight * at(b.right) + b.sd * z[k + 1];
      }
      return;
    }
    case path_construction::pca: {
      for (std::size_t i = 0; i < s_; ++i) {
        const double* row = pca_.data() + i * s_;
        double sum = 0.0;
        for (std::size_t k = 0; k < s_; ++k) sum += row[k] * z[k];
        w[i] = sum;
      }
      return;
    }
  }
}

void geometric_asian::evaluate(std::span<const double> x, std::span<double> y) const noexcept {
  using namespace boost::math::policies;
  // erfc_inv(0) and erfc_inv(2) return ±∞ instead of throwing; outside [0, 2] it returns NaN.
  // promote_double<false>: Boost's double rational approximations (a few ulp) instead of its
  // default long double evaluation, which cost about 0.4 µs per coordinate here, 90 % of a run
  // at s = 1024 (measured with perf on the high_dimension scene).
  using quiet =
      policy<overflow_error<ignore_error>, domain_error<ignore_error>, promote_double<false>>;
  std::array<double, max_dimension> z, w;
  const double sigma_over_s = p_.volatility / static_cast<double>(s_);
  for (std::size_t i = 0; i < y.size(); ++i) {
    bool outside = false, face = false;
    for (std::size_t j = 0; j < s_; ++j) {
      const double xj = x[i * s_ + j];
      outside = outside || !(xj >= 0.0 && xj <= 1.0);
      face = face || xj == 0.0 || xj == 1.0;
      // Φ⁻¹(p) = −√2·erfc⁻¹(2p): accurate in both tails, unlike Φ⁻¹ through erf⁻¹(2p − 1).
      z[j] = -std::numbers::sqrt2 * boost::math::erfc_inv(2.0 * xj, quiet());
    }
    if (outside || face) {
      y[i] = outside ? std::numeric_limits<double>::quiet_NaN() : 0.0;
      continue;
    }
    path(std::span<const double>(z.data(), s_), std::span<double>(w.data(), s_));
    double sum = 0.0;
    for (std::size_t j = 0; j < s_; ++j) sum += w[j];
    const double g = std::exp(log_drift_ + sigma_over_s * sum);
    y[i] = g > p_.strike ? discount_ * (g - p_.strike) : 0.0;
  }
}

integrand_info geometric_asian::info() const {
  return integrand_info{
      .name = "geometric_asian",
      .formula =
          fmt::format("e^(−rT)·max((Π S(tᵢ))^(1/s) − K, 0), W by {}", to_string(p_.construction)),
      .domain = box::unit(s_),
      .exact = exact_,
      .reference = "closed form [Kemna & Vorst 1990]: log G normal, a Black–Scholes formula",
      .regularity = smoothness::c0};
}

}  // namespace quadmc
