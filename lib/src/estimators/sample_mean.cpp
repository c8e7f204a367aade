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
                                unsigned threads, std::size_t block,
                                sample_point_source make_points, sample_value_source make_values) {
  const std::uint64_t group = structure.points_per_group();
  const chunking layout{n, group * std::max<std::uint64_t>(1, sample_chunk_points / group)};
  // No block longer than a chunk: its buffers are the chunk's, allocated once per chunk.
  const std::size_t block_points = static_cast<std::size_t>(std::min<std::uint64_t>(
      evaluation_block_points(block), std::max<std::uint64_t>(batch_points, layout.chunk)));
  const sample_statistics total = parallel_reduce(
      layout.chunks(), threads, sample_statistics(structure),
      [&](std::size_t c) {
        sample_statistics stats(structure);
        std::vector<double> u(block_points * s);
        std::vector<double> y(block_points);
        // Points and statistics per batch (core/batching.hpp), values per block.
        for_each_block(layout, c, block_points, [&](std::uint64_t first, std::size_t count) {
          for_each_batch_of(count, [&](std::size_t offset, std::size_t k) {
            make_points(first + offset, std::span<double>(u.data() + offset * s, k * s));
          });
          make_values(first, std::span<double>(u.data(), count * s),
                      std::span<double>(y.data(), count));
          for_each_batch_of(count, [&](std::size_t offset, std::size_t k) {
            stats.add_batch(first + offset, std::span<const double>(y.data() + offset, k));
          });
        });
        return stats;
      },
      [](sample_statistics& acc, const sample_statistics& part) { acc.merge(part); });
  return total.result();
}

}  // namespace quadmc::detail
