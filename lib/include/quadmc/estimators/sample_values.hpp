// The values themselves, not their mean: y_i = vol·f(a + (b − a)∘x_(first+i)) for a run of
// points of a set, each written to its own place.
//
// Use it where an algorithm needs every value (the transforms of the guaranteed stopping rules,
// estimators/stopping_rules.hpp) or sums blocks of them itself (the replicate rule). Not for a
// sample mean (sample_mean.hpp keeps only the statistics and never stores N values).
//
// Chunks of sample_chunk_points run in parallel and write disjoint parts of y, so the values do
// not depend on the thread count; no chunk result is exchanged between the processes of an MPI
// run (process_local): every process computes all of its values. A Sobol' set generates in
// Gray-code order; `gray_to_natural` writes the value of the point at Gray position q to the
// place of its natural index g(q) = q ⊕ (q >> 1) instead, which for a run [2^k, 2^(k+1)) (or
// [0, 2^k)) is a permutation of the run: the order of the Walsh transform.
#pragma once

#include "quadmc/core/batching.hpp"
#include "quadmc/core/chunk_exchange.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/sampling/point_set.hpp"

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace quadmc {

template <integrand F, point_set P>
void sample_values(const F& f, const P& points, std::uint64_t first, std::span<double> y,
                   unsigned threads, bool gray_to_natural = false) {
  const integrand_info info = f.info();
  const std::size_t s = f.dimension();
  const box_map to_box(info, s, points.dimension());
  const double volume = to_box.volume();
  if (gray_to_natural) {
    const std::uint64_t n = y.size();
    require(std::has_single_bit(n) && (first == 0 || first == n), "run of points",
            std::to_string(first) + " … " + std::to_string(first + n - 1),
            "[0, 2^k) or [2^k, 2^(k+1)) (a Gray-code run that is a whole block of indices)");
  }
  const chunking layout{y.size(), sample_chunk_points};
  parallel_reduce(
      layout.chunks(), threads, process_local<int>{0},
      [&](std::size_t c) {
        std::vector<double> x(batch_points * s);
        std::vector<double> v(batch_points);
        for_each_batch(layout, c, [&](std::uint64_t offset, std::size_t count) {
          const std::span<double> batch(x.data(), count * s);
          points.generate(first + offset, batch);
          to_box.apply(batch);
          const std::span<double> values(v.data(), count);
          f.evaluate(std::span<const double>(batch), values);
          check_finite_batch(info.name, batch, values, s);
          for (std::size_t i = 0; i < count; ++i) {
            const std::uint64_t q = first + offset + i;
            const std::uint64_t at = gray_to_natural ? (q ^ (q >> 1)) - first : offset + i;
            y[at] = volume * values[i];
          }
        });
        return process_local<int>{0};
      },
      [](process_local<int>&, const process_local<int>&) {});
}

}  // namespace quadmc
