// Importance sampling: F = (1/N)Σ f(Xᵢ)/p(Xᵢ) with Xᵢ = warp(Uᵢ) (docs/theory.md#importance;
// [Ramamoorthi 2009, §4.1]).
//
// Use it when a density p roughly proportional to |f| can be sampled: the variance is
// (∫f²/p − I²)/N, zero when p ∝ f and f keeps one sign (docs/theory.md#zero-variance). A poor p can
// make it larger than plain Monte Carlo (and infinite when p → 0 faster than f²), which the tests
// show. Any point set can feed the warp (stratified u gives stratified X). Not when the warp's
// support misses part of f's: the estimate is then biased, and we throw instead of returning it.
//
// The warp's output must lie in the integrand's domain and its pdf must be a density with
// respect to the measure f is integrated against (sampling/warp.hpp). No box volume enters.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/estimators/estimate.hpp"
#include "quadmc/estimators/sample_mean.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/sampling/point_set.hpp"
#include "quadmc/sampling/warp.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace quadmc {

// The pdf was 0 (or negative, or not finite) at a sample where f ≠ 0: X came from outside the
// warp's claimed support, so f/p is undefined there and the estimator would be biased.
[[noreturn]] inline void throw_pdf_not_positive(std::string_view integrand_name,
                                                std::span<const double> x, double f, double p) {
  throw invalid_argument(fmt::format(
      "importance sampling of {}: pdf = {} at x = ({}) where f = {}; expected pdf > 0 wherever "
      "f ≠ 0 (the warp must cover the integrand's support)",
      integrand_name, p, fmt::join(x, ", "), f));
}

template <integrand F, warp W, point_set P>
estimate importance_sampling(const F& f, const W& w, const P& points, unsigned threads = 1) {
  const integrand_info info = f.info();
  const std::size_t s_in = w.input_dimension();
  const std::size_t s_out = w.output_dimension();
  require(points.dimension() == s_in, "point set dimension", points.dimension(),
          "the warp's input dimension " + std::to_string(s_in));
  require(f.dimension() == s_out, "integrand dimension", f.dimension(),
          "the warp's output dimension " + std::to_string(s_out));
  const auto values = [&](std::uint64_t, std::span<double> u, std::span<double> y) {
    // x and p are per-batch scratch: thread_local so a chunk allocates once.
    thread_local std::vector<double> x;
    thread_local std::vector<double> p;
    x.resize(y.size() * s_out);
    p.resize(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) {
      const std::span<double> xi(x.data() + i * s_out, s_out);
      w.sample(std::span<const double>(u.data() + i * s_in, s_in), xi);
      p[i] = w.pdf(std::span<const double>(xi));
    }
    const std::span<const double> xs(x.data(), y.size() * s_out);
    f.evaluate(xs, y);
    check_finite_batch(info.name, xs, y, s_out);
    for (std::size_t i = 0; i < y.size(); ++i) {
      if (y[i] == 0.0) continue;  // f = 0: contributes 0 whatever p is
      if (!(p[i] > 0.0) || !std::isfinite(p[i])) [[unlikely]] {
        throw_pdf_not_positive(info.name, xs.subspan(i * s_out, s_out), y[i], p[i]);
      }
      y[i] /= p[i];
    }
  };
  return sample_mean(points, threads, values, info.evaluation_block);
}

}  // namespace quadmc
