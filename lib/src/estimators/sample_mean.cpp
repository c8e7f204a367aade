// The kernel of estimators/sample_mean.hpp, compiled once: chunks of the point set, the
// statistics of each, folded in chunk order by parallel_reduce (core/parallel_reduce.hpp), over
// the batches that the caller's template code makes (detail::sample_batch_source). The header
// says why the chunks are what they are and why the bits do not depend on the thread count.
#include "quadmc/estimators/sample_mean.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/core/parallel_reduce.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc::detail {

estimate sample_mean_of_batches(std::uint64_t n, std::size_t s, variance_structure structure,
                                unsigned threads, sample_batch_source make_batch) {
  const std::uint64_t group = structure.points_per_group();
  const chunking layout{n, group * std::max<std::uint64_t>(1, sample_chunk_points / group)};
  const sample_statistics total = parallel_reduce(
      layout.chunks(), threads, sample_statistics(structure),
      [&](std::size_t c) {
        sample_statistics stats(structure);
        std::vector<double> u(batch_points * s);
        std::vector<double> y(batch_points);
        for_each_batch(layout, c, [&](std::uint64_t first, std::size_t count) {
          const std::span<double> ub(u.data(), count * s);
          const std::span<double> yb(y.data(), count);
          make_batch(first, ub, yb);
          stats.add_batch(first, yb);
        });
        return stats;
      },
      [](sample_statistics& acc, const sample_statistics& part) { acc.merge(part); });
  return total.result();
}

}  // namespace quadmc::detail
