// The half-space volume (indicators.hpp), an alternating sum in 50-digit arithmetic: compiled here
// once, so that the files that include indicators.hpp neither parse Boost.Multiprecision nor
// generate its arithmetic again (docs/design.md#build-time).
#include "quadmc/functions/indicators.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/functions/inclusion_exclusion.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace quadmc {

half_space_indicator::half_space_indicator(std::vector<double> w, double t)
    : w_(std::move(w)), t_(t) {
  require(!w_.empty(), "w", w_.size(), "a non-empty vector (its length is the dimension s ≥ 1)");
  require(w_.size() <= max_dimension, "dimension", w_.size(),
          "s ≤ 20 (the half-space volume sums 2^s terms)");
  double largest = 0.0;
  for (double wi : w_) {
    require(std::isfinite(wi) && wi != 0.0, "w", wi, "finite non-zero weights wᵢ (of any sign)");
    largest = std::max(largest, std::abs(wi));
  }
  require(std::isfinite(t_), "t", t_, "a finite threshold t");
  const std::vector<double> given_w = w_;
  const int exponent = std::ilogb(largest);
  // The reflection x_j ↦ 1 − x_j of every axis with w_j < 0 keeps volumes and turns w_j·x_j into
  // w_j + |w_j|·x_j: the region is {Σ |w_j|·x_j ≤ t + Σ_(w_j<0) |w_j|}, whose volume is the
  // positive-weight closed form. The sums below are exact in 50 digits (s ≤ 20 doubles).
  wide_float below = 0;  // Σ_(w_j<0) w_j: the smallest value of w·x on the cube
  wide_float above = 0;  // Σ_(w_j>0) w_j: the largest
  std::vector<double> magnitude(w_.size());
  for (std::size_t j = 0; j < w_.size(); ++j) {
    const double given = w_[j];
    w_[j] = std::ldexp(w_[j], -exponent);
    require(std::isnormal(w_[j]), "w", given,
            fmt::format("weights within a factor 2^1021 of the largest, {}", largest));
    magnitude[j] = std::abs(w_[j]);
    (w_[j] < 0.0 ? below : above) += w_[j];
  }
  const double given_t = t_;
  t_ = std::ldexp(t_, -exponent);
  require((t_ == 0.0 || std::isnormal(t_)) && t_ > below && t_ < above, "t", given_t,
          fmt::format("a plane cutting the cube, Σ_(wᵢ<0) wᵢ = {:.17g} < t < Σ_(wᵢ>0) wᵢ = {:.17g}",
                      std::ldexp(static_cast<double>(below), exponent),
                      std::ldexp(static_cast<double>(above), exponent)));
  const std::size_t s = w_.size();
  const wide_float eps = std::numeric_limits<wide_float>::epsilon();
  const wide_float tw = wide_float(t_) - below;  // t + Σ_(w_j<0) |w_j|, exact
  const double n = static_cast<double>(s);
  // g(τ) = (t − τ)₊^s. d = t − τ is off by ≤ Δτ + ε·|t − τ|, and the power moves it by
  // ≤ s·(|d| + δ)^{s−1}·δ, plus s roundings of the power itself.
  const vertex_sum sum =
      alternating_vertex_sum(magnitude, [&](const wide_float& tau, const wide_float& dt) {
        const wide_float d = tw - tau;
        const wide_float delta = dt + eps * boost::multiprecision::abs(d);
        wide_float g =
            d > 0 ? wide_float(boost::multiprecision::pow(d, static_cast<int>(s))) : wide_float(0);
        wide_float error = n *
                               boost::multiprecision::pow(boost::multiprecision::abs(d) + delta,
                                                          static_cast<int>(s) - 1) *
                               delta +
                           n * eps * g;
        return std::pair{std::move(g), std::move(error)};
      });
  wide_float denominator = 1;
  for (std::size_t j = 0; j < s; ++j) denominator *= static_cast<double>(j + 1) * magnitude[j];
  exact_ = static_cast<double>(sum.value / denominator);
  require(exact_ >= std::numeric_limits<double>::min(), "t", given_t,
          fmt::format("a threshold whose half-space has a normal double volume (it is {:.3g})",
                      exact_));
  error_bound_ =
      static_cast<double>(sum.error_bound / boost::multiprecision::abs(sum.value) + 2 * n * eps);
  require(error_bound_ <= max_relative_error, "w",
          fmt::format("[{}] with t = {} (relative rounding bound {:.3g})", fmt::join(given_w, ", "),
                      given_t, error_bound_),
          "parameters whose closed form is accurate to 1e-10 relative (a smaller s)");
}

}  // namespace quadmc
