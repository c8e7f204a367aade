// The sample mean of a periodized integrand: F = vol(box)·(1/N)Σ g(Uᵢ) with
// g(u) = f(a + (b − a)∘φ(u))·∏_j φ'(u_j), for a periodizing transform φ of
// sampling/periodizing_transforms.hpp (docs/theory.md#lattice-periodizations). ∫g = ∫f/vol:
// the transform changes the error, not the value estimated.
//
// Use it with a randomly shifted lattice (the `lattice` method's `periodization = "c0"` …
// `"c3sin"`) on smooth, non-periodic f: g is periodic with m − 1 derivatives, so the lattice's
// rate steepens from −1 to −(m + 1). Not for discontinuous f (no gain is proven there), and with
// care in high s, where ∏φ' grows the variance ((∫φ'²)^s on f = 1). The points themselves are the
// set's (generated as monte_carlo's are); per batch the transform replaces them in place and the
// weights ∏φ' multiply f's values: no allocation, virtual call or lock per point, and the same
// chunks as monte_carlo (estimators/sample_mean.hpp), so the bits do not depend on the thread
// count.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/estimators/estimate.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/estimators/sample_mean.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/sampling/periodizing_transforms.hpp"
#include "quadmc/sampling/point_set.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace quadmc {

template <periodizing_transform T, integrand F, point_set P>
estimate periodized_monte_carlo(const F& f, const P& points, unsigned threads = 1) {
  const integrand_info info = f.info();
  const std::size_t s = f.dimension();
  const box_map to_box(info, s, points.dimension());
  const double volume = to_box.volume();
  const auto values = [&](std::uint64_t, std::span<double> x, std::span<double> y) {
    // The weights of one batch on the stack; an integrand that asks for blocks of several
    // batches per call (integrand_info::evaluation_block, a call that costs microseconds) gets
    // them from the heap, once per block.
    double on_stack[batch_points];
    std::vector<double> on_heap;
    std::span<double> weight(on_stack, y.size() <= batch_points ? y.size() : 0);
    if (y.size() > batch_points) {
      on_heap.resize(y.size());
      weight = on_heap;
    }
    periodize_points<T>(x, s, weight);
    to_box.apply(x);
    f.evaluate(std::span<const double>(x), y);
    check_finite_batch(info.name, x, y, s);
    for (std::size_t i = 0; i < y.size(); ++i) y[i] *= weight[i];
    // ∏φ' ≤ (8/3)^s can overflow only beyond s ≈ 720, near the cube's centre: say so rather
    // than average an infinity (v·0 is NaN exactly for a value that is not finite).
    double any_nan = 0.0;
    for (const double v : y) any_nan += v * 0.0;
    if (std::isnan(any_nan)) [[unlikely]] {
      for (std::size_t i = 0; i < y.size(); ++i) {
        if (!std::isfinite(y[i])) {
          throw non_finite_value(info.name + " times the " + std::string(T::name) + " Jacobian",
                                 std::span<const double>(x).subspan(i * s, s), y[i]);
        }
      }
    }
  };
  estimate e = sample_mean(points, threads, values, info.evaluation_block);
  e.value *= volume;
  e.std_error *= volume;
  e.variance *= volume * volume;
  return e;
}

}  // namespace quadmc
